// RTL equivalence tests of the perspective box filter against the golden
// functions: cube4_box_axis (combinational) against box_axis()
// (golden/units/dda_perspective.hpp), cube4_interp_box (pipelined) against
// box_filter() (golden/units/interp_box.hpp), each at the default widths
// and at two other width sets (rtl/groups/interp_box.cmake). The pipelined
// unit is driven with one window per clock and again with random valid
// gaps; each output is compared with the golden result of the input that
// entered `latency` cycles earlier (rtl_check.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "Vcube4_box_axis.h"
#include "Vcube4_box_axis_w10.h"
#include "Vcube4_box_axis_w6.h"
#include "Vcube4_interp_box.h"
#include "Vcube4_interp_box_w10.h"
#include "Vcube4_interp_box_w6.h"
#include "golden/units/dda_perspective.hpp"
#include "golden/units/interp_box.hpp"
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

constexpr int kBoxLatency = 3;  // cube4_interp_box's header
const long kRandom = cube4::rtl::vector_count(1000000);
const long kRandomGaps = cube4::rtl::vector_count(1000000);

// golden box_recip_bits() for these widths.
constexpr int recip_bits(int V, int W) { return V + 2 * W + 5; }

// ---------------------------------------------------------------------------
// cube4_box_axis

// Widths of one cube4_box_axis model (rtl/groups/interp_box.cmake).
struct AxisWidths {
  int D, F, W;
};

template <class M>
void test_box_axis(const char* unit, AxisWidths w) {
  const int D = w.D, F = w.F, W = w.W, shift = F - W;
  const int64_t one = int64_t{1} << W, unit_f = int64_t{1} << F;
  const int64_t pos_min = -(int64_t{1} << (D - 1)), pos_max = (int64_t{1} << (D - 1)) - 1;
  const int64_t spacing_max = (int64_t{1} << (F + 2)) - 1;
  const uint64_t pos_mask = (uint64_t{1} << D) - 1;
  const auto dut = cube4::rtl::make_dut<M>();
  M& m = *dut;
  cube4::rtl::Checker c(unit);
  uint64_t n = 0;
  uint64_t linear = 0, complete = 0;
  auto in_fields = [&](int64_t pos, int64_t spacing) { return Fields{{"pos", pos}, {"spacing", spacing}}; };
  auto out_fields = [](int64_t first, const std::array<int64_t, 4>& ov) {
    return Fields{{"first", first}, {"ov0", ov[0]}, {"ov1", ov[1]}, {"ov2", ov[2]}, {"ov3", ov[3]}};
  };
  auto one_vec = [&](int64_t pos, int64_t spacing) {
    m.pos_i = static_cast<uint64_t>(pos) & pos_mask;
    m.spacing_i = static_cast<uint64_t>(spacing);
    m.eval();
    const g::BoxAxis exp = g::box_axis(pos, spacing, F, W);
    const int64_t got_first = sign_extend(m.first_o, D - F + 1);
    std::array<int64_t, 4> got{}, want{};
    bool equal = got_first == exp.first;
    for (int j = 0; j < 4; ++j) {
      got[j] = static_cast<int64_t>(get_bits(m.overlap_o, j * (W + 1), W + 1));
      want[j] = exp.overlap[static_cast<size_t>(j)];
      equal = equal && got[j] == want[j];
    }
    c.check_lazy(n, equal, [&] { return in_fields(pos, spacing); }, [&] { return out_fields(exp.first, want); },
                 [&] { return out_fields(got_first, got); });
    // The header's claims, on the RTL's outputs: in [1, 3] voxels the four
    // cells hold the whole box (overlaps sum to the extent); an extent of
    // exactly one voxel gives the linear weights (1 - f, f, 0, 0) of
    // voxels floor(pos) and floor(pos) + 1.
    if (spacing >= unit_f && spacing <= 3 * unit_f) {
      ++complete;
      if (got[0] + got[1] + got[2] + got[3] != g::box_extent(spacing, F, W))
        c.fail(n, in_fields(pos, spacing), "overlaps do not sum to the extent");
    }
    if (spacing == unit_f) {
      ++linear;
      const int64_t f = (pos >> shift) & (one - 1);
      if (got_first != (pos >> F) || got[0] != one - f || got[1] != f || got[2] != 0 || got[3] != 0)
        c.fail(n, in_fields(pos, spacing), "extent 1 is not linear interpolation");
    }
    ++n;
  };

  // Directed. Spacings around one, two and three voxels (exactly, one ulp
  // either side, and their truncation steps), the smallest and largest
  // port values.
  std::vector<int64_t> spacings = {0, 1, unit_f / 2, spacing_max - 1, spacing_max};
  for (int64_t k : {1, 2, 3, 4})
    for (int64_t d : {-(int64_t{1} << shift), int64_t{-1}, int64_t{0}, int64_t{1}, int64_t{1} << shift})
      if (k * unit_f + d <= spacing_max) spacings.push_back(k * unit_f + d);
  // For each spacing, the box start on every W-step of cells -3 .. 3, at
  // the step and one DDA ulp either side (just below / at a cell edge),
  // negative positions included; then the ends of the position range.
  for (int64_t s : spacings) {
    const int64_t edge0 = -(int64_t{1} << (F - 1)) + (s >> 1);  // pos whose box starts at 0
    for (int64_t t = -3 * one; t <= 3 * one; ++t)
      for (int64_t d : {-1, 0, 1}) one_vec(edge0 + (t << shift) + d, s);
    for (int64_t p : {pos_min, pos_min + 1, pos_min + unit_f, int64_t{-1}, int64_t{0}, int64_t{1}, pos_max - unit_f,
                      pos_max - 1, pos_max})
      one_vec(p, s);
  }
  const uint64_t directed = n;

  // Random: spacings mostly in [1, 3] voxels (their ends often), some over
  // the whole port; positions mostly near the volume (within 2^10 voxels),
  // some over the whole DDA range.
  Random rng(300 + W * 10 + F);
  for (long i = 0; i < kRandom; ++i) {
    int64_t s;
    if (rng.chance(0.8)) {
      s = unit_f + rng.edgy(2 * unit_f);
    } else {
      s = rng.edgy(spacing_max);
    }
    const int64_t p = rng.chance(0.9) ? rng.range(-(unit_f << 10), unit_f << 10) : rng.range(pos_min, pos_max);
    one_vec(p, s);
  }
  m.final();
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_GT(linear, 1000u);
  std::printf("  %s: %llu vectors (%llu directed, %llu of extent 1, %llu in [1, 3] voxels)\n", unit,
              static_cast<unsigned long long>(n), static_cast<unsigned long long>(directed),
              static_cast<unsigned long long>(linear), static_cast<unsigned long long>(complete));
}

