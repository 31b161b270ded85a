// RTL equivalence tests of the gradient datapath cube4_gradient against the
// golden functions (golden/units/gradient.hpp) at default and non-default
// widths, parallel (sample_gradient(); the lateral reciprocal port driven
// with junk, which must not matter) and with HasPerspective
// (gradient_perspective(), every x and y difference at the ray spacings 1,
// 1.5, 2 and 3 besides the random ones). The ring around it is tested in
// test_gradient_ring.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include "Vcube4_gradient.h"
#include "Vcube4_gradient_persp.h"
#include "Vcube4_gradient_persp_v8.h"
#include "Vcube4_gradient_v16.h"
#include "Vcube4_gradient_v8.h"
#include "golden/pipeline.hpp"
#include "golden/units/gradient.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
using cube4::rtl::Fields;
using cube4::rtl::Random;
using cube4::rtl::Scoreboard;
using cube4::rtl::Timer;
using cube4::rtl::put_bits;
using cube4::rtl::run_stream;
using cube4::rtl::sign_extend;

constexpr int kGradientLatency = 3;  // cube4_gradient's header
// Random vectors per parameter set: a stream with valid_i always high, and
// one with random valid gaps (CUBE4_RTL_VECTORS overrides).
const long kRandom = cube4::rtl::vector_count(1000000);
const long kRandomGaps = cube4::rtl::vector_count(1000000);

struct GradIn {
  uint32_t left = 0, right = 0, up = 0, down = 0;
  std::array<uint32_t, 4> behind{}, ahead{};
  uint32_t bwx = 0, bwy = 0, awx = 0, awy = 0;
  int s = 1;
  uint32_t recip = 0;  // the lateral reciprocal (perspective)
  Fields fields() const {
    Fields f{{"left", left}, {"right", right}, {"up", up}, {"down", down}};
    for (int i = 0; i < 4; ++i) f.push_back({"behind" + std::to_string(i), behind[i]});
    for (int i = 0; i < 4; ++i) f.push_back({"ahead" + std::to_string(i), ahead[i]});
    f.insert(f.end(),
             {{"behind_wx", bwx}, {"behind_wy", bwy}, {"ahead_wx", awx}, {"ahead_wy", awy}, {"S", s}, {"recip", recip}});
    return f;
  }
};
struct GradOut {
  int32_t x = 0, y = 0, z = 0;
  bool operator==(const GradOut& o) const { return x == o.x && y == o.y && z == o.z; }
  Fields fields() const { return {{"gx", x}, {"gy", y}, {"gz", z}}; }
};

