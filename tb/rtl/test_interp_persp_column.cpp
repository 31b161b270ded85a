// RTL equivalence tests of the perspective interpolation unit's column
// stage, cube4_interp_persp_column, against golden box_taps()
// (golden/units/interp_box.hpp) over the volume's own columns: random
// volumes streamed pass after pass as the system streams them (each pass's
// voxel slice by its z weight, passes back to back, two flush beams at the
// end, random idle cycles), random y boxes per beam; every step's two
// column sums against the window rows of its cell's pass, the drain beams'
// rows of the finished pass included, one cycle later. The HasZDiff
// variant (VolumePro's z gradient) streams a priming pass and a slice
// ahead, and gives the column sums of the voxel z differences too.
//
// CUBE4_RTL_VECTORS overrides the step count (default 1,000,000).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "Vcube4_interp_persp_column.h"
#include "Vcube4_interp_persp_column_zdiff.h"
#include "golden/units/dda.hpp"
#include "golden/units/gradient.hpp"
#include "golden/units/interp_box.hpp"
#include "tb/rtl/rtl_check.hpp"
#include "tb/rtl/voxel_grid.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;

constexpr int kV = 12, kW = 8;
constexpr int kBeamDepth = 32, kSliceDepth = 1024;  // rtl/groups/interp_persp.cmake

using Volume = rtl::VoxelGrid;

// One beam's y box: four overlaps and whether it starts a row before the home.
struct BeamBox {
  g::BoxAxis box;
  bool left = false;
};

struct Expected {
  bool check = false;
  bool check_dhi = false;  // zdiff with wz > 0 (wz = 0 weighs D(z+1) zero)
  int64_t front = 0, back = 0, dlo = 0, dhi = 0;
  Fields where;
};

// The window rows of cell row Y (rows Y-1 .. Y+2) in the box's order:
// voxel slice z, or with `diff` its voxel z differences V(z+1) - V(z-1).
int64_t column_sum(const Volume& vol, int x, int Y, int z, const BeamBox& b, bool diff = false) {
  std::array<int32_t, 4> rows{};
  for (int j = 0; j < 4; ++j) {
    const int y = Y - 1 + j;
    rows[static_cast<size_t>(j)] = diff ? g::voxel_z_difference(vol.at(x, y, z + 1), vol.at(x, y, z - 1))
                                        : static_cast<int32_t>(vol.at(x, y, z));
  }
  g::BoxAxis window{};
  for (int j = 0; j < 4; ++j) {
    const int from = b.left ? j : j - 1;
    window.overlap[static_cast<size_t>(j)] = from < 0 ? 0u : b.box.overlap[static_cast<size_t>(from)];
  }
  return g::box_taps(rows, window);
}

