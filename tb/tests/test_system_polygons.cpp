// System tests of Cube-5's polygons (ctest label `system`): scenes with
// meshes through the system model at transaction level, loosely timed and
// clocked beat by beat, bit-exact against golden render_fixed() with the
// same polygon frame (base plane and final image), at p = 1, 4 and 5, from
// all six base planes; the polygons cost the model no cycle; an empty list
// or a mesh that draws nothing changes nothing; a unit at RTL refuses them.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "golden/polygons.hpp"
#include "golden/renderers.hpp"
#include "systemc/core/machine.hpp"
#include "systemc/core/polygon_source.hpp"
#include "systemc/core/system.hpp"
#include "tb/tests/system_support.hpp"
#include "tb/tests/test_support.hpp"

namespace {

using namespace cube4;
using namespace cube4::test;
using sysc::Level;

// A scene as the host programs it, with its polygon frame.
struct Hybrid {
  Setup s;
  golden::PolygonFrame frame;
  const golden::PolygonFrame* polygons() const { return s.meshes.empty() ? nullptr : &frame; }
};
Hybrid hybrid(Setup s) {
  Hybrid h{std::move(s), {}};
  if (!h.s.meshes.empty()) h.frame = golden::rasterise_polygons(h.s.scene, h.s.meshes, h.s.host);
  return h;
}

golden::BasePlane golden_plane(const Hybrid& h, const golden::PolygonFrame* polygons) {
  golden::FixedOptions opt;
  opt.polygons = polygons;
  return golden::render_fixed(h.s.volume, h.s.host.regs, opt);
}

void expect_same_plane(const golden::BasePlane& want, const golden::BasePlane& got) {
  ASSERT_EQ(got.width, want.width);
  ASSERT_EQ(got.height, want.height);
  size_t bad = 0, first = 0;
  for (size_t i = 0; i < want.rgba.size(); ++i)
    if (got.rgba[i] != want.rgba[i] && bad++ == 0) first = i;
  EXPECT_EQ(bad, 0u) << "first differing channel value at pixel (" << first / 4 % static_cast<size_t>(want.width)
                     << ", " << first / 4 / static_cast<size_t>(want.width) << ") channel " << first % 4
                     << ": expected " << want.rgba[first] << ", got " << got.rgba[first];
}

sysc::SystemConfig tlm_config(int p, bool cycle_level) {
  sysc::SystemConfig cfg;
  cfg.p = p;
  cfg.levels = kTlm;
  cfg.cycle_level = cycle_level;
  cfg.check = cycle_level;  // every unit's stream against golden's
  return cfg;
}

// A hybrid frame's cycles: the volume-only frame's plus the waits for slab
// images, which are what the polygon source's schedule gives for passes
// streamed back to back (so the clocked and RTL runs, whose waits are gaps
// in a simulated stream, are held to the analytic count, and the loosely
// timed run is that count).
void expect_polygon_cycles(const Hybrid& h, const sysc::SystemConfig& cfg, const sysc::SystemResult& res) {
  const golden::Registers& regs = h.s.host.regs;
  const sysc::CycleCount cc = sysc::frame_cycles(regs, cfg.p);
  const sysc::FramePlan plan(regs, cfg.p);
  sysc::PolygonSource source(plan, golden::polygon_work(h.frame), cfg.polygon_engine, cfg.clock_hz);
  const uint64_t waits = source.stalls_of_frame(plan.pass_beats());
  EXPECT_EQ(res.polygon_stall_cycles, waits) << sysc::polygon_connection_name(cfg.polygon_engine.connection);
  EXPECT_EQ(res.stream_cycles, cc.stream + waits);
  if (cfg.all_tlm() && !cfg.cycle_level) {
    EXPECT_EQ(res.frame_cycles, cc.latency + waits) << "the cycle model's count and the waits";
    return;
  }
  EXPECT_EQ(res.last_beat[0], cc.stream + cc.flush + waits) << "voxel beats per frame and the gaps of the waits";
  const sysc::SystemResult volume_only = sysc::run_frame(regs, h.s.volume, cfg);
  EXPECT_EQ(res.frame_cycles, volume_only.frame_cycles + waits) << "the simulated frame: the volume's and the waits";
}

// One frame of the scene through the system at TLM: base plane and final
// image equal golden's with the polygons; the cycles are the volume-only
// frame's (the cycle model's when loosely timed, the clocked run's own
// count without the polygons when clocked).
void run_hybrid(const Hybrid& h, int p, bool cycle_level,
                golden::PolygonConnection connection = golden::PolygonConnection::Rle) {
  SCOPED_TRACE("p = " + std::to_string(p) + (cycle_level ? ", clocked" : ", loosely timed") + ", connection " +
               sysc::polygon_connection_name(connection));
  const golden::Registers& regs = h.s.host.regs;
  sysc::SystemConfig cfg = tlm_config(p, cycle_level);
  cfg.polygon_engine.connection = connection;
  const sysc::SystemResult res = sysc::run_frame(regs, h.s.volume, cfg, {}, h.polygons());
  const golden::BasePlane want = golden_plane(h, h.polygons());
  expect_same_plane(want, res.plane);
  EXPECT_FALSE(res.mismatch) << res.mismatch->describe();
  const golden::ImageF want_image = golden::warp(want.to_float(), want.shift_x, want.shift_y, h.s.host.view);
  const golden::ImageF got_image =
      golden::warp(res.plane.to_float(), res.plane.shift_x, res.plane.shift_y, h.s.host.view);
  EXPECT_TRUE(got_image.rgba == want_image.rgba) << "the final images differ";
  // The polygons must show: the image differs from the volume-only one.
  if (h.polygons() && h.frame.counts.opaque + h.frame.counts.translucent > 0) {
    EXPECT_NE(golden_plane(h, nullptr).rgba, want.rgba) << "the test's polygons draw nothing";
  }
  expect_polygon_cycles(h, cfg, res);
}

Hybrid scene_file(const std::string& name) { return hybrid(setup_file(std::string(CUBE4_SOURCE_DIR) + "/scenes/" + name)); }

// A small shaded sphere, a translucent box around it crossing the volume's
// faces, an opaque needle through it, a translucent sphere in front and a
// translucent plate beside the volume (margins).
std::string small_scene(const std::string& direction, const std::string& up, const std::string& polygons) {
  return R"({"volume": {"synthetic": "sphere", "size": [13, 11, 9]},
      "view": {"direction": )" + direction + R"(, "up": )" + up + R"(},
      "output": {"width": 48, "height": 48}, "supersampling": 2, "shading": true, )" + std::string(kTransfer) +
         R"(, "polygons": )" + polygons + "}";
}
const char* kMeshes = R"([
    {"shape": "box", "size": [11, 9, 7], "transform": {"translate": [6, 5, 4], "rotate": [10, 20, 0]},
     "color": [0.2, 0.5, 1], "opacity": 0.3},
    {"shape": "needle", "radius": 1, "length": 20, "transform": {"translate": [-3, 5, 4], "rotate": [0, 80, 10]},
     "color": [0.9, 0.9, 0.9]},
    {"shape": "sphere", "radius": 2.5, "segments": 12, "rings": 6, "transform": {"translate": [6, 5, -3]},
     "color": [1, 0.3, 0.2], "opacity": 0.5, "lit": false},
    {"shape": "box", "size": [3, 3, 1], "transform": {"translate": [-4, 5, 4]}, "color": [0, 1, 0], "opacity": 0.6}])";