template <class M>
void test_gradient(const char* unit, const g::Precision& p, bool perspective = false) {
  const int V = p.voxel_bits, W = p.weight_bits, G = p.gradient_bits;
  const uint32_t vmax = (1u << V) - 1, wmax = 1u << W;
  // The lateral reciprocal: its fraction, the port's largest value, and the
  // reciprocal of a ray spacing m (DDA fraction F, m >= 1).
  const int R = g::lateral_recip_bits(p), F = p.dda_frac_bits;
  const uint32_t recip_max = (2u << R) - 1;
  auto recip_of = [&](double m) {
    return static_cast<uint32_t>(g::lateral_reciprocal(std::llround(std::ldexp(m, F)), F, R));
  };
  std::vector<GradIn> directed;
  // Every S with extreme neighbourhoods and end-point weights: zero and
  // saturated gradients of both signs in all three components.
  for (int s = 1; s <= 8; ++s)
    for (int lr = 0; lr < 16; ++lr)
      for (uint32_t b : {0u, vmax / 2, vmax})
        for (uint32_t a : {0u, vmax / 2, vmax})
          for (int wsel = 0; wsel < 16; ++wsel) {
            GradIn in;
            in.left = (lr & 1) ? vmax : 0, in.right = (lr & 2) ? vmax : 0;
            in.up = (lr & 4) ? vmax : 0, in.down = (lr & 8) ? vmax : 0;
            in.behind.fill(b), in.ahead.fill(a);
            in.bwx = (wsel & 1) ? wmax : 0, in.bwy = (wsel & 2) ? wmax : 0;
            in.awx = (wsel & 4) ? wmax : 0, in.awy = (wsel & 8) ? wmax : 0;
            in.s = s;
            directed.push_back(in);
          }
  // Every full difference -vmax .. vmax in x, y and z, for every S: each
  // rounding step and the saturation threshold of all three components.
  for (int s = 1; s <= 8; ++s)
    for (int64_t d = -int64_t{vmax}; d <= int64_t{vmax}; ++d) {
      GradIn in;
      const uint32_t lo = d < 0 ? static_cast<uint32_t>(-d) : 0, hi = d < 0 ? 0 : static_cast<uint32_t>(d);
      in.left = lo, in.right = hi, in.up = hi, in.down = lo;
      in.behind.fill(lo), in.ahead.fill(hi);
      in.bwx = in.bwy = in.awx = in.awy =
          (d & 3) == 0 ? 0 : (d & 3) == 1 ? wmax : static_cast<uint32_t>(d & 0x7f) % (wmax + 1);
      in.s = s;
      directed.push_back(in);
    }
  // The sets above at the spacing 1 (perspective) or with junk (parallel).
  const size_t n_parallel_sets = directed.size();
  // Perspective: every difference in x and y at the spacings 1 (the parallel
  // gradient), 1.5, 2 and 3 (the box filter's limit), and the reciprocal's
  // ends.
  if (perspective)
    for (const uint32_t recip : {recip_of(1), recip_of(1.5), recip_of(2), recip_of(3), 0u, recip_max})
      for (int64_t d = -int64_t{vmax}; d <= int64_t{vmax}; ++d) {
        GradIn in;
        const uint32_t lo = d < 0 ? static_cast<uint32_t>(-d) : 0, hi = d < 0 ? 0 : static_cast<uint32_t>(d);
        in.left = lo, in.right = hi, in.up = hi, in.down = lo;
        in.s = 1;
        in.recip = recip;
        directed.push_back(in);
      }
  Random rng(20 + V * 100 + W + (perspective ? 7 : 0));
  // Mostly a spacing the host would program, now and then any port value;
  // for the parallel unit, junk it must ignore.
  auto random_recip = [&] {
    if (!perspective || rng.chance(0.2)) return static_cast<uint32_t>(rng.edgy(recip_max));
    return recip_of(1 + 2 * std::ldexp(static_cast<double>(rng.bits(20)), -20));
  };
  for (size_t i = 0; i < n_parallel_sets; ++i) directed[i].recip = perspective ? recip_of(1) : random_recip();
  auto random_in = [&] {
    GradIn in;
    // Half the vectors in a smooth neighbourhood (small differences, where
    // gz does not saturate), half anywhere.
    const bool smooth = rng.chance(0.5);
    const int64_t c = rng.bits(V), spread = smooth ? (int64_t{1} << std::max(1, V - 6)) : vmax;
    auto val = [&] {
      return static_cast<uint32_t>(smooth ? std::clamp<int64_t>(c + rng.range(-spread, spread), 0, vmax)
                                          : rng.edgy(vmax, 0.05));
    };
    in.left = val(), in.right = val(), in.up = val(), in.down = val();
    for (auto& x : in.behind) x = val();
    for (auto& x : in.ahead) x = val();
    in.bwx = rng.edgy(wmax), in.bwy = rng.edgy(wmax), in.awx = rng.edgy(wmax), in.awy = rng.edgy(wmax);
    in.s = static_cast<int>(rng.range(1, 8));
    in.recip = random_recip();
    return in;
  };
  auto drive = [&](M& m, const GradIn& in) {
    m.left_i = in.left, m.right_i = in.right, m.up_i = in.up, m.down_i = in.down;
    for (int i = 0; i < 4; ++i) {
      put_bits(m.behind_i, i * V, V, in.behind[i]);
      put_bits(m.ahead_i, i * V, V, in.ahead[i]);
    }
    m.behind_wx_i = in.bwx, m.behind_wy_i = in.bwy, m.ahead_wx_i = in.awx, m.ahead_wy_i = in.awy;
    m.supersampling_i = in.s;
    m.lateral_recip_i = in.recip;
  };
  // The golden checker: sample_gradient() of the pipeline composition.
  g::Registers regs;
  regs.p = p;
  auto golden = [&](const GradIn& in) {
    if (perspective) {
      const uint32_t behind = g::abc_sample(in.behind[0], in.behind[1], in.behind[2], in.behind[3], in.bwx, in.bwy, W);
      const uint32_t ahead = g::abc_sample(in.ahead[0], in.ahead[1], in.ahead[2], in.ahead[3], in.awx, in.awy, W);
      const g::Gradient r =
          g::gradient_perspective(in.left, in.right, in.up, in.down, behind, ahead, in.s, in.recip, p);
      return GradOut{r.x, r.y, r.z};
    }
    regs.supersampling = in.s;
    g::SliceControl c;
    c.behind_x.weight = in.bwx, c.behind_y.weight = in.bwy;
    c.ahead_x.weight = in.awx, c.ahead_y.weight = in.awy;
    g::Neighbourhood n;
    n.left = in.left, n.right = in.right, n.up = in.up, n.down = in.down;
    n.behind = in.behind, n.ahead = in.ahead;
    const g::Gradient r = g::sample_gradient(regs, c, n);
    return GradOut{r.x, r.y, r.z};
  };
  auto read = [&](M& m) {
    return GradOut{static_cast<int32_t>(sign_extend(m.gx_o, G)), static_cast<int32_t>(sign_extend(m.gy_o, G)),
                   static_cast<int32_t>(sign_extend(m.gz_o, G))};
  };

  auto m = cube4::rtl::make_dut<M>();
  const long nd = static_cast<long>(directed.size());
  {
    Timer t(unit);
    Scoreboard<GradIn, GradOut> sb(unit, kGradientLatency);
    auto gen = [&](long i) { return i >= 0 && i < nd ? directed[i] : random_in(); };
    run_stream(*m, sb, nd + kRandom, 1.0, rng, gen, drive, golden, read, kGradientLatency);
    EXPECT_TRUE(sb.ok()) << sb.report();
    Scoreboard<GradIn, GradOut> gaps(std::string(unit) + " (valid gaps)", kGradientLatency);
    run_stream(*m, gaps, kRandomGaps, cube4::rtl::kGapValid, rng, [&](long) { return random_in(); }, drive, golden, read,
           kGradientLatency);
    EXPECT_TRUE(gaps.ok()) << gaps.report();
    std::printf("  %s V=%d W=%d G=%d shift=%d: %llu directed+random, %llu with gaps\n", unit, V, W, G,
                p.gradient_shift, static_cast<unsigned long long>(sb.checked()),
                static_cast<unsigned long long>(gaps.checked()));
  }
  m->final();
}

