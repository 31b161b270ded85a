// Perspective frames through the system model: loosely timed at TLM (one
// transaction through the golden perspective renderer, the cycle model's
// count), directly and through the host interface (MODE's perspective bit,
// SCALE_START, SCALE_STEP); clocked, with the perspective interpolation
// unit as clocked TLM or RTL (cube4_interp_persp_ring), the gradient unit
// as clocked TLM (its ring's schedule) and shading and compositing loosely
// timed: every sample and gradient checked against golden, the stream's
// beats and the last sample's and gradient's cycles exactly the
// dataflow's, the clocked TLM interpolation unit beat for beat the ring;
// and refused where a unit has no perspective model at the level asked for.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/renderers.hpp"
#include "systemc/core/machine.hpp"
#include "systemc/core/perspective_frame.hpp"
#include "systemc/core/stream_former.hpp"
#include "systemc/core/system.hpp"
#include "systemc/core/voxel_memory.hpp"
#include "systemc/tlm/tlm_addr.hpp"
#include "systemc/tlm/tlm_composite_persp.hpp"
#include "systemc/tlm/tlm_gradient_persp.hpp"
#include "systemc/tlm/tlm_shade.hpp"
#include "systemc/tlm/tlm_interp_persp.hpp"
#include "tb/tests/system_support.hpp"
#include "tb/tests/test_support.hpp"

// verilated.h calls sc_time_stamp() unqualified once SystemC is included.
#include <systemc>
using sc_core::sc_time_stamp;
#include "systemc/core/trace_window.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#if CUBE4_TEST_RTL  // verilated.h is on the include path only in a build with RTL
#include "systemc/rtl/vl_context.hpp"
#endif

namespace {

using namespace cube4;
using namespace cube4::test;

std::string scene(const std::string& eye) {
  return R"({"volume": {"synthetic": "sphere", "size": [21, 17, 13]}, "shading": true,
      "view": {"projection": "perspective", "fov": 50, "eye": )" + eye + R"(, "up": [1, 1, 1]},
      "output": {"width": 48, "height": 48}, "supersampling": 2})";
}
// Eyes in front of each of the six faces.
const char* const kEyes[6] = {"[12, 9, -20]", "[9, 7, 35]", "[-25, 9, 5]", "[45, 7, 7]", "[10, -22, 6]", "[11, 40, 5]"};

sysc::SystemConfig tlm_config(int p) {
  sysc::SystemConfig cfg;
  cfg.p = p;
  cfg.levels = kTlm;
  return cfg;
}

void expect_plane(const golden::BasePlane& want, const golden::BasePlane& got) {
  ASSERT_EQ(got.width, want.width);
  ASSERT_EQ(got.height, want.height);
  EXPECT_TRUE(got.rgba == want.rgba) << "the base planes differ";
  // Where the plane lies, which the warp to the image reads.
  EXPECT_EQ(got.shift_x, want.shift_x);
  EXPECT_EQ(got.shift_y, want.shift_y);
}

// The cycle the interpolation unit's last sample of a stream of `frames`
// frames leaves, by the dataflow: the stream position that forms it
// (golden forming_position()), a beat per cycle from cycle 1, the link's
// cycle and the ring's 4. With `gradient`, the gradient unit's last
// gradient instead: its position (gradient_forming_position()), then the
// next link and the unit's 3 cycles.
// The cycle a frame's last-formed ray leaves the interpolation unit (or
// with `gradient` the gradient unit); `after` positions later in the
// stream (the compositor blends kPerspectiveReach after its gradient).
uint64_t last_sample_cycle(const golden::Registers& r, int p, int frames, bool gradient = false, int after = 0) {
  const int nx = r.dim[0], ny = r.dim[1], K = r.sample_slices();
  const int64_t row = static_cast<int64_t>((nx + p - 1) / p) * p;
  const int F = r.p.dda_frac_bits;
  // VolumePro's z gradient: each frame's priming pass comes before its slices.
  const int primed = sysc::zdiff_stream(r) ? 1 : 0;
  int64_t last = -1;
  for (int k = 0; k < K; ++k) {
    const golden::PerspectiveSlice s = golden::perspective_slice(r, k);
    if (s.rays_x.empty() || s.rays_y.empty()) continue;
    // The last-formed ray of a slice: the largest home row, then column.
    const int64_t hy = golden::home_cell(golden::ray_position(s.ray0_y, s.spacing, s.rays_y.hi - 1), F);
    const int64_t hx = golden::home_cell(golden::ray_position(s.ray0_x, s.spacing, s.rays_x.hi - 1), F);
    const int64_t pass = int64_t{frames - 1} * (K + primed) + primed + k;
    last = std::max(last, gradient ? golden::gradient_forming_position(pass, hx, hy, row, ny)
                                   : golden::forming_position(pass, hx, hy, row, ny));
  }
  return static_cast<uint64_t>((last + after) / p) + 1 + 1 + 4 + (gradient ? 1 + sysc::TlmGradientPersp::kLatency : 0);
}

}  // namespace

TEST(SystemPerspective, LooselyTimedTlmEqualsGoldenFromEveryFaceAtP1458) {
  for (const char* eye : kEyes) {
    const test::Setup s = setup(scene(eye));
    ASSERT_TRUE(s.host.regs.perspective);
    golden::RenderStats stats;
    const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, &stats);
    for (int p : {1, 4, 5, 8}) {
      SCOPED_TRACE(std::string("eye ") + eye + ", p = " + std::to_string(p));
      const sysc::SystemResult res = sysc::run_frame(s.host.regs, s.volume, tlm_config(p));
      expect_plane(want, res.plane);
      // The rays spread: fewer samples than a parallel frame's nx * ny per slice.
      const golden::Registers& r = s.host.regs;
      EXPECT_EQ(res.samples, stats.samples);
      EXPECT_LT(res.samples, static_cast<uint64_t>(r.dim[0]) * r.dim[1] * r.sample_slices());
      // The cycle model's count: a perspective frame streams the volume as a
      // parallel one does (one voxel per pipeline per cycle), and ends when
      // its last ray's pixel is written: its last gradient's cycle (the
      // dataflow's position), the link, the shading unit and the
      // compositor's 7 from its blend kPerspectiveReach positions after the
      // gradient, no later than the stream's last beat and the drain
      // (measured by the clocked tests below).
      ASSERT_TRUE(r.gradient);
      golden::Registers parallel = s.host.regs;
      parallel.perspective = false;
      const sysc::CycleCount cc = sysc::frame_cycles(s.host.regs, p);
      const auto shade = static_cast<uint64_t>(sysc::shade_latency(r.p));
      EXPECT_EQ(res.frame_cycles, cc.latency);
      EXPECT_EQ(cc.stream, sysc::frame_cycles(parallel, p).stream);
      // The result says what the same volume costs in parallel projection.
      EXPECT_EQ(res.parallel_frame_cycles, sysc::frame_cycles(parallel, p).latency);
      EXPECT_EQ(res.parallel_stream_cycles, res.stream_cycles);
      EXPECT_EQ(cc.latency, last_sample_cycle(r, p, 1, true, sysc::kPerspectiveReach) + 1 + shade + 1 +
                                sysc::TlmCompositePersp::kLatency);
      EXPECT_LE(cc.latency, cc.stream + cc.flush + 1 + 4 + 1 + sysc::TlmGradientPersp::kLatency + 1 + shade + 1 +
                                sysc::TlmCompositePersp::kLatency);
    }
  }
}

