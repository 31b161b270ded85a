// The perspective gradient unit's schedule (docs/perspective.md,
// "Gradient"): its clocked TLM model (systemc/tlm/tlm_gradient_persp.hpp)
// behind the stream former and the clocked TLM interpolation unit, over
// whole streams of frames. Every ray of every slice gets its gradient once
// a frame, equal to golden's from golden's samples, at the stream position
// gradient_forming_position() gives, with every operand arrived by then
// (the unit throws otherwise); and, over many random views, the plan's
// claim that every operand is formed at or before that position.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "golden/permuted_volume.hpp"
#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/stream_former.hpp"
#include "systemc/core/voxel_memory.hpp"
#include "systemc/tlm/tlm_addr.hpp"
#include "systemc/tlm/tlm_gradient_persp.hpp"
#include "systemc/tlm/tlm_interp_persp.hpp"
#include "tb/tests/perspective_views.hpp"
#include "tb/tests/test_support.hpp"

namespace {

using namespace cube4;

std::string scene(const std::string& eye, int fov, int supersampling) {
  return R"({"volume": {"synthetic": "sphere", "size": [21, 17, 13]}, "shading": true,
      "view": {"projection": "perspective", "fov": )" +
         std::to_string(fov) + R"(, "eye": )" + eye + R"(, "up": [1, 1, 1]},
      "output": {"width": 48, "height": 48}, "supersampling": )" +
         std::to_string(supersampling) + "}";
}
// Eyes in front of each of the six faces.
const char* const kEyes[6] = {"[12, 9, -20]", "[9, 7, 35]", "[-25, 9, 5]", "[45, 7, 7]", "[10, -22, 6]", "[11, 40, 5]"};

// Golden's samples of every slice's rays, and the gradient of a ray from them.
class GoldenSlices {
 public:
  explicit GoldenSlices(const golden::Registers& r, const golden::Volume& vol) : r_(r) {
    const golden::PermutedVolume pv(vol, r.perm, r.flip);
    for (int k = 0; k < r.sample_slices(); ++k) {
      const golden::PerspectiveSlice& s = slices_.emplace_back(golden::perspective_slice(r, k));
      std::map<std::pair<int64_t, int64_t>, uint32_t>& m = samples_.emplace_back();
      for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
        for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u)
          m[{u, v}] =
              golden::perspective_sample(r, s, u, v, [&](int x, int y, int dz) { return pv.at(x, y, s.z_voxel + dz); });
    }
  }
  const golden::PerspectiveSlice& slice(int k) const { return slices_[static_cast<size_t>(k)]; }
  uint32_t sample(int k, int64_t u, int64_t v) const {
    if (k < 0 || k >= static_cast<int>(slices_.size()) || !golden::samples(slice(k), u, v)) return 0;
    return samples_[static_cast<size_t>(k)].at({u, v});
  }
  golden::Gradient gradient(int k, int64_t u, int64_t v) const {
    auto at = [&](int slice) { return [this, slice](int64_t a, int64_t b) { return sample(slice, a, b); }; };
    return golden::perspective_gradient(r_, slice(k), u, v, at(k), at(k - 1), at(k + 1));
  }
  int64_t rays() const {
    int64_t n = 0;
    for (const golden::PerspectiveSlice& s : slices_)
      if (!s.rays_x.empty() && !s.rays_y.empty()) n += (s.rays_x.hi - s.rays_x.lo) * (s.rays_y.hi - s.rays_y.lo);
    return n;
  }

 private:
  const golden::Registers& r_;
  std::vector<golden::PerspectiveSlice> slices_;
  std::vector<std::map<std::pair<int64_t, int64_t>, uint32_t>> samples_;
};

// A ray's home cell on slice s.
std::pair<int64_t, int64_t> home(const golden::Registers& r, const golden::PerspectiveSlice& s, int64_t u, int64_t v) {
  const int F = r.p.dda_frac_bits;
  return {golden::home_cell(golden::ray_position(s.ray0_x, s.spacing, u), F),
          golden::home_cell(golden::ray_position(s.ray0_y, s.spacing, v), F)};
}


}  // namespace

