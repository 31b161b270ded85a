// RTL equivalence tests of the parallel projection's weight generator,
// cube4_dda, against golden slice_control() (golden/pipeline.hpp): every
// field of every slice k = 0 .. K (K: the slice past the last, whose
// control the system's stream tag and compositor read too), for random
// frame registers (steps of either sign, whole-voxel and zero steps,
// supersampling up to the unit's limit) and for the registers the host
// programs for scenes from all six base planes; commands come with idle
// cycles between them (the control holds), and a frame is now and then
// restarted part-way (start_i wins over advance_i). Two width sets: the
// defaults (FracBits 20 = golden's dda_frac_bits, W 8, 48-bit DDA) and
// Vcube4_dda_w12 (rtl/groups/dda.cmake: W 12 over a 32-bit DDA of 16
// fraction bits, S up to 31, and no perspective hardware). The same unit
// in perspective frames (perspective_i) against golden perspective_slice():
// every constant of every slice of random cameras and of the host's
// perspective views from all six base planes, the divisions' exact cycle
// count, commands while they run, and frames of both projections in turn.
//
// CUBE4_RTL_VECTORS overrides the random slice count (default 1,000,000
// per width set).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "Vcube4_dda.h"
#include "Vcube4_dda_w12.h"
#include "golden/host_driver.hpp"
#include "golden/pipeline.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "systemc/rtl/dda_control.hpp"
#include "tb/rtl/persp_registers.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;

struct Widths {
  int frac_bits, weight_bits, pos_bits, supersampling_bits;
};
constexpr Widths kDefault{20, 8, 48, 4};   // cube4_dda's defaults
constexpr Widths kW12{16, 12, 32, 5};       // Vcube4_dda_w12 (dda.cmake)

uint64_t mask(int64_t v, int bits) { return static_cast<uint64_t>(v) & ((uint64_t{1} << bits) - 1); }

Fields control_fields(const g::SliceControl& c) {
  return {{"k", c.k},
          {"z_voxel", c.z_voxel},
          {"wx", c.wx},
          {"wy", c.wy},
          {"wz", c.wz},
          {"ix", c.ix},
          {"iy", c.iy},
          {"dx", c.dx},
          {"dy", c.dy},
          {"behind_x.base", c.behind_x.base},
          {"behind_x.weight", c.behind_x.weight},
          {"behind_y.base", c.behind_y.base},
          {"behind_y.weight", c.behind_y.weight},
          {"ahead_x.base", c.ahead_x.base},
          {"ahead_x.weight", c.ahead_x.weight},
          {"ahead_y.base", c.ahead_y.base},
          {"ahead_y.weight", c.ahead_y.weight}};
}

template <class M>
class Bench {
 public:
  explicit Bench(const Widths& w) : w_(w) { rtl::reset(m_); }

  // Runs the frame of r from slice 0 to slice K (or, with restart_at >= 0,
  // starts it again when slice restart_at is reached, once); idle cycles
  // between commands with probability `idle`.
  void frame(const g::Registers& r, rtl::Checker& c, rtl::Random& rng, double idle = 0, int restart_at = -1) {
    m_.x_start_i = mask(r.x_start, w_.pos_bits);
    m_.x_step_i = mask(r.x_step, w_.pos_bits);
    m_.y_start_i = mask(r.y_start, w_.pos_bits);
    m_.y_step_i = mask(r.y_step, w_.pos_bits);
    m_.supersampling_i = static_cast<uint32_t>(r.supersampling);
    m_.perspective_i = 0;
    command(true, rng.chance(0.5));  // start_i wins over advance_i
    const int K = r.sample_slices();
    for (int k = 0;; ++k) {
      check(r, k, c);
      while (rng.chance(idle)) {
        command(false, false);
        check(r, k, c);
      }
      if (k == restart_at) {
        restart_at = -1;
        command(true, true);
        k = -1;
        continue;
      }
      if (k == K) break;
      command(false, true);
    }
  }