TEST(SystemPerspective, ThroughTheHostInterfaceTlm) {
  if (!sysc::host_interface_available(4))
    GTEST_SKIP() << "this process cannot build the host interface for p = 4 any more (ctest runs each test alone)";
  for (const char* eye : {kEyes[0], kEyes[3]}) {
    const test::Setup s = setup(scene(eye));
    const sysc::SystemResult res = sysc::render_through_host(s.host.regs, s.volume, tlm_config(4), {});
    expect_plane(golden::render_fixed(s.volume, s.host.regs), res.plane);
  }
  // A parallel frame after a perspective one: MODE's bit is cleared again.
  const test::Setup par = setup(R"({"volume": {"synthetic": "sphere", "size": [21, 17, 13]}, "view": {"rotate": [10, 20, 0]}})");
  expect_plane(golden::render_fixed(par.volume, par.host.regs),
               sysc::render_through_host(par.host.regs, par.volume, tlm_config(4), {}).plane);
}

// Cube-5's polygons in perspective: the loosely timed frame composites
// the golden polygon frame as render_fixed() does, directly at p = 1, 4, 5
// and 8 (slab lines laid out for that p) and through the host interface
// (POLY_WIDTH x POLY_HEIGHT: the perspective base plane with its margins).
// A box, a needle through the volume and a sphere beside it.
const char kPolygons[] = R"(, "polygons": [
      {"shape": "box", "size": [18, 14, 10], "transform": {"translate": [10, 8, 6], "rotate": [10, 20, 0]},
       "color": [0.2, 0.5, 1], "opacity": 0.3},
      {"shape": "needle", "radius": 1, "length": 40, "transform": {"translate": [10, 8, 6], "rotate": [0, 80, 10]}},
      {"shape": "sphere", "radius": 3, "segments": 12, "rings": 6, "transform": {"translate": [-6, 8, 6]},
       "color": [1, 0.3, 0.2], "opacity": 0.5}]})";

std::string with_polygons(const char* eye) {
  std::string json = scene(eye);
  const std::string polygons = kPolygons;
  json.insert(json.rfind('}'), polygons.substr(0, polygons.size() - 1));
  return json;
}

TEST(SystemPerspective, PolygonsInPerspectiveAtTlm) {
  for (const char* eye : {kEyes[0], kEyes[3]}) {
    test::Setup s = setup(with_polygons(eye));
    ASSERT_TRUE(s.host.regs.perspective);
    ASSERT_FALSE(s.meshes.empty());
    for (int p : {1, 4, 5, 8}) {
      SCOPED_TRACE(std::string("eye ") + eye + ", p = " + std::to_string(p));
      s.scene.pipelines = p;
      const golden::PolygonFrame frame = golden::rasterise_polygons(s.scene, s.meshes, s.host);
      EXPECT_GT(frame.counts.in_slabs, 0u);
      golden::FixedOptions opt;
      opt.polygons = &frame;
      const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, opt);
      expect_plane(want, sysc::run_frame(s.host.regs, s.volume, tlm_config(p), {}, &frame).plane);
      if (p == 4 && sysc::host_interface_available(4))
        expect_plane(want, sysc::render_through_host(s.host.regs, s.volume, tlm_config(4), {}, nullptr, &frame).plane);
    }
  }
}

namespace {

sysc::SystemConfig clocked_config(int p, bool rtl_interp) {
  sysc::SystemConfig cfg = tlm_config(p);
  cfg.cycle_level = true;
  cfg.check = true;
  if (rtl_interp) cfg.levels[static_cast<size_t>(sysc::Unit::Interp)] = sysc::Level::Rtl;
  return cfg;
}

// A clocked frame with every unit clocked and nothing mismatched: golden's
// base plane and accumulators.
void expect_clocked_plane(const golden::BasePlane& want, const sysc::SystemResult& res) {
  EXPECT_FALSE(res.mismatch) << res.mismatch->describe();
  EXPECT_FALSE(res.back_loosely_timed);
  expect_plane(want, res.plane);
  ASSERT_EQ(res.plane.acc.size(), want.acc.size());
  size_t differ = 0;
  for (size_t i = 0; i < want.acc.size(); ++i) differ += !(res.plane.acc[i] == want.acc[i]);
  EXPECT_EQ(differ, 0u);
}

bool has(const std::vector<int>& pipes, int p) { return std::find(pipes.begin(), pipes.end(), p) != pipes.end(); }

bool rtl_perspective(int p) {
  if (!CUBE4_TEST_RTL) return false;
  const std::vector<int> pipes = sysc::rtl_persp_pipes();
  return std::find(pipes.begin(), pipes.end(), p) != pipes.end();
}

sysc::SystemResult expect_clocked(const test::Setup& s, const sysc::SystemConfig& cfg, const golden::BasePlane& want,
                                  const golden::RenderStats& stats) {
  const golden::Registers& r = s.host.regs;
  const sysc::SystemResult res = sysc::run_frame(r, s.volume, cfg);
  EXPECT_FALSE(res.mismatch) << res.mismatch->describe();
  expect_plane(want, res.plane);
  // Every unit clocked: shading and compositing too (no polygons here).
  EXPECT_FALSE(res.back_loosely_timed);
  // The weight generator runs at the interpolation unit's level.
  EXPECT_EQ(res.weight_generator, cfg.levels[static_cast<size_t>(sysc::Unit::Interp)]);
  EXPECT_EQ(res.samples, stats.samples);
  // The stream: every pass back to back, then the zero pass and six flush
  // beams with gradients (three without), a beat a cycle from cycle 1.
  const sysc::CycleCount cc = sysc::frame_cycles(r, cfg.p);
  EXPECT_EQ(res.last_beat[0], cc.stream * static_cast<uint64_t>(cfg.frames) + cc.flush);
  EXPECT_EQ(res.last_beat[1], last_sample_cycle(r, cfg.p, cfg.frames));
  // The model's interpolation latency bounds it: no sample after the
  // stream's last beat, the link and the ring's 4 cycles.
  EXPECT_LE(res.last_beat[1], res.last_beat[0] + 1 + 4);
  // With gradients the gradient unit's last gradient, in the cycle its
  // schedule gives, and within the stream's drain.
  EXPECT_EQ(res.last_beat[2], r.gradient ? last_sample_cycle(r, cfg.p, cfg.frames, true) : 0);
  EXPECT_LE(res.last_beat[2], res.last_beat[0] + 1 + 4 + 1 + sysc::TlmGradientPersp::kLatency);
  EXPECT_EQ(res.frame_cycles, cfg.frames > 1 ? cc.latency_followed : cc.latency);
  if (cfg.frames > 1) {
    EXPECT_EQ(res.measured_interval, cc.stream);
  }
  return res;
}

}  // namespace

