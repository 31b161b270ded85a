// VolPack .den density files (libvolpack's examples/denfile.c is the
// reference reader): a 62-byte header of shorts and one int, then one byte
// per voxel, x fastest.
#include <unistd.h>
#include <zlib.h>

#include <algorithm>

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "golden/quantise.hpp"
#include "golden/volume_io.hpp"

namespace cube4::golden {

namespace {

constexpr size_t kHeaderBytes = 62;
constexpr size_t kMapLenOffset = 50;     // short map_len[3]
constexpr size_t kMapLengthOffset = 58;  // int map_length
constexpr size_t kTrailerBytes = size_t{1} << 20;

struct GzCloser {
  void operator()(gzFile_s* f) const { gzclose(f); }
};

// gzerror prefixes its message with the path, which ours already names.
std::string zlib_message(gzFile_s* f, const std::string& path) {
  int err = 0;
  std::string m = gzerror(f, &err);
  if (err == Z_ERRNO) return std::strerror(errno);
  if (m.compare(0, path.size() + 2, path + ": ") == 0) m.erase(0, path.size() + 2);
  return m;
}

using GzPtr = std::unique_ptr<gzFile_s, GzCloser>;

// zlib reads uncompressed files transparently, so one reader serves both
// brainsmall.den and a gzipped brainsmall.den.gz.
GzPtr open_den(const std::string& path) {
  const int fd = open_regular_file(path, "density file");
  errno = 0;
  GzPtr f(gzdopen(fd, "rb"));
  if (!f) {
    ::close(fd);
    throw InputError(path + ": cannot open density file (" + (errno ? std::strerror(errno) : "out of memory") + ")");
  }
  gzbuffer(f.get(), 1u << 18);
  return f;
}

// Reads up to `want` bytes; fewer only at the end of the data. Only what the
// header declares is ever read, so a small file that inflates to gigabytes
// costs no more than its header says.
// The buffer grows as data arrives, so a short file declaring a large
// volume costs what the file holds, not what it declares.
std::vector<unsigned char> read_up_to(gzFile_s* f, size_t want, const std::string& path) {
  std::vector<unsigned char> buf;
  size_t got = 0;
  constexpr size_t kChunk = size_t{1} << 22;  // a few large calls keep the 1.4 MB head to milliseconds
  while (got < want) {
    const unsigned n = static_cast<unsigned>(std::min(kChunk, want - got));
    buf.resize(got + n);
    const int r = gzread(f, buf.data() + got, n);
    if (r < 0)
      throw InputError(path + ": cannot read density file, truncated or corrupt (" + zlib_message(f, path) + ")");
    got += static_cast<size_t>(r);
    if (static_cast<unsigned>(r) < n) break;
  }
  // A gzip stream cut short reads as a clean end of file; zlib flags it here.
  int err = 0;
  gzerror(f, &err);
  if (err != Z_OK)
    throw InputError(path + ": truncated or corrupt compressed density file (" + zlib_message(f, path) + ")");
  buf.resize(got);
  return buf;
}

struct DenHeader {
  bool swapped;  // written on a machine of the other byte order
  std::array<int, 3> dim;
  int64_t map_length;
};

std::string hex16(unsigned v) {
  char s[8];
  std::snprintf(s, sizeof s, "0x%04x", v & 0xffffu);
  return s;
}

// The magic short tells the file's byte order: 1 as written, 0x0100 swapped.
DenHeader parse_header(const std::vector<unsigned char>& b, const std::string& path) {
  if (b.size() < 2)
    throw InputError(path + ": truncated header (" + std::to_string(b.size()) + " of " +
                     std::to_string(kHeaderBytes) + " bytes; empty file?)");
  const unsigned magic_le = b[0] | (b[1] << 8);
  DenHeader h{};
  if (magic_le == 0x0001) {
    h.swapped = false;
  } else if (magic_le == 0x0100) {
    h.swapped = true;
  } else {
    throw InputError(path + ": not a VolPack density file (magic " + hex16(magic_le) +
                     ", expected 0x0001 or byte-swapped 0x0100)");
  }
  if (b.size() < kHeaderBytes)
    throw InputError(path + ": truncated header (" + std::to_string(b.size()) + " of " +
                     std::to_string(kHeaderBytes) + " bytes)");
  auto u16 = [&](size_t o) -> unsigned {
    return h.swapped ? (b[o] << 8) | b[o + 1] : b[o] | (b[o + 1] << 8);
  };
  auto u32 = [&](size_t o) -> uint32_t {
    const uint32_t lo = u16(o), hi = u16(o + 2);
    return h.swapped ? (lo << 16) | hi : (hi << 16) | lo;
  };
  for (int a = 0; a < 3; ++a) h.dim[a] = static_cast<int16_t>(u16(kMapLenOffset + 2 * a));
  h.map_length = static_cast<int32_t>(u32(kMapLengthOffset));
  return h;
}

void check_header(const DenHeader& h, const std::string& path) {
  const std::string dims =
      std::to_string(h.dim[0]) + "x" + std::to_string(h.dim[1]) + "x" + std::to_string(h.dim[2]);
  if (h.dim[0] <= 0 || h.dim[1] <= 0 || h.dim[2] <= 0)
    throw InputError(path + ": nonpositive dimensions " + dims + " in the header");
  const int64_t product = static_cast<int64_t>(h.dim[0]) * h.dim[1] * h.dim[2];
  if (h.map_length != product)
    throw InputError(path + ": inconsistent header: map_length is " + std::to_string(h.map_length) +
                     " but the dimensions " + dims + " give " + std::to_string(product));
}

}  // namespace

Volume load_den(const std::string& path, const Quantisation& q, int voxel_bits, bool header_only) {
  check_voxel_bits(voxel_bits);
  GzPtr f = open_den(path);
  const DenHeader h = parse_header(read_up_to(f.get(), kHeaderBytes, path), path);
  check_header(h, path);
  const size_t expected = static_cast<size_t>(h.map_length);
  check_memory(path, "the volume", volume_load_bytes(static_cast<double>(expected), 1),
               dims_text(h.dim[0], h.dim[1], h.dim[2]) + " voxels");
  Volume v;
  v.dim = h.dim;
  v.bits = voxel_bits;
  v.source = path;
  if (header_only) return v;
  const std::vector<unsigned char> bytes = read_up_to(f.get(), expected, path);
  // Like VolPack's read_den, bytes after the map are ignored; a little of
  // them is read so that a gzip stream that ends there has its CRC checked
  // (damage inside the data can inflate cleanly), without inflating a bomb.
  if (bytes.size() == expected) read_up_to(f.get(), kTrailerBytes, path);
  if (bytes.size() < expected)
    throw InputError(path + ": truncated data: expected " + std::to_string(expected) +
                     " bytes after the " + std::to_string(kHeaderBytes) + "-byte header, found " +
                     std::to_string(bytes.size()));
  v.data = quantise(bytes.data(), SampleType::UInt8, h.dim, q, voxel_bits, path);
  return v;
}

}  // namespace cube4::golden
