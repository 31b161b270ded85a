// Headerless ("raw") volumes: the scene supplies what the file cannot, so
// the file size is the only check that the description matches the file.
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "golden/quantise.hpp"
#include "golden/volume_io.hpp"

namespace cube4::golden {

namespace {

SampleType parse_type(const std::string& s) {
  static const std::pair<const char*, SampleType> kTypes[] = {
      {"uint8", SampleType::UInt8},     {"uint12", SampleType::UInt12},
      {"uint16", SampleType::UInt16},   {"int16", SampleType::Int16},
      {"uint32", SampleType::UInt32},   {"int32", SampleType::Int32},
      {"float32", SampleType::Float32}, {"float64", SampleType::Float64}};
  for (const auto& [name, t] : kTypes)
    if (s == name) return t;
  throw InputError("volume.type: unknown raw sample type '" + s +
                   "' (expected uint8, uint12, uint16, int16, uint32, int32, float32 or float64)");
}

bool parse_big_endian(const std::string& s) {
  if (s == "little") return false;
  if (s == "big") return true;
  throw InputError("volume.endian: unknown byte order '" + s + "' (expected little or big)");
}

void check_dim(const std::array<int, 3>& d) {
  if (d[0] <= 0 || d[1] <= 0 || d[2] <= 0)
    throw InputError("volume.dim: raw volumes need positive dimensions, got " +
                     std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" +
                     std::to_string(d[2]));
}

// Guards the byte count against overflow before any arithmetic in integers.
void check_size(const std::array<int, 3>& d, uint64_t width, uint64_t header) {
  const double bytes =
      static_cast<double>(d[0]) * d[1] * d[2] * width + static_cast<double>(header);
  if (bytes > 0x1p62)
    throw InputError("volume.dim: " + std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" +
                     std::to_string(d[2]) + " with header " + std::to_string(header) +
                     " bytes is too large a file to load");
}

std::vector<unsigned char> read_exact(const std::string& path, uint64_t expected,
                                      const std::string& layout) {
  const FdCloser fd{open_regular_file(path, "raw volume")};
  struct stat st {};
  if (::fstat(fd.fd, &st) != 0) throw InputError(path + ": cannot open raw volume (" + std::strerror(errno) + ")");
  const auto actual = static_cast<uint64_t>(st.st_size);
  // A larger file is as suspicious as a short one: the description is wrong.
  if (actual != expected)
    throw InputError(path + ": file is " + std::to_string(actual) + " bytes, expected " +
                     std::to_string(expected) + " (" + layout + ")");
  std::vector<unsigned char> buf(static_cast<size_t>(expected));
  const size_t got = read_fd(fd.fd, buf.data(), buf.size(), path, "raw volume");
  if (got != expected)
    throw InputError(path + ": read " + std::to_string(got) + " of " + std::to_string(expected) + " bytes");
  return buf;
}

bool host_is_big_endian() {
  const uint16_t probe = 1;
  unsigned char first;
  std::memcpy(&first, &probe, 1);
  return first == 0;
}

void swap_samples(unsigned char* p, size_t count, size_t width) {
  if (width == 1) return;
  for (size_t i = 0; i < count; ++i, p += width) std::reverse(p, p + width);
}

}  // namespace

Volume load_raw(const VolumeSource& src, const std::string& path, int voxel_bits, bool header_only) {
  check_voxel_bits(voxel_bits);
  const SampleType t = parse_type(src.type);
  const bool big = parse_big_endian(src.endian);
  check_dim(src.dim);
  const uint64_t n = static_cast<uint64_t>(src.dim[0]) * src.dim[1] * src.dim[2];
  const uint64_t width = sample_bytes(t);
  check_size(src.dim, width, src.header_bytes);
  const std::string layout = "header " + std::to_string(src.header_bytes) + " + " +
                             std::to_string(src.dim[0]) + "x" + std::to_string(src.dim[1]) + "x" +
                             std::to_string(src.dim[2]) + " voxels x " + std::to_string(width) +
                             " bytes " + src.type;
  check_memory(path, "the volume", volume_load_bytes(static_cast<double>(n), static_cast<double>(width)),
               dims_text(src.dim[0], src.dim[1], src.dim[2]) + " voxels of " + std::to_string(width) + " bytes");
  Volume v;
  v.dim = src.dim;
  v.bits = voxel_bits;
  v.source = path;
  if (header_only) return v;
  std::vector<unsigned char> bytes = read_exact(path, src.header_bytes + n * width, layout);
  unsigned char* samples = bytes.data() + src.header_bytes;
  if (big != host_is_big_endian()) swap_samples(samples, n, width);
  v.data = quantise(samples, t, src.dim, src.quantisation, voxel_bits, path);
  return v;
}

}  // namespace cube4::golden