// Clocked perspective frames from in front of each face, p = 1, 4, 5 and
// 8: the interpolation unit as clocked TLM and as the verilated ring, each
// sample checked as it leaves, the image golden's, the stream's beats and
// the last sample's cycle exact.
TEST(SystemPerspective, ClockedInterpolationFromEveryFaceAtP1458) {
  for (const char* eye : kEyes) {
    const test::Setup s = setup(scene(eye));
    golden::RenderStats stats;
    const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, &stats);
    for (int p : {1, 4, 5, 8})
      for (const bool rtl : {false, true}) {
        if (rtl && !rtl_perspective(p)) continue;
        SCOPED_TRACE(std::string("eye ") + eye + ", p = " + std::to_string(p) + (rtl ? ", RTL" : ", clocked TLM"));
        expect_clocked(s, clocked_config(p, rtl), want, stats);
      }
  }
}

// The shading units at RTL (cube4_shade_unit, each lane's ray on its
// unit's side channel) in a clocked perspective frame, behind the
// interpolation unit at either level, from every face at p = 1, 4, 5 and
// 8: golden's image, every sample and gradient checked, and the cycles of
// the clocked TLM shading unit (the same latency).
TEST(SystemPerspective, ClockedShadingAtRtlFromEveryFace) {
  if (!CUBE4_TEST_RTL) GTEST_SKIP() << "a build without RTL";
  for (const char* eye : kEyes) {
    const test::Setup s = setup(scene(eye));
    golden::RenderStats stats;
    const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, &stats);
    for (int p : {1, 4, 5, 8})
      for (const bool rtl_interp : {false, true}) {
        if (rtl_interp && !rtl_perspective(p)) continue;
        SCOPED_TRACE(std::string("eye ") + eye + ", p = " + std::to_string(p) + (rtl_interp ? ", RTL ring" : ""));
        sysc::SystemConfig cfg = clocked_config(p, rtl_interp);
        cfg.levels[static_cast<size_t>(sysc::Unit::Shade)] = sysc::Level::Rtl;
        expect_clocked(s, cfg, want, stats);
      }
  }
}

// The gradient ring at RTL (cube4_gradient_persp_ring) in a clocked
// perspective frame, behind the interpolation unit at either level, from
// every face at p = 1, 4, 5 and 8: golden's image, every gradient checked
// as it leaves, and the cycles of the clocked TLM gradient unit (the same
// schedule); and with every unit that has perspective RTL at RTL.
TEST(SystemPerspective, ClockedGradientAtRtlFromEveryFace) {
  if (!CUBE4_TEST_RTL) GTEST_SKIP() << "a build without RTL";
  for (const char* eye : kEyes) {
    const test::Setup s = setup(scene(eye));
    golden::RenderStats stats;
    const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, &stats);
    for (int p : {1, 4, 5, 8}) {
      if (!rtl_perspective(p)) continue;
      for (const bool rtl_interp : {false, true}) {
        SCOPED_TRACE(std::string("eye ") + eye + ", p = " + std::to_string(p) + (rtl_interp ? ", RTL ring" : ""));
        sysc::SystemConfig cfg = clocked_config(p, rtl_interp);
        cfg.levels[static_cast<size_t>(sysc::Unit::Gradient)] = sysc::Level::Rtl;
        if (rtl_interp) {
          cfg.levels[static_cast<size_t>(sysc::Unit::Shade)] = sysc::Level::Rtl;
          cfg.levels[static_cast<size_t>(sysc::Unit::Addr)] = sysc::Level::Rtl;
        }
        expect_clocked(s, cfg, want, stats);
      }
    }
  }
}

// The clocked TLM gradient unit is the ring, beat by beat: the same
// samples through both (the stream former and the clocked TLM
// interpolation unit, two frames back to back), every output beat
// compared (lanes, steps, gradients, samples, rays, tags), from every face
// and at p = 1, 4, 5 and 8.
TEST(SystemPerspective, TheClockedTlmGradientUnitIsTheRingBeatByBeat) {
#if CUBE4_TEST_RTL
  long compared = 0;
  for (const char* eye : kEyes) {
    const test::Setup s = setup(scene(eye));
    for (int p : {1, 4, 5, 8}) {
      if (!rtl_perspective(p)) continue;
      SCOPED_TRACE(std::string("eye ") + eye + ", p = " + std::to_string(p));
      const sysc::FramePlan plan(s.host.regs, p);
      sysc::VoxelMemory mem(s.volume, p);
      sysc::TlmAddr addr(mem.layout(), golden::SkewTraversal{s.host.regs.perm, s.host.regs.flip});
      sysc::StreamFormer former(plan, mem, addr, 2);
      sysc::TlmInterpPersp interp(plan);
      rtl::ScopedVerilatedContext ctx(1, false, true);
      auto ring = sysc::make_rtl_gradient_persp(plan, *ctx, sysc::TraceWindow{});
      sysc::TlmGradientPersp tlm(plan);
      sysc::RaySampleBeat samples;
      sysc::RayGradientBeat a, b;
      int drain = 0;
      for (int cycle = 0; drain < 8; ++cycle) {
        const sysc::VoxelBeat in = former.done() ? sysc::VoxelBeat{} : former.next();
        interp.clock(in, samples);
        ring->clock(samples, a);
        tlm.clock(samples, b);
        ASSERT_EQ(std::make_tuple(a.valid, a.step), std::make_tuple(b.valid, b.step)) << "cycle " << cycle;
        for (int k = 0; k < p; ++k) {
          if (!(a.valid >> k & 1)) continue;
          const auto i = static_cast<size_t>(k);
          ASSERT_EQ(std::make_tuple(a.gx[i], a.gy[i], a.gz[i], a.sample[i], a.u[i], a.v[i], a.tag[i], a.vtag[i]),
                    std::make_tuple(b.gx[i], b.gy[i], b.gz[i], b.sample[i], b.u[i], b.v[i], b.tag[i], b.vtag[i]))
              << "cycle " << cycle << ", lane " << k;
          ++compared;
        }
        // The last gradients leave within the interpolation ring's 4 cycles and the gradient ring's 3.
        if (former.done()) ++drain;
      }
    }
  }
  EXPECT_GT(compared, 20000);
#else
  GTEST_SKIP() << "a build without RTL";
#endif
}

