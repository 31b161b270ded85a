// RTL equivalence tests of the perspective weight generator's per-slice
// part, cube4_persp_slice, against golden perspective_slice()
// (golden/perspective.hpp): every constant of a slice, for random frame
// registers and slices (the first and last slice among them), and for every
// slice of the registers the host programs for perspective scenes (the
// sphere and brainsmall, all six base planes, several fields of view).
// Each slice takes the unit's documented cycle count exactly.
//
// CUBE4_RTL_VECTORS overrides the random slice count (default 20,000: a
// slice is about 840 cycles of the serial divider).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "Vcube4_persp_slice.h"
#include "golden/host_driver.hpp"
#include "golden/perspective.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "tb/rtl/persp_registers.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;

constexpr int kFracBits = 20;  // the unit's default FracBits
constexpr int kPosBits = 48;
constexpr int kDivBits = kPosBits + kFracBits;
// The header's count: the start cycle, then per division a load, DivBits
// quotient bits and a finish.
constexpr int kSliceCycles = 1 + 12 * (kDivBits + 2);

int64_t sext(uint64_t v, int bits) { return static_cast<int64_t>(v << (64 - bits)) >> (64 - bits); }

class Bench {
 public:
  Bench() { rtl::reset(m_); }

  // Runs slice k of r; checks every constant and the cycle count.
  void check(const g::Registers& r, int k, rtl::Checker& c) {
    m_.scale_start_i = static_cast<uint64_t>(r.scale_start);
    m_.scale_step_i = static_cast<uint64_t>(r.scale_step);
    m_.x_start_i = static_cast<uint64_t>(r.x_start);
    m_.x_step_i = static_cast<uint64_t>(r.x_step);
    m_.y_start_i = static_cast<uint64_t>(r.y_start);
    m_.y_step_i = static_cast<uint64_t>(r.y_step);
    m_.dim_x_i = static_cast<uint32_t>(r.dim[0]);
    m_.dim_y_i = static_cast<uint32_t>(r.dim[1]);
    m_.last_slice_i = static_cast<uint32_t>(r.sample_slices() - 1);
    m_.k_i = static_cast<uint32_t>(k);
    m_.start_i = 1;
    rtl::settle(m_);
    rtl::rise(m_);
    ++cycle_;
    m_.start_i = 0;
    int cycles = 1;
    for (;; ++cycles) {
      rtl::settle(m_);
      if (m_.done_o || cycles > 4 * kSliceCycles) break;
      rtl::rise(m_);
      ++cycle_;
    }
    const g::PerspectiveSlice s = g::perspective_slice(r, k);
    auto in = [&] {
      return Fields{{"k", k},           {"K", r.sample_slices()}, {"scale_start", r.scale_start},
                    {"scale_step", r.scale_step}, {"x_start", r.x_start}, {"x_step", r.x_step},
                    {"y_start", r.y_start}, {"y_step", r.y_step}, {"nx", r.dim[0]}, {"ny", r.dim[1]}};
    };
    const Fields expected{{"cycles", kSliceCycles},
                          {"spacing", s.spacing},
                          {"ray0_x", s.ray0_x},
                          {"ray0_y", s.ray0_y},
                          {"rays_x_lo", s.rays_x.lo},
                          {"rays_x_hi", s.rays_x.hi},
                          {"rays_y_lo", s.rays_y.lo},
                          {"rays_y_hi", s.rays_y.hi},
                          {"box_recip", static_cast<int64_t>(s.box_reciprocal)},
                          {"lateral_recip", s.lateral_reciprocal},
                          {"behind_start_x", s.behind_x.start},
                          {"behind_start_y", s.behind_y.start},
                          {"behind_step_x", s.behind_x.step},
                          {"behind_step_y", s.behind_y.step},
                          {"ahead_start_x", s.ahead_x.start},
                          {"ahead_start_y", s.ahead_y.start},
                          {"ahead_step_x", s.ahead_x.step},
                          {"ahead_step_y", s.ahead_y.step}};
    auto get = [&](uint64_t v) { return sext(v, kPosBits); };
    const Fields got{{"cycles", m_.done_o ? cycles : -1},
                     {"spacing", get(m_.spacing_o)},
                     {"ray0_x", get(m_.ray0_x_o)},
                     {"ray0_y", get(m_.ray0_y_o)},
                     {"rays_x_lo", get(m_.rays_x_lo_o)},
                     {"rays_x_hi", get(m_.rays_x_hi_o)},
                     {"rays_y_lo", get(m_.rays_y_lo_o)},
                     {"rays_y_hi", get(m_.rays_y_hi_o)},
                     {"box_recip", get(m_.box_recip_o)},
                     {"lateral_recip", get(m_.lateral_recip_o)},
                     {"behind_start_x", get(m_.behind_start_x_o)},
                     {"behind_start_y", get(m_.behind_start_y_o)},
                     {"behind_step_x", get(m_.behind_step_o)},
                     {"behind_step_y", get(m_.behind_step_o)},
                     {"ahead_start_x", get(m_.ahead_start_x_o)},
                     {"ahead_start_y", get(m_.ahead_start_y_o)},
                     {"ahead_step_x", get(m_.ahead_step_o)},
                     {"ahead_step_y", get(m_.ahead_step_o)}};
    c.check(cycle_, in(), expected, got);
    rtl::rise(m_);  // the done cycle
    ++cycle_;
  }

