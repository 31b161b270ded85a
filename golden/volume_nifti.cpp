// NIfTI-1 volumes (.nii, .nii.gz, .hdr/.img) through niftilib. niftilib
// reports failures on stderr and returns NULL, so every NULL is turned into
// an InputError here, after checks that give the user a precise reason.
// The data is read with niftilib's znzlib rather than nifti_image_load,
// because nifti_image_load zero-fills a short read and reports success: a
// truncated file would load as a volume with a black slab.
#include <nifti1_io.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "golden/errors.hpp"
#include "golden/quantise.hpp"
#include "golden/volume_io.hpp"

namespace cube4::golden {

namespace {

struct NimFree {
  void operator()(nifti_image* p) const { nifti_image_free(p); }
};
using NimPtr = std::unique_ptr<nifti_image, NimFree>;

struct ZnzClose {
  void operator()(znzptr* f) const { Xznzclose(&f); }
};
using ZnzPtr = std::unique_ptr<znzptr, ZnzClose>;

void check_readable(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(path + ": cannot open NIfTI file (no such file)");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": cannot open NIfTI file (it is a directory)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open NIfTI file (" + std::strerror(errno) + ")");
}

SampleType sample_type(const nifti_image& nim, const std::string& path) {
  switch (nim.datatype) {
    case DT_UINT8: return SampleType::UInt8;
    case DT_INT8: return SampleType::Int8;
    case DT_UINT16: return SampleType::UInt16;
    case DT_INT16: return SampleType::Int16;
    case DT_UINT32: return SampleType::UInt32;
    case DT_INT32: return SampleType::Int32;
    case DT_FLOAT32: return SampleType::Float32;
    case DT_FLOAT64: return SampleType::Float64;
    default:
      throw InputError(path + ": NIfTI datatype " + nifti_datatype_string(nim.datatype) + " (" +
                       std::to_string(nim.datatype) +
                       ") is not supported (expected uint8, int8, uint16, int16, uint32, int32, "
                       "float32 or float64)");
  }
}

std::string dims_text(const nifti_image& nim) {
  std::string s;
  const int n = std::max(1, std::min(nim.ndim, 7));
  for (int i = 1; i <= n; ++i) s += (i > 1 ? "x" : "") + std::to_string(nim.dim[i]);
  return s;
}

std::array<int, 3> volume_dims(const nifti_image& nim, const std::string& path) {
  // Time series, vector and tensor images have no single scalar per voxel.
  if (nim.nt > 1 || nim.nu > 1 || nim.nv > 1 || nim.nw > 1)
    throw InputError(path + ": NIfTI image is " + std::to_string(nim.ndim) + "-D (" +
                     dims_text(nim) + "); only 3-D scalar volumes are supported");
  if (nim.nx < 1 || nim.ny < 1 || nim.nz < 1)
    throw InputError(path + ": NIfTI image has nonpositive dimensions " + dims_text(nim));
  return {nim.nx, nim.ny, nim.nz};
}

double spacing_of(float pixdim) {
  const double d = std::fabs(static_cast<double>(pixdim));
  return (d > 0 && std::isfinite(d)) ? d : 1.0;  // 0 means "unknown" in many writers
}

Scaling scaling_of(const nifti_image& nim) {
  // scl_slope 0 means "no scaling" in the NIfTI-1 standard.
  const double slope = nim.scl_slope, inter = nim.scl_inter;
  if (slope == 0 || !std::isfinite(slope)) return {};
  return {slope, std::isfinite(inter) ? inter : 0.0};
}

// Reads exactly nvox samples, native byte order, or throws.
std::vector<unsigned char> read_data(const nifti_image& nim, const std::string& path) {
  const size_t ntot = nim.nvox * static_cast<size_t>(nim.nbyper);
  const std::string iname = nim.iname ? nim.iname : path;
  // Negative offsets (ANALYZE "data at the end") are not used by NIfTI writers.
  if (nim.iname_offset < 0)
    throw InputError(path + ": negative NIfTI data offset " + std::to_string(nim.iname_offset) +
                     " is not supported");
  ZnzPtr fp(znzopen(iname.c_str(), "rb", nifti_is_gzfile(iname.c_str())));
  if (!fp) throw InputError(iname + ": cannot open NIfTI data file");
  // Grown chunk by chunk, so a header claiming a huge volume cannot make us
  // allocate more than the file actually holds.
  constexpr size_t kChunk = size_t{1} << 26;
  std::vector<unsigned char> buf;
  size_t got = 0;
  if (znzseek(fp.get(), nim.iname_offset, SEEK_SET) >= 0) {
    while (got < ntot) {
      buf.resize(std::min(ntot, got + kChunk));
      const size_t n = znzread(buf.data() + got, 1, buf.size() - got, fp.get());
      got += n;
      if (got < buf.size()) break;
    }
  }
  if (got != ntot)
    throw InputError(iname + ": truncated or corrupt NIfTI data: expected " + std::to_string(ntot) +
                     " bytes at offset " + std::to_string(nim.iname_offset) + ", found " +
                     std::to_string(got));
  if (nim.swapsize > 1 && nim.byteorder != nifti_short_order())
    nifti_swap_Nbytes(nim.nvox, nim.swapsize, buf.data());
  return buf;
}

}  // namespace

Volume load_nifti(const std::string& path, const Quantisation& q, int voxel_bits) {
  check_voxel_bits(voxel_bits);
  check_readable(path);
  nifti_set_debug_level(0);
  // Header first, so a wrong shape or type is reported without reading data.
  NimPtr nim(nifti_image_read(path.c_str(), 0));
  if (!nim) throw InputError(path + ": not a readable NIfTI-1 file (bad or truncated header)");
  const SampleType t = sample_type(*nim, path);
  const std::array<int, 3> dim = volume_dims(*nim, path);
  const std::vector<unsigned char> data = read_data(*nim, path);
  Volume v;
  v.dim = dim;
  v.spacing = {spacing_of(nim->pixdim[1]), spacing_of(nim->pixdim[2]), spacing_of(nim->pixdim[3])};
  v.bits = voxel_bits;
  v.data = quantise(data.data(), t, dim, q, voxel_bits, path, scaling_of(*nim));
  v.source = path;
  return v;
}

}  // namespace cube4::golden
