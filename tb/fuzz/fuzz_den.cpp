// The VolPack .den loader (plain and gzipped) on arbitrary bytes.
#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "golden/volume_io.hpp"
#include "tb/fuzz/fuzz_support.hpp"

namespace {

using namespace cube4;

fuzz::Bytes den(int nx, int ny, int nz, bool big) {
  fuzz::Bytes b;
  auto put16 = [&](unsigned v) {
    const auto lo = static_cast<unsigned char>(v & 0xff), hi = static_cast<unsigned char>((v >> 8) & 0xff);
    b.push_back(big ? hi : lo);
    b.push_back(big ? lo : hi);
  };
  put16(1);
  for (int block = 0; block < 3; ++block) {  // orig, extr, map: min, max, len
    for (int i = 0; i < 3; ++i) put16(0);
    put16(nx - 1), put16(ny - 1), put16(nz - 1);
    put16(nx), put16(ny), put16(nz);
  }
  put16(0);
  const unsigned n = static_cast<unsigned>(nx * ny * nz);
  put16(big ? n >> 16 : n & 0xffff), put16(big ? n & 0xffff : n >> 16);
  for (unsigned i = 0; i < n; ++i) b.push_back(static_cast<unsigned char>(i * 37));
  return b;
}

}  // namespace

void cube4::fuzz::write_seeds(const std::string& dir) {
  fuzz::write_seed(dir, "small.den", den(3, 2, 2, false));
  fuzz::write_seed(dir, "big_endian.den", den(2, 3, 4, true));
  fuzz::write_seed(dir, "small.den.gz", fuzz::gzip(den(4, 4, 4, false)));
  fuzz::write_seed(dir, "header_only.den", den(1, 1, 1, false));
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string& path = fuzz::scratch_file(".den", data, size);
  try {
    golden::load_den(path, golden::Quantisation{}, 12);
  } catch (const golden::InputError&) {
  }
  return 0;
}