template <class M>
void random_streams(bool zdiff, uint64_t seed) {
  rtl::Random rng(seed);
  const auto dut = rtl::make_dut<M>();
  M& m = *dut;
  rtl::reset(m);
  rtl::Checker c(zdiff ? "cube4_interp_persp_column (HasZDiff)" : "cube4_interp_persp_column");
  constexpr int kDColBits = kV + kW + 3;
  auto diff_sum = [](uint64_t bits) { return rtl::sign_extend(bits, kDColBits); };
  const long n = rtl::vector_count(1000000);
  rtl::Timer t(std::string(zdiff ? "cube4_interp_persp_column (HasZDiff): " : "cube4_interp_persp_column: ") + std::to_string(n) + " steps");
  uint64_t cycle = 0;
  long steps = 0, checked = 0;
  std::deque<Expected> due;  // the result of the step one cycle ago
  auto clock = [&](bool valid) {
    rtl::settle(m);
    rtl::rise(m);
    ++cycle;
    rtl::settle(m);
    if (m.valid_o) {
      if (due.empty()) {
        c.check(cycle, {{"unexpected valid_o", 1}}, {{"valid", 0}}, {{"valid", 1}});
      } else {
        const Expected e = due.front();
        due.pop_front();
        if (e.check) {
          Fields want{{"front", e.front}, {"back", e.back}};
          Fields got{{"front", static_cast<int64_t>(m.col_front_o)}, {"back", static_cast<int64_t>(m.col_back_o)}};
          if (zdiff) {
            want.push_back({"D(z)", e.dlo});
            got.push_back({"D(z)", diff_sum(m.col_dlo_o)});
            want.push_back({"D(z+1)", e.check_dhi ? e.dhi : 0});
            got.push_back({"D(z+1)", e.check_dhi ? diff_sum(m.col_dhi_o) : 0});
          } else {
            EXPECT_EQ(m.col_dlo_o, 0u);
            EXPECT_EQ(m.col_dhi_o, 0u);
          }
          c.check(cycle, e.where, want, got);
          ++checked;
        }
      }
    } else if (!due.empty() && valid) {
      c.check(cycle, due.front().where, {{"valid", 1}}, {{"valid", 0}});
    }
  };
  while (steps < n && c.ok()) {
    Volume vol;
    const int nx = static_cast<int>(rng.range(1, kBeamDepth)), ny = static_cast<int>(rng.range(2, 12));
    if (nx * ny > kSliceDepth) continue;
    vol.resize(nx, ny, static_cast<int>(rng.range(1, 5)));
    for (uint32_t& x : vol.v) x = static_cast<uint32_t>(rng.chance(0.1) ? (rng.chance(0.5) ? 0 : 4095) : rng.bits(kV));
    const int S = static_cast<int>(rng.range(1, 3)), K = vol.nz * S;
    // Pass P's beams 0 .. ny-1, then two flush beams after the last pass;
    // with zdiff the priming pass P = -1 first (slice 0, wz = 0), and each
    // pass streams a slice ahead.
    for (int P = zdiff ? -1 : 0; P <= K && c.ok(); ++P) {
      const bool flush = P == K, prime = P < 0;
      const int beams = flush ? 2 : vol.ny;
      const uint32_t wz = flush || prime ? 0 : g::z_weight(P, S, kW);
      const int zv = flush || prime ? 0 : g::z_voxel_slice(P, S);
      const int z_in = prime ? 0 : (wz == 0 ? zv : zv + 1) + (zdiff ? 1 : 0);
      for (int b = 0; b < beams && c.ok(); ++b) {
        BeamBox box;
        for (uint32_t& o : box.box.overlap) o = static_cast<uint32_t>(rng.range(0, 1 << kW));
        box.left = rng.chance(0.5);
        // Whose cell this beam forms: its own pass's row b - 2, or in the
        // first two beams (or the flush beams) the finished pass's last rows.
        int cell_pass = P, Y = b - 2;
        if (flush || b < 2) {
          cell_pass = P - 1;
          Y = vol.ny - 2 + b;
        }
        const bool has_cell = cell_pass >= 0;  // not the priming pass's
        const uint32_t cwz = has_cell ? g::z_weight(cell_pass, S, kW) : 0;
        const int czv = has_cell ? g::z_voxel_slice(cell_pass, S) : 0;
        for (int j = 0; j < vol.nx && c.ok(); ++j) {
          while (rng.chance(0.2)) {  // idle cycles, junk inputs
            m.valid_i = 0;
            m.voxel_i = static_cast<uint16_t>(rng.bits(kV));
            m.wz_i = static_cast<uint16_t>(rng.bits(kW + 1));
            clock(false);
          }
          m.valid_i = 1;
          m.beam_start_i = j == 0;
          m.beam_end_i = j == vol.nx - 1;
          m.slice_start_i = !flush && b == 0;
          m.slice_end_i = !flush && b == vol.ny - 1;
          m.flush_i = flush;
          m.prime_i = prime ? 1 : rng.chance(0.1) && !zdiff;  // ignored without HasZDiff
          m.voxel_i = static_cast<uint16_t>(flush ? rng.bits(kV) : vol.at(j, b, z_in));
          m.wz_i = static_cast<uint16_t>(wz);
          uint64_t oy = 0;
          for (int o = 0; o < 4; ++o) oy |= static_cast<uint64_t>(box.box.overlap[static_cast<size_t>(o)]) << (o * (kW + 1));
          m.oy_i = oy;
          m.oy_left_i = box.left;
          Expected e;
          e.check = has_cell;
          if (has_cell) {
            e.front = column_sum(vol, j, Y, czv, box);
            e.back = column_sum(vol, j, Y, cwz == 0 && !zdiff ? czv : czv + 1, box);
            e.dlo = column_sum(vol, j, Y, czv, box, true);
            e.dhi = column_sum(vol, j, Y, czv + 1, box, true);
            e.check_dhi = cwz != 0;
            e.where = {{"nx", vol.nx}, {"ny", vol.ny}, {"nz", vol.nz}, {"S", S}, {"pass", P}, {"beam", b},
                       {"x", j}, {"cell pass", cell_pass}, {"cell row", Y}, {"box left", box.left}};
          }
          due.push_back(e);
          clock(true);
          ++steps;
        }
      }
    }
  }
  m.valid_i = 0;
  clock(false);
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_TRUE(due.empty());
  EXPECT_GT(checked, n / 2);
}

TEST(RtlInterpPerspColumn, EveryStepOfRandomStreamsMatchesGolden) {
  random_streams<Vcube4_interp_persp_column>(false, 71);
}

// VolumePro's z gradient: the priming pass, the stream a slice ahead, and
// the difference sums of the slices below and above.
TEST(RtlInterpPerspColumn, EveryStepOfRandomStreamsMatchesGoldenWithVoxelZDifferences) {
  random_streams<Vcube4_interp_persp_column_zdiff>(true, 72);
}

}  // namespace
