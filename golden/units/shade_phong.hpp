// Phong combine (VolumePro §3.5):
//   RGB = (ke + Id·Gd·kd)·SampleRGB + Is·Gs·ks·SpecularColor
// Id, Is: reflectance-map values (map_frac_bits fraction); ke, kd, ks:
// coefficients (coef_frac_bits fraction); Gd, Gs: GmLUT values at alpha_bits
// when modulation is on, else the full unit. Colours are alpha_bits wide.
#pragma once
#include <array>
#include <cstdint>

#include "golden/fixed.hpp"
#include "golden/precision.hpp"

namespace cube4::golden {

using Rgb = std::array<uint32_t, 3>;

struct ShadeCoefs {
  uint32_t ke = 0, kd = 0, ks = 0;  // coef_bits, coef_frac_bits fraction
  Rgb specular{0, 0, 0};            // alpha_bits unit
};

// The colour channel of the classification table widened to alpha_bits.
constexpr Rgb widen_color(uint32_t r, uint32_t g, uint32_t b, const Precision& p) {
  return {static_cast<uint32_t>(expand_bits(r, p.color_bits, p.alpha_bits)),
          static_cast<uint32_t>(expand_bits(g, p.color_bits, p.alpha_bits)),
          static_cast<uint32_t>(expand_bits(b, p.color_bits, p.alpha_bits))};
}

// Diffuse factor ke + kd·Id·Gd, with coef_frac_bits of fraction.
constexpr int64_t diffuse_factor(uint32_t id, uint32_t gd, const ShadeCoefs& k, const Precision& p) {
  return k.ke + round_shift(int64_t{k.kd} * mul_frac(id, gd, p.alpha_bits), p.map_frac_bits);
}

// Specular factor ks·Is·Gs, with coef_frac_bits of fraction.
constexpr int64_t specular_factor(uint32_t is, uint32_t gs, const ShadeCoefs& k, const Precision& p) {
  return round_shift(int64_t{k.ks} * mul_frac(is, gs, p.alpha_bits), p.map_frac_bits);
}

constexpr Rgb phong(const Rgb& color, uint32_t id, uint32_t is, uint32_t gd, uint32_t gs,
                    const ShadeCoefs& k, const Precision& p) {
  const int64_t fd = diffuse_factor(id, gd, k, p);
  const int64_t fs = specular_factor(is, gs, k, p);
  Rgb out{};
  for (int c = 0; c < 3; ++c) {
    out[c] = static_cast<uint32_t>(sat_unsigned(round_shift(color[c] * fd, p.coef_frac_bits) +
                                                    round_shift(k.specular[c] * fs, p.coef_frac_bits),
                                                p.alpha_bits));
  }
  return out;
}

}  // namespace cube4::golden
