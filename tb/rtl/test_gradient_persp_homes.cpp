// RTL equivalence tests of cube4_gradient_persp_homes against golden
// gradient_operand_homes() (golden/perspective_dataflow.hpp): for random
// frames, slices, axes and rays, every home and validity of a ray's
// gradient operands along the axis and the realigned points' weights; and,
// directed, the frame's first and last slices (no slice behind or ahead:
// the inputs there scrambled) and each slice's first and last ray along
// both axes (a neighbour missing).
//
// CUBE4_RTL_VECTORS overrides the random vector count (default 1,000,000).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "Vcube4_gradient_persp_homes.h"
#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "tb/rtl/persp_registers.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;

constexpr int kFracBits = 20, kPosBits = 48, kRayBits = 16, kHomeBits = kPosBits - kFracBits;

uint64_t word(int64_t v) { return static_cast<uint64_t>(v) & ((uint64_t{1} << kPosBits) - 1); }
uint16_t ray_word(int64_t v) { return static_cast<uint16_t>(v); }  // RayBits = 16, two's complement

Fields golden_homes(const g::OperandHomes& o) {
  Fields f{{"home", o.home}};
  auto pair = [&](const std::string& name, const std::array<int64_t, 2>& h) {
    for (size_t i = 0; i < 2; ++i) {
      f.push_back({name + std::to_string(i) + ".valid", h[i] != g::kNoRow});
      if (h[i] != g::kNoRow) f.push_back({name + std::to_string(i), h[i]});
    }
  };
  pair("side", o.side);
  pair("behind", o.behind);
  pair("ahead", o.ahead);
  // A missing slice's weight is the golden default 0; the unit's is don't-care.
  if (o.behind[0] != g::kNoRow || o.behind[1] != g::kNoRow) f.push_back({"behind_weight", o.behind_weight});
  if (o.ahead[0] != g::kNoRow || o.ahead[1] != g::kNoRow) f.push_back({"ahead_weight", o.ahead_weight});
  return f;
}

Fields rtl_homes(const Vcube4_gradient_persp_homes& m) {
  Fields f{{"home", rtl::sign_extend(static_cast<uint64_t>(m.home_o) & ((uint64_t{1} << kHomeBits) - 1), kHomeBits)}};
  auto pair = [&](const std::string& name, uint64_t valid, uint64_t homes) {
    for (int i = 0; i < 2; ++i) {
      const bool v = (valid >> i & 1) != 0;
      f.push_back({name + std::to_string(i) + ".valid", v});
      if (v) f.push_back({name + std::to_string(i), rtl::sign_extend(homes >> (i * kHomeBits) & ((uint64_t{1} << kHomeBits) - 1), kHomeBits)});
    }
  };
  pair("side", m.side_valid_o, m.side_o);
  pair("behind", m.behind_valid_o, m.behind_o);
  pair("ahead", m.ahead_valid_o, m.ahead_o);
  if (m.behind_valid_o != 0) f.push_back({"behind_weight", m.behind_weight_o});
  if (m.ahead_valid_o != 0) f.push_back({"ahead_weight", m.ahead_weight_o});
  return f;
}

// Drives one neighbouring slice's ports: the slice along the axis and the
// realignment into it, or (absent) random words the unit must ignore.
struct Neighbour {
  bool present;
  g::AxisSlice s;
  g::RealignDda d;
};
template <class Ports>
void drive(rtl::Random& rng, const Neighbour& n, Ports&& ports) {
  if (n.present) {
    ports(1, word(n.s.spacing), word(n.s.ray0), ray_word(n.s.rays.lo), ray_word(n.s.rays.hi), word(n.d.start),
          word(n.d.step));
  } else {
    ports(0, rng.bits(kPosBits), rng.bits(kPosBits), static_cast<uint16_t>(rng.bits(kRayBits)),
          static_cast<uint16_t>(rng.bits(kRayBits)), rng.bits(kPosBits), rng.bits(kPosBits));
  }
}