const char* const kDirections[6] = {"[0.2, 0.1, 1]", "[-0.2, 0.1, -1]", "[1, 0.15, 0.2]",
                                    "[-1, 0.15, -0.2]", "[0.1, 1, 0.25]", "[0.1, -1, -0.25]"};
std::string up_for(const std::string& direction) { return direction.find("0.1, ") == 1 ? "[1, 0, 0]" : "[0, 1, 0]"; }

}  // namespace

// The scenes of scenes/ with polygons, loosely timed, p = 1, 4, 5.
TEST(SystemPolygons, BrainProbeTlm) {
  const Hybrid h = scene_file("brain_probe.json");
  for (int p : {1, 4, 5}) run_hybrid(h, p, false);
}
TEST(SystemPolygons, BrainProbeTranslucentTlm) {
  const Hybrid h = scene_file("brain_probe_translucent.json");
  for (int p : {1, 4, 5}) run_hybrid(h, p, false);
}
TEST(SystemPolygons, SphereBoxTlm) {
  const Hybrid h = scene_file("sphere_box.json");
  for (int p : {1, 4, 5}) run_hybrid(h, p, false);
}
// A scene clocked beat by beat: the per-unit TLM compositing unit draws them.
// Its box's faces put more into a slab than a slice's time draws, so both
// connections wait; the ideal one does not.
TEST(SystemPolygons, SphereBoxTlmClockedP4) {
  const Hybrid h = scene_file("sphere_box.json");
  for (const auto c : {golden::PolygonConnection::Rle, golden::PolygonConnection::Dual, golden::PolygonConnection::Ideal})
    run_hybrid(h, 4, true, c);
}

