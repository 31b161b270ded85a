// RTL equivalence tests of the interpolation datapath against the golden
// functions (golden/units/interp.hpp): cube4_lerp (combinational) and
// cube4_interp at default and non-default widths. The ring around them is
// tested in test_interp_ring.cpp. Pipelined units are driven with one input
// set per clock and again with random valid gaps; each output is compared
// with the golden result of the input that entered `latency` cycles earlier
// (rtl_check.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include "Vcube4_lerp.h"
#include "Vcube4_interp.h"
#include "Vcube4_interp_w10.h"
#include "Vcube4_interp_w6.h"
#include "Vcube4_interp_t4.h"
#include "golden/units/interp.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
using cube4::rtl::Fields;
using cube4::rtl::Random;
using cube4::rtl::Scoreboard;
using cube4::rtl::Timer;
using cube4::rtl::put_bits;
using cube4::rtl::run_stream;

constexpr int kInterpLatency = 3;  // cube4_interp's header
// Random vectors per parameter set: a stream with valid_i always high, and
// one with random valid gaps (CUBE4_RTL_VECTORS overrides).
const long kRandom = cube4::rtl::vector_count(1000000);
const long kRandomGaps = cube4::rtl::vector_count(1000000);

TEST(RtlLerp, MatchesGolden) {
  constexpr int V = 12, W = 8;
  constexpr int64_t vmax = (1 << V) - 1, wmax = 1 << W;
  const auto dut = cube4::rtl::make_dut<Vcube4_lerp>();
  Vcube4_lerp& m = *dut;
  cube4::rtl::Checker c("cube4_lerp");
  uint64_t n = 0;
  auto one = [&](int64_t a, int64_t b, int64_t w) {
    m.a_i = a;
    m.b_i = b;
    m.w_i = w;
    m.eval();
    const int64_t exp = g::lerp(a, b, w, W), got = m.y_o;
    c.check_lazy(n++, exp == got, [&] { return Fields{{"a", a}, {"b", b}, {"w", w}}; },
                 [&] { return Fields{{"y", exp}}; }, [&] { return Fields{{"y", got}}; });
  };
  // Directed: extreme and mid values against every weight 0 .. 2^W.
  const int64_t vals[] = {0, 1, 2, vmax / 2, vmax / 2 + 1, vmax - 2, vmax - 1, vmax};
  for (int64_t a : vals)
    for (int64_t b : vals)
      for (int64_t w = 0; w <= wmax; ++w) one(a, b, w);
  // Every difference b - a with the rounding-critical weights.
  for (int64_t d = -vmax; d <= vmax; ++d)
    for (int64_t w : {int64_t{1}, wmax / 2 - 1, wmax / 2, wmax / 2 + 1, wmax - 1})
      one(d < 0 ? -d : 0, d < 0 ? 0 : d, w);
  Random rng(1);
  for (long i = 0; i < kRandom; ++i) one(rng.bits(V), rng.bits(V), rng.edgy(wmax));
  m.final();
  EXPECT_TRUE(c.ok()) << c.report();
  std::printf("  cube4_lerp: %llu vectors\n", static_cast<unsigned long long>(c.checked()));
}

struct TriIn {
  std::array<uint32_t, 8> v{};
  uint32_t wx = 0, wy = 0, wz = 0;
  Fields fields() const {
    Fields f;
    for (int i = 0; i < 8; ++i) f.push_back({"v" + std::to_string(i), v[i]});
    f.push_back({"wx", wx});
    f.push_back({"wy", wy});
    f.push_back({"wz", wz});
    return f;
  }
};
struct TriOut {
  uint32_t sample = 0;
  bool operator==(const TriOut& o) const { return sample == o.sample; }
  Fields fields() const { return {{"sample", sample}}; }
};

template <class M>
void test_trilinear(const char* unit, int V, int W) {
  const uint32_t vmax = (1u << V) - 1, wmax = 1u << W;
  // Directed: every {0, max} voxel pattern with every combination of corner
  // weights; then constant volumes (every weight must return the voxel).
  std::vector<TriIn> directed;
  const uint32_t wc[] = {0, 1, wmax / 2, wmax - 1, wmax};
  for (uint32_t pat = 0; pat < 256; ++pat)
    for (uint32_t wx : wc)
      for (uint32_t wy : wc)
        for (uint32_t wz : wc) {
          TriIn in;
          for (int i = 0; i < 8; ++i) in.v[i] = (pat >> i & 1) ? vmax : 0;
          in.wx = wx, in.wy = wy, in.wz = wz;
          directed.push_back(in);
        }
  Random rng(10 + V * 100 + W);
  for (int k = 0; k < 2000; ++k) {
    TriIn in;
    in.v.fill(static_cast<uint32_t>(rng.edgy(vmax)));
    in.wx = rng.range(0, wmax), in.wy = rng.range(0, wmax), in.wz = rng.range(0, wmax);
    directed.push_back(in);
  }
  auto random_in = [&] {
    TriIn in;
    for (auto& x : in.v) x = static_cast<uint32_t>(rng.edgy(vmax, 0.05));
    in.wx = rng.edgy(wmax), in.wy = rng.edgy(wmax), in.wz = rng.edgy(wmax);
    return in;
  };
  auto drive = [&](M& m, const TriIn& in) {
    for (int i = 0; i < 8; ++i) put_bits(m.voxels_i, i * V, V, in.v[i]);
    m.wx_i = in.wx;
    m.wy_i = in.wy;
    m.wz_i = in.wz;
  };
  auto golden = [&](const TriIn& in) { return TriOut{g::trilinear(in.v, in.wx, in.wy, in.wz, W)}; };
  auto read = [](M& m) { return TriOut{static_cast<uint32_t>(m.sample_o)}; };

  auto m = cube4::rtl::make_dut<M>();
  const long nd = static_cast<long>(directed.size());
  {
    Timer t(unit);
    Scoreboard<TriIn, TriOut> sb(unit, kInterpLatency);
    auto gen = [&](long i) { return i >= 0 && i < nd ? directed[i] : random_in(); };
    run_stream(*m, sb, nd + kRandom, 1.0, rng, gen, drive, golden, read, kInterpLatency);
    EXPECT_TRUE(sb.ok()) << sb.report();
    Scoreboard<TriIn, TriOut> gaps(std::string(unit) + " (valid gaps)", kInterpLatency);
    run_stream(*m, gaps, kRandomGaps, cube4::rtl::kGapValid, rng, [&](long) { return random_in(); }, drive, golden, read,
           kInterpLatency);
    EXPECT_TRUE(gaps.ok()) << gaps.report();
    std::printf("  %s V=%d W=%d: %llu directed+random, %llu with gaps\n", unit, V, W,
                static_cast<unsigned long long>(sb.checked()), static_cast<unsigned long long>(gaps.checked()));
  }
  m->final();
}