// Voxel tags (bela §III) in a clocked perspective frame: two spheres with
// their own classes, each sample's tag the nearest voxel's, through the
// clocked TLM unit and the ring's tag variant (p = 4, in both
// CUBE4_SYSTEM_PERSP_PIPES and CUBE4_SYSTEM_TAG_PIPES by default).
TEST(SystemPerspective, ClockedVoxelTags) {
  const test::Setup s = setup(R"({"volume": {"synthetic": "spheres", "size": [24, 20, 16]},
      "view": {"projection": "perspective", "fov": 45, "eye": [30, -20, -25], "up": [0, 1, 0]},
      "output": {"width": 48, "height": 48}, "precision": {"tag_bits": 2},
      "tags": {"label": [{"tag": 1, "sphere": {"center": [6, 10, 8], "radius": 6}},
                         {"tag": 2, "sphere": {"center": [17, 10, 8], "radius": 6}}],
               "classes": [{"tag": 1, "color": [[0, 1, 0.15, 0.1], [1, 1, 0.15, 0.1]]},
                           {"tag": 2, "color": [[0, 0.1, 0.2, 0.9], [1, 0.1, 0.2, 0.9]],
                            "opacity": [[0, 0], [0.3, 0], [0.5, 0.9], [1, 0.9]]}]}})");
  ASSERT_EQ(s.host.regs.p.tag_bits, 2);
  golden::RenderStats stats;
  const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, &stats);
  for (const bool rtl : {false, true}) {
    if (rtl && !rtl_perspective(4)) continue;
    SCOPED_TRACE(rtl ? "RTL" : "clocked TLM");
    sysc::SystemConfig cfg = clocked_config(4, rtl);
    expect_clocked(s, cfg, want, stats);
    // The shading units' and the gradient ring's tag variants (each tag's
    // class and material; each sample's tag stored with it).
    if (!rtl) continue;
    cfg.levels[static_cast<size_t>(sysc::Unit::Shade)] = sysc::Level::Rtl;
    expect_clocked(s, cfg, want, stats);
    cfg.levels[static_cast<size_t>(sysc::Unit::Gradient)] = sysc::Level::Rtl;
    expect_clocked(s, cfg, want, stats);
  }
}

// Two frames back to back (the second's passes follow the first's, which
// drains in them), with and without gradients (the zero pass), with the
// address generation at RTL too.
TEST(SystemPerspective, ClockedFramesBackToBackWithAndWithoutGradients) {
  for (const char* effects : {R"("shading": true)", R"("shading": false)"}) {
    std::string json = scene(kEyes[3]);
    json.replace(json.find(R"("shading": true)"), 15, effects);
    const test::Setup s = setup(json);
    golden::RenderStats stats;
    const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, &stats);
    for (const bool rtl : {false, true}) {
      if (rtl && !rtl_perspective(4)) continue;
      SCOPED_TRACE(std::string(effects) + (rtl ? ", RTL" : ", clocked TLM"));
      sysc::SystemConfig cfg = clocked_config(4, rtl);
      cfg.frames = 2;
      if (rtl) {
        cfg.levels[static_cast<size_t>(sysc::Unit::Addr)] = sysc::Level::Rtl;
        cfg.levels[static_cast<size_t>(sysc::Unit::Gradient)] = sysc::Level::Rtl;
      }
      expect_clocked(s, cfg, want, stats);
    }
  }
}

// The clocked compositor keeps golden's accumulators (each ray's, by the
// full-α rule the renderer keeps them by) and blends by the scene's mode:
// a maximum intensity projection and a composited frame with the
// accumulators asked for, both with cropping, give golden's base plane and
// accumulators exactly.
TEST(SystemPerspective, ClockedCompositingKeepsGoldensAccumulatorsAndBlendModes) {
  for (const char* extra : {R"("blend": "mip")", R"("blend": "composite")"}) {
    std::string json = scene(kEyes[5]);
    json.insert(1, std::string(extra) + R"(, "cropping": {"x": [2, 18], "y": [0, 12], "z": [1, 11]}, )");
    const test::Setup s = setup(json);
    golden::FixedOptions opt;
    opt.accumulators = true;
    const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, opt);
    ASSERT_FALSE(want.acc.empty());
    for (const bool rtl : {false, true}) {
      if (rtl && !rtl_perspective(4)) continue;
      SCOPED_TRACE(std::string(extra) + (rtl ? ", the compositing ring at RTL" : ", clocked TLM"));
      sysc::SystemConfig cfg = clocked_config(4, false);
      cfg.accumulators = true;
      if (rtl) cfg.levels[static_cast<size_t>(sysc::Unit::Composite)] = sysc::Level::Rtl;
      const sysc::SystemResult res = sysc::run_frame(s.host.regs, s.volume, cfg);
      expect_clocked_plane(want, res);
    }
  }
}