TEST(RtlGradient, DefaultWidths) { test_gradient<Vcube4_gradient>("cube4_gradient", g::Precision{}); }
TEST(RtlGradient, PerspectiveDefaultWidths) {
  test_gradient<Vcube4_gradient_persp>("cube4_gradient (HasPerspective)", g::Precision{}, true);
}
TEST(RtlGradient, PerspectiveVoxel8Weight6Shift1) {
  g::Precision p;
  p.voxel_bits = 8, p.weight_bits = 6, p.gradient_bits = 8, p.gradient_shift = 1;
  test_gradient<Vcube4_gradient_persp_v8>("cube4_gradient_persp_v8", p, true);
}
TEST(RtlGradient, Voxel8Weight6Shift1) {
  g::Precision p;
  p.voxel_bits = 8, p.weight_bits = 6, p.gradient_bits = 8, p.gradient_shift = 1;
  test_gradient<Vcube4_gradient_v8>("cube4_gradient_v8", p);
}
TEST(RtlGradient, Voxel16Weight10Gradient12) {
  g::Precision p;
  p.voxel_bits = 16, p.weight_bits = 10, p.gradient_bits = 12, p.gradient_shift = 6;
  test_gradient<Vcube4_gradient_v16>("cube4_gradient_v16", p);
}

}  // namespace