TEST(RtlBoxAxis, DefaultWidths) { test_box_axis<Vcube4_box_axis>("cube4_box_axis", {40, 20, 8}); }
TEST(RtlBoxAxis, Dda32Frac16Weight6) { test_box_axis<Vcube4_box_axis_w6>("cube4_box_axis_w6", {32, 16, 6}); }
TEST(RtlBoxAxis, Weight10) { test_box_axis<Vcube4_box_axis_w10>("cube4_box_axis_w10", {40, 20, 10}); }

// ---------------------------------------------------------------------------
// cube4_interp_box

using Window = std::array<std::array<uint32_t, 4>, 4>;

struct BoxIn {
  Window v{};
  g::BoxAxis x, y;
  uint64_t recip = 0;
  Fields fields() const {
    Fields f;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) f.push_back({"v" + std::to_string(j) + std::to_string(i), v[j][i]});
    for (int i = 0; i < 4; ++i) f.push_back({"ox" + std::to_string(i), x.overlap[i]});
    for (int j = 0; j < 4; ++j) f.push_back({"oy" + std::to_string(j), y.overlap[j]});
    f.push_back({"recip", static_cast<int64_t>(recip)});
    return f;
  }
};
struct BoxOut {
  uint32_t sample = 0;
  bool operator==(const BoxOut& o) const { return sample == o.sample; }
  Fields fields() const { return {{"sample", sample}}; }
};

// The overlaps come from golden box_axis() with the DDA's 20 fraction bits;
// the reciprocal is that of the same extent (the unit's input range).
constexpr int kFrac = 20;