TEST(GradientPersp, EveryRaysGradientIsGoldensAtItsPlannedPositionFromEveryFace) {
  constexpr int kFrames = 2;
  int64_t checked = 0;
  std::vector<std::string> scenes;
  for (int view = 0; view < 6; ++view)
    for (int S : {1, 2}) scenes.push_back(scene(kEyes[view], view % 2 ? 80 : 40, S));
  // Between the axes, where the outer rays are steepest: operands up to
  // three cells from the home on the slice and ahead.
  for (int view = 0; view < 16; ++view) scenes.push_back(test::random_perspective_view(view));
  for (const std::string& json : scenes) {
    const test::Setup s = test::setup(json);
    const golden::Registers& r = s.host.regs;
    ASSERT_TRUE(r.perspective);
    const GoldenSlices want(r, s.volume);
    for (int p : {1, 4, 5, 8, 16}) {
      SCOPED_TRACE(json + ", p = " + std::to_string(p));
      const sysc::FramePlan plan(r, p);
      sysc::VoxelMemory mem(s.volume, p);
      sysc::TlmAddr addr(mem.layout(), golden::SkewTraversal{r.perm, r.flip});
      sysc::StreamFormer former(plan, mem, addr, kFrames);
      sysc::TlmInterpPersp interp(plan);
      sysc::TlmGradientPersp gradient(plan);
      const int64_t row = static_cast<int64_t>(plan.B) * p;
      // The last slice's gradients spill up to six beams past the zero
      // pass; the stream former gives the interpolation ring's three.
      int extra_flush = 3 * plan.B;
      std::map<std::tuple<int, int64_t, int64_t>, int> seen;
      sysc::RaySampleBeat samples;
      sysc::RayGradientBeat out;
      for (int idle = 0; idle < 16;) {
        sysc::VoxelBeat in;
        if (!former.done()) {
          in = former.next();
        } else if (extra_flush > 0) {
          --extra_flush;
          in.valid = true;
          in.f.flush = true;
        }
        interp.clock(in, samples);
        ASSERT_NO_THROW(gradient.clock(samples, out));
        idle = former.done() && extra_flush == 0 ? idle + 1 : 0;
        for (int lane = 0; lane < p; ++lane) {
          if (!(out.valid >> lane & 1)) continue;
          const auto i = static_cast<size_t>(lane);
          const int k = static_cast<int>(out.tag[i]);
          const int64_t u = out.u[i], v = out.v[i];
          ASSERT_TRUE(k >= 0 && k < plan.K && golden::samples(want.slice(k), u, v)) << "slice " << k;
          const int frame = seen[{k, u, v}]++;
          ASSERT_LT(frame, kFrames) << "slice " << k << ", ray (" << u << ", " << v << ") twice a frame";
          const golden::Gradient g = want.gradient(k, u, v);
          ASSERT_EQ(std::make_tuple(out.gx[i], out.gy[i], out.gz[i], out.sample[i]),
                    std::make_tuple(g.x, g.y, g.z, want.sample(k, u, v)))
              << "slice " << k << ", ray (" << u << ", " << v << ")";
          // Frames before the stream's last have no zero pass.
          const auto [X, Y] = home(r, want.slice(k), u, v);
          EXPECT_EQ(out.step * p + lane,
                    golden::gradient_forming_position(static_cast<int64_t>(frame) * plan.K + k, X, Y, row, plan.ny))
              << "slice " << k << ", ray (" << u << ", " << v << ")";
          ++checked;
        }
      }
      EXPECT_EQ(static_cast<int64_t>(seen.size()), want.rays());
      for (const auto& [ray, n] : seen) ASSERT_EQ(n, kFrames);
      EXPECT_EQ(gradient.gradients(), static_cast<uint64_t>(kFrames * want.rays()));
    }
  }
  EXPECT_GT(checked, 100000);
}