// Cube-5's polygons in clocked perspective frames, from every face: the
// compositing unit as clocked TLM and as the verilated ring with polygon
// hardware (p = 1, 4 and 5, CUBE4_SYSTEM_POLYGON_PIPES; every unit at RTL
// at p = 4; its slab pixels run-length decoded by cube4_persp_slab_decode),
// golden's image and accumulators, every sample checked, and the same
// cycles at either level; and two frames back to back at p = 4.
TEST(SystemPerspective, PolygonsInClockedPerspectiveFramesWithTheRingAtRtl) {
  int rtl_frames = 0;
  for (const char* eye : kEyes) {
    test::Setup s = setup(with_polygons(eye));
    for (int p : {1, 4, 5}) {
      s.scene.pipelines = p;
      const golden::PolygonFrame frame = golden::rasterise_polygons(s.scene, s.meshes, s.host);
      // The slab images hold fragments, so the decoders' pixels count.
      size_t slab_fragments = 0;
      for (const golden::SlabImage& slab : frame.slabs)
        for (int y = 0; y < slab.beams(); ++y) slab.for_each_pixel(y, [&](int, const golden::Pixel&) { ++slab_fragments; });
      EXPECT_GT(slab_fragments, 0u) << eye;
      golden::FixedOptions opt;
      opt.polygons = &frame;
      opt.accumulators = true;
      const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, opt);
      uint64_t tlm_cycles = 0;
      for (const int level : {0, 1, 2}) {  // clocked TLM, the ring at RTL, every unit at RTL
        if (level > 0 && !(rtl_perspective(p) && has(sysc::rtl_persp_polygon_pipes(), p))) continue;
        if (level == 2 && p != 4) continue;
        SCOPED_TRACE(std::string("eye ") + eye + ", p = " + std::to_string(p) + ", level " + std::to_string(level));
        sysc::SystemConfig cfg = clocked_config(p, false);
        cfg.accumulators = true;
        if (level == 1) cfg.levels[static_cast<size_t>(sysc::Unit::Composite)] = sysc::Level::Rtl;
        if (level == 2) cfg.levels = kRtl;
        const sysc::SystemResult res = sysc::run_frame(s.host.regs, s.volume, cfg, {}, &frame);
        expect_clocked_plane(want, res);
        if (level == 0) tlm_cycles = res.frame_cycles;
        EXPECT_EQ(res.frame_cycles, tlm_cycles);
        rtl_frames += level > 0;
      }
      // Two frames back to back (the polygon images again for the second):
      // the ring at RTL as the clocked TLM unit, the same interval.
      if (p == 4 && has(sysc::rtl_persp_polygon_pipes(), 4)) {
        uint64_t interval = 0;
        for (const bool rtl : {false, true}) {
          sysc::SystemConfig cfg = clocked_config(4, false);
          cfg.accumulators = true;
          cfg.frames = 2;
          if (rtl) cfg.levels = kRtl;
          const sysc::SystemResult res = sysc::run_frame(s.host.regs, s.volume, cfg, {}, &frame);
          expect_clocked_plane(want, res);
          if (!rtl) interval = res.measured_interval;
          EXPECT_EQ(res.measured_interval, interval) << "eye " << eye;
          EXPECT_GT(res.measured_interval, 0u);
        }
      }
    }
  }
  if (CUBE4_TEST_RTL) {
    EXPECT_EQ(rtl_frames, 6 * 4);  // every face: p = 1, 4, 5, and every unit at p = 4
  }
}

// Every unit at RTL (--model rtl): the perspective interpolation, gradient
// and compositing rings, the shading units and the address generation,
// from every face at p = 1, 4, 5 and 8: golden's image, every sample and
// gradient checked, and the clocked TLM units' cycles (the same schedule);
// and two frames back to back.
TEST(SystemPerspective, EveryUnitAtRtlFromEveryFace) {
  if (!CUBE4_TEST_RTL) GTEST_SKIP() << "a build without RTL";
  for (const char* eye : kEyes) {
    const test::Setup s = setup(scene(eye));
    golden::RenderStats stats;
    const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, &stats);
    for (int p : {1, 4, 5, 8}) {
      if (!rtl_perspective(p)) continue;
      SCOPED_TRACE(std::string("eye ") + eye + ", p = " + std::to_string(p));
      sysc::SystemConfig cfg = clocked_config(p, true);
      cfg.levels = kRtl;
      expect_clocked(s, cfg, want, stats);
      if (p != 4) continue;
      cfg.frames = 2;
      expect_clocked(s, cfg, want, stats);
    }
  }
}

// VolumePro's voxel-difference z gradient in clocked perspective frames:
// the stream reads a voxel slice ahead after each frame's priming pass,
// the interpolation unit gives each sample's filtered z difference with
// it, and the gradient unit takes z from there (docs/perspective.md,
// "Gradient"). From every face at p = 1, 4 and 5 with the units at clocked
// TLM, the shading unit and compositing ring at RTL where built, then the
// interpolation and gradient rings too where their z-gradient variants are
// (HasZDiff, HasVoxelZ; each alone at one face), and two frames back to
// back: golden's image and accumulators, every sample, z difference and
// gradient checked as it leaves, the cycles the cycle model's (one pass
// more than the 12-neighbourhood's stream) at every level.
TEST(SystemPerspective, VoxelDifferenceZGradientClockedFromEveryFace) {
  for (const char* eye : kEyes) {
    std::string json = scene(eye);
    json.insert(1, R"("z_gradient": "voxel_differences", )");
    const test::Setup s = setup(json);
    const golden::Registers& r = s.host.regs;
    ASSERT_EQ(r.z_gradient, golden::ZGradient::VoxelDifferences);
    golden::FixedOptions opt;
    opt.accumulators = true;
    golden::RenderStats stats;
    opt.stats = &stats;
    const golden::BasePlane want = golden::render_fixed(s.volume, r, opt);
    opt.stats = nullptr;
    // Not the 12-neighbourhood's image: the z gradient chosen shows.
    golden::Registers twelve = r;
    twelve.z_gradient = golden::ZGradient::Abc;
    EXPECT_FALSE(golden::render_fixed(s.volume, twelve, opt).rgba == want.rgba) << eye;
    golden::Registers parallel_stream = twelve;
    EXPECT_EQ(sysc::frame_cycles(r, 4).stream,
              sysc::frame_cycles(parallel_stream, 4).stream + static_cast<uint64_t>(r.dim[1]) * ((r.dim[0] + 3) / 4));
    for (int p : {1, 4, 5}) {
      SCOPED_TRACE(std::string("eye ") + eye + ", p = " + std::to_string(p));
      sysc::SystemConfig cfg = clocked_config(p, false);
      cfg.accumulators = true;
      expect_clocked_plane(want, expect_clocked(s, cfg, want, stats));
      if (!rtl_perspective(p)) continue;
      cfg.levels[static_cast<size_t>(sysc::Unit::Shade)] = sysc::Level::Rtl;
      cfg.levels[static_cast<size_t>(sysc::Unit::Composite)] = sysc::Level::Rtl;
      cfg.levels[static_cast<size_t>(sysc::Unit::Addr)] = sysc::Level::Rtl;
      {
        SCOPED_TRACE("shading, compositing and address generation at RTL");
        expect_clocked_plane(want, expect_clocked(s, cfg, want, stats));
      }
      if (!has(sysc::rtl_persp_zdiff_pipes(), p)) continue;
      if (eye == kEyes[0])
        for (const sysc::Unit ring : {sysc::Unit::Interp, sysc::Unit::Gradient}) {
          sysc::SystemConfig alone = clocked_config(p, false);
          alone.accumulators = true;
          alone.levels[static_cast<size_t>(ring)] = sysc::Level::Rtl;
          SCOPED_TRACE(std::string(sysc::unit_name(ring)) + " ring alone at RTL");
          expect_clocked_plane(want, expect_clocked(s, alone, want, stats));
        }
      cfg.levels[static_cast<size_t>(sysc::Unit::Interp)] = sysc::Level::Rtl;
      cfg.levels[static_cast<size_t>(sysc::Unit::Gradient)] = sysc::Level::Rtl;
      SCOPED_TRACE("every unit at RTL");
      expect_clocked_plane(want, expect_clocked(s, cfg, want, stats));
      if (p != 4) continue;
      cfg.frames = 2;
      expect_clocked_plane(want, expect_clocked(s, cfg, want, stats));
    }
  }
}

