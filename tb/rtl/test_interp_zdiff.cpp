// RTL equivalence test of VolumePro's z gradient unit, cube4_interp_zdiff,
// against golden interpolated_z_difference() of the eight
// voxel_z_difference()s (golden/units/gradient.hpp), at the default widths
// and at two other width sets (rtl/groups/interp_zdiff.cmake). Driven with
// one input set per clock and again with random valid gaps; each output is
// compared with the golden result of the input that entered 3 cycles
// earlier (rtl_check.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "Vcube4_interp_zdiff.h"
#include "Vcube4_interp_zdiff_v16.h"
#include "Vcube4_interp_zdiff_v8.h"
#include "golden/units/gradient.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
using cube4::rtl::Fields;
using cube4::rtl::get_bits;
using cube4::rtl::put_bits;
using cube4::rtl::Random;
using cube4::rtl::run_stream;
using cube4::rtl::Scoreboard;
using cube4::rtl::sign_extend;
using cube4::rtl::Timer;

constexpr int kLatency = 3;  // cube4_interp_zdiff's header
const long kRandom = cube4::rtl::vector_count(1000000);
const long kRandomGaps = cube4::rtl::vector_count(1000000);

// The sample's eight voxels (z and z + 1) and the eight beyond them in z
// (z - 1 under corners 0..3, z + 2 over corners 4..7), as the ports order them.
struct ZIn {
  std::array<uint32_t, 8> voxels{}, outer{};
  uint32_t wx = 0, wy = 0, wz = 0;
  Fields fields() const {
    Fields f;
    for (int i = 0; i < 8; ++i) f.push_back({"v" + std::to_string(i), voxels[static_cast<size_t>(i)]});
    for (int i = 0; i < 8; ++i) f.push_back({"outer" + std::to_string(i), outer[static_cast<size_t>(i)]});
    f.push_back({"wx", wx});
    f.push_back({"wy", wy});
    f.push_back({"wz", wz});
    return f;
  }
};
struct ZOut {
  int64_t zdiff = 0;
  bool operator==(const ZOut& o) const { return zdiff == o.zdiff; }
  Fields fields() const { return {{"zdiff", zdiff}}; }
};

ZOut golden_zdiff(const ZIn& in, int W) {
  std::array<int32_t, 8> d{};
  for (size_t i = 0; i < 4; ++i) d[i] = g::voxel_z_difference(in.voxels[i + 4], in.outer[i]);
  for (size_t i = 4; i < 8; ++i) d[i] = g::voxel_z_difference(in.outer[i], in.voxels[i - 4]);
  return {g::interpolated_z_difference(d, in.wx, in.wy, in.wz, W)};
}

