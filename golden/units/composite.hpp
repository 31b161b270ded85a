// Compositor: front-to-back α-blending, MIP and MinIP (VolumePro Table 1),
// all at alpha_bits. Colours in the accumulator are premultiplied by α.
#pragma once
#include <cstdint>

#include "golden/fixed.hpp"
#include "golden/precision.hpp"
#include "golden/units/phong.hpp"

namespace cube4::golden {

enum class BlendMode : uint8_t { Composite = 0, Mip = 1, MinIp = 2 };

struct RayAcc {
  uint16_t r = 0, g = 0, b = 0, a = 0;  // premultiplied colour and opacity
  uint16_t value = 0;                   // MIP/MinIP: the selected sample value
  bool valid = false;                   // MIP/MinIP: a sample has been selected
  friend constexpr bool operator==(const RayAcc& x, const RayAcc& y) {
    return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a && x.value == y.value &&
           x.valid == y.valid;
  }
};

struct ShadedSample {
  Rgb rgb{0, 0, 0};     // not premultiplied
  uint32_t alpha = 0;
  uint32_t value = 0;   // the interpolated sample, for MIP/MinIP
  bool visible = true;  // cropping and cut plane
};

// C += (1 - α_acc)·α·C_s ; α_acc += (1 - α_acc)·α. The increment is a
// fraction of the remaining transparency, so α_acc never passes full
// opacity; colour rounding can pass it by an LSB, hence the saturation.
constexpr RayAcc blend_front_to_back(const RayAcc& acc, const ShadedSample& s, const Precision& p) {
  if (!s.visible) return acc;
  const int n = p.alpha_bits;
  const int64_t t = max_unsigned(n) - acc.a;
  RayAcc r = acc;
  auto add = [&](uint16_t c_acc, uint32_t c) {
    return static_cast<uint16_t>(sat_unsigned(c_acc + mul_frac(t, mul_frac(c, s.alpha, n), n), n));
  };
  r.r = add(acc.r, s.rgb[0]);
  r.g = add(acc.g, s.rgb[1]);
  r.b = add(acc.b, s.rgb[2]);
  r.a = static_cast<uint16_t>(acc.a + mul_frac(t, s.alpha, n));
  return r;
}

// MIP/MinIP keep the premultiplied colour of the extreme sample value; ties
// keep the earlier (front) sample.
constexpr RayAcc blend_extreme(const RayAcc& acc, const ShadedSample& s, bool maximum,
                               const Precision& p) {
  if (!s.visible) return acc;
  const bool take = !acc.valid || (maximum ? s.value > acc.value : s.value < acc.value);
  if (!take) return acc;
  const int n = p.alpha_bits;
  RayAcc r;
  r.r = static_cast<uint16_t>(mul_frac(s.rgb[0], s.alpha, n));
  r.g = static_cast<uint16_t>(mul_frac(s.rgb[1], s.alpha, n));
  r.b = static_cast<uint16_t>(mul_frac(s.rgb[2], s.alpha, n));
  r.a = static_cast<uint16_t>(s.alpha);
  r.value = static_cast<uint16_t>(s.value);
  r.valid = true;
  return r;
}

constexpr RayAcc blend(BlendMode mode, const RayAcc& acc, const ShadedSample& s, const Precision& p) {
  switch (mode) {
    case BlendMode::Mip: return blend_extreme(acc, s, true, p);
    case BlendMode::MinIp: return blend_extreme(acc, s, false, p);
    default: return blend_front_to_back(acc, s, p);
  }
}

}  // namespace cube4::golden