// The polygon source's schedule on loads made up to be worked by hand: three
// slabs, 100-cycle passes, the engine's rates in cycles of a 1 Hz clock.
TEST(SystemPolygons, PolygonSourceSchedulesTheTwoConnections) {
  const Hybrid h = hybrid(setup(small_scene(kDirections[0], up_for(kDirections[0]), "[]")));
  golden::Registers regs = h.s.host.regs;
  golden::PolygonEngine e;
  e.fill_rate = 1;         // a fragment a cycle
  e.triangle_rate = 1e9;   // never the bound
  e.dual_fill_rate = 2;    // two pixels a cycle
  e.rle_clock_hz = 1e9;    // copying never the bound
  golden::PolygonWork work;
  work.slabs.resize(static_cast<size_t>(regs.sample_slices()));
  const uint64_t fragments[3] = {150, 20, 300};
  for (int k = 0; k < 3; ++k) work.slabs[static_cast<size_t>(k)].fragments = fragments[k];
  work.opaque_fragments = 40;
  const sysc::FramePlan plan(regs, 4);
  ASSERT_EQ(plan.passes, plan.K + 1) << "the scene runs the gradient unit: slice k composites in pass k + 1";
  {  // Rle: slabs 0 and 1 drawn from the start (150, then 170); pass 1 (slice 0) due at 100 waits to 150;
     // slice 1 due at 250 (drawn at 170); slab 2 then goes into slab 0's half: drawn 250 + 300 = 550;
     // slice 2 due at 350 waits to 550.
    e.connection = golden::PolygonConnection::Rle;
    sysc::PolygonSource s(plan, work, e, 1.0);
    EXPECT_EQ(s.release(0, 0), 0u);
    EXPECT_EQ(s.release(1, 100), 150u);
    EXPECT_EQ(s.release(2, 250), 250u);
    EXPECT_EQ(s.release(3, 350), 550u);
    EXPECT_EQ(s.stall_cycles(), 250u);
  }
  {  // Dual: the opaque polygons (20 cycles) before the frame, each slab (75, 10, 150) before its slice.
    e.connection = golden::PolygonConnection::Dual;
    sysc::PolygonSource s(plan, work, e, 1.0);
    EXPECT_EQ(s.release(0, 0), 20u);
    EXPECT_EQ(s.release(1, 120), 195u);
    EXPECT_EQ(s.release(2, 295), 305u);
    EXPECT_EQ(s.release(3, 405), 555u);
    EXPECT_EQ(s.stall_cycles(), 20u + 75u + 10u + 150u);
  }
  e.connection = golden::PolygonConnection::Ideal;
  EXPECT_EQ(sysc::PolygonSource(plan, work, e, 1.0).stalls_of_frame(100), 0u);
}

// Every base plane, p = 1, 4, 5, loosely timed and clocked.
class PolygonBasePlanes : public ::testing::TestWithParam<int> {};
TEST_P(PolygonBasePlanes, TlmLooselyTimedAndClocked) {
  const std::string d = kDirections[GetParam()];
  const Hybrid h = hybrid(setup(small_scene(d, up_for(d), kMeshes)));
  EXPECT_GT(h.frame.counts.opaque, 0u);
  EXPECT_GT(h.frame.counts.in_slabs, 0u);
  EXPECT_GT(h.s.host.regs.margin_lo[0] + h.s.host.regs.margin_lo[1] + h.s.host.regs.margin_hi[0] +
                h.s.host.regs.margin_hi[1],
            0)
      << "polygons beside the volume: the base plane has margins";
  for (int p : {1, 4, 5})
    for (bool clocked : {false, true}) run_hybrid(h, p, clocked);
  run_hybrid(h, 4, true, golden::PolygonConnection::Dual);
}
INSTANTIATE_TEST_SUITE_P(SystemPolygons, PolygonBasePlanes, ::testing::Range(0, 6));

