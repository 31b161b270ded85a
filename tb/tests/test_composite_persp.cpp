// The plan for the perspective compositing ring (docs/perspective.md, "The
// plan for the compositing ring"), checked on the golden model's rays over
// many random views: each ray's accumulator of the slice before lies within
// the blending lane's window and has been stored by the time it is read;
// two accumulator stores suffice (and one does not); each ray samples one
// run of slices, so its pixel is written once, when it leaves. And the
// clocked TLM compositor that follows the plan (systemc/tlm/
// tlm_composite_persp.hpp) refuses what breaks it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/tlm/tlm_composite_persp.hpp"
#include "tb/tests/perspective_views.hpp"
#include "tb/tests/test_support.hpp"

namespace {

using namespace cube4;

// cube4_composite's latency: a blended accumulator is ready this many
// cycles after its sample enters; the plan adds one cycle per lane it goes
// back to be stored.
constexpr int64_t kBlendLatency = 7;

struct Blend {
  int64_t position;  // in the stream
  int64_t x, y;      // the ray's home
};

// Every ray's blend of every slice, by slice and ray.
std::vector<std::map<std::pair<int64_t, int64_t>, Blend>> blends(const golden::Registers& r, int64_t row, int reach) {
  const int F = r.p.dda_frac_bits, ny = r.dim[1];
  std::vector<std::map<std::pair<int64_t, int64_t>, Blend>> out(static_cast<size_t>(r.sample_slices()));
  for (int k = 0; k < r.sample_slices(); ++k) {
    const golden::PerspectiveSlice s = golden::perspective_slice(r, k);
    const golden::AxisSlice ax = golden::axis_slice(s, 0), ay = golden::axis_slice(s, 1);
    for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
      for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
        const int64_t X = golden::ray_home(ax, u, F), Y = golden::ray_home(ay, v, F);
        out[static_cast<size_t>(k)][{u, v}] = {golden::composite_position(k, X, Y, row, ny, reach), X, Y};
      }
  }
  return out;
}

}  // namespace

// For every ray's sample of slice k > 0 whose ray sampled slice k - 1: its
// accumulator there, at home (X', Y'), is stored on the lane X' + 5, which
// the blending lane X + 5 + R finds d = X - X' + R lanes back (0 .. 2R) in
// the same beam, and the row Y' within R of Y; the column stage reads it in
// the step of position blend - d, after the accumulator's own blend, its
// latency and its R lanes back have passed. With two stores (by slice
// parity) the next write to the same cell of the same store comes after
// that read; with one store some read would come too late.
TEST(CompositePersp, EveryAccumulatorIsStoredWithinTheWindowBeforeItsRayBlendsAgain) {
  int64_t reads = 0, one_store_conflicts = 0;
  bool window_edges[2] = {false, false};
  for (int view = 0; view < 40; ++view) {
    const test::Setup setup = test::setup(test::random_perspective_view(view));
    const golden::Registers& r = setup.host.regs;
    const int K = r.sample_slices(), nx = r.dim[0];
    const int reach = std::max<int>(1, static_cast<int>(golden::largest_home_move(golden::perspective_reach(r))));
    for (int p : {1, 4, 5}) {
      SCOPED_TRACE("view " + std::to_string(view) + ", p = " + std::to_string(p) + ", R = " + std::to_string(reach));
      const int64_t row = static_cast<int64_t>((nx + p - 1) / p) * p;
      const auto all = blends(r, row, reach);
      const int64_t write_latency = kBlendLatency + reach;
      // By store (slice parity) and cell: when the accumulator stored there
      // is last read, and when each slice's blend writes it.
      std::map<std::tuple<int, int64_t, int64_t>, int64_t> last_read;      // (k, x, y) -> step
      std::map<std::tuple<int, int64_t, int64_t>, int64_t> write_blend;    // (k, x, y) -> step of the blend
      for (int k = 0; k < K; ++k)
        for (const auto& [ray, b] : all[static_cast<size_t>(k)]) {
          write_blend[{k, b.x, b.y}] = b.position / p;
          if (k == 0) continue;
          const auto prev = all[static_cast<size_t>(k - 1)].find(ray);
          if (prev == all[static_cast<size_t>(k - 1)].end()) continue;  // the ray enters the volume here
          const Blend& a = prev->second;
          const int64_t d = b.x - a.x + reach;
          ASSERT_GE(d, 0) << "slice " << k << ", ray (" << ray.first << ", " << ray.second << ")";
          ASSERT_LE(d, 2 * reach) << "slice " << k << ", ray (" << ray.first << ", " << ray.second << ")";
          ASSERT_LE(std::abs(b.y - a.y), reach) << "slice " << k << ", ray (" << ray.first << ", " << ray.second << ")";
          window_edges[0] = window_edges[0] || d == 0;
          window_edges[1] = window_edges[1] || d == 2 * reach;
          const int64_t read_step = (b.position - d) / p;
          ASSERT_LE(a.position / p + write_latency, read_step)
              << "slice " << k << ", ray (" << ray.first << ", " << ray.second << "): its accumulator is not stored yet";
          last_read[{k - 1, a.x, a.y}] = read_step;
          ++reads;
        }
      // Two stores: slice k + 2 writes the cell only after slice k + 1 read
      // slice k's accumulator there. One store: slice k + 1's own blends.
      for (const auto& [cell, read_step] : last_read) {
        const auto [k, x, y] = cell;
        const auto two = write_blend.find({k + 2, x, y});
        if (two != write_blend.end()) {
          ASSERT_LT(read_step, two->second) << "slice " << k << ", cell (" << x << ", " << y << ")";
        }
        const auto one = write_blend.find({k + 1, x, y});
        if (one != write_blend.end() && one->second + write_latency <= read_step) ++one_store_conflicts;
      }
    }
  }
  // The figures docs/perspective.md quotes.
  std::printf("  [%ld accumulator reads checked; one store would have %ld reads after the cell's next write]\n",
              static_cast<long>(reads), static_cast<long>(one_store_conflicts));
  EXPECT_GT(reads, 100000);
  // The window is as wide as it must be: both of its ends are used.
  EXPECT_TRUE(window_edges[0] && window_edges[1]);
  EXPECT_GT(one_store_conflicts, 0) << "one accumulator store would do";
}