// The SystemC schedule (a process for the stream former and one for the
// unit, on the machine's clock) and the plain loop give the same frames:
// image, beats, the last beat's and last sample's cycles and the cycles
// simulated, for one frame and two back to back, with the unit at clocked
// TLM and RTL. A parallel frame between two perspective ones (the machine's
// top runs on the same clock while the perspective top waits) and a frame
// after one that failed in a process (a throwing progress callback) run as
// they would alone.
TEST(SystemPerspective, SystemCAndThePlainLoopClockTheSameFrames) {
  const test::Setup s = setup(scene(kEyes[4]));
  golden::RenderStats stats;
  const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, &stats);
  for (const bool rtl : {false, true}) {
    if (rtl && !rtl_perspective(5)) continue;
    for (const int frames : {1, 2}) {
      SCOPED_TRACE(std::string(rtl ? "RTL" : "clocked TLM") + ", frames " + std::to_string(frames));
      sysc::SystemConfig cfg = clocked_config(5, rtl);
      cfg.frames = frames;
      cfg.kernel = sysc::Kernel::PlainLoop;
      const sysc::SystemResult plain = sysc::run_frame(s.host.regs, s.volume, cfg);
      cfg.kernel = sysc::Kernel::SystemC;
      expect_clocked(s, cfg, want, stats);
      const sysc::SystemResult sc = sysc::run_frame(s.host.regs, s.volume, cfg);
      ASSERT_FALSE(plain.mismatch);
      ASSERT_FALSE(sc.mismatch);
      expect_plane(plain.plane, sc.plane);
      EXPECT_EQ(sc.last_beat, plain.last_beat);
      EXPECT_EQ(sc.simulated_cycles, plain.simulated_cycles);
      EXPECT_EQ(sc.frame_cycles, plain.frame_cycles);
    }
  }
  // A parallel frame on the machine's top between perspective ones.
  const test::Setup par = setup(R"({"volume": {"synthetic": "sphere", "size": [21, 17, 13]}, "shading": true,
      "output": {"width": 48, "height": 48}})");
  ASSERT_FALSE(par.host.regs.perspective);
  const sysc::SystemResult pr = sysc::run_frame(par.host.regs, par.volume, clocked_config(4, false));
  EXPECT_FALSE(pr.mismatch);
  expect_plane(golden::render_fixed(par.volume, par.host.regs), pr.plane);
  // A frame whose unit fails in its process, then one that runs.
  struct Failing final : sysc::PerspInterpIf {
    void clock(const sysc::VoxelBeat&, sysc::RaySampleBeat&) override {
      if (++clocks == 100) throw std::runtime_error("the unit failed");
    }
    sysc::Level level() const override { return sysc::Level::Tlm; }
    int clocks = 0;
  } failing;
  const sysc::FramePlan plan(s.host.regs, 4);
  sysc::VoxelMemory mem(s.volume, 4);
  sysc::TlmAddr addr(mem.layout(), golden::SkewTraversal{s.host.regs.perm, s.host.regs.flip});
  sysc::StreamFormer former(plan, mem, addr, 1);
  const sysc::PerspectiveFrameInput in{plan, s.volume, 1, false, false, nullptr, {}, nullptr, sysc::Kernel::SystemC};
  EXPECT_THROW(sysc::run_perspective_frame(in, former, failing), std::runtime_error);
  EXPECT_EQ(failing.clocks, 100);
  expect_clocked(s, clocked_config(4, false), want, stats);
}

// The clocked TLM unit is the ring, beat by beat: the same stream through
// both, every output beat compared (lanes, samples, rays, tags), over two
// frames of several views.
TEST(SystemPerspective, TheClockedTlmInterpolationUnitIsTheRingBeatByBeat) {
  if (!rtl_perspective(4) || !rtl_perspective(5)) GTEST_SKIP() << "no RTL perspective ring at p = 4 and 5";
#if CUBE4_TEST_RTL
  long compared = 0;
  for (int view = 0; view < 4; ++view) {
    const test::Setup s = setup(scene(kEyes[view]));
    for (int p : {4, 5}) {
      SCOPED_TRACE("eye " + std::string(kEyes[view]) + ", p = " + std::to_string(p));
      const sysc::FramePlan plan(s.host.regs, p);
      sysc::VoxelMemory mem(s.volume, p);
      sysc::TlmAddr addr(mem.layout(), golden::SkewTraversal{s.host.regs.perm, s.host.regs.flip});
      sysc::StreamFormer former(plan, mem, addr, 2);
      rtl::ScopedVerilatedContext ctx(1, false, true);
      auto ring = sysc::make_rtl_interp_persp(plan, *ctx, sysc::TraceWindow{});
      sysc::TlmInterpPersp tlm(plan);
      sysc::RaySampleBeat a, b;
      int drain = 0;
      for (int cycle = 0; drain < 8; ++cycle) {
        const sysc::VoxelBeat in = former.done() ? sysc::VoxelBeat{} : former.next();
        ring->clock(in, a);
        tlm.clock(in, b);
        ASSERT_EQ(std::make_tuple(a.valid, a.step), std::make_tuple(b.valid, b.step)) << "cycle " << cycle;
        // The step's control, which the gradient ring takes with the samples.
        if (a.step >= 0) {
          ASSERT_EQ(std::make_tuple(a.f.beam_start, a.f.beam_end, a.f.slice_start, a.f.slice_end, a.f.flush, a.pass_tag),
                    std::make_tuple(b.f.beam_start, b.f.beam_end, b.f.slice_start, b.f.slice_end, b.f.flush, b.pass_tag))
              << "cycle " << cycle;
        }
        for (int k = 0; k < p; ++k) {
          if (!(a.valid >> k & 1)) continue;
          const auto i = static_cast<size_t>(k);
          ASSERT_EQ(std::make_tuple(a.sample[i], a.u[i], a.v[i], a.tag[i]),
                    std::make_tuple(b.sample[i], b.u[i], b.v[i], b.tag[i]))
              << "cycle " << cycle << ", lane " << k;
          ++compared;
        }
        if (former.done()) ++drain;  // the ring's last samples leave within its 4 cycles
      }
    }
  }
  EXPECT_GT(compared, 10000);
#endif
}