// No list, an empty list, a mesh that draws nothing (its polygon frame
// taken, blank): the volume-only image, loosely timed and clocked.
TEST(SystemPolygons, EmptyOrInvisiblePolygonsGiveTheVolumeOnlyImage) {
  const std::string d = kDirections[0];
  const std::string plain = small_scene(d, up_for(d), "[]");
  const test::Setup none = setup(plain.substr(0, plain.rfind(", \"polygons\"")) + "}");
  const golden::BasePlane want = golden::render_fixed(none.volume, none.host.regs);
  const Hybrid empty = hybrid(setup(plain));
  ASSERT_EQ(empty.polygons(), nullptr);
  const Hybrid invisible = hybrid(setup(small_scene(
      d, up_for(d), R"([{"shape": "box", "size": [20, 20, 20], "transform": {"translate": [6, 5, 4]}, "opacity": 0}])")));
  ASSERT_NE(invisible.polygons(), nullptr);
  for (int p : {1, 4, 5})
    for (bool clocked : {false, true}) {
      SCOPED_TRACE("p = " + std::to_string(p) + (clocked ? ", clocked" : ", loosely timed"));
      expect_same_plane(want, sysc::run_frame(empty.s.host.regs, empty.s.volume, tlm_config(p, clocked)).plane);
      expect_same_plane(want, sysc::run_frame(invisible.s.host.regs, invisible.s.volume, tlm_config(p, clocked), {},
                                              invisible.polygons())
                                  .plane);
    }
}

// Any unit at RTL refuses polygons by name (before it needs an RTL build).
TEST(SystemPolygons, RtlCompositingWithoutPolygonHardwareRefuses) {
  if (!CUBE4_TEST_RTL) GTEST_SKIP() << "a build without RTL (which refuses every RTL unit)";
  // p = 2 has no ring with polygon hardware (CUBE4_SYSTEM_POLYGON_PIPES);
  // the units before the compositor never see the polygons.
  const std::string d = kDirections[0];
  const Hybrid h = hybrid(setup(small_scene(d, up_for(d), kMeshes)));
  sysc::SystemConfig cfg;
  cfg.p = 2;
  cfg.levels = only(sysc::Unit::Composite);
  try {
    sysc::run_frame(h.s.host.regs, h.s.volume, cfg, {}, h.polygons());
    ADD_FAILURE() << "a frame with polygons ran on a ring without polygon hardware";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("polygon hardware"), std::string::npos) << e.what();
  }
}

// The RTL compositing ring with polygon hardware in the system: the small
// scene from all six base planes at p = 1, 4, 5, every unit at RTL and the
// compositor alone at RTL, equal to golden with the polygons, in the
// volume-only frame's cycles.
void run_hybrid_rtl(const Hybrid& scene, int p, const std::array<sysc::Level, sysc::kUnits>& levels,
                    golden::PolygonConnection connection = golden::PolygonConnection::Rle) {
  SCOPED_TRACE("p = " + std::to_string(p) + ", connection " + sysc::polygon_connection_name(connection));
  // The slab images are laid out for the p decoders that read them.
  Hybrid h = scene;
  h.s.scene.pipelines = p;
  h.frame = golden::rasterise_polygons(h.s.scene, h.s.meshes, h.s.host);
  sysc::SystemConfig cfg;
  cfg.p = p;
  cfg.levels = levels;
  cfg.check = true;
  cfg.polygon_engine.connection = connection;
  const sysc::SystemResult res = sysc::run_frame(h.s.host.regs, h.s.volume, cfg, {}, h.polygons());
  expect_same_plane(golden_plane(h, h.polygons()), res.plane);
  EXPECT_FALSE(res.mismatch) << res.mismatch->describe();
  expect_polygon_cycles(h, cfg, res);
}

