// The compositor with polygons (Cube-5 §§2, 5): the Z test of a sample
// against the opaque polygons' depth, and the double composition of a
// sample and a translucent slab pixel in one step. The host rasterises the
// polygons (golden/polygons.hpp) into the images these functions read; a
// scene without polygons runs none of this (render_fixed, SliceCompositor).
//
// Depth Z is measured along the processing axis in sample slices, the unit
// in which the volume's own samples lie (sample slice k at depth k): an
// unsigned kZBits-bit value with kZFracBits fraction bits (Cube-5 §4 keeps
// 24 bits of depth per coxel). The hardware compares, it never computes
// depth: the host clamps it into [0, kZNone].
//
// Polygon pixels (the slab images and the front and back images of
// golden/polygons.hpp) are the base plane's pixel format: premultiplied
// R, G, B, α at alpha_bits each (`Pixel`); a blank pixel (all zero) holds
// no fragment. Premultiplied so that fragments of one pixel blend by the
// compositing node alone, and at alpha_bits because a slab pixel is one
// rounded contribution, like a shaded sample, not a sum of many.
#pragma once
#include <cstdint>

#include "golden/precision.hpp"
#include "golden/units/compose.hpp"
#include "golden/units/composite.hpp"

namespace cube4::golden {

inline constexpr int kZFracBits = 8;
inline constexpr int kZBits = 24;
// No opaque polygon on the ray: the largest Z, behind every sample slice
// (at most 8·4096 = 2^15 slices, so k·2^8 <= 2^23 < kZNone).
inline constexpr uint32_t kZNone = (uint32_t{1} << kZBits) - 1;

// The Z test (Cube-5 §5): sample slice k is composited iff it lies strictly
// in front of the ray's opaque polygon. A sample at the polygon's depth is
// hidden: the surface wins the tie, as a translucent fragment at a slice's
// depth is composited before that slice's sample (golden/polygons.hpp).
constexpr bool sample_before_z(int k, uint32_t z) { return (static_cast<int64_t>(k) << kZFracBits) < z; }

// The widths of polygon pixels: the compositor's, with no guard bits, so
// that the compositing node works on them at alpha_bits.
constexpr Precision pixel_precision(const Precision& p) {
  Precision q = p;
  q.acc_guard_bits = 0;
  return q;
}

constexpr bool blank(const Pixel& x) { return (x.r | x.g | x.b | x.a) == 0; }

constexpr RayAcc pixel_as_node(const Pixel& x) {
  RayAcc r;
  r.r = x.r;
  r.g = x.g;
  r.b = x.b;
  r.a = x.a;
  return r;
}

// A fragment of colour rgb and opacity α (alpha_bits, not premultiplied) as
// a polygon pixel: premultiply() at alpha_bits, one rounding half up, never
// above α; α = 0 gives the blank pixel, full α the colour itself.
constexpr Pixel polygon_pixel(const Rgb& rgb, uint32_t alpha, const Precision& p) {
  const Precision q = pixel_precision(p);
  return {static_cast<uint16_t>(premultiply(rgb[0], alpha, q)), static_cast<uint16_t>(premultiply(rgb[1], alpha, q)),
          static_cast<uint16_t>(premultiply(rgb[2], alpha, q)), static_cast<uint16_t>(alpha)};
}

// Two fragments of one pixel, front over back: the compositing node at
// alpha_bits (compose_over with no guard bits), one rounding per channel.
// This is the RLE buffer's Blend (Cube-5 §5, Algorithm 1), fragments
// arriving front to back. A blank side gives the other exactly; a
// non-blank front gives a non-blank result (α only grows).
constexpr Pixel pixel_over(const Pixel& front, const Pixel& back, const Precision& p) {
  if (blank(front)) return back;  // what the node gives (mul_frac by full is exact); the test saves the multiplies
  const RayAcc r = compose_over(pixel_as_node(front), pixel_as_node(back), pixel_precision(p));
  return {static_cast<uint16_t>(r.r), static_cast<uint16_t>(r.g), static_cast<uint16_t>(r.b),
          static_cast<uint16_t>(r.a)};
}

// A polygon pixel in the accumulator domain (to_acc per channel: bit
// replication, exact for 0 and full; acc_to_pixel undoes it exactly).
constexpr RayAcc pixel_to_acc(const Pixel& x, const Precision& p) {
  RayAcc r;
  r.r = to_acc(x.r, p);
  r.g = to_acc(x.g, p);
  r.b = to_acc(x.b, p);
  r.a = to_acc(x.a, p);
  return r;
}

// The ray so far over a polygon pixel behind it: the node of
// golden/units/compose.hpp. A blank pixel leaves the ray exactly as it is
// (the node would too; the test saves the multiplies).
constexpr RayAcc ray_over_pixel(const RayAcc& ray, const Pixel& px, const Precision& p) {
  if (blank(px)) return ray;
  // Over an empty ray (nothing composited yet) the node gives the pixel
  // exactly (mul_frac by full is exact, as in pixel_over), keeping the
  // ray's other fields; the test saves the multiplies on the first
  // fragment of most rays.
  if ((ray.r | ray.g | ray.b | ray.a) == 0) {
    RayAcc r = pixel_to_acc(px, p);
    r.value = ray.value;
    r.valid = ray.valid;
    return r;
  }
  return compose_over(ray, pixel_to_acc(px, p), p);
}

// Cube-5 §5's double composition, restated for our front-to-back
// accumulator. The paper blends, back to front, the slab's fragment p over
// the coxel c and then the sample v over that; front to back the same order
// of depth is: the ray so far, then the sample (if the Z test passes), then
// the slab pixel, which lies between this sample slice and the next:
//   acc' = (acc over v) over p
// two applications of the node, each rounding once per channel (half up).
// The paper's two-multiply rewriting is a back-to-front identity; front to
// back the node's own form (one multiply per channel and node) is already
// the cheap one.
constexpr RayAcc double_composite(const RayAcc& acc, const ShadedSample& s, bool before_z, const Pixel& slab,
                                  const Precision& p) {
  return ray_over_pixel(before_z ? blend_front_to_back(acc, s, p) : acc, slab, p);
}

// A ray leaving the volume: what lies behind its last sample (the back
// image: translucent fragments, then the opaque polygon) goes behind it,
// and the result is the base-plane pixel.
constexpr Pixel leave_with_polygons(const RayAcc& ray, const Pixel& back, const Precision& p) {
  return pixel_of(ray_over_pixel(ray, back, p), p);
}

}  // namespace cube4::golden