// The plan over many random views (the perspective reach table's kind):
// each ray's operands, its neighbours on its slice and the four rays
// around the points straight behind and ahead, are formed (formed_cell())
// at or before the position that forms its gradient, and no two rays of a
// slice share that position.
TEST(GradientPersp, EveryOperandIsFormedByItsGradientsPositionInRandomViews) {
  int64_t operands = 0;
  for (int view = 0; view < 40; ++view) {
    const std::string json = test::random_perspective_view(view);
    const test::Setup s = test::setup(json);
    const golden::Registers& r = s.host.regs;
    const int K = r.sample_slices(), nx = r.dim[0], ny = r.dim[1];
    for (int p : {1, 4, 5}) {
      const int64_t row = static_cast<int64_t>((nx + p - 1) / p) * p;
      for (int k = 0; k < K; ++k) {
        const golden::PerspectiveSlice s0 = golden::perspective_slice(r, k);
        std::map<int64_t, int> positions;
        auto formed = [&](int slice, int64_t u, int64_t v) -> int64_t {
          if (slice < 0 || slice >= K) return INT64_MIN;
          const golden::PerspectiveSlice sl = golden::perspective_slice(r, slice);
          if (!golden::samples(sl, u, v)) return INT64_MIN;
          const auto [x, y] = home(r, sl, u, v);
          return golden::forming_position(slice, x, y, row, ny);
        };
        for (int64_t v = s0.rays_y.lo; v < s0.rays_y.hi; ++v)
          for (int64_t u = s0.rays_x.lo; u < s0.rays_x.hi; ++u) {
            const auto [X, Y] = home(r, s0, u, v);
            const int64_t at = golden::gradient_forming_position(k, X, Y, row, ny);
            ASSERT_EQ(positions[at]++, 0) << "two gradients of slice " << k << " at position " << at;
            std::vector<int64_t> needs = {formed(k, u, v), formed(k, u - 1, v), formed(k, u + 1, v),
                                          formed(k, u, v - 1), formed(k, u, v + 1)};
            const int F = r.p.dda_frac_bits, W = r.p.weight_bits;
            for (const auto& [slice, dx, dy] :
                 {std::make_tuple(k - 1, s0.behind_x, s0.behind_y), std::make_tuple(k + 1, s0.ahead_x, s0.ahead_y)}) {
              if (slice < 0 || slice >= K) continue;
              const golden::RayPoint px = golden::realigned_ray(dx, u, F, W), py = golden::realigned_ray(dy, v, F, W);
              for (int64_t a : {px.ray, px.ray + 1})
                for (int64_t b : {py.ray, py.ray + 1}) needs.push_back(formed(slice, a, b));
            }
            for (int64_t n : needs) {
              ASSERT_LE(n, at) << "slice " << k << ", ray (" << u << ", " << v << "), p = " << p << ", view " << view;
              ++operands;
            }
          }
      }
    }
  }
  EXPECT_GT(operands, 100000);
}