  // Runs the perspective frame of r, slices 0 .. K - 1: after each command
  // the divided constants take exactly kSliceCycles (ready_o low until
  // then) and every constant is golden's; now and then a command comes
  // while the divisions run (they start over for the new slice) and idle
  // cycles follow (the constants hold).
  void perspective_frame(const g::Registers& r, rtl::Checker& c, rtl::Random& rng, double interrupt = 0) {
    m_.x_start_i = mask(r.x_start, w_.pos_bits);
    m_.x_step_i = mask(r.x_step, w_.pos_bits);
    m_.y_start_i = mask(r.y_start, w_.pos_bits);
    m_.y_step_i = mask(r.y_step, w_.pos_bits);
    m_.scale_start_i = mask(r.scale_start, w_.pos_bits);
    m_.scale_step_i = mask(r.scale_step, w_.pos_bits);
    m_.supersampling_i = static_cast<uint32_t>(r.supersampling);
    m_.dim_x_i = static_cast<uint32_t>(r.dim[0]);
    m_.dim_y_i = static_cast<uint32_t>(r.dim[1]);
    const int K = r.sample_slices();
    m_.last_slice_i = static_cast<uint32_t>(K - 1);
    m_.perspective_i = 1;
    command(true, rng.chance(0.5));
    for (int k = 0; k < K; ++k) {
      if (k + 1 < K && rng.chance(interrupt)) {
        // The next slice before this one's divisions are done.
        const int wait = static_cast<int>(rng.range(0, kSliceCycles - 2));
        for (int i = 0; i < wait && !m_.ready_o; ++i) command(false, false);
        if (!m_.ready_o) {
          ++interrupted_;
          command(false, true);
          continue;
        }
      }
      int cycles = 1;  // the command's edge
      while (!m_.ready_o && cycles <= 2 * kSliceCycles) {
        command(false, false);
        ++cycles;
      }
      check_perspective(r, k, cycles, c);
      while (rng.chance(0.1)) {
        command(false, false);
        check_perspective(r, k, 0, c);
      }
      if (k + 1 < K) command(false, true);
    }
    m_.perspective_i = 0;
  }

  long interrupted() const { return interrupted_; }

  // The clock edges from a command's (the first) to the one that raises
  // ready_o in a perspective frame: cube4_persp_slice's start and twelve
  // divisions of DivBits quotient bits, each with a load and a store (the
  // unit's header).
  static constexpr int kSliceCycles = 1 + 12 * (48 + 20 + 2);

 private:
  void check_perspective(const g::Registers& r, int k, int cycles, rtl::Checker& c) {
    const g::PerspectiveSlice e = g::perspective_slice(r, k);
    const g::PerspectiveSlice got = rtl::read_perspective_slice(m_, w_.pos_bits);
    // The first check of a slice counts its cycles; later ones (idle) hold.
    const int expected_cycles = cycles == 0 ? 0 : kSliceCycles;
    auto fields = [](const g::PerspectiveSlice& s, int cyc, bool ready) {
      Fields f{{"ready", ready},     {"cycles", cyc},       {"k", s.k},           {"z_voxel", s.z_voxel},
               {"wz", s.wz},         {"spacing", s.spacing}, {"ray0_x", s.ray0_x}, {"ray0_y", s.ray0_y}};
      const Fields divided = rtl::divided_fields(s);
      f.insert(f.end(), divided.begin(), divided.end());
      return f;
    };
    c.check(cycle_,
            Fields{{"k", k},
                   {"K", r.sample_slices()},
                   {"S", r.supersampling},
                   {"scale_start", r.scale_start},
                   {"scale_step", r.scale_step},
                   {"x_start", r.x_start},
                   {"x_step", r.x_step},
                   {"y_start", r.y_start},
                   {"y_step", r.y_step},
                   {"nx", r.dim[0]},
                   {"ny", r.dim[1]}},
            fields(e, expected_cycles, true), fields(got, cycles, m_.ready_o));
  }

  void command(bool start, bool advance) {
    m_.start_i = start;
    m_.advance_i = advance;
    rtl::settle(m_);
    rtl::rise(m_);
    ++cycle_;
    m_.start_i = 0;
    m_.advance_i = 0;
    rtl::settle(m_);
  }

  void check(const g::Registers& r, int k, rtl::Checker& c) {
    const g::SliceControl e = g::slice_control(r, k);
    const g::SliceControl got = rtl::read_dda_control(m_, w_.pos_bits - w_.frac_bits);
    // Parallel frames need no divisions: ready_o is valid_o.
    const bool valid = m_.valid_o && m_.ready_o;
    const bool equal = valid && got.k == e.k && got.z_voxel == e.z_voxel && got.wx == e.wx && got.wy == e.wy &&
                       got.wz == e.wz && got.ix == e.ix && got.iy == e.iy && got.dx == e.dx && got.dy == e.dy &&
                       same(got.behind_x, e.behind_x) && same(got.behind_y, e.behind_y) &&
                       same(got.ahead_x, e.ahead_x) && same(got.ahead_y, e.ahead_y);
    c.check_lazy(
        cycle_, equal,
        [&] {
          return Fields{{"k", k},
                        {"S", r.supersampling},
                        {"x_start", r.x_start},
                        {"x_step", r.x_step},
                        {"y_start", r.y_start},
                        {"y_step", r.y_step}};
        },
        [&] {
          Fields f = control_fields(e);
          f.insert(f.begin(), {"valid", 1});
          return f;
        },
        [&] {
          Fields f = control_fields(got);
          f.insert(f.begin(), {"valid", valid});
          return f;
        });
  }
  static bool same(const g::Realign& a, const g::Realign& b) { return a.base == b.base && a.weight == b.weight; }

