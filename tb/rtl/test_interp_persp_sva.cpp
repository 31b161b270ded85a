// The perspective interpolation ring's assertions
// (rtl/assert/cube4_interp_persp_column_sva.sv, cube4_persp_lanes_sva.sv),
// each driven into its violation: it must fire, in the cycle of the
// violation, with the values at fault in its message; the same stream
// without the fault must not. The ring's and its parts' tests run the same
// assertions on correct streams, where any of them would abort.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>

#include "Vcube4_interp_persp_column.h"
#include "Vcube4_persp_lanes_p4.h"
#include "tb/rtl/rtl_check.hpp"
#include "tb/rtl/sva_check.hpp"

namespace {

using namespace cube4::rtl;

using Column = Vcube4_interp_persp_column;  // BeamDepth 32, SliceDepth 1024

// A pass of `ny` beams of `b` partial beams (wz = 0), then (flush) two flush beams.
void pass(Column& m, int ny, int b, bool flush = true) {
  for (int y = 0; y < ny + (flush ? 2 : 0); ++y)
    for (int j = 0; j < b; ++j) {
      m.valid_i = 1;
      m.beam_start_i = j == 0;
      m.beam_end_i = j == b - 1;
      m.slice_start_i = y == 0 && y < ny;
      m.slice_end_i = y == ny - 1;
      m.flush_i = y >= ny;
      m.voxel_i = 0x123;
      m.wz_i = 0;
      m.oy_i = 0;
      m.oy_left_i = 1;
      settle(m);
      rise(m);
    }
}

void run_column(const std::function<void(Column&)>& stream, const std::string& label,
                std::initializer_list<std::string> parts) {
  run_expecting<Column>(stream, label, parts);
}

TEST(RtlInterpPerspSva, TwoBeamsAPass) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  run_column([](Column& m) { pass(m, 2, 3); }, "", {});
  run_column([](Column& m) { pass(m, 1, 3); }, "a_two_beams", {"cycle 3:", "a pass of one beam"});
}

TEST(RtlInterpPerspSva, BeamAndSliceFit) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  run_column([](Column& m) { pass(m, 2, 32); }, "", {});
  run_column([](Column& m) { pass(m, 2, 33); }, "a_beam_fits",
             {"cycle 33:", "partial beam 32 of a beam, but the row delay holds 32"});
  run_column([](Column& m) { pass(m, 32, 32); }, "", {});
  run_column([](Column& m) { pass(m, 33, 32); }, "a_slice_fits",
             {"cycle 1025:", "voxel 1024 of a pass, but the slice store holds 1024"});
}

TEST(RtlInterpPerspSva, SpacingRange) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  constexpr int64_t kOne = int64_t{1} << 20;
  auto walk = [](int64_t spacing, const std::string& label, std::initializer_list<std::string> parts) {
    run_expecting<Vcube4_persp_lanes_p4>(
        [&](Vcube4_persp_lanes_p4& m) {
          m.spacing_i = static_cast<uint64_t>(spacing);
          m.ray0_i = 0;
          m.rays_lo_i = 0;
          m.rays_hi_i = 8;
          m.start_i = 1;
          settle(m);
          rise(m);
        },
        label, parts);
  };
  walk(kOne, "", {});
  walk(4 * kOne - 1, "", {});
  walk(kOne - 1, "a_spacing_range", {"cycle 1:", "spacing 1048575 (20 fraction bits), outside [1, 4) voxels"});
  walk(4 * kOne, "a_spacing_range", {"cycle 1:", "spacing 4194304"});
}

}  // namespace