// A unit whose output is wrong: the checker names the first sample (or
// gradient) that differs (its slice and ray), and a ray that never leaves.
// Faulty<Inner> drops, or spoils with `spoil`, the first lane of slice
// `slice` that the clocked TLM unit Inner gives.
namespace {
template <class Inner>
class Faulty final : public Inner::Interface {
 public:
  using In = typename Inner::In;
  using Out = typename Inner::Out;
  Faulty(const sysc::FramePlan& plan, bool drop, uint32_t slice, void (*spoil)(Out&, size_t))
      : inner_(plan), drop_(drop), slice_(slice), spoil_(spoil) {}
  void clock(const In& in, Out& out) override {
    inner_.clock(in, out);
    for (int k = 0; k < 16 && !done_; ++k)
      if (out.valid >> k & 1 && out.tag[static_cast<size_t>(k)] == slice_) {
        if (drop_) out.valid &= ~(1u << k);
        else spoil_(out, static_cast<size_t>(k));
        u_ = out.u[static_cast<size_t>(k)];
        v_ = out.v[static_cast<size_t>(k)];
        done_ = true;
      }
  }
  sysc::Level level() const override { return sysc::Level::Tlm; }
  int64_t u_ = 0, v_ = 0;
  bool done_ = false;

 private:
  typename Inner::Unit inner_;
  bool drop_;
  uint32_t slice_;
  void (*spoil_)(Out&, size_t);
};
struct InterpUnit {
  using Interface = sysc::PerspInterpIf;
  using Unit = sysc::TlmInterpPersp;
  using In = sysc::VoxelBeat;
  using Out = sysc::RaySampleBeat;
};
struct GradientUnit {
  using Interface = sysc::PerspGradientIf;
  using Unit = sysc::TlmGradientPersp;
  using In = sysc::RaySampleBeat;
  using Out = sysc::RayGradientBeat;
};
void flip_sample(sysc::RaySampleBeat& b, size_t lane) { b.sample[lane] ^= 1; }
void flip_gradient(sysc::RayGradientBeat& b, size_t lane) { b.gy[lane] ^= 2; }
}  // namespace

TEST(SystemPerspective, TheCheckNamesAWrongOrMissingSampleBySliceAndRay) {
  const test::Setup s = setup(scene(kEyes[1]));
  for (const bool drop : {false, true}) {
    SCOPED_TRACE(drop ? "dropped" : "flipped");
    const sysc::FramePlan plan(s.host.regs, 4);
    sysc::VoxelMemory mem(s.volume, 4);
    sysc::TlmAddr addr(mem.layout(), golden::SkewTraversal{s.host.regs.perm, s.host.regs.flip});
    sysc::StreamFormer former(plan, mem, addr, 1);
    Faulty<InterpUnit> unit(plan, drop, 3, flip_sample);
    const sysc::PerspectiveFrameResult res = sysc::run_perspective_frame({plan, s.volume, 1, true, false, nullptr, {}}, former, unit);
    ASSERT_TRUE(unit.done_);
    ASSERT_TRUE(res.mismatch);
    EXPECT_EQ(res.mismatch->unit, sysc::Unit::Interp);
    EXPECT_EQ(res.mismatch->slice, 3);
    EXPECT_EQ(res.mismatch->x, unit.u_);
    EXPECT_EQ(res.mismatch->y, unit.v_);
    if (drop) {
      EXPECT_EQ(res.mismatch->got, "0 time(s)");
    }
    // Without the check the same frame is an error, not an image.
    sysc::VoxelMemory mem2(s.volume, 4);
    sysc::TlmAddr addr2(mem2.layout(), golden::SkewTraversal{s.host.regs.perm, s.host.regs.flip});
    sysc::StreamFormer former2(plan, mem2, addr2, 1);
    Faulty<InterpUnit> unit2(plan, drop, 3, flip_sample);
    if (drop) {
      EXPECT_THROW(sysc::run_perspective_frame({plan, s.volume, 1, false, false, nullptr, {}}, former2, unit2), std::logic_error);
    }
  }
}

// Likewise a gradient unit whose output is wrong: the check names the
// first gradient that differs from golden's of the interpolation unit's
// samples, and a ray whose gradient never leaves.
TEST(SystemPerspective, TheCheckNamesAWrongOrMissingGradientBySliceAndRay) {
  const test::Setup s = setup(scene(kEyes[2]));
  ASSERT_TRUE(s.host.regs.gradient);
  for (const bool drop : {false, true})
    for (const bool check : {true, false}) {
      SCOPED_TRACE(std::string(drop ? "dropped" : "flipped") + (check ? ", checked" : ", unchecked"));
      const sysc::FramePlan plan(s.host.regs, 4);
      sysc::VoxelMemory mem(s.volume, 4);
      sysc::TlmAddr addr(mem.layout(), golden::SkewTraversal{s.host.regs.perm, s.host.regs.flip});
      sysc::StreamFormer former(plan, mem, addr, 1);
      sysc::TlmInterpPersp interp(plan);
      Faulty<GradientUnit> unit(plan, drop, 4, flip_gradient);
      const sysc::PerspectiveFrameInput in{plan, s.volume, 1, check, false, nullptr, {}};
      if (!check) {
        // Unchecked, a missing gradient is still an error, not an image; a
        // wrong one goes into it.
        if (drop) EXPECT_THROW(sysc::run_perspective_frame(in, former, interp, &unit), std::logic_error);
        else EXPECT_NO_THROW(sysc::run_perspective_frame(in, former, interp, &unit));
        continue;
      }
      const sysc::PerspectiveFrameResult res = sysc::run_perspective_frame(in, former, interp, &unit);
      ASSERT_TRUE(unit.done_);
      ASSERT_TRUE(res.mismatch);
      EXPECT_EQ(res.mismatch->unit, sysc::Unit::Gradient);
      EXPECT_EQ(res.mismatch->slice, 4);
      EXPECT_EQ(res.mismatch->x, unit.u_);
      EXPECT_EQ(res.mismatch->y, unit.v_);
      if (drop) EXPECT_EQ(res.mismatch->got, "0 time(s)");
      else EXPECT_NE(res.mismatch->got.find("gradient ("), std::string::npos) << res.mismatch->got;
    }
}