// A ray samples one run of consecutive slices (it enters the volume once
// and leaves it once), so the ring keeps one accumulator per ray, starts it
// empty where the ray enters and writes the ray's pixel when it blends its
// last sample: once per frame.
TEST(CompositePersp, EveryRaySamplesOneRunOfSlices) {
  int64_t rays = 0;
  for (int view = 0; view < 40; ++view) {
    const test::Setup setup = test::setup(test::random_perspective_view(view));
    const golden::Registers& r = setup.host.regs;
    std::map<std::pair<int64_t, int64_t>, std::vector<int>> slices;
    for (int k = 0; k < r.sample_slices(); ++k) {
      const golden::PerspectiveSlice s = golden::perspective_slice(r, k);
      for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
        for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) slices[{u, v}].push_back(k);
    }
    for (const auto& [ray, ks] : slices) {
      ASSERT_EQ(ks.back() - ks.front() + 1, static_cast<int>(ks.size()))
          << "view " << view << ", ray (" << ray.first << ", " << ray.second << ") samples slices "
          << ks.front() << " .. " << ks.back() << " with gaps";
      ++rays;
    }
  }
  EXPECT_GT(rays, 10000);
}

// The clocked TLM compositor checks the plan as it runs: a ray's sample of
// slice 1 blended before its accumulator of slice 0 is stored (7 + R steps
// after that blend), or with none stored, or with a move beyond the unit's
// reach, is an error naming the ray and slice.
TEST(CompositePersp, TheClockedUnitRefusesWhatBreaksThePlan) {
  const test::Setup setup = test::setup(test::random_perspective_view(3));
  const golden::Registers& r = setup.host.regs;
  const sysc::FramePlan plan(r, 4);
  // A ray that samples slices 0 and 1 (the first rays do).
  const golden::PerspectiveSlice& s0 = plan.persp[0];
  const int64_t u = s0.rays_x.lo + (s0.rays_x.hi - s0.rays_x.lo) / 2, v = s0.rays_y.lo + (s0.rays_y.hi - s0.rays_y.lo) / 2;
  ASSERT_TRUE(golden::samples(plan.persp[1], u, v));
  auto beat = [&](int64_t step, uint32_t k) {
    sysc::RayShadedBeat b;
    b.step = step;
    b.valid = 1;
    b.u[0] = static_cast<int32_t>(u);
    b.v[0] = static_cast<int32_t>(v);
    b.tag[0] = k;
    b.alpha[0] = 100;
    return b;
  };
  auto expect_error = [&](const std::vector<sysc::RayShadedBeat>& beats, const std::string& says) {
    sysc::TlmCompositePersp unit(plan, false);
    sysc::CompositeOut out;
    try {
      for (const sysc::RayShadedBeat& b : beats) unit.clock(b, out);
      ADD_FAILURE() << "ran; expected an error saying: " << says;
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("slice 1, ray (" + std::to_string(u) + ", " + std::to_string(v) + ")"),
                std::string::npos)
          << e.what();
    }
  };
  expect_error({beat(0, 0), beat(1, 1)}, "is stored at step");
  expect_error({beat(0, 1)}, "is not in its store");
  // Given time, the same two samples blend.
  sysc::TlmCompositePersp unit(plan, false);
  sysc::CompositeOut out;
  unit.clock(beat(0, 0), out);
  EXPECT_NO_THROW(unit.clock(beat(1000, 1), out));
  // A unit of reach 0 cannot follow a ray that moves.
  const golden::PerspectiveReach reach = golden::perspective_reach(r);
  ASSERT_GT(golden::largest_home_move(reach), 0);
  int64_t moved_u = -1, moved_v = -1;
  const golden::PerspectiveSlice& s1 = plan.persp[1];
  for (int64_t a = s1.rays_x.lo; a < s1.rays_x.hi && moved_u < 0; ++a)
    for (int64_t b = s1.rays_y.lo; b < s1.rays_y.hi && moved_u < 0; ++b)
      if (golden::samples(s0, a, b)) {
        const int F = r.p.dda_frac_bits;
        if (golden::ray_home(golden::axis_slice(s0, 0), a, F) != golden::ray_home(golden::axis_slice(s1, 0), a, F) ||
            golden::ray_home(golden::axis_slice(s0, 1), b, F) != golden::ray_home(golden::axis_slice(s1, 1), b, F)) {
          moved_u = a;
          moved_v = b;
        }
      }
  ASSERT_GE(moved_u, 0);
  sysc::TlmCompositePersp rigid(plan, false, nullptr, 0);
  sysc::RayShadedBeat first = beat(0, 0), second = beat(1000, 1);
  first.u[0] = second.u[0] = static_cast<int32_t>(moved_u);
  first.v[0] = second.v[0] = static_cast<int32_t>(moved_v);
  rigid.clock(first, out);
  try {
    rigid.clock(second, out);
    ADD_FAILURE() << "a move beyond the reach ran";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("beyond the reach 0"), std::string::npos) << e.what();
  }
}
