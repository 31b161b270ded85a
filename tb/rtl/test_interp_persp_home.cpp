// RTL equivalence tests of the perspective interpolation unit's home stage,
// cube4_interp_persp_home, against golden perspective_sample()
// (golden/perspective.hpp): random rays (spacings 1 to 3 voxels, exactly 1, 2
// and 3 often; positions anywhere in their cells, on cell edges often; z weights,
// zero often) over random voxels, the unit fed the column sums golden
// box_taps() makes of the ray's window (what cube4_interp_persp_column
// gives) and the ray's x box; every sample 3 cycles later, with random
// valid gaps. The signed variant (Signed = 1) filters VolumePro's voxel z
// differences instead, against golden perspective_z_difference().
//
// CUBE4_RTL_VECTORS overrides the ray count (default 1,000,000).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>

#include "Vcube4_interp_persp_home.h"
#include "Vcube4_interp_persp_home_signed.h"
#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/units/interp_box.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;

constexpr int kV = 12, kW = 8, kF = 20;

// The box's overlaps in the window's order (cells home-1 .. home+2).
g::BoxAxis window_order(const g::BoxAxis& b, int64_t home) {
  g::BoxAxis w{};
  const int64_t from0 = home - 1 - b.first;  // the box cell at window cell 0
  for (int i = 0; i < 4; ++i) {
    const int64_t c = from0 + i;
    w.overlap[static_cast<size_t>(i)] = c >= 0 && c < 4 ? b.overlap[static_cast<size_t>(c)] : 0u;
  }
  return w;
}

struct HomeIn {
  std::array<std::array<std::array<int32_t, 4>, 4>, 2> v{};  // [dz][row j][column i] of the window
  int64_t spacing = 0, pos_x = 0, pos_y = 0;
  uint32_t wz = 0;
  Fields fields() const {
    return {{"spacing", spacing}, {"pos_x", pos_x}, {"pos_y", pos_y}, {"wz", wz}};
  }
};
struct HomeOut {
  int64_t sample = 0;
  bool operator==(const HomeOut& o) const { return sample == o.sample; }
  Fields fields() const { return {{"sample", sample}}; }
};

