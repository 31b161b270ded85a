// Compositing node of an image composition network (bela §III.D): two
// partial-image pixels, in visibility order (front, back), merged into one
// pixel of the same format, for the three blend modes of the compositor.
//
// Pixel format: a partial ray's accumulator, RayAcc: premultiplied R, G, B
// and α in the accumulator domain, A = alpha_bits + acc_guard_bits bits
// (full = 2^A − 1), and for MIP/MinIP the selected sample value
// (voxel_bits) with its valid bit. The node works there, not at the base
// plane's alpha_bits, because (a) what a compositing unit holds at the end
// of a ray (or of a slab of slices) is exactly this value, so partial
// images are composed before any rounding to alpha_bits (one
// acc_to_pixel() at the very end, as for a single ray), and (b) the
// compositor's own per-sample blend is this node with a sample as the back
// pixel (golden/units/composite.hpp: blend() = compose(acc, sample_pixel)),
// so the network and the ray casting are one arithmetic. With
// acc_guard_bits = 0 the domain is alpha_bits (VolumePro's compositor).
//
// Over (front to back, premultiplied):
//   t = (2^A − 1) − α_f
//   C = sat_unsigned(C_f + mul_frac(t, C_b, A), A)   per colour channel
//   α = α_f + mul_frac(t, α_b, A)                   (never above full: mul_frac(t, ·) <= t)
//   value, valid = the front pixel's
// One rounding (half up) per channel and node. mul_frac(t, 0) = 0 and
// mul_frac(2^A − 1, x) = x, so an empty pixel (all zero) on either side
// gives the other exactly, and an opaque front gives the front.
// MIP / MinIP: the back pixel replaces the front iff it has a selected
// sample (valid) and the front has none, or its value is strictly greater
// (MIP) / smaller (MinIP); ties keep the front. No arithmetic, no rounding.
//
// Overlay and underlay (bela §III.D: a transparent surface in front of the
// final image, a background, usually opaque black, behind it) are this node
// with one input from a register or an image memory: overlay(layer, pixel)
// = compose(layer, pixel), underlay(pixel, layer) = compose(pixel, layer).
#pragma once
#include <cstdint>

#include "golden/fixed.hpp"
#include "golden/precision.hpp"

namespace cube4::golden {

enum class BlendMode : uint8_t { Composite = 0, Mip = 1, MinIp = 2 };

// A partial ray, or a partial-image pixel: premultiplied colour and opacity
// in the accumulator domain; for MIP/MinIP the selected sample and whether
// there is one. RayAcc{} is the empty pixel (nothing in front, nothing
// selected).
struct RayAcc {
  uint32_t r = 0, g = 0, b = 0, a = 0;  // premultiplied colour and opacity, A bits
  uint16_t value = 0;                   // MIP/MinIP: the selected sample value
  bool valid = false;                   // MIP/MinIP: a sample has been selected
  friend constexpr bool operator==(const RayAcc& x, const RayAcc& y) {
    return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a && x.value == y.value &&
           x.valid == y.valid;
  }
};

constexpr int acc_bits(const Precision& p) { return p.alpha_bits + p.acc_guard_bits; }

// front over back. The increment is a fraction of the front's remaining
// transparency, so α never passes full opacity; colour rounding can pass it
// by an LSB, hence the saturation.
constexpr RayAcc compose_over(const RayAcc& front, const RayAcc& back, const Precision& p) {
  const int a = acc_bits(p);
  const int64_t t = max_unsigned(a) - front.a;
  auto add = [&](uint32_t c_front, uint32_t c_back) {
    return static_cast<uint32_t>(sat_unsigned(c_front + mul_frac(t, c_back, a), a));
  };
  RayAcc r = front;
  r.r = add(front.r, back.r);
  r.g = add(front.g, back.g);
  r.b = add(front.b, back.b);
  r.a = static_cast<uint32_t>(front.a + mul_frac(t, back.a, a));
  return r;
}

// MIP (maximum) or MinIP: the pixel of the extreme selected value; ties and
// a back pixel with nothing selected keep the front.
constexpr bool extreme_takes_back(const RayAcc& front, bool back_valid, uint16_t back_value, bool maximum) {
  return back_valid && (!front.valid || (maximum ? back_value > front.value : back_value < front.value));
}
constexpr RayAcc compose_extreme(const RayAcc& front, const RayAcc& back, bool maximum) {
  return extreme_takes_back(front, back.valid, back.value, maximum) ? back : front;
}

constexpr RayAcc compose(BlendMode mode, const RayAcc& front, const RayAcc& back, const Precision& p) {
  switch (mode) {
    case BlendMode::Mip: return compose_extreme(front, back, true);
    case BlendMode::MinIp: return compose_extreme(front, back, false);
    default: return compose_over(front, back, p);
  }
}

// The final image's two extra nodes: a layer (a register or an image
// memory) in front of the stream's pixel, or behind it.
constexpr RayAcc overlay(BlendMode mode, const RayAcc& layer, const RayAcc& pixel, const Precision& p) {
  return compose(mode, layer, pixel, p);
}
constexpr RayAcc underlay(BlendMode mode, const RayAcc& pixel, const RayAcc& layer, const Precision& p) {
  return compose(mode, pixel, layer, p);
}

// Two networks of n − 1 nodes for the partial images px[0 .. n) in
// visibility order (px[0] in front); n = 0 gives the empty pixel.
// A linear chain, front to back: ((px0 ∘ px1) ∘ px2) ∘ …, the front image
// passes n − 1 nodes (bela's "parallel planes").
constexpr RayAcc compose_chain(BlendMode mode, const RayAcc* px, int n, const Precision& p) {
  RayAcc r = n > 0 ? px[0] : RayAcc{};
  for (int i = 1; i < n; ++i) r = compose(mode, r, px[i], p);
  return r;
}
// A balanced tree (bela's hierarchical composition tree): the front half's
// tree over the back half's, every image passes at most ceil(log2 n) nodes.
constexpr RayAcc compose_tree(BlendMode mode, const RayAcc* px, int n, const Precision& p) {
  if (n <= 1) return n == 1 ? px[0] : RayAcc{};
  const int front = (n + 1) / 2;
  return compose(mode, compose_tree(mode, px, front, p), compose_tree(mode, px + front, n - front, p), p);
}

}  // namespace cube4::golden
