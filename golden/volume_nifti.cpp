// NIfTI-1 volumes (.nii, .nii.gz, .hdr/.img). The 348-byte header is read
// and checked here against the NIfTI-1 rules (nifti1.h) rather than by
// nifti_image_read, which prints its own complaints on stderr before ours
// and accepts what the standard forbids (dim[0] = 0, sizeof_hdr = 0, a NaN
// vox_offset). The data is read through niftilib's znzlib (gzip or not),
// exactly as many bytes as the header declares: nifti_image_load would
// zero-fill a short read and report success.
#include <nifti1_io.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "golden/quantise.hpp"
#include "golden/volume_io.hpp"

namespace cube4::golden {

namespace {

struct ZnzClose {
  void operator()(znzptr* f) const { Xznzclose(&f); }
};
using ZnzPtr = std::unique_ptr<znzptr, ZnzClose>;

constexpr int kHeaderBytes = 348;

template <class T>
void swap_field(T& v) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  std::reverse(b, b + sizeof(T));
  std::memcpy(&v, b, sizeof(T));
}

struct SampleInfo {
  SampleType type;
  int bytes;
};

SampleInfo sample_type(int datatype, const std::string& path) {
  switch (datatype) {
    case DT_UINT8: return {SampleType::UInt8, 1};
    case DT_INT8: return {SampleType::Int8, 1};
    case DT_UINT16: return {SampleType::UInt16, 2};
    case DT_INT16: return {SampleType::Int16, 2};
    case DT_UINT32: return {SampleType::UInt32, 4};
    case DT_INT32: return {SampleType::Int32, 4};
    case DT_FLOAT32: return {SampleType::Float32, 4};
    case DT_FLOAT64: return {SampleType::Float64, 8};
    default:
      throw InputError(path + ": NIfTI datatype " + nifti_datatype_string(datatype) + " (" +
                       std::to_string(datatype) +
                       ") is not supported (expected uint8, int8, uint16, int16, uint32, int32, "
                       "float32 or float64)");
  }
}

ZnzPtr open_znz(const std::string& path, const char* what) {
  require_regular_file(path, what);
  ZnzPtr fp(znzopen(path.c_str(), "rb", nifti_is_gzfile(path.c_str())));
  if (!fp) throw InputError(path + ": cannot open " + what);
  return fp;
}

// Reads exactly n bytes or returns how many there were.
// Reads up to n bytes. The buffer grows as data arrives, so a short file
// declaring a large volume costs what the file holds, not what it declares.
std::vector<unsigned char> read_bytes(znzFile fp, size_t n, const std::string& path) {
  std::vector<unsigned char> out;
  size_t got = 0;
  constexpr size_t kChunk = size_t{1} << 22;
  while (got < n) {
    const size_t want = std::min(kChunk, n - got);
    out.resize(got + want);
    // znzread passes on gzread's -1 for a corrupt stream, as a size_t.
    const size_t r = znzread(out.data() + got, 1, want, fp);
    if (r > want) throw InputError(path + ": corrupt compressed NIfTI file (zlib could not inflate it)");
    got += r;
    if (r < want) break;
  }
  out.resize(got);
  return out;
}

[[noreturn]] void bad_header(const std::string& path, const std::string& problem) {
  throw InputError(path + ": not a valid NIfTI-1 header: " + problem);
}

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

struct Header {
  nifti_1_header h;
  bool swapped;
  bool single_file;  // "n+1": data in the same file, after vox_offset
};

Header read_header(znzFile fp, const std::string& path) {
  Header r{};
  const std::vector<unsigned char> bytes = read_bytes(fp, kHeaderBytes, path);
  const size_t got = bytes.size();
  if (got < static_cast<size_t>(kHeaderBytes))
    bad_header(path, "truncated (" + std::to_string(got) + " of " + std::to_string(kHeaderBytes) + " bytes)");
  static_assert(sizeof(nifti_1_header) == kHeaderBytes);
  std::memcpy(&r.h, bytes.data(), kHeaderBytes);
  nifti_1_header& h = r.h;
  // sizeof_hdr is 348 in the writer's byte order: it tells the order.
  if (h.sizeof_hdr != kHeaderBytes) {
    int s = h.sizeof_hdr;
    swap_field(s);
    if (s != kHeaderBytes) bad_header(path, "sizeof_hdr is " + std::to_string(h.sizeof_hdr) + ", must be 348");
    r.swapped = true;
    swap_field(h.sizeof_hdr);
    for (auto& d : h.dim) swap_field(d);
    swap_field(h.datatype);
    swap_field(h.bitpix);
    for (auto& p : h.pixdim) swap_field(p);
    swap_field(h.vox_offset);
    swap_field(h.scl_slope);
    swap_field(h.scl_inter);
  }
  if (std::memcmp(h.magic, "n+1", 4) == 0) {
    r.single_file = true;
  } else if (std::memcmp(h.magic, "ni1", 4) == 0) {
    r.single_file = false;
  } else {
    char shown[16];
    std::snprintf(shown, sizeof shown, "%02x %02x %02x %02x", static_cast<unsigned char>(h.magic[0]),
                  static_cast<unsigned char>(h.magic[1]), static_cast<unsigned char>(h.magic[2]),
                  static_cast<unsigned char>(h.magic[3]));
    bad_header(path, std::string("magic is ") + shown + ", must be \"n+1\" or \"ni1\" (ANALYZE 7.5 is not read)");
  }
  if (h.dim[0] < 1 || h.dim[0] > 7)
    bad_header(path, "dim[0] = " + std::to_string(h.dim[0]) + " is out of range 1..7");
  for (int i = 1; i <= h.dim[0]; ++i)
    if (h.dim[i] < 1)
      bad_header(path, "dim[" + std::to_string(i) + "] = " + std::to_string(h.dim[i]) + " must be >= 1");
  const double off = h.vox_offset;
  const double min_off = r.single_file ? 352 : 0;
  if (!std::isfinite(off) || off != std::floor(off) || off < min_off || off > 0x1p52)
    bad_header(path, "vox_offset = " + fmt(off) + " must be a whole number >= " + fmt(min_off) +
                         (r.single_file ? " in a single-file (.nii) image" : ""));
  return r;
}

// .hdr -> .img, keeping a .gz, or trying the other if that file is missing.
std::string image_file_of(const std::string& hdr) {
  const bool gz = hdr.size() > 3 && hdr.compare(hdr.size() - 3, 3, ".gz") == 0;
  const std::string stem = hdr.substr(0, hdr.size() - (gz ? 7 : 4));
  const std::string first = stem + (gz ? ".img.gz" : ".img"), second = stem + (gz ? ".img" : ".img.gz");
  std::error_code ec;
  return std::filesystem::exists(first, ec) || !std::filesystem::exists(second, ec) ? first : second;
}

double spacing_of(float pixdim) {
  const double d = std::fabs(static_cast<double>(pixdim));
  return (d > 0 && std::isfinite(d)) ? d : 1.0;  // 0 means "unknown" in many writers
}

Scaling scaling_of(const nifti_1_header& h) {
  // scl_slope 0 means "no scaling" in the NIfTI-1 standard.
  const double slope = h.scl_slope, inter = h.scl_inter;
  if (slope == 0 || !std::isfinite(slope)) return {};
  return {slope, std::isfinite(inter) ? inter : 0.0};
}

void swap_samples(unsigned char* p, size_t count, size_t width) {
  if (width == 1) return;
  for (size_t i = 0; i < count; ++i, p += width) std::reverse(p, p + width);
}

}  // namespace