  Widths w_;
  rtl::Dut<M> dut_ = rtl::make_dut<M>();
  M& m_ = *dut_;
  uint64_t cycle_ = 0;
  long interrupted_ = 0;
};

g::Registers frame_registers(const Widths& w) {
  g::Registers r;
  r.p.dda_frac_bits = w.frac_bits;
  r.p.weight_bits = w.weight_bits;
  return r;
}

// Random registers whose every slice, and the slices -1 and K + 1 the
// accumulators hold, fits the DDA's width.
g::Registers random_registers(rtl::Random& rng, const Widths& w) {
  g::Registers r = frame_registers(w);
  const int64_t one = int64_t{1} << w.frac_bits;
  const int smax = (1 << w.supersampling_bits) - 1;
  r.supersampling = static_cast<int>(rng.chance(0.2) ? rng.edgy(smax - 1) + 1 : rng.range(1, 4));
  r.dim = {1, 1, static_cast<int>(rng.range(1, rng.chance(0.1) ? 300 : 40))};
  auto step = [&] {
    switch (rng.range(0, 5)) {
      case 0: return int64_t{0};
      case 1: return rng.chance(0.5) ? one : -one;                     // a whole voxel per slice
      case 2: return rng.range(-2, 2);                                  // an LSB or two
      case 3: return rng.range(-4 * one, 4 * one);                      // steeper than the host's
      default: return rng.range(-one, one) / std::max(1, r.supersampling);
    }
  };
  // Slices -1 .. K + 1 within half the reach; the start in the rest.
  const int64_t reach = int64_t{1} << (w.pos_bits - 3);
  const int64_t K = r.sample_slices() + 2;
  auto clamped = [&](int64_t s) { return std::clamp(s, -reach / 2 / K, reach / 2 / K); };
  r.x_step = clamped(step());
  r.y_step = clamped(step());
  auto start = [&](int64_t s) {
    const int64_t room = reach - std::abs(s) * K;
    return rng.chance(0.3) ? rng.range(-2 * one, 2 * one) : rng.range(-room, room);
  };
  r.x_start = start(r.x_step);
  r.y_start = start(r.y_step);
  return r;
}

template <class M>
void random_frames(const Widths& w, const std::string& unit) {
  rtl::Random rng(73 + static_cast<uint64_t>(w.weight_bits));
  Bench<M> b(w);
  rtl::Checker c(unit);
  const long n = rtl::vector_count(1000000);
  rtl::Timer t(unit + ": " + std::to_string(n) + " random slices");
  long slices = 0;
  while (slices < n && c.ok()) {
    const g::Registers r = random_registers(rng, w);
    const int K = r.sample_slices();
    const int restart = rng.chance(0.05) ? static_cast<int>(rng.range(0, K)) : -1;
    b.frame(r, c, rng, rng.chance(0.1) ? 0.3 : 0.0, restart);
    slices += K + 1;
  }
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_GE(c.checked(), static_cast<uint64_t>(n));
}

TEST(RtlDda, FracBitsIsGoldens) { EXPECT_EQ(g::Precision{}.dda_frac_bits, kDefault.frac_bits); }

TEST(RtlDda, RandomFramesMatchGolden) { random_frames<Vcube4_dda>(kDefault, "cube4_dda"); }

TEST(RtlDda, RandomFramesMatchGoldenAtOtherWidths) { random_frames<Vcube4_dda_w12>(kW12, "cube4_dda (W 12)"); }

// The corners: fractions just below and at a whole voxel, where the
// weights wrap and the realignment borrows; S = 1 (wz always 0) and the
// largest S.
TEST(RtlDda, DirectedCornersMatchGolden) {
  rtl::Random rng(5);
  Bench<Vcube4_dda> b(kDefault);
  rtl::Checker c("cube4_dda");
  const int64_t one = int64_t{1} << kDefault.frac_bits;
  const int64_t starts[] = {0, 1, one - 1, one, -1, -one, -one + 1, 255 * one + one / 2};
  const int64_t steps[] = {0, 1, -1, one, -one, one / 3, -one / 3, one - 1, -(one - 1), one / 256, -(one / 256) - 1};
  for (int s : {1, 2, 3, 15})
    for (int64_t xs : starts)
      for (int64_t st : steps) {
        g::Registers r = frame_registers(kDefault);
        r.supersampling = s;
        r.dim = {1, 1, 9};
        r.x_start = xs;
        r.x_step = st;
        r.y_start = -xs;
        r.y_step = -st;
        b.frame(r, c, rng);
      }
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_GT(c.checked(), 3000u);
}