template <class M>
void test_interp_box(const char* unit, int V, int W) {
  const int Q = recip_bits(V, W), shift = kFrac - W;
  const uint32_t vmax = (1u << V) - 1;
  const int64_t one = int64_t{1} << W, unit_f = int64_t{1} << kFrac;
  Random rng(500 + V * 100 + W);

  // A window whose boxes have extent `e` (W fraction bits) and start `ax`,
  // `ay` into their first cells.
  auto window = [&](int64_t e, int64_t ax, int64_t ay) {
    BoxIn in;
    const int64_t s = e << shift, edge0 = -(int64_t{1} << (kFrac - 1)) + (s >> 1);
    in.x = g::box_axis(edge0 + (ax << shift), s, kFrac, W);
    in.y = g::box_axis(edge0 + (ay << shift), s, kFrac, W);
    in.recip = g::box_reciprocal(e, Q);
    return in;
  };
  auto random_voxels = [&](BoxIn& in, double edge) {
    for (auto& row : in.v)
      for (auto& x : row) x = static_cast<uint32_t>(rng.edgy(vmax, edge));
  };
  auto random_in = [&] {
    // Spacing mostly in [1, 3] voxels (the ends often), some up to just
    // below 4 (the header's whole range); random positions and DDA bits.
    int64_t s = rng.chance(0.9) ? unit_f + rng.edgy(2 * unit_f) : unit_f + rng.edgy(3 * unit_f - 1);
    BoxIn in;
    in.x = g::box_axis(rng.range(-(unit_f << 8), unit_f << 8), s, kFrac, W);
    in.y = g::box_axis(rng.range(-(unit_f << 8), unit_f << 8), s, kFrac, W);
    in.recip = g::box_reciprocal(g::box_extent(s, kFrac, W), Q);
    random_voxels(in, 0.05);
    return in;
  };

  std::vector<BoxIn> directed;
  // Extents of exactly 1, 2 and 3 voxels, their neighbours and the largest
  // the ports allow, every start a cell edge, one step off it, or half a cell.
  const int64_t extents[] = {one, one + 1, 2 * one - 1, 2 * one, 2 * one + 1, 3 * one - 1, 3 * one, 4 * one - 1};
  const int64_t starts[] = {0, 1, one / 2, one - 1};
  const uint32_t constants[] = {0, 1, vmax / 2, vmax - 1, vmax};
  uint64_t constant_windows = 0;
  for (int64_t e : extents)
    for (int64_t ax : starts)
      for (int64_t ay : starts) {
        // Constant windows, the largest voxel among them: the mean is the
        // constant whenever the four cells hold the whole box (always for
        // extents up to 3 voxels; golden's claim, checked here; the RTL
        // against golden in the stream below). Beyond, box_axis() drops
        // the fifth cell and the mean falls short, in golden and RTL alike.
        const bool whole = ax + e <= 4 * one && ay + e <= 4 * one;
        for (uint32_t cst : constants) {
          BoxIn in = window(e, ax, ay);
          for (auto& row : in.v) row.fill(cst);
          if (whole)
            EXPECT_EQ(g::box_filter(in.v, in.x, in.y, in.recip, Q), cst) << "golden: constant " << cst << " extent " << e;
          directed.push_back(in);
          ++constant_windows;
        }
        // Checkerboards of 0 and the largest voxel, and random windows.
        for (int pat = 0; pat < 2; ++pat) {
          BoxIn in = window(e, ax, ay);
          for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) in.v[j][i] = ((i + j + pat) & 1) ? vmax : 0;
          directed.push_back(in);
        }
        for (int k = 0; k < 4; ++k) {
          BoxIn in = window(e, ax, ay);
          random_voxels(in, 0.2);
          directed.push_back(in);
        }
      }
  // Extent 1 with the sample on a voxel (the box is exactly cell first):
  // that voxel.
  for (int k = 0; k < 100; ++k) {
    BoxIn in = window(one, 0, 0);
    random_voxels(in, 0.2);
    EXPECT_EQ(g::box_filter(in.v, in.x, in.y, in.recip, Q), in.v[0][0]) << "golden: extent 1 on a voxel";
    directed.push_back(in);
  }

  auto drive = [&](M& m, const BoxIn& in) {
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) put_bits(m.voxels_i, (4 * j + i) * V, V, in.v[j][i]);
    for (int i = 0; i < 4; ++i) {
      put_bits(m.ox_i, i * (W + 1), W + 1, in.x.overlap[i]);
      put_bits(m.oy_i, i * (W + 1), W + 1, in.y.overlap[i]);
    }
    m.recip_i = in.recip;
  };
  auto golden = [&](const BoxIn& in) { return BoxOut{g::box_filter(in.v, in.x, in.y, in.recip, Q)}; };
  auto read = [](M& m) { return BoxOut{static_cast<uint32_t>(m.sample_o)}; };

  auto m = cube4::rtl::make_dut<M>();
  const long nd = static_cast<long>(directed.size());
  Timer t(unit);
  Scoreboard<BoxIn, BoxOut> sb(unit, kBoxLatency);
  auto gen = [&](long i) { return i >= 0 && i < nd ? directed[static_cast<size_t>(i)] : random_in(); };
  run_stream(*m, sb, nd + kRandom, 1.0, rng, gen, drive, golden, read, kBoxLatency);
  EXPECT_TRUE(sb.ok()) << sb.report();
  Scoreboard<BoxIn, BoxOut> gaps(std::string(unit) + " (valid gaps)", kBoxLatency);
  run_stream(*m, gaps, kRandomGaps, cube4::rtl::kGapValid, rng, [&](long) { return random_in(); }, drive, golden, read,
             kBoxLatency);
  EXPECT_TRUE(gaps.ok()) << gaps.report();
  std::printf("  %s: %llu directed+random (%llu directed, %llu constant windows), %llu with gaps\n", unit,
              static_cast<unsigned long long>(sb.checked()), static_cast<unsigned long long>(nd),
              static_cast<unsigned long long>(constant_windows), static_cast<unsigned long long>(gaps.checked()));
  m->final();
}

TEST(RtlInterpBox, DefaultWidths) { test_interp_box<Vcube4_interp_box>("cube4_interp_box", 12, 8); }
TEST(RtlInterpBox, Voxel8Weight6) { test_interp_box<Vcube4_interp_box_w6>("cube4_interp_box_w6", 8, 6); }
TEST(RtlInterpBox, Voxel16Weight10) { test_interp_box<Vcube4_interp_box_w10>("cube4_interp_box_w10", 16, 10); }

}  // namespace