Volume load_nifti(const std::string& path, const Quantisation& q, int voxel_bits, bool header_only) {
  check_voxel_bits(voxel_bits);
  ZnzPtr fp = open_znz(path, "NIfTI file");
  const Header hd = read_header(fp.get(), path);
  const nifti_1_header& h = hd.h;
  const SampleInfo t = sample_type(h.datatype, path);
  if (h.bitpix != 8 * t.bytes)
    bad_header(path, "bitpix = " + std::to_string(h.bitpix) + " does not match datatype " +
                         nifti_datatype_string(h.datatype) + " (" + std::to_string(8 * t.bytes) + ")");
  std::array<int, 7> d{1, 1, 1, 1, 1, 1, 1};
  for (int i = 1; i <= h.dim[0]; ++i) d[static_cast<size_t>(i - 1)] = h.dim[i];
  // Time series, vector and tensor images have no single scalar per voxel.
  if (d[3] > 1 || d[4] > 1 || d[5] > 1 || d[6] > 1) {
    std::string all;
    for (int i = 1; i <= h.dim[0]; ++i) all += (i > 1 ? "x" : "") + std::to_string(h.dim[i]);
    throw InputError(path + ": NIfTI image is " + std::to_string(h.dim[0]) + "-D (" + all +
                     "); only 3-D scalar volumes are supported");
  }
  const std::array<int, 3> dim{d[0], d[1], d[2]};
  const double voxels = static_cast<double>(dim[0]) * dim[1] * dim[2];
  check_memory(path, "the volume", volume_load_bytes(voxels, t.bytes),
               dims_text(dim[0], dim[1], dim[2]) + " voxels of " + std::to_string(t.bytes) + " bytes");
  Volume v;
  v.dim = dim;
  v.spacing = {spacing_of(h.pixdim[1]), spacing_of(h.pixdim[2]), spacing_of(h.pixdim[3])};
  v.bits = voxel_bits;
  v.source = path;
  if (header_only) return v;
  const std::string iname = hd.single_file ? path : image_file_of(path);
  ZnzPtr data_fp = hd.single_file ? std::move(fp) : open_znz(iname, "NIfTI data file");
  const size_t ntot = static_cast<size_t>(voxels) * static_cast<size_t>(t.bytes);
  const long offset = static_cast<long>(h.vox_offset);
  std::vector<unsigned char> data;
  if (znzseek(data_fp.get(), offset, SEEK_SET) >= 0) data = read_bytes(data_fp.get(), ntot, iname);
  const size_t got = data.size();
  if (got != ntot)
    throw InputError(iname + ": truncated or corrupt NIfTI data: expected " + std::to_string(ntot) +
                     " bytes at offset " + std::to_string(offset) + ", found " + std::to_string(got));
  // As for .den.gz: reading a little past the data has zlib check the CRC
  // of a stream that ends there.
  read_bytes(data_fp.get(), size_t{1} << 20, iname);
  if (hd.swapped) swap_samples(data.data(), static_cast<size_t>(voxels), static_cast<size_t>(t.bytes));
  v.data = quantise(data.data(), t.type, dim, q, voxel_bits, path, scaling_of(h));
  return v;
}

}  // namespace cube4::golden
