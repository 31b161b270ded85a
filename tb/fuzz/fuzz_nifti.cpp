// The NIfTI-1 loader on arbitrary bytes, as .nii, or as .nii.gz when the
// input starts like a gzip stream.
#include <nifti1.h>

#include <cstring>

#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "golden/volume_io.hpp"
#include "tb/fuzz/fuzz_support.hpp"

namespace {

using namespace cube4;

fuzz::Bytes nii(short datatype, short bitpix, short nx, short ny, short nz) {
  nifti_1_header h{};
  h.sizeof_hdr = 348;
  h.dim[0] = 3;
  for (int i = 1; i < 8; ++i) h.dim[i] = 1;
  h.dim[1] = nx, h.dim[2] = ny, h.dim[3] = nz;
  h.datatype = datatype;
  h.bitpix = bitpix;
  h.pixdim[0] = 1;
  h.pixdim[1] = 1, h.pixdim[2] = 2, h.pixdim[3] = 0.5f;
  h.vox_offset = 352;
  h.scl_slope = 1;
  std::memcpy(h.magic, "n+1", 4);
  fuzz::Bytes b(sizeof h + 4, 0);
  std::memcpy(b.data(), &h, sizeof h);
  const size_t n = static_cast<size_t>(nx) * ny * nz * (bitpix / 8);
  for (size_t i = 0; i < n; ++i) b.push_back(static_cast<unsigned char>(i * 53));
  return b;
}

}  // namespace

void cube4::fuzz::write_seeds(const std::string& dir) {
  fuzz::write_seed(dir, "u8.nii", nii(DT_UINT8, 8, 3, 2, 2));
  fuzz::write_seed(dir, "i16.nii", nii(DT_INT16, 16, 2, 2, 2));
  fuzz::write_seed(dir, "f32.nii", nii(DT_FLOAT32, 32, 2, 1, 2));
  fuzz::write_seed(dir, "f64.nii", nii(DT_FLOAT64, 64, 1, 2, 2));
  const fuzz::Bytes plain = nii(DT_UINT16, 16, 2, 2, 2);
  const fuzz::Bytes gz = fuzz::gzip(plain);
  fuzz::write_seed(dir, "u16.nii.gz", gz);
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool gz = size >= 2 && data[0] == 0x1f && data[1] == 0x8b;
  const std::string& path = fuzz::scratch_file(gz ? ".nii.gz" : ".nii", data, size);
  try {
    golden::load_nifti(path, golden::Quantisation{}, 12);
  } catch (const golden::InputError&) {
  }
  return 0;
}