// Random rays through model M: voxels (unsigned, V bits), or with `diff`
// voxel z differences (signed, V+1 bits, the unit's Signed variant).
template <class M>
void random_rays(bool diff, uint64_t seed) {
  rtl::Random rng(seed);
  const auto dut = rtl::make_dut<M>();
  M& m = *dut;
  const int data_bits = kV + (diff ? 1 : 0), col_bits = data_bits + kW + 2;
  const int64_t vmax = (1 << kV) - 1;
  g::Registers r;
  r.perspective = true;
  const int64_t one = int64_t{1} << kF;
  auto reciprocal = [&](int64_t spacing) {
    return g::box_reciprocal(g::box_extent(spacing, kF, kW), g::box_recip_bits(r.p));
  };
  auto gen = [&](long i) {
    HomeIn in;
    // Extents of exactly 1, 2 and 3 voxels, and anything between (i < 0:
    // a junk cycle's inputs, any).
    const long kind = i < 0 ? 4 : i % 5;
    in.spacing = kind < 3 ? (1 + kind) * one : one + static_cast<int64_t>(rng.range(0, 2 * one));
    auto position = [&] {
      const int64_t cell = rng.range(0, 60);
      return cell * one + (rng.chance(0.1) ? 0 : rng.chance(0.1) ? one - 1 : rng.range(0, one - 1));
    };
    in.pos_x = position();
    in.pos_y = position();
    in.wz = rng.chance(0.3) ? 0u : static_cast<uint32_t>(rng.range(0, (1 << kW) - 1));
    for (auto& slice : in.v)
      for (auto& row : slice)
        for (auto& x : row)
          x = static_cast<int32_t>(diff ? rng.edgy(2 * vmax, 0.2) - vmax : rng.edgy(vmax, 0.2));
    return in;
  };
  // The unit's inputs: the window's column sums and the ray's x box.
  auto drive = [&](M& d, const HomeIn& in) {
    const int64_t hx = g::home_cell(in.pos_x, kF), hy = g::home_cell(in.pos_y, kF);
    const g::BoxAxis bx = g::box_axis(in.pos_x, in.spacing, kF, kW);
    const g::BoxAxis wy = window_order(g::box_axis(in.pos_y, in.spacing, kF, kW), hy);
    for (int dz = 0; dz < 2; ++dz) {
      auto& port = dz == 0 ? d.cols_front_i : d.cols_back_i;
      for (int c = 0; c < 4; ++c) {
        std::array<int32_t, 4> column{};
        for (int j = 0; j < 4; ++j)
          column[static_cast<size_t>(j)] = in.v[static_cast<size_t>(dz)][static_cast<size_t>(j)][static_cast<size_t>(c)];
        const uint64_t sum = static_cast<uint64_t>(g::box_taps(column, wy)) & ((uint64_t{1} << col_bits) - 1);
        rtl::put_bits(port, c * col_bits, col_bits, sum);
      }
    }
    uint64_t ox = 0;
    for (int o = 0; o < 4; ++o) ox |= static_cast<uint64_t>(bx.overlap[static_cast<size_t>(o)]) << (o * (kW + 1));
    d.ox_i = ox;
    d.ox_left_i = bx.first < hx;
    d.recip_i = static_cast<uint32_t>(reciprocal(in.spacing));
    d.wz_i = static_cast<uint16_t>(in.wz);
  };
  // Golden: the ray's sample, as ray 0 of a slice placed at its position.
  auto golden = [&](const HomeIn& in) {
    const int64_t hx = g::home_cell(in.pos_x, kF), hy = g::home_cell(in.pos_y, kF);
    g::PerspectiveSlice s;
    s.spacing = in.spacing;
    s.ray0_x = in.pos_x;
    s.ray0_y = in.pos_y;
    s.wz = in.wz;
    s.box_reciprocal = reciprocal(in.spacing);
    auto value = [&](int x, int y, int dz) -> int32_t {
      const int64_t i = x - (hx - 1), j = y - (hy - 1);
      if (i < 0 || i >= 4 || j < 0 || j >= 4) return 0;
      return in.v[static_cast<size_t>(dz)][static_cast<size_t>(j)][static_cast<size_t>(i)];
    };
    if (diff) return HomeOut{g::perspective_z_difference(r, s, 0, 0, value)};
    return HomeOut{g::perspective_sample(r, s, 0, 0, [&](int x, int y, int dz) {
      return static_cast<uint32_t>(value(x, y, dz));
    })};
  };
  auto read = [&](const M& d) {
    const auto out = static_cast<uint64_t>(d.sample_o);
    return HomeOut{diff ? rtl::sign_extend(out, data_bits) : static_cast<int64_t>(out)};
  };
  const long n = rtl::vector_count(1000000);
  const std::string name = diff ? "cube4_interp_persp_home (Signed)" : "cube4_interp_persp_home";
  rtl::Timer t(name + ": 2 x " + std::to_string(n) + " random rays");
  for (double valid : {1.0, rtl::kGapValid}) {
    rtl::Scoreboard<HomeIn, HomeOut> sb(name, 3);
    rtl::run_stream(m, sb, n, valid, rng, gen, drive, golden, read, 3);
    EXPECT_TRUE(sb.ok()) << sb.report();
    EXPECT_EQ(sb.checked(), static_cast<uint64_t>(n));
  }
}

TEST(RtlInterpPerspHome, RandomRaysMatchGoldenPerspectiveSample) {
  random_rays<Vcube4_interp_persp_home>(false, 81);
}

// VolumePro's voxel-difference z gradient: the second home stage filters
// the rays' voxel z differences (signed, extremes often) with the same
// boxes, reciprocal and z lerp.
TEST(RtlInterpPerspHome, RandomRaysMatchGoldenPerspectiveZDifferenceSigned) {
  random_rays<Vcube4_interp_persp_home_signed>(true, 82);
}

}  // namespace