TEST_P(PolygonBasePlanes, RtlCompositingRing) {
  if (!CUBE4_TEST_RTL) GTEST_SKIP() << "a build without RTL";
  const std::string d = kDirections[GetParam()];
  const Hybrid h = hybrid(setup(small_scene(d, up_for(d), kMeshes)));
  for (int p : {1, 4, 5}) run_hybrid_rtl(h, p, only(sysc::Unit::Composite));
  run_hybrid_rtl(h, 4, kRtl);
  // The dual-use buffer's waits come before every slice: gaps all through
  // the RTL's stream, which must not change a pixel.
  run_hybrid_rtl(h, 4, kRtl, golden::PolygonConnection::Dual);
}

TEST(SystemPolygons, BrainProbeTranslucentRtlP4) {
  if (!CUBE4_TEST_RTL) GTEST_SKIP() << "a build without RTL";
  run_hybrid_rtl(scene_file("brain_probe_translucent.json"), 4, kRtl);
}

// Frames of the view back to back through the RTL compositing ring with
// polygon hardware: each frame's decoders read the same slab lines again
// (they ran out after the first frame until 2026-12-06, an internal error).
// Every stream checked and the last frame's base plane golden's, with the
// 12-neighbourhood and with VolumePro's z gradient (a priming pass before
// each frame).
TEST(SystemPolygons, FramesBackToBackRtl) {
  if (!CUBE4_TEST_RTL) GTEST_SKIP() << "a build without RTL";
  for (const bool voxel_z : {false, true}) {
    SCOPED_TRACE(voxel_z ? "voxel-difference z gradient" : "12-neighbourhood");
    const std::string d = kDirections[0];
    std::string json = small_scene(d, up_for(d), kMeshes);
    if (voxel_z) json.insert(json.size() - 1, R"(, "z_gradient": "voxel_differences")");
    Hybrid h = hybrid(setup(json));
    sysc::SystemConfig cfg;
    cfg.p = 4;
    cfg.levels = kRtl;
    cfg.check = true;
    cfg.frames = 3;
    const sysc::SystemResult res = sysc::run_frame(h.s.host.regs, h.s.volume, cfg, {}, h.polygons());
    EXPECT_FALSE(res.mismatch) << res.mismatch->describe();
    expect_same_plane(golden_plane(h, h.polygons()), res.plane);
    EXPECT_GT(res.measured_interval, 0u);
  }
}

// Through the host interface: registers (the margins too) and volume over
// the bus, the polygon frame handed to the machine; the base plane read
// back over the bus equals golden's with the polygons.
TEST(SystemPolygons, ThroughTheHostInterfaceTlm) {
  if (!sysc::host_interface_available(4))
    GTEST_SKIP() << "this process cannot build the host interface for p = 4 any more (ctest runs each test alone)";
  // The small scene's plate beside the volume: the base plane has margins,
  // which MARGIN_U and MARGIN_V carry.
  const std::string d = kDirections[2];
  const Hybrid h = hybrid(setup(small_scene(d, up_for(d), kMeshes)));
  ASSERT_GT(h.s.host.regs.margin_lo[0] + h.s.host.regs.margin_lo[1] + h.s.host.regs.margin_hi[0] +
                h.s.host.regs.margin_hi[1],
            0);
  const sysc::SystemResult res =
      sysc::render_through_host(h.s.host.regs, h.s.volume, tlm_config(4, false), {}, nullptr, h.polygons());
  expect_same_plane(golden_plane(h, h.polygons()), res.plane);
  // The next frame without polygons is the volume-only one: the machine
  // keeps no frame's polygons.
  const sysc::SystemResult plain = sysc::render_through_host(h.s.host.regs, h.s.volume, tlm_config(4, false), {});
  expect_same_plane(golden_plane(h, nullptr), plain.plane);
  // And brain_probe_translucent, the scene of scenes/.
  const Hybrid probe = scene_file("brain_probe_translucent.json");
  expect_same_plane(golden_plane(probe, probe.polygons()),
                    sysc::render_through_host(probe.s.host.regs, probe.s.volume, tlm_config(4, false), {}, nullptr,
                                              probe.polygons())
                        .plane);
}