// Voxel tags (bela §III): the sample's tag is its nearest voxel's, golden
// sample_tag(), delayed with the sample; every corner, every weight around
// the half (the tie goes up) and the ends, then a million random sets.
struct TagIn {
  TriIn tri;
  std::array<uint32_t, 8> t{};
  Fields fields() const {
    Fields f = tri.fields();
    for (int i = 0; i < 8; ++i) f.push_back({"t" + std::to_string(i), t[i]});
    return f;
  }
};
struct TagOut {
  uint32_t sample = 0, tag = 0;
  bool operator==(const TagOut& o) const { return sample == o.sample && tag == o.tag; }
  Fields fields() const { return {{"sample", sample}, {"tag", tag}}; }
};

TEST(RtlInterp, VoxelTagsTakeTheNearestVoxels) {
  constexpr int V = 12, W = 8, T = 4;
  const uint32_t vmax = (1u << V) - 1, wmax = 1u << W, tmax = (1u << T) - 1;
  Random rng(77);
  auto random_in = [&] {
    TagIn in;
    for (auto& x : in.tri.v) x = static_cast<uint32_t>(rng.edgy(vmax, 0.05));
    for (auto& x : in.t) x = static_cast<uint32_t>(rng.bits(T));
    in.tri.wx = rng.edgy(wmax), in.tri.wy = rng.edgy(wmax), in.tri.wz = rng.edgy(wmax);
    return in;
  };
  std::vector<TagIn> directed;
  const uint32_t wc[] = {0, 1, wmax / 2 - 1, wmax / 2, wmax / 2 + 1, wmax - 1, wmax};
  for (uint32_t wx : wc)
    for (uint32_t wy : wc)
      for (uint32_t wz : wc) {
        TagIn in = random_in();
        for (int i = 0; i < 8; ++i) in.t[i] = i == 0 ? tmax : static_cast<uint32_t>(i);
        in.tri.wx = wx, in.tri.wy = wy, in.tri.wz = wz;
        directed.push_back(in);
      }
  auto drive = [&](Vcube4_interp_t4& m, const TagIn& in) {
    for (int i = 0; i < 8; ++i) put_bits(m.voxels_i, i * V, V, in.tri.v[i]);
    m.wx_i = in.tri.wx;
    m.wy_i = in.tri.wy;
    m.wz_i = in.tri.wz;
    uint64_t tags = 0;
    for (int i = 0; i < 8; ++i) tags |= uint64_t{in.t[i]} << (T * i);
    m.vtags_i = static_cast<uint32_t>(tags);
  };
  auto golden = [&](const TagIn& in) {
    return TagOut{g::trilinear(in.tri.v, in.tri.wx, in.tri.wy, in.tri.wz, W),
                  g::sample_tag(in.t, in.tri.wx, in.tri.wy, in.tri.wz, W)};
  };
  auto read = [](Vcube4_interp_t4& m) { return TagOut{static_cast<uint32_t>(m.sample_o), static_cast<uint32_t>(m.vtag_o)}; };
  auto m = cube4::rtl::make_dut<Vcube4_interp_t4>();
  const long nd = static_cast<long>(directed.size());
  Scoreboard<TagIn, TagOut> sb("cube4_interp_t4", kInterpLatency);
  auto gen = [&](long i) { return i >= 0 && i < nd ? directed[i] : random_in(); };
  run_stream(*m, sb, nd + kRandom, 1.0, rng, gen, drive, golden, read, kInterpLatency);
  EXPECT_TRUE(sb.ok()) << sb.report();
  Scoreboard<TagIn, TagOut> gaps("cube4_interp_t4 (valid gaps)", kInterpLatency);
  run_stream(*m, gaps, kRandomGaps, cube4::rtl::kGapValid, rng, [&](long) { return random_in(); }, drive, golden, read,
             kInterpLatency);
  EXPECT_TRUE(gaps.ok()) << gaps.report();
  std::printf("  cube4_interp_t4: %llu directed+random, %llu with gaps\n", static_cast<unsigned long long>(sb.checked()),
              static_cast<unsigned long long>(gaps.checked()));
  m->final();
}

TEST(RtlInterp, DefaultWidths) { test_trilinear<Vcube4_interp>("cube4_interp", 12, 8); }
TEST(RtlInterp, Voxel8Weight6) { test_trilinear<Vcube4_interp_w6>("cube4_interp_w6", 8, 6); }
TEST(RtlInterp, Voxel16Weight10) { test_trilinear<Vcube4_interp_w10>("cube4_interp_w10", 16, 10); }

}  // namespace
