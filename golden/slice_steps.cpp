// Interpolation of a slice and the other slice steps' out-of-line parts
// (golden/slice_steps.hpp).
#include "golden/slice_steps.hpp"

#include <cmath>
#include <stdexcept>

namespace cube4::golden {

void load_voxel_slice(const PermutedVolume& pv, int z, Plane& out) {
  for (int y = 0; y < out.ny; ++y) pv.load_beam(y, z, out.row(y));
}

void load_voxel_slice(const PermutedVolume& pv, int z, Plane& out, int y0, int y1, const Span* spans) {
  for (int y = y0; y < y1; ++y)
    if (!spans[y].empty()) pv.load_beam(y, z, out.row(y), spans[y].begin, spans[y].end);
}

void load_tag_slice(const PermutedVolume& pv, int z, Plane& out, int y0, int y1, const Span* spans) {
  for (int y = y0; y < y1; ++y)
    if (!spans[y].empty()) pv.load_tag_beam(y, z, out.row(y), spans[y].begin, spans[y].end);
}

SliceInterp::SliceInterp(int nx, int ny, int weight_bits) : nx_(nx), ny_(ny), w_(weight_bits),
  tx_(static_cast<size_t>(nx) * (ny + 1)), ty_lo_(static_cast<size_t>(nx) * ny), ty_hi_(ty_lo_.size()),
  whole_(static_cast<size_t>(ny), Span{0, nx}) {}

void SliceInterp::bilinear(const Plane& v, int32_t wx, int32_t wy, std::vector<int32_t>& out, int y0, int y1,
                            const Span* spans) {
  // Locals, so that stores through int32_t pointers cannot alias them.
  const int nx = nx_, w = w_;
  // Voxel beam y serves sample beams y - 1 and y.
  for (int y = y0; y <= y1; ++y) {
    const Span s = hull(y < y1 ? spans[y] : Span{}, y > y0 ? spans[y - 1] : Span{});
    const int x0 = s.begin, x1 = s.end;
    const int32_t* __restrict a = v.row(y);
    int32_t* __restrict t = &tx_[static_cast<size_t>(y) * nx];
    if (wx == 0) {
      std::copy(a + x0, a + std::max(x0, x1), t + x0);
    } else {
      for (int x = x0; x < x1; ++x) t[x] = lerp_t<int32_t>(a[x], a[x + 1], wx, w);
    }
  }
  for (int y = y0; y < y1; ++y) {
    const int x0 = spans[y].begin, x1 = spans[y].end;
    const int32_t* __restrict t0 = &tx_[static_cast<size_t>(y) * nx];
    const int32_t* __restrict t1 = t0 + nx;
    int32_t* __restrict o = &out[static_cast<size_t>(y) * nx];
    if (wy == 0) {
      std::copy(t0 + x0, t0 + std::max(x0, x1), o + x0);
    } else {
      for (int x = x0; x < x1; ++x) o[x] = lerp_t<int32_t>(t0[x], t1[x], wy, w);
    }
  }
}

void SliceInterp::slice(const Plane& lo, const Plane& hi, const SliceControl& c, Plane& out) {
  slice(lo, hi, c, out, 0, ny_, whole_.data());
}

void SliceInterp::slice(const Plane& lo, const Plane& hi, const SliceControl& c, Plane& out, int y0, int y1,
                         const Span* spans) {
  const auto wx = static_cast<int32_t>(c.wx), wy = static_cast<int32_t>(c.wy), wz = static_cast<int32_t>(c.wz);
  const int nx = nx_, w = w_;
  bilinear(lo, wx, wy, ty_lo_, y0, y1, spans);
  if (wz != 0) bilinear(hi, wx, wy, ty_hi_, y0, y1, spans);
  for (int y = y0; y < y1; ++y) {
    const int x0 = spans[y].begin, x1 = spans[y].end;
    const int32_t* __restrict a = &ty_lo_[static_cast<size_t>(y) * nx];
    const int32_t* __restrict b = &ty_hi_[static_cast<size_t>(y) * nx];
    int32_t* __restrict o = out.row(y);
    if (wz == 0) {
      std::copy(a + x0, a + std::max(x0, x1), o + x0);
    } else {
      for (int x = x0; x < x1; ++x) o[x] = lerp_t<int32_t>(a[x], b[x], wz, w);
    }
  }
}

void SliceInterp::tags(const Plane& lo, const Plane& hi, const SliceControl& c, Plane& out, int y0, int y1,
                       const Span* spans) const {
  // One corner serves the whole slice: the weights are the slice's.
  const int corner = nearest_corner(c.wx, c.wy, c.wz, w_);
  const Plane& v = corner & 4 ? hi : lo;
  const int ux = corner & 1, uy = corner >> 1 & 1;
  for (int y = y0; y < y1; ++y) {
    const int32_t* a = v.row(y + uy) + ux;
    std::copy(a + spans[y].begin, a + std::max(spans[y].begin, spans[y].end), out.row(y) + spans[y].begin);
  }
}

template <class R>
void BasicSliceCompositor<R>::start_polygons() {
  const size_t n = rays_.size();
  if (poly_->width != width_ || poly_->height != r_.base_height() || poly_->front.size() != n ||
      poly_->back.size() != n || poly_->z.size() != n || poly_->slabs.size() != static_cast<size_t>(K_) ||
      r_.blend != BlendMode::Composite)
    throw std::logic_error("SliceCompositor: the polygon frame does not fit the registers' base plane and blend");
  // Often nothing lies in front of or behind the volume at all: one
  // reduction over both images (vectorised) saves the walk below.
  uint16_t any = 0;
  for (size_t i = 0; i < n; ++i) {
    const Pixel &f = poly_->front[i], &b = poly_->back[i];
    any |= f.r | f.g | f.b | f.a | b.r | b.g | b.b | b.a;
  }
  for (size_t i = 0; any != 0 && i < n; ++i) {
    // Nothing in front or behind: the ray starts at 0 (rays_ is) and, if
    // nothing reaches it, leaves as the pixel 0 the base plane holds.
    if (blank(poly_->front[i]) && blank(poly_->back[i])) continue;
    rays_[i] = pixel_to_acc(poly_->front[i], r_.p);
    const auto u = static_cast<int>(i % static_cast<size_t>(width_)), v = static_cast<int>(i / width_);
    mark_if_stopped(u, v);
    write_pixel(bp_, u, v, leave_with_polygons(rays_[i], poly_->back[i], r_.p));
  }
}

template <class R>
void BasicSliceCompositor<R>::composite_slab(const SliceControl& c, int y, RayAcc* ray) {
  const SlabImage& slab = poly_->slabs[static_cast<size_t>(c.k)];
  if (slab.empty()) return;
  // A blank slab pixel leaves its ray as it is (ray_over_pixel): only the
  // slab's fragments are composited, and not on a stopped ray, whose pixel
  // they cannot change (RayStopRule).
  const int shift = ix_last_ - c.ix, v = y - c.iy + iy_last_;
  uint64_t* stopped = words_ > 0 ? &stopped_[static_cast<size_t>(v) * words_] : nullptr;
  slab.for_each_pixel(y, [&](int x, const Pixel& px) {
    const int u = x + shift;
    if (stopped && (stopped[u >> 6] >> (u & 63) & 1)) return;
    // Field by field: the node changes only colour and opacity, and a
    // whole-struct copy here compiled to a store-forwarding stall.
    RayAcc& acc = ray[x];
    const RayAcc over = ray_over_pixel(acc, px, r_.p);
    acc.r = over.r, acc.g = over.g, acc.b = over.b, acc.a = over.a;
    if (stopped && stop_.can_stop(acc)) stopped[u >> 6] |= uint64_t{1} << (u & 63);
  });
}

template class BasicSliceCompositor<Registers>;
template class BasicSliceCompositor<DefaultPrecisionRegisters>;

BasePlane empty_base_plane(const Registers& r) {
  BasePlane bp;
  bp.width = r.base_width();
  bp.height = r.base_height();
  bp.bits = r.p.alpha_bits;
  bp.rgba.assign(static_cast<size_t>(bp.width) * bp.height * 4, 0);
  set_base_plane_shift(bp, r);
  return bp;
}

void set_base_plane_shift(BasePlane& bp, const Registers& r) {
  const double frac_one = std::ldexp(1.0, r.p.dda_frac_bits);
  bp.shift_x = r.base_origin_x() - r.x_start / frac_one;
  bp.shift_y = r.base_origin_y() - r.y_start / frac_one;
}

}  // namespace cube4::golden