 private:
  cube4::rtl::Dut<Vcube4_persp_slice> dut_ = cube4::rtl::make_dut<Vcube4_persp_slice>();
  Vcube4_persp_slice& m_ = *dut_;
  uint64_t cycle_ = 0;
};

TEST(RtlPerspSlice, FracBitsIsGoldens) { EXPECT_EQ(g::Precision{}.dda_frac_bits, kFracBits); }

TEST(RtlPerspSlice, RandomRegistersAndSlicesMatchGolden) {
  rtl::Random rng(41);
  Bench b;
  rtl::Checker c("cube4_persp_slice");
  const long n = rtl::vector_count(20000);
  rtl::Timer t("cube4_persp_slice: " + std::to_string(n) + " random slices");
  for (long i = 0; i < n && c.ok(); ++i) {
    const g::Registers r = cube4::rtl::random_perspective_registers(rng, kFracBits);
    const int K = r.sample_slices();
    // The first and the last slice (no neighbour behind, none ahead) often.
    const int k = i % 4 == 0 ? 0 : i % 4 == 1 ? K - 1 : static_cast<int>(rng.range(0, K - 1));
    b.check(r, k, c);
  }
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_EQ(c.checked(), static_cast<uint64_t>(n));
}

TEST(RtlPerspSlice, EverySliceOfPerspectiveScenesMatchesGolden) {
  Bench b;
  rtl::Checker c("cube4_persp_slice");
  const std::string views[] = {
      R"({"projection": "perspective", "fov": 20, "rotate": [20, 30, 0]})",
      R"({"projection": "perspective", "fov": 60, "rotate": [-40, 130, 10]})",
      R"({"projection": "perspective", "fov": 80, "direction": [0.2, -1, 0.3]})",
      R"({"projection": "perspective", "fov": 45, "direction": [1, 0.1, -0.2]})",
      R"({"projection": "perspective", "fov": 45, "direction": [-0.3, 0.2, -1]})",
      R"({"projection": "perspective", "fov": 30, "direction": [0, 0, 1]})",
  };
  int slices = 0;
  for (const std::string& view : views)
    for (const char* volume : {R"({"synthetic": "sphere", "size": [40, 56, 24]})",
                               R"({"synthetic": "sphere", "size": [64, 64, 64]})"}) {
      const g::Scene s = g::parse_scene(std::string(R"({"volume": )") + volume + R"(, "view": )" + view +
                                            R"(, "supersampling": 2})",
                                        "test.json");
      const g::Volume vol = g::load_volume(s.volume, s.precision.voxel_bits, ".");
      const g::HostProgram h = g::program_host(s, vol);
      for (int k = 0; k < h.regs.sample_slices(); ++k, ++slices) b.check(h.regs, k, c);
    }
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_GT(slices, 1000);
}

}  // namespace
