// RTL equivalence tests of the perspective lane assignment, cube4_persp_lanes,
// against golden home_lane() (golden/perspective_dataflow.hpp): for random
// frames, slices and axes, every lane of every step of a walk (with random
// pauses, the slice's inputs scrambled once the walk has started) holds the
// golden ray, box and weight of its cell, at p = 1, 4, 5 and 16; and over a
// walk every ray of the slice is placed exactly once.
//
// CUBE4_RTL_VECTORS overrides the random lane count (default 1,000,000).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "Vcube4_persp_lanes_p1.h"
#include "Vcube4_persp_lanes_p16.h"
#include "Vcube4_persp_lanes_p4.h"
#include "Vcube4_persp_lanes_p5.h"
#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "tb/rtl/persp_registers.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;

constexpr int kFracBits = 20, kPosBits = 48, kRayBits = 16, kW = 8;

uint64_t word(int64_t v) { return static_cast<uint64_t>(v) & ((uint64_t{1} << kPosBits) - 1); }

Fields golden_lane(const g::HomeLane& h) {
  Fields f{{"valid", h.valid}};
  if (!h.valid) return f;
  f.push_back({"ray", h.ray});
  f.push_back({"box_left", h.box_left});
  for (int j = 0; j < 4; ++j) f.push_back({"overlap" + std::to_string(j), h.box.overlap[static_cast<size_t>(j)]});
  f.push_back({"weight", h.weight});
  return f;
}

template <class M>
Fields rtl_lane(const M& m, int k) {
  auto bits = [](const auto& port, int lsb, int width) { return static_cast<int64_t>(rtl::get_bits(port, lsb, width)); };
  Fields f{{"valid", bits(m.valid_o, k, 1)}};
  if (!f[0].value) return f;
  f.push_back({"ray", rtl::sign_extend(rtl::get_bits(m.ray_o, k * kRayBits, kRayBits), kRayBits)});
  f.push_back({"box_left", bits(m.box_left_o, k, 1)});
  for (int j = 0; j < 4; ++j)
    f.push_back({"overlap" + std::to_string(j), bits(m.overlap_o, (k * 4 + j) * (kW + 1), kW + 1)});
  f.push_back({"weight", bits(m.weight_o, k * kW, kW)});
  return f;
}

template <class M>
void walk_random_slices(int pipes, uint64_t salt) {
  rtl::Random rng(salt);
  const auto dut = rtl::make_dut<M>();
  M& m = *dut;
  rtl::reset(m);
  rtl::Checker c("cube4_persp_lanes p=" + std::to_string(pipes));
  const long n = rtl::vector_count(1000000);
  rtl::Timer t("cube4_persp_lanes p=" + std::to_string(pipes) + ": " + std::to_string(n) + " random lanes");
  uint64_t cycle = 0;
  long lanes = 0;
  while (lanes < n && c.ok()) {
    const g::Registers r = rtl::random_perspective_registers(rng, kFracBits);
    const int k = static_cast<int>(rng.range(0, r.sample_slices() - 1));
    const g::PerspectiveSlice s = g::perspective_slice(r, k);
    // Along x with the pipelines' lanes, or along y one beam a step (the
    // unit at p = 1 walks the rows as well).
    const int axis = pipes == 1 && rng.chance(0.5) ? 1 : 0;
    const g::RayRange rays = axis ? s.rays_y : s.rays_x;
    const int64_t ray0 = axis ? s.ray0_y : s.ray0_x;
    const int cells = r.dim[static_cast<size_t>(axis)];
    m.spacing_i = word(s.spacing);
    m.ray0_i = word(ray0);
    m.rays_lo_i = static_cast<uint16_t>(rays.lo);  // RayBits = 16, two's complement
    m.rays_hi_i = static_cast<uint16_t>(rays.hi);
    m.start_i = 1;
    m.advance_i = 0;
    int64_t placed = 0;
    // The steps over the axis's cells, and one past them (no ray).
    const int steps = (cells + pipes - 1) / pipes + 1;
    for (int j = 0; j < steps && c.ok();) {
      rtl::settle(m);
      rtl::rise(m);
      ++cycle;
      if (m.start_i) {
        // The walk keeps the slice it started on: the inputs may move on.
        m.spacing_i = word(static_cast<int64_t>(rng.bits(kPosBits)));
        m.ray0_i = word(static_cast<int64_t>(rng.bits(kPosBits)));
        m.rays_lo_i = static_cast<uint16_t>(rng.bits(kRayBits));
        m.rays_hi_i = static_cast<uint16_t>(rng.bits(kRayBits));
      }
      m.start_i = 0;
      rtl::settle(m);
      for (int lane = 0; lane < pipes; ++lane) {
        const int64_t cell = int64_t{j} * pipes + lane;
        const g::HomeLane h = g::home_lane(ray0, s.spacing, rays, cell, r.p.dda_frac_bits, r.p.weight_bits);
        c.check(cycle, {{"slice", k}, {"axis", axis}, {"step", j}, {"lane", lane}, {"cell", cell},
                        {"spacing", s.spacing}, {"ray0", ray0}, {"rays_lo", rays.lo}, {"rays_hi", rays.hi}},
                golden_lane(h), rtl_lane(m, lane));
        ++lanes;
      }
      // Pauses hold the step; advancing moves to the next.
      m.advance_i = rng.chance(0.85) ? 1 : 0;
      if (m.advance_i) {
        for (int lane = 0; lane < pipes; ++lane) placed += static_cast<int64_t>(rtl::get_bits(m.valid_o, lane, 1));
        ++j;
      }
    }
    if (c.ok()) {
      EXPECT_EQ(placed, rays.empty() ? 0 : rays.hi - rays.lo) << "slice " << k << " axis " << axis;
    }
  }
  EXPECT_TRUE(c.ok()) << c.report();
}

TEST(RtlPerspLanes, EveryLaneOfRandomWalksMatchesGoldenAtP1) { walk_random_slices<Vcube4_persp_lanes_p1>(1, 61); }
TEST(RtlPerspLanes, EveryLaneOfRandomWalksMatchesGoldenAtP4) { walk_random_slices<Vcube4_persp_lanes_p4>(4, 62); }
TEST(RtlPerspLanes, EveryLaneOfRandomWalksMatchesGoldenAtP5) { walk_random_slices<Vcube4_persp_lanes_p5>(5, 63); }
TEST(RtlPerspLanes, EveryLaneOfRandomWalksMatchesGoldenAtP16) { walk_random_slices<Vcube4_persp_lanes_p16>(16, 64); }

}  // namespace