// The system's RTL weight generator (cube4_dda, its divisions included)
// gives every slice golden's constants (its z weights too), for views from each face; a wrong constant in the
// plan the unit runs with is caught by the frame's check, which keeps
// golden's slices.
TEST(SystemPerspective, TheRtlWeightGeneratorGivesGoldensSlicesAndAWrongOneIsCaught) {
  const auto fields = [](const golden::PerspectiveSlice& s) {
    return std::vector<int64_t>{s.k, s.z_voxel, s.wz, s.spacing, s.ray0_x, s.ray0_y, s.rays_x.lo, s.rays_x.hi,
                                s.rays_y.lo, s.rays_y.hi, static_cast<int64_t>(s.box_reciprocal),
                                s.lateral_reciprocal, s.behind_x.start, s.behind_x.step, s.behind_y.start,
                                s.behind_y.step, s.ahead_x.start, s.ahead_x.step, s.ahead_y.start, s.ahead_y.step};
  };
#if CUBE4_TEST_RTL
  {
    for (const char* eye : kEyes) {
      const test::Setup s = setup(scene(eye));
      rtl::ScopedVerilatedContext ctx(1, false, true);
      const std::vector<golden::PerspectiveSlice> got = sysc::rtl_perspective_slices(s.host.regs, *ctx);
      ASSERT_EQ(got.size(), static_cast<size_t>(s.host.regs.sample_slices())) << eye;
      for (int k = 0; k < s.host.regs.sample_slices(); ++k)
        EXPECT_EQ(fields(got[static_cast<size_t>(k)]), fields(golden::perspective_slice(s.host.regs, k)))
            << "eye " << eye << ", slice " << k;
    }
  }
#else
  (void)fields;
#endif
  const test::Setup s = setup(scene(kEyes[2]));
  std::vector<golden::PerspectiveSlice> wrong;
  for (int k = 0; k < s.host.regs.sample_slices(); ++k) wrong.push_back(golden::perspective_slice(s.host.regs, k));
  wrong[5].ray0_x += int64_t{1} << (s.host.regs.p.dda_frac_bits - 2);  // a quarter voxel
  const sysc::FramePlan plan(s.host.regs, 4, sysc::kUserTagBits, 0, {}, wrong);
  sysc::VoxelMemory mem(s.volume, 4);
  sysc::TlmAddr addr(mem.layout(), golden::SkewTraversal{s.host.regs.perm, s.host.regs.flip});
  sysc::StreamFormer former(plan, mem, addr, 1);
  sysc::TlmInterpPersp unit(plan);
  const sysc::PerspectiveFrameResult res =
      sysc::run_perspective_frame({plan, s.volume, 1, true, false, nullptr, {}}, former, unit);
  ASSERT_TRUE(res.mismatch);
  EXPECT_EQ(res.mismatch->unit, sysc::Unit::Interp);
  EXPECT_EQ(res.mismatch->slice, 5);
}

TEST(SystemPerspective, FramesOutsideTheRingsPlansAreRefusedNamingWhy) {
  const test::Setup s = setup(scene(kEyes[0]));
  auto refused = [&](const sysc::SystemConfig& cfg, const golden::Registers& r, const std::string& says) {
    try {
      sysc::run_frame(r, s.volume, cfg);
      ADD_FAILURE() << "ran; expected a refusal saying: " << says;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  // The compositing ring's preconditions: a beam of 8 + R positions.
  sysc::SystemConfig composite = clocked_config(4, false);
  composite.levels[static_cast<size_t>(sysc::Unit::Composite)] = sysc::Level::Rtl;
  golden::Registers narrow = s.host.regs;
  narrow.dim[0] = 7;
  refused(composite, narrow, "the RTL perspective compositing ring needs at least 6 rows and 11 positions a beam");  // 8 at p = 4
  // Polygons need the ring's polygon variant: p = 8 has none by default.
  if (CUBE4_TEST_RTL && !has(sysc::rtl_persp_polygon_pipes(), 8)) {
    sysc::SystemConfig at8 = clocked_config(8, false);
    at8.levels[static_cast<size_t>(sysc::Unit::Composite)] = sysc::Level::Rtl;
    try {
      sysc::check_polygon_levels(at8, true);
      ADD_FAILURE() << "polygons accepted at a perspective compositing ring without polygon hardware";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("CUBE4_SYSTEM_POLYGON_PIPES"), std::string::npos) << e.what();
    }
  }
  // The gradient ring's preconditions, named with what to do instead:
  // five rows (a slice's neighbours would not be within its four stores).
  sysc::SystemConfig gradient = clocked_config(4, false);
  gradient.levels[static_cast<size_t>(sysc::Unit::Gradient)] = sysc::Level::Rtl;
  golden::Registers short_rows = s.host.regs;
  short_rows.dim[1] = 5;
  refused(gradient, short_rows, "the RTL perspective gradient ring needs at least 6 rows");
  // Rays that move four cells a slice (every ray drifts by x_step), beyond
  // the compositing ring's reach, at any clocked level.
  golden::Registers drifting = s.host.regs;
  drifting.x_step += int64_t{4} << drifting.p.dda_frac_bits;
  refused(clocked_config(4, false), drifting, "more than the perspective compositing ring's reach 3");
  // VolumePro's z gradient needs the rings' z-gradient variants: refused
  // by name at a p with the perspective rings but not those (p = 5 by
  // default), and with voxel tags (no ring has both).
  golden::Registers zdiff = s.host.regs;
  zdiff.gradient = true;
  zdiff.z_gradient = golden::ZGradient::VoxelDifferences;
  for (const sysc::Unit ring : {sysc::Unit::Interp, sysc::Unit::Gradient}) {
    if (!CUBE4_TEST_RTL) break;
    for (const int p : sysc::rtl_persp_pipes()) {
      if (has(sysc::rtl_persp_zdiff_pipes(), p)) continue;
      sysc::SystemConfig cfg = clocked_config(p, false);
      cfg.levels[static_cast<size_t>(ring)] = sysc::Level::Rtl;
      refused(cfg, zdiff, "CUBE4_SYSTEM_PERSP_PIPES and CUBE4_SYSTEM_ZDIFF_PIPES");
      break;
    }
    golden::Registers tagged_zdiff = zdiff;
    tagged_zdiff.p.tag_bits = 2;
    sysc::SystemConfig cfg = clocked_config(4, false);
    cfg.levels[static_cast<size_t>(ring)] = sysc::Level::Rtl;
    refused(cfg, tagged_zdiff, "no RTL perspective interpolation and gradient rings have both");
  }
  if (CUBE4_TEST_RTL) {
    refused(clocked_config(2, true), s.host.regs, "CUBE4_SYSTEM_PERSP_PIPES");
    sysc::SystemConfig gradient_p2 = clocked_config(2, false);
    gradient_p2.levels[static_cast<size_t>(sysc::Unit::Gradient)] = sysc::Level::Rtl;
    refused(gradient_p2, s.host.regs, "CUBE4_SYSTEM_PERSP_PIPES");
    // Tags need the ring's tag variant: p = 5 has the ring but no tag variant.
    golden::Registers tagged = s.host.regs;
    tagged.p.tag_bits = 2;
    refused(clocked_config(5, true), tagged, "CUBE4_SYSTEM_TAG_PIPES");
  }
}
