// RTL equivalence tests of the perspective weight generator's per-sample
// part, cube4_persp_ray, against the golden functions it accumulates
// (golden/perspective.hpp, golden/units/dda_perspective.hpp): for random
// frames, slices and beams, every ray of the beam (walked with random
// pauses) gets the golden position, sample place, nearest voxel and
// realigned points behind and ahead.
//
// CUBE4_RTL_VECTORS overrides the random ray count (default 1,000,000).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "Vcube4_persp_ray.h"
#include "golden/perspective.hpp"
#include "tb/rtl/persp_registers.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;

constexpr int kFracBits = 20, kPosBits = 48;

int64_t sext(uint64_t v) { return static_cast<int64_t>(v << (64 - kPosBits)) >> (64 - kPosBits); }
uint64_t word(int64_t v) { return static_cast<uint64_t>(v) & ((uint64_t{1} << kPosBits) - 1); }

Fields golden_ray(const g::Registers& r, const g::PerspectiveSlice& s, int64_t u, int64_t v) {
  const int F = r.p.dda_frac_bits, W = r.p.weight_bits;
  const g::SamplePlace place = g::sample_place(r, s, u, v);
  const g::RayPoint bx = g::realigned_ray(s.behind_x, u, F, W), by = g::realigned_ray(s.behind_y, v, F, W);
  const g::RayPoint ax = g::realigned_ray(s.ahead_x, u, F, W), ay = g::realigned_ray(s.ahead_y, v, F, W);
  return {{"pos_x", g::ray_position(s.ray0_x, s.spacing, u)},
          {"pos_y", g::ray_position(s.ray0_y, s.spacing, v)},
          {"column", place.x},
          {"row", place.y},
          {"wx", place.wx},
          {"wy", place.wy},
          {"nearest_x", g::nearest_voxel(g::ray_position(s.ray0_x, s.spacing, u), F)},
          {"nearest_y", g::nearest_voxel(g::ray_position(s.ray0_y, s.spacing, v), F)},
          {"behind_ray_x", bx.ray},
          {"behind_ray_y", by.ray},
          {"behind_wx", bx.weight},
          {"behind_wy", by.weight},
          {"ahead_ray_x", ax.ray},
          {"ahead_ray_y", ay.ray},
          {"ahead_wx", ax.weight},
          {"ahead_wy", ay.weight}};
}

Fields rtl_ray(const Vcube4_persp_ray& m) {
  return {{"pos_x", sext(m.pos_x_o)},
          {"pos_y", sext(m.pos_y_o)},
          {"column", sext(m.column_o)},
          {"row", sext(m.row_o)},
          {"wx", m.wx_o},
          {"wy", m.wy_o},
          {"nearest_x", sext(m.nearest_x_o)},
          {"nearest_y", sext(m.nearest_y_o)},
          {"behind_ray_x", sext(m.behind_ray_x_o)},
          {"behind_ray_y", sext(m.behind_ray_y_o)},
          {"behind_wx", m.behind_wx_o},
          {"behind_wy", m.behind_wy_o},
          {"ahead_ray_x", sext(m.ahead_ray_x_o)},
          {"ahead_ray_y", sext(m.ahead_ray_y_o)},
          {"ahead_wx", m.ahead_wx_o},
          {"ahead_wy", m.ahead_wy_o}};
}

TEST(RtlPerspRay, EveryRayOfRandomBeamsMatchesGolden) {
  rtl::Random rng(43);
  const auto dut = cube4::rtl::make_dut<Vcube4_persp_ray>();
  Vcube4_persp_ray& m = *dut;
  rtl::reset(m);
  rtl::Checker c("cube4_persp_ray");
  const long n = rtl::vector_count(1000000);
  rtl::Timer t("cube4_persp_ray: " + std::to_string(n) + " random rays");
  uint64_t cycle = 0;
  long rays = 0;
  while (rays < n && c.ok()) {
    const g::Registers r = rtl::random_perspective_registers(rng, kFracBits);
    const int K = r.sample_slices();
    const int k = static_cast<int>(rng.range(0, K - 1));
    const g::PerspectiveSlice s = g::perspective_slice(r, k);
    if (s.rays_x.empty() || s.rays_y.empty()) continue;
    m.spacing_i = word(s.spacing);
    m.ray0_x_i = word(s.ray0_x);
    m.ray0_y_i = word(s.ray0_y);
    m.behind_start_x_i = word(s.behind_x.start);
    m.behind_start_y_i = word(s.behind_y.start);
    m.behind_step_i = word(s.behind_x.step);
    m.ahead_start_x_i = word(s.ahead_x.start);
    m.ahead_start_y_i = word(s.ahead_y.start);
    m.ahead_step_i = word(s.ahead_x.step);
    // A few beams of the slice, each from its first ray (or one further in).
    for (int beam = 0; beam < 4 && rays < n && c.ok(); ++beam) {
      const int64_t v = rng.range(s.rays_y.lo, s.rays_y.hi - 1);
      const int64_t u0 = rng.chance(0.8) ? s.rays_x.lo : rng.range(s.rays_x.lo, s.rays_x.hi - 1);
      const int64_t u1 = std::min(s.rays_x.hi, u0 + 3000);
      m.u0_i = static_cast<uint16_t>(u0);  // RayBits = 16, two's complement
      m.v_i = static_cast<uint16_t>(v);
      m.start_i = 1;
      m.advance_i = 0;
      int64_t u = u0;
      for (;;) {
        rtl::settle(m);
        rtl::rise(m);
        ++cycle;
        m.start_i = 0;
        rtl::settle(m);
        const Fields expected = golden_ray(r, s, u, v);
        const Fields got = rtl_ray(m);
        c.check(cycle, {{"k", k}, {"u", u}, {"v", v}, {"spacing", s.spacing}, {"ray0_x", s.ray0_x}}, expected, got);
        ++rays;
        if (u + 1 >= u1 || rays >= n || !c.ok()) break;
        // Pauses hold the ray; advancing moves to the next.
        m.advance_i = rng.chance(0.8) ? 1 : 0;
        if (m.advance_i) ++u;
      }
    }
  }
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_GE(rays, n);
}

}  // namespace
