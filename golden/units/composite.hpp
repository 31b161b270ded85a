// Compositor: front-to-back α-blending, MIP and MinIP (VolumePro Table 1).
// Samples arrive at alpha_bits (n); the accumulator holds colour and α at
// n + acc_guard_bits (the accumulator domain, A), premultiplied by α, and a
// finished ray is rounded back to n bits for the base plane (pixel_of).
// The guard bits are what keeps translucent material stable: a sample's
// contribution t·α·C is often well under one LSB of n bits, and rounding it
// there (as VolumePro's 12-bit compositor does) is a systematic error that
// grows with the ray's length (docs/fixed-point.md, "Compositing error").
// With acc_guard_bits = 0 this is VolumePro's compositor exactly.
#pragma once
#include <cstdint>

#include "golden/fixed.hpp"
#include "golden/precision.hpp"
#include "golden/units/compose.hpp"
#include "golden/units/shade_phong.hpp"

namespace cube4::golden {

struct ShadedSample {
  Rgb rgb{0, 0, 0};     // not premultiplied
  uint32_t alpha = 0;
  uint32_t value = 0;   // the interpolated sample, for MIP/MinIP
  bool visible = true;  // cropping and cut plane
};

// A unit value (colour or α, alpha_bits) widened to the accumulator domain,
// 1.0 -> 1.0 (bit replication).
constexpr uint32_t to_acc(uint32_t v, const Precision& p) {
  return static_cast<uint32_t>(expand_bits(v, p.alpha_bits, acc_bits(p)));
}

// A sample's premultiplied colour C·α in the accumulator domain: the colour
// widened first, so the product keeps acc_guard_bits more of its fraction
// than mul_frac(C, α) would (one rounding, half up), and full colour at full
// α is full. Never above the sample's α: the widened colour's replicated
// bits can carry the product up to half a sample LSB past to_acc(α), so it
// is clamped there (with no guard bits mul_frac(C, α) <= α already, and the
// clamp changes nothing: VolumePro's compositor).
constexpr uint32_t premultiply(uint32_t c, uint32_t alpha, const Precision& p) {
  const uint32_t product = static_cast<uint32_t>(mul_frac(to_acc(c, p), alpha, p.alpha_bits));
  const uint32_t limit = to_acc(alpha, p);
  return product < limit ? product : limit;
}

// A sample as a pixel of the composition (golden/units/compose.hpp): its
// premultiplied colour and α in the accumulator domain, its value selected;
// an invisible sample (cropping, cut plane) is the empty pixel, which the
// node leaves out in every mode (over adds mul_frac(t, 0) = 0; MIP/MinIP
// never take a pixel with nothing selected).
constexpr RayAcc sample_pixel(const ShadedSample& s, const Precision& p) {
  if (!s.visible) return RayAcc{};
  RayAcc r;
  r.r = premultiply(s.rgb[0], s.alpha, p);
  r.g = premultiply(s.rgb[1], s.alpha, p);
  r.b = premultiply(s.rgb[2], s.alpha, p);
  r.a = to_acc(s.alpha, p);
  r.value = static_cast<uint16_t>(s.value);
  r.valid = true;
  return r;
}

// C += (1 - α_acc)·C_s·α ; α_acc += (1 - α_acc)·α, in the accumulator
// domain: the ray so far over the sample (compose_over).
constexpr RayAcc blend_front_to_back(const RayAcc& acc, const ShadedSample& s, const Precision& p) {
  return compose_over(acc, sample_pixel(s, p), p);
}

// MIP/MinIP keep the premultiplied colour of the extreme sample value; ties
// keep the earlier (front) sample (compose_extreme).
constexpr RayAcc blend_extreme(const RayAcc& acc, const ShadedSample& s, bool maximum,
                               const Precision& p) {
  // compose_extreme(acc, sample_pixel(s, p), maximum), deciding first: most
  // samples are not taken, and their premultiplied colour is not needed.
  return extreme_takes_back(acc, s.visible, static_cast<uint16_t>(s.value), maximum) ? sample_pixel(s, p) : acc;
}

// A finished ray as a base-plane pixel: each channel scaled from the
// accumulator domain (full = 2^A - 1) to alpha_bits (full = 2^n - 1),
// rounded half up. A plain shift by the guard bits would read full scale as
// 2^n - 2^-g and brighten every pixel by up to one LSB; v - (v >> n) is the
// inverse of the bit replication of to_acc() (full -> full, 0 -> 0,
// monotonic, never above 2^n - 1), within 2^-g LSB of the exact scaling.
struct Pixel {
  uint16_t r = 0, g = 0, b = 0, a = 0;
};
constexpr uint16_t acc_to_pixel(uint32_t v, const Precision& p) {
  return static_cast<uint16_t>(round_shift(v - (v >> p.alpha_bits), p.acc_guard_bits));
}
constexpr Pixel pixel_of(const RayAcc& acc, const Precision& p) {
  return {acc_to_pixel(acc.r, p), acc_to_pixel(acc.g, p), acc_to_pixel(acc.b, p), acc_to_pixel(acc.a, p)};
}

// One sample into its ray: the composition node with the sample behind.
constexpr RayAcc blend(BlendMode mode, const RayAcc& acc, const ShadedSample& s, const Precision& p) {
  switch (mode) {  // compose(mode, acc, sample_pixel(s, p), p)
    case BlendMode::Mip: return blend_extreme(acc, s, true, p);
    case BlendMode::MinIp: return blend_extreme(acc, s, false, p);
    default: return blend_front_to_back(acc, s, p);
  }
}

// False when blend(mode, acc, s, p) is acc for every ray acc: an invisible
// sample (sample_pixel() is empty, which no node takes), or, compositing,
// a transparent one (over adds mul_frac(t, 0) = 0 to every channel). A
// model may skip such samples without changing a bit.
constexpr bool blend_changes_ray(BlendMode mode, const ShadedSample& s) {
  return s.visible && (mode != BlendMode::Composite || s.alpha != 0);
}

}  // namespace cube4::golden
