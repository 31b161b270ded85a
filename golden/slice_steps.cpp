// Interpolation of a slice and the other slice steps' out-of-line parts
// (golden/slice_steps.hpp).
#include "golden/slice_steps.hpp"

#include <cmath>

namespace cube4::golden {

void load_voxel_slice(const PermutedVolume& pv, int z, Plane& out) {
  for (int y = 0; y < out.ny; ++y) pv.load_beam(y, z, out.row(y));
}

SliceInterp::SliceInterp(int nx, int ny, int weight_bits) : nx_(nx), ny_(ny), w_(weight_bits),
  tx_(static_cast<size_t>(nx) * (ny + 1)), ty_lo_(static_cast<size_t>(nx) * ny), ty_hi_(ty_lo_.size()) {}

void SliceInterp::bilinear(const Plane& v, int32_t wx, int32_t wy, std::vector<int32_t>& out) {
  // Locals, so that stores through int32_t pointers cannot alias them.
  const int nx = nx_, ny = ny_, w = w_;
  for (int y = 0; y <= ny; ++y) {
    const int32_t* __restrict a = v.row(y);
    int32_t* __restrict t = &tx_[static_cast<size_t>(y) * nx];
    if (wx == 0) {
      std::copy(a, a + nx, t);
    } else {
      for (int x = 0; x < nx; ++x) t[x] = lerp_t<int32_t>(a[x], a[x + 1], wx, w);
    }
  }
  for (int y = 0; y < ny; ++y) {
    const int32_t* __restrict t0 = &tx_[static_cast<size_t>(y) * nx];
    const int32_t* __restrict t1 = t0 + nx;
    int32_t* __restrict o = &out[static_cast<size_t>(y) * nx];
    if (wy == 0) {
      std::copy(t0, t0 + nx, o);
    } else {
      for (int x = 0; x < nx; ++x) o[x] = lerp_t<int32_t>(t0[x], t1[x], wy, w);
    }
  }
}

void SliceInterp::slice(const Plane& lo, const Plane& hi, const SliceControl& c, Plane& out) {
  const auto wx = static_cast<int32_t>(c.wx), wy = static_cast<int32_t>(c.wy), wz = static_cast<int32_t>(c.wz);
  const int nx = nx_, ny = ny_, w = w_;
  bilinear(lo, wx, wy, ty_lo_);
  if (wz != 0) bilinear(hi, wx, wy, ty_hi_);
  for (int y = 0; y < ny; ++y) {
    const int32_t* __restrict a = &ty_lo_[static_cast<size_t>(y) * nx];
    const int32_t* __restrict b = &ty_hi_[static_cast<size_t>(y) * nx];
    int32_t* __restrict o = out.row(y);
    if (wz == 0) {
      std::copy(a, a + nx, o);
    } else {
      for (int x = 0; x < nx; ++x) o[x] = lerp_t<int32_t>(a[x], b[x], wz, w);
    }
  }
}

BasePlane empty_base_plane(const Registers& r) {
  const int K = r.sample_slices();
  BasePlane bp;
  bp.width = r.base_width();
  bp.height = r.base_height();
  bp.bits = r.p.alpha_bits;
  bp.rgba.assign(static_cast<size_t>(bp.width) * bp.height * 4, 0);
  const double frac_one = std::ldexp(1.0, r.p.dda_frac_bits);
  bp.shift_x = r.x_offset(K - 1).integer - r.x_start / frac_one;
  bp.shift_y = r.y_offset(K - 1).integer - r.y_start / frac_one;
  return bp;
}

}  // namespace cube4::golden