// The plan for the ring's RTL (docs/perspective.md): over the same random
// views, every operand of every gradient lies in a row gradient_rows()
// names for its beam (left, right and centre in the beam's own row, up
// and down in the rows of rays v -/+ 1, the 2x2s in the rows of py, py + 1),
// and is stored on a lane (its home column + 2) among the forming lane
// (home + 5) and the six to its left, the one gradient_window() names.
TEST(GradientPersp, EachBeamReadsOneSetOfRowsAndEachGradientASevenColumnWindow) {
  int64_t operands = 0, violations = 0;
  std::string first;
  for (int view = 0; view < 40; ++view) {
    const test::Setup setup = test::setup(test::random_perspective_view(view));
    const golden::Registers& r = setup.host.regs;
    const int K = r.sample_slices(), F = r.p.dda_frac_bits, W = r.p.weight_bits;
    std::vector<golden::PerspectiveSlice> slices;
    for (int k = 0; k < K; ++k) slices.push_back(golden::perspective_slice(r, k));
    auto at = [&](int k) { return k >= 0 && k < K ? &slices[static_cast<size_t>(k)] : nullptr; };
    for (int k = 0; k < K; ++k) {
      const golden::PerspectiveSlice& s = slices[static_cast<size_t>(k)];
      for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
        for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
          const std::pair<int64_t, int64_t> cell = home(r, s, u, v);
          const int64_t X = cell.first, Y = cell.second;
          const golden::GradientRows rows = golden::gradient_rows(r, s, at(k - 1), at(k + 1), Y);
          const golden::GradientWindow window = golden::gradient_window(r, s, at(k - 1), at(k + 1), u);
          ASSERT_TRUE(rows.valid);
          ASSERT_EQ(rows.v, v);
          // An operand of slice `on` at ray (a, b): in a row the beam reads
          // and within the window; rays that miss the slice read zero.
          auto operand = [&](const golden::PerspectiveSlice* on, int64_t a, int64_t b, std::vector<int64_t> beam_rows,
                             int window_lane) {
            if (!on || !golden::samples(*on, a, b)) return;
            ++operands;
            const auto [x, y] = home(r, *on, a, b);
            const int64_t back = X + 5 - (x + 2);
            if (std::find(beam_rows.begin(), beam_rows.end(), y) != beam_rows.end() && back >= 0 && back <= 6 &&
                back == window_lane)
              return;
            if (violations++ == 0)
              first = "view " + std::to_string(view) + ", slice " + std::to_string(k) + ", ray (" + std::to_string(u) +
                      ", " + std::to_string(v) + "): operand ray (" + std::to_string(a) + ", " + std::to_string(b) +
                      ") at home (" + std::to_string(x) + ", " + std::to_string(y) + "), the gradient's home (" +
                      std::to_string(X) + ", " + std::to_string(Y) + ")";
          };
          operand(&s, u - 1, v, {Y}, window.left);
          operand(&s, u + 1, v, {Y}, window.right);
          operand(&s, u, v - 1, {rows.up}, 3);  // the ray's own column: stored 3 lanes back
          operand(&s, u, v + 1, {rows.down}, 3);
          for (const auto& [on, dx, dy, beam, lanes] :
               {std::make_tuple(at(k - 1), s.behind_x, s.behind_y, rows.behind, window.behind),
                std::make_tuple(at(k + 1), s.ahead_x, s.ahead_y, rows.ahead, window.ahead)}) {
            const int64_t px = golden::realigned_ray(dx, u, F, W).ray, py = golden::realigned_ray(dy, v, F, W).ray;
            for (int i = 0; i < 2; ++i)
              for (int64_t b : {py, py + 1}) operand(on, px + i, b, {beam[0], beam[1]}, lanes[static_cast<size_t>(i)]);
          }
        }
    }
  }
  EXPECT_EQ(violations, 0) << "first: " << first;
  EXPECT_GT(operands, 100000);
}

// A parallel frame is not the unit's; VolumePro's z gradient is (its z
// from the samples' beats: SystemPerspective.VoxelDifferenceZGradient...).
TEST(GradientPersp, RefusesWhatItDoesNotModel) {
  const test::Setup par = test::setup(R"({"volume": {"synthetic": "sphere", "size": [9, 9, 9]}, "shading": true})");
  const sysc::FramePlan plan(par.host.regs, 4);
  EXPECT_THROW(sysc::TlmGradientPersp{plan}, std::invalid_argument);
  const test::Setup zd = test::setup(scene(kEyes[0], 40, 1).insert(1, R"("z_gradient": "voxel_differences", )"));
  const sysc::FramePlan zplan(zd.host.regs, 4);
  EXPECT_TRUE(zplan.zdiff);
  EXPECT_NO_THROW(sysc::TlmGradientPersp{zplan});
}