template <class M>
void test_interp_zdiff(const char* unit, int V, int W) {
  const uint32_t vmax = (1u << V) - 1, one = 1u << W;
  Random rng(700 + V * 100 + W);
  auto random_in = [&](double edge) {
    ZIn in;
    for (auto& v : in.voxels) v = static_cast<uint32_t>(rng.edgy(vmax, edge));
    for (auto& v : in.outer) v = static_cast<uint32_t>(rng.edgy(vmax, edge));
    // Weights as the weight generator makes them (below 2^W), and 2^W, the
    // port's top value, now and then.
    auto weight = [&] { return static_cast<uint32_t>(rng.chance(0.02) ? one : rng.edgy(one - 1, 0.1)); };
    in.wx = weight();
    in.wy = weight();
    in.wz = weight();
    return in;
  };

  std::vector<ZIn> directed;
  const uint32_t weights[] = {0, 1, one / 2 - 1, one / 2, one / 2 + 1, one - 1, one};
  // The largest differences of each sign everywhere (the signed lerps'
  // extremes), a step between the corners, and zero differences.
  for (uint32_t wx : weights)
    for (uint32_t wy : weights)
      for (uint32_t wz : weights)
        for (int pattern = 0; pattern < 5; ++pattern) {
          ZIn in;
          in.wx = wx;
          in.wy = wy;
          in.wz = wz;
          for (size_t i = 0; i < 8; ++i) {
            const bool up = pattern == 0 || (pattern == 2 && (i & 1)) || (pattern == 3 && (i >> 2));
            const bool constant = pattern == 4;
            // up: above = vmax, below = 0 (difference +vmax); else the reverse.
            const uint32_t above = constant ? vmax / 3 : (up ? vmax : 0), below = constant ? vmax / 3 : (up ? 0 : vmax);
            if (i < 4) {
              in.voxels[i + 4] = above;
              in.outer[i] = below;
            } else {
              in.outer[i] = above;
              in.voxels[i - 4] = below;
            }
          }
          directed.push_back(in);
        }
  // Constant differences interpolate to themselves (golden's claim).
  for (int k = 0; k < 200; ++k) {
    ZIn in = random_in(0.1);
    const int32_t d = g::voxel_z_difference(in.voxels[4], in.outer[0]);
    for (size_t i = 0; i < 4; ++i) {
      in.voxels[i + 4] = in.voxels[4];
      in.outer[i] = in.outer[0];
      in.outer[i + 4] = static_cast<uint32_t>(static_cast<int32_t>(in.voxels[i]) + d);
    }
    bool fits = true;
    for (uint32_t v : in.outer) fits = fits && v <= vmax;
    if (!fits) continue;
    EXPECT_EQ(golden_zdiff(in, W).zdiff, d) << "golden: constant difference";
    directed.push_back(in);
  }

  auto drive = [&](M& m, const ZIn& in) {
    for (int i = 0; i < 8; ++i) {
      put_bits(m.voxels_i, i * V, V, in.voxels[static_cast<size_t>(i)]);
      put_bits(m.outer_i, i * V, V, in.outer[static_cast<size_t>(i)]);
    }
    m.wx_i = in.wx;
    m.wy_i = in.wy;
    m.wz_i = in.wz;
  };
  auto golden = [&](const ZIn& in) { return golden_zdiff(in, W); };
  auto read = [&](M& m) { return ZOut{sign_extend(get_bits(m.zdiff_o, 0, V + 1), V + 1)}; };

  auto m = cube4::rtl::make_dut<M>();
  const long nd = static_cast<long>(directed.size());
  Timer t(unit);
  Scoreboard<ZIn, ZOut> sb(unit, kLatency);
  auto gen = [&](long i) { return i >= 0 && i < nd ? directed[static_cast<size_t>(i)] : random_in(0.05); };
  run_stream(*m, sb, nd + kRandom, 1.0, rng, gen, drive, golden, read, kLatency);
  EXPECT_TRUE(sb.ok()) << sb.report();
  Scoreboard<ZIn, ZOut> gaps(std::string(unit) + " (valid gaps)", kLatency);
  run_stream(*m, gaps, kRandomGaps, cube4::rtl::kGapValid, rng, [&](long) { return random_in(0.05); }, drive, golden,
             read, kLatency);
  EXPECT_TRUE(gaps.ok()) << gaps.report();
  std::printf("  %s: %llu directed+random (%llu directed), %llu with gaps\n", unit,
              static_cast<unsigned long long>(sb.checked()), static_cast<unsigned long long>(nd),
              static_cast<unsigned long long>(gaps.checked()));
  m->final();
}

TEST(RtlInterpZdiff, DefaultWidths) { test_interp_zdiff<Vcube4_interp_zdiff>("cube4_interp_zdiff", 12, 8); }
TEST(RtlInterpZdiff, Voxel8Weight6) { test_interp_zdiff<Vcube4_interp_zdiff_v8>("cube4_interp_zdiff_v8", 8, 6); }
TEST(RtlInterpZdiff, Voxel16Weight14) {
  test_interp_zdiff<Vcube4_interp_zdiff_v16>("cube4_interp_zdiff_v16", 16, 14);
}

}  // namespace
