// The raw loader: the first 8 input bytes choose the layout the scene would
// give (size, sample type, byte order, header, mapping, voxel width), the
// rest is the file.
#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "golden/volume_io.hpp"
#include "tb/fuzz/fuzz_support.hpp"

namespace {

using namespace cube4;

constexpr size_t kLayoutBytes = 8;
const char* const kTypes[] = {"uint8", "uint12", "uint16", "int16", "uint32", "int32", "float32", "float64"};

}  // namespace

void cube4::fuzz::write_seeds(const std::string& dir) {
  for (unsigned t = 0; t < 8; ++t) {
    // 2x2x2, type t, little endian, 4 header bytes, minmax, 12 bits
    fuzz::Bytes b{1, 1, 1, static_cast<unsigned char>(t), 0, 4, 1, 4};
    static const unsigned width[] = {1, 2, 2, 2, 4, 4, 4, 8};
    for (unsigned i = 0; i < 4 + 8 * width[t]; ++i) b.push_back(static_cast<unsigned char>(i * 29 + t));
    fuzz::write_seed(dir, std::string("raw_") + kTypes[t], b);
  }
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < kLayoutBytes) return 0;
  golden::VolumeSource src;
  src.kind = "raw";
  src.dim = {1 + data[0] % 16, 1 + data[1] % 16, 1 + data[2] % 16};
  src.type = kTypes[data[3] % 8];
  src.endian = data[4] & 1 ? "big" : "little";
  src.header_bytes = data[5] % 64;
  switch (data[6] % 3) {
    case 0: break;
    case 1: src.quantisation.mode = golden::Quantisation::Mode::MinMax; break;
    default:
      src.quantisation.mode = golden::Quantisation::Mode::Window;
      src.quantisation.lo = -static_cast<double>(data[7]);
      src.quantisation.hi = 1.0 + data[7] * 1000.0;
  }
  const int bits = 8 + data[7] % 9;
  const std::string& path = fuzz::scratch_file(".raw", data + kLayoutBytes, size - kLayoutBytes);
  try {
    golden::load_raw(src, path, bits);
  } catch (const golden::InputError&) {
  }
  return 0;
}