// Checks ray u of slice k of frame r along `axis`.
void check_ray(Vcube4_gradient_persp_homes& m, rtl::Random& rng, rtl::Checker& c, const g::Registers& r, int k,
               const g::PerspectiveSlice& s, const g::PerspectiveSlice* behind, const g::PerspectiveSlice* ahead,
               int axis, int64_t u, uint64_t vector) {
  const g::AxisSlice here = g::axis_slice(s, axis);
  const Neighbour b{behind != nullptr, behind ? g::axis_slice(*behind, axis) : g::AxisSlice{},
                    axis == 0 ? s.behind_x : s.behind_y};
  const Neighbour a{ahead != nullptr, ahead ? g::axis_slice(*ahead, axis) : g::AxisSlice{},
                    axis == 0 ? s.ahead_x : s.ahead_y};
  m.u_i = ray_word(u);
  m.spacing_i = word(here.spacing);
  m.ray0_i = word(here.ray0);
  m.rays_lo_i = ray_word(here.rays.lo);
  m.rays_hi_i = ray_word(here.rays.hi);
  drive(rng, b, [&](int present, uint64_t sp, uint64_t r0, uint16_t lo, uint16_t hi, uint64_t start, uint64_t step) {
    m.behind_present_i = present, m.behind_spacing_i = sp, m.behind_ray0_i = r0, m.behind_lo_i = lo,
    m.behind_hi_i = hi, m.behind_start_i = start, m.behind_step_i = step;
  });
  drive(rng, a, [&](int present, uint64_t sp, uint64_t r0, uint16_t lo, uint16_t hi, uint64_t start, uint64_t step) {
    m.ahead_present_i = present, m.ahead_spacing_i = sp, m.ahead_ray0_i = r0, m.ahead_lo_i = lo, m.ahead_hi_i = hi,
    m.ahead_start_i = start, m.ahead_step_i = step;
  });
  m.eval();
  const g::OperandHomes o = g::gradient_operand_homes(here, b.present ? &b.s : nullptr, b.d, a.present ? &a.s : nullptr,
                                                      a.d, u, r.p.dda_frac_bits, r.p.weight_bits);
  c.check(vector, {{"slice", k}, {"axis", axis}, {"u", u}, {"spacing", here.spacing}, {"ray0", here.ray0},
                          {"rays_lo", here.rays.lo}, {"rays_hi", here.rays.hi}},
                 golden_homes(o), rtl_homes(m));
}

// The slices around k, as golden's renderer has them (none past the frame's ends).
struct Around {
  g::PerspectiveSlice s, behind, ahead;
  bool has_behind, has_ahead;
  Around(const g::Registers& r, int k)
      : s(g::perspective_slice(r, k)), has_behind(k > 0), has_ahead(k + 1 < r.sample_slices()) {
    if (has_behind) behind = g::perspective_slice(r, k - 1);
    if (has_ahead) ahead = g::perspective_slice(r, k + 1);
  }
};

TEST(RtlGradientPerspHomes, EveryOperandsHomeOfRandomRaysMatchesGolden) {
  rtl::Random rng(71);
  const auto dut = rtl::make_dut<Vcube4_gradient_persp_homes>();
  rtl::Checker c("cube4_gradient_persp_homes");
  const long n = rtl::vector_count(1000000);
  rtl::Timer t("cube4_gradient_persp_homes: " + std::to_string(n) + " random rays");
  long vectors = 0;
  while (vectors < n && c.ok()) {
    const g::Registers r = rtl::random_perspective_registers(rng, kFracBits);
    const int k = static_cast<int>(rng.range(0, r.sample_slices() - 1));
    const Around at(r, k);
    // A frame's registers are costly to make: many rays of each slice.
    for (int i = 0; i < 64 && vectors < n && c.ok(); ++i) {
      const int axis = static_cast<int>(rng.bits(1));
      const g::RayRange rays = axis ? at.s.rays_y : at.s.rays_x;
      if (rays.empty()) break;
      const int64_t u = rng.range(rays.lo, rays.hi - 1);
      check_ray(*dut, rng, c, r, k, at.s, at.has_behind ? &at.behind : nullptr, at.has_ahead ? &at.ahead : nullptr,
                axis, u, static_cast<uint64_t>(vectors++));
    }
  }
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_GE(vectors, n);
}

TEST(RtlGradientPerspHomes, FirstAndLastSlicesAndRaysMatchGolden) {
  rtl::Random rng(72);
  const auto dut = rtl::make_dut<Vcube4_gradient_persp_homes>();
  rtl::Checker c("cube4_gradient_persp_homes (directed)");
  uint64_t vector = 0;
  for (int f = 0; f < 200 && c.ok(); ++f) {
    const g::Registers r = rtl::random_perspective_registers(rng, kFracBits);
    const int K = r.sample_slices();
    for (int k : {0, K - 1}) {
      const Around at(r, k);
      for (int axis = 0; axis < 2; ++axis) {
        const g::RayRange rays = axis ? at.s.rays_y : at.s.rays_x;
        if (rays.empty()) continue;
        for (int64_t u : {rays.lo, rays.hi - 1})
          check_ray(*dut, rng, c, r, k, at.s, at.has_behind ? &at.behind : nullptr,
                    at.has_ahead ? &at.ahead : nullptr, axis, u, vector++);
      }
    }
  }
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_GT(vector, 400u) << "too few directed cases: the random frames had empty slices";
}

}  // namespace