// Every slice the host programs for parallel views from all six base
// planes (and oblique ones), at S = 1, 2 and 3.
TEST(RtlDda, EverySliceOfScenesMatchesGolden) {
  rtl::Random rng(9);
  Bench<Vcube4_dda> b(kDefault);
  rtl::Checker c("cube4_dda");
  const std::string views[] = {
      R"({"direction": [1, 0.2, -0.1]})",  R"({"direction": [-1, 0.3, 0.2]})",
      R"({"direction": [0.1, 1, -0.4]})",  R"({"direction": [0.2, -1, 0.3]})",
      R"({"direction": [0.4, -0.1, 1]})",  R"({"direction": [-0.2, 0.3, -1]})",
      R"({"rotate": [20, 30, 0]})",        R"({"rotate": [-40, 130, 10]})",
  };
  int frames = 0;
  for (const std::string& view : views)
    for (int s : {1, 2, 3}) {
      const g::Scene sc = g::parse_scene(R"({"volume": {"synthetic": "sphere", "size": [40, 56, 24]}, "view": )" +
                                             view + R"(, "supersampling": )" + std::to_string(s) + "}",
                                         "test.json");
      const g::Volume vol = g::load_volume(sc.volume, sc.precision.voxel_bits, ".");
      b.frame(g::program_host(sc, vol).regs, c, rng, 0.1);
      ++frames;
    }
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_EQ(frames, 24);
}

// Perspective frames: every slice of random cameras (up to 60 slices a
// frame, so that many frames fit), with commands now and then while the
// divisions run.
TEST(RtlDda, RandomPerspectiveFramesMatchGolden) {
  rtl::Random rng(17);
  Bench<Vcube4_dda> b(kDefault);
  rtl::Checker c("cube4_dda (perspective)");
  const long n = rtl::vector_count(20000);
  rtl::Timer t("cube4_dda: " + std::to_string(n) + " random perspective slices");
  long slices = 0;
  while (slices < n && c.ok()) {
    const g::Registers r = rtl::random_perspective_registers(rng, kDefault.frac_bits, {1023, 1023, 20}, {1, 1, 1}, 3);
    b.perspective_frame(r, c, rng, 0.05);
    slices += r.sample_slices();
  }
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_GT(b.interrupted(), 100);
}

// Every slice the host programs for perspective views from all six base
// planes and oblique ones, several fields of view, S = 2.
TEST(RtlDda, EverySliceOfPerspectiveScenesMatchesGolden) {
  rtl::Random rng(23);
  Bench<Vcube4_dda> b(kDefault);
  rtl::Checker c("cube4_dda (perspective)");
  const std::string views[] = {
      R"({"projection": "perspective", "fov": 20, "rotate": [20, 30, 0]})",
      R"({"projection": "perspective", "fov": 60, "rotate": [-40, 130, 10]})",
      R"({"projection": "perspective", "fov": 80, "direction": [0.2, -1, 0.3]})",
      R"({"projection": "perspective", "fov": 45, "direction": [0.1, 1, -0.4]})",
      R"({"projection": "perspective", "fov": 45, "direction": [1, 0.1, -0.2]})",
      R"({"projection": "perspective", "fov": 35, "direction": [-1, 0.3, 0.2]})",
      R"({"projection": "perspective", "fov": 45, "direction": [-0.3, 0.2, -1]})",
      R"({"projection": "perspective", "fov": 30, "direction": [0, 0, 1]})",
  };
  int slices = 0;
  for (const std::string& view : views)
    for (const char* volume : {R"({"synthetic": "sphere", "size": [40, 56, 24]})",
                               R"({"synthetic": "sphere", "size": [64, 64, 64]})"}) {
      const g::Scene sc = g::parse_scene(std::string(R"({"volume": )") + volume + R"(, "view": )" + view +
                                             R"(, "supersampling": 2})",
                                         "test.json");
      const g::Volume vol = g::load_volume(sc.volume, sc.precision.voxel_bits, ".");
      const g::Registers r = g::program_host(sc, vol).regs;
      b.perspective_frame(r, c, rng);
      slices += r.sample_slices();
    }
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_GT(slices, 1000);
}

// One unit serves both projections: frames of either kind in turn, each
// from a unit the other kind left behind.
TEST(RtlDda, ProjectionsInTurnMatchGolden) {
  rtl::Random rng(29);
  Bench<Vcube4_dda> b(kDefault);
  rtl::Checker c("cube4_dda (both projections)");
  for (int i = 0; i < 40 && c.ok(); ++i) {
    if (i % 2 == 0)
      b.perspective_frame(rtl::random_perspective_registers(rng, kDefault.frac_bits, {300, 300, 12}, {1, 1, 1}, 2), c,
                          rng, 0.2);
    else
      b.frame(random_registers(rng, kDefault), c, rng, 0.1);
  }
  EXPECT_TRUE(c.ok()) << c.report();
}

}  // namespace
