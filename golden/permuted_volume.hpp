// Address generation, functionally: the volume as the pipelines see it, in
// permuted axes (x', y', z') = object axes (perm[0], perm[1], perm[2]), each
// walked backwards where flip[i]. Outside the volume every voxel is zero.
#pragma once
#include <array>
#include <cstdint>

#include "golden/volume.hpp"

namespace cube4::golden {

class PermutedVolume {
 public:
  PermutedVolume(const Volume& v, const std::array<int, 3>& perm, const std::array<bool, 3>& flip) : vol_(v) {
    const int64_t object_stride[3] = {1, v.dim[0], int64_t{v.dim[0]} * v.dim[1]};
    for (int i = 0; i < 3; ++i) {
      dim_[i] = v.dim[perm[i]];
      stride_[i] = object_stride[perm[i]] * (flip[i] ? -1 : 1);
      if (flip[i]) origin_ += (dim_[i] - 1) * object_stride[perm[i]];
    }
  }

  const std::array<int, 3>& dim() const { return dim_; }

  uint16_t at(int x, int y, int z) const {
    if (x < 0 || y < 0 || z < 0 || x >= dim_[0] || y >= dim_[1] || z >= dim_[2]) return 0;
    return vol_.data[static_cast<size_t>(origin_ + stride_[0] * x + stride_[1] * y + stride_[2] * z)];
  }
  uint8_t tag_at(int x, int y, int z) const {
    if (vol_.tags.empty() || x < 0 || y < 0 || z < 0 || x >= dim_[0] || y >= dim_[1] || z >= dim_[2]) return 0;
    return vol_.tags[static_cast<size_t>(origin_ + stride_[0] * x + stride_[1] * y + stride_[2] * z)];
  }

  // Voxels x0 .. x1-1 of beam y of slice z into dst[x0 .. x1-1]; zeros
  // beyond the volume.
  template <class T>
  void load_beam(int y, int z, T* __restrict dst, int x0, int x1) const {
    load_from(vol_.data.data(), y, z, dst, x0, x1);
  }
  // The same voxels' tags (zeros for a volume without tags).
  template <class T>
  void load_tag_beam(int y, int z, T* __restrict dst, int x0, int x1) const {
    load_from(vol_.tags.empty() ? nullptr : vol_.tags.data(), y, z, dst, x0, x1);
  }
  template <class T>
  void load_beam(int y, int z, T* __restrict dst) const { load_beam(y, z, dst, 0, dim_[0]); }

 private:
  template <class S, class T>
  void load_from(const S* data, int y, int z, T* __restrict dst, int x0, int x1) const {
    if (!data || y < 0 || z < 0 || y >= dim_[1] || z >= dim_[2]) {
      for (int x = x0; x < x1; ++x) dst[x] = T{0};
      return;
    }
    const S* __restrict src = data + origin_ + stride_[1] * y + stride_[2] * z;
    const int64_t sx = stride_[0];
    if (sx == 1) {
      for (int x = x0; x < x1; ++x) dst[x] = static_cast<T>(src[x]);
    } else {
      for (int x = x0; x < x1; ++x) dst[x] = static_cast<T>(src[sx * x]);
    }
  }

  const Volume& vol_;
  std::array<int, 3> dim_{};
  int64_t stride_[3] = {0, 0, 0};
  int64_t origin_ = 0;
};

}  // namespace cube4::golden
