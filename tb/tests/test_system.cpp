// System tests (ctest label `system`): whole frames through the system
// model at every level mix, bit-exact against golden render_fixed(), and
// the frame's cycles at RTL equal to the cycle model's count. Each test
// renders one frame: ctest runs every test in a process of its own, and
// SystemC elaborates once per process.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "systemc/core/machine.hpp"
#include "systemc/host/register_map.hpp"
#include "tb/tests/system_support.hpp"
#include "tb/tests/test_support.hpp"

namespace {

using namespace cube4;
using namespace cube4::test;
using sysc::Level;

// Pipelines.
TEST(System, SphereP1) { run(Case{}, 1, kRtl); }
TEST(System, SphereP4) { run(Case{}, 4, kRtl); }
TEST(System, SphereP5) { run(Case{}, 5, kRtl); }
TEST(System, SphereP8) { run(Case{}, 8, kRtl); }
TEST(System, SphereP2) { run(Case{}, 2, kRtl); }
TEST(System, SphereP16) {
  Case c;
  c.volume = R"({"synthetic": "sphere", "size": [37, 21, 19]})";
  run(c, 16, kRtl);
}
TEST(System, SphereTlmP4) { run(Case{}, 4, kTlm); }
TEST(System, SphereTlmP16) { run(Case{}, 16, kTlm); }
// Every unit's TLM model clocked beat by beat (the models mixed runs use).
TEST(System, SphereTlmCycleLevelP4) { run(Case{}, 4, kTlm, true); }
TEST(System, SphereTlmCycleLevelNoGradientP5) {
  Case c;
  c.effects = R"("shading": false, "blend": "mip")";
  run(c, 5, kTlm, true);
}
// Unchecked clocked TLM skips the gradient and shading of samples that
// cannot change their ray (run() runs it unchecked too): not under MIP,
// where every sample counts, nor past α's modulation and the cut plane.
TEST(System, ClockedTlmSkipsOnlyWhatCannotChangeARay) {
  for (const char* effects :
       {R"("shading": true, "blend": "mip")",
        R"("shading": true, "gradient_modulation": {"opacity": true}, "gm_lut": [[0, 0.2], [1, 1]],)"
        R"( "cut_plane": {"normal": [1, 0.5, 1], "dmin": 5, "dmax": 9, "falloff": 2.5})"}) {
    SCOPED_TRACE(effects);
    Case c;
    c.effects = effects;
    // The highest values transparent: MIP takes them, so their values must
    // stream even where their shading does not.
    c.transfer = R"("transfer": {"color": [[0, 1, 0.2, 0], [1, 0.1, 0, 1]],)"
                 R"( "opacity": [[0, 0.4], [0.5, 0.6], [0.6, 0], [1, 0]]})";
    run(c, 4, kTlm, true);
  }
}
// Every p from 1 to 16 clocked (the TLM models; RTL is built for the p of
// CUBE4_SYSTEM_PIPES, tested above), and loosely timed beyond.
TEST(System, EveryPipelineCountClockedTlm) {
  for (int p = 1; p <= 16; ++p) {
    SCOPED_TRACE("p = " + std::to_string(p));
    Case c;
    c.volume = R"({"synthetic": "noise", "size": [11, 9, 7], "seed": 5})";
    run(c, p, kTlm, true);
  }
}
TEST(System, LargePipelineCountsTlm) {
  for (int p : {17, 32, 64, 128}) run(Case{}, p, kTlm);
}
// The plain C++ schedule (the benchmarks' ceiling) simulates the same machine.
TEST(System, SpherePlainLoopP4) { run(Case{}, 4, kRtl, false, sysc::Kernel::PlainLoop); }
// One thread or two (the shading and compositing units on a thread of
// their own, and at RTL the upper quarter of the pipelines' shading units
// on the first: systemc/core/schedules.hpp), under both kernels: the same
// frames, cycles, streams and reads. The shading units split 3 + 1 at
// p = 4, 4 + 1 at p = 5 and 6 + 2 at p = 8.
TEST(System, TwoThreadsSimulateTheSameFrames) {
  const auto [vol, regs] = program(Case{});
  const std::array<Level, sysc::kUnits> mixed_shade{Level::Tlm, Level::Tlm, Level::Rtl, Level::Tlm, Level::Tlm};
  for (const auto& [levels, p] : {std::pair{kRtl, 4}, std::pair{kRtl, 5}, std::pair{kRtl, 8}, std::pair{mixed_shade, 4},
                                 std::pair{kTlm, 5}})
    for (sysc::Kernel kernel : {sysc::Kernel::SystemC, sysc::Kernel::PlainLoop}) {
      SCOPED_TRACE("p = " + std::to_string(p) + (levels == kRtl ? ", rtl" : levels == kTlm ? ", tlm" : ", mixed:shade") +
                   (kernel == sysc::Kernel::SystemC ? ", SystemC" : ", plain loop"));
      sysc::SystemConfig cfg;
      cfg.p = p;
      cfg.levels = levels;
      cfg.cycle_level = true;
      cfg.check = true;
      cfg.frames = 2;
      cfg.kernel = kernel;
      if (!cfg.all_tlm() && !sysc::rtl_available(p)) continue;
      cfg.threads = 1;
      const sysc::SystemResult one = sysc::run_frame(regs, vol, cfg);
      cfg.threads = 2;
      const sysc::SystemResult two = sysc::run_frame(regs, vol, cfg);
      EXPECT_FALSE(one.mismatch) << one.mismatch->describe();
      EXPECT_FALSE(two.mismatch) << two.mismatch->describe();
      EXPECT_EQ(two.plane.rgba, one.plane.rgba);
      EXPECT_EQ(two.plane.rgba, golden::render_fixed(vol, regs).rgba);
      EXPECT_EQ(two.frame_cycles, one.frame_cycles);
      EXPECT_EQ(two.measured_interval, one.measured_interval);
      EXPECT_EQ(two.simulated_cycles, one.simulated_cycles);
      EXPECT_EQ(two.last_beat, one.last_beat);
      EXPECT_EQ(two.voxel_reads, one.voxel_reads);
    }
}

// The six base planes (p = 5 does not divide any axis: padding everywhere).
class BasePlanes : public ::testing::TestWithParam<const char*> {};
TEST_P(BasePlanes, AllRtlP5) {
  Case c;
  c.volume = R"({"synthetic": "noise", "size": [12, 9, 7], "seed": 3})";
  c.direction = GetParam();
  c.up = std::string(GetParam()).find("0, 1") != std::string::npos ? "[1, 0, 0]" : "[0, 1, 0]";
  run(c, 5, kRtl);
}
INSTANTIATE_TEST_SUITE_P(System, BasePlanes,
                         ::testing::Values("[0.2, 0.1, 1]", "[-0.2, 0.1, -1]", "[1, 0.15, 0.2]", "[-1, 0.15, -0.2]",
                                           "[0.1, 1, 0.25]", "[0.1, -1, -0.25]"));

// Effects.
TEST(System, Mip) { Case c; c.effects = R"("shading": false, "blend": "mip")"; run(c, 4, kRtl); }
TEST(System, MinIp) { Case c; c.effects = R"("shading": false, "blend": "minip")"; run(c, 4, kRtl); }
// An unshaded MIP needs no gradient unit; simulating it anyway changes
// nothing in the image (only the cycles: the zero pass).
TEST(System, MipWithUnneededGradientUnit) {
  Case c;
  c.effects = R"("shading": false, "blend": "mip")";
  run(c, 4, kRtl, false, sysc::Kernel::SystemC, true);
}
// Translucent material (docs/fixed-point.md, "Compositing error"): long rays
// of per-sample α a few LSB of VolumePro's 12 bits, where the accumulator's
// guard bits carry every contribution: RTL equals golden bit for bit.
TEST(System, TranslucentLongRaysRtlP4) {
  for (int S : {1, 4})
    for (const char* effects : {R"("shading": true, "material": {"ke": 0.75, "kd": 0, "ks": 0})",
                                R"("shading": false)"}) {
      Case c;
      c.volume = R"({"synthetic": "constant", "size": [9, 9, 40], "value": 0.5})";
      c.direction = "[0, 0, 1]";
      c.S = S;
      c.transfer = R"("transfer": {"color": [[0, 1, 0.5, 0.1], [1, 1, 0.5, 0.1]], "opacity": [[0, 0.002], [1, 0.002]]})";
      c.effects = effects;
      SCOPED_TRACE(std::string("S = ") + std::to_string(S) + ", " + effects);
      run(c, 4, kRtl);
    }
}

TEST(System, TranslucentCloudRtlP4) {
  Case c;
  c.volume = R"({"synthetic": "field", "field": "gaussian", "size": [16, 14, 12]})";
  c.S = 2;
  c.transfer = R"("transfer": {"color": [[0, 0.7, 0.8, 1], [1, 1, 0.6, 0.3]], "opacity": [[0, 0], [0.05, 0.003], [0.5, 0.003], [0.6, 1], [1, 1]]})";
  run(c, 4, kRtl);
}

TEST(System, ShadingOff) { Case c; c.effects = R"("shading": false)"; run(c, 4, kRtl); }
TEST(System, Specular) {
  Case c;
  c.effects = R"("shading": true, "lights": [{"direction": [0.3, 0.5, 1], "intensity": 0.8}, {"direction": [-1, 0.2, 0.5]}],)"
              R"( "material": {"ks": 0.6, "exponent": 12})";
  run(c, 4, kRtl);
}
TEST(System, GradientModulation) {
  Case c;
  c.effects = R"("shading": true, "gm_lut": [[0, 0.2], [0.5, 1], [1, 1]],)"
              R"( "gradient_modulation": {"opacity": true, "diffuse": true, "specular": true})";
  run(c, 4, kRtl);
}
TEST(System, Supersampling2) { Case c; c.S = 2; run(c, 4, kRtl); }
TEST(System, Cropping) {
  Case c;
  c.effects = R"("shading": true, "cropping": {"x": [2, 8], "y": [1, 9], "combine": "cross"})";
  run(c, 4, kRtl);
}
TEST(System, CutPlane) {
  Case c;
  c.effects = R"("shading": false, "cut_plane": {"normal": [1, 0.5, 1], "dmin": 5, "dmax": 9, "falloff": 2.5})";
  run(c, 4, kRtl);
}

// Every unit alone at RTL, the rest at TLM.
TEST(System, InterpAloneAtRtl) { run(Case{}, 4, only(sysc::Unit::Interp)); }
TEST(System, GradientAloneAtRtl) { run(Case{}, 4, only(sysc::Unit::Gradient)); }
TEST(System, ShadeAloneAtRtl) { run(Case{}, 4, only(sysc::Unit::Shade)); }
TEST(System, CompositeAloneAtRtl) { run(Case{}, 4, only(sysc::Unit::Composite)); }
TEST(System, AddressGenerationAloneAtRtl) {
  Case c;
  c.S = 3;  // slices walked three times: the generator's repeat_slice_i
  run(c, 5, only(sysc::Unit::Addr));
}

// Real data: the MRI head, default view, all RTL (about 350 000 cycles).
TEST(System, BrainsmallAllRtl) {
  Case c;
  c.volume = std::string(R"({"file": ")") + CUBE4_BRAINSMALL + R"("})";
  c.direction = "[0.3, -0.5, 1]";
  run(c, 4, kRtl);
}

}  // namespace

// Cube-4 Table 1's first configuration (64^3, 8 pipelines) at RTL: the
// cycle model that docs/performance.md's Table 1 comparison uses is the
// RTL's count (run() asserts equality). Larger rows: test_system_slow.
namespace {
TEST(System, Table1Row64P8) {
  Case c;
  c.volume = R"({"synthetic": "sphere", "size": [64, 64, 64]})";
  c.direction = "[0, 0, 1]";
  run(c, 8, kRtl);
}
}  // namespace

// Several frames in one process: the SystemC top is elaborated once and each
// frame resumes the kernel (different p, levels and scenes in a row).
namespace {
TEST(System, FramesInARowOneProcess) {
  Case a;
  Case b;
  b.direction = "[-1, 0.2, 0.3]";
  b.effects = R"("shading": false, "blend": "mip")";
  run(a, 4, kRtl);
  run(b, 5, kRtl);
  run(a, 1, only(sysc::Unit::Gradient));
  run(b, 8, kTlm, true);
}
}  // namespace

// --trace: one FST file per verilated unit, holding only the cycle window
// (checked through GTKWave's fst2vcd when it is installed).
namespace {
TEST(System, TraceWritesTheWindowPerUnit) {
  const std::string dir = ::testing::TempDir() + "cube4_trace_test";
  std::filesystem::create_directories(dir);
  const auto [vol, regs] = program(Case{});
  sysc::SystemConfig cfg;
  cfg.p = 4;
  if (!sysc::rtl_available(cfg.p)) GTEST_SKIP() << "no RTL build for p = " << cfg.p;
  cfg.trace.file = dir + "/t.fst";
  cfg.trace.first = 50;
  cfg.trace.last = 60;
  const sysc::SystemResult res = sysc::run_frame(regs, vol, cfg);
  EXPECT_EQ(res.plane.rgba, golden::render_fixed(vol, regs).rgba);
  const bool have_fst2vcd = std::system("command -v fst2vcd >/dev/null 2>&1") == 0;
  for (const char* unit : {"interp", "gradient", "shade0", "composite"}) {
    const std::string f = dir + "/t." + unit + ".fst";
    ASSERT_TRUE(std::filesystem::exists(f)) << f;
    EXPECT_GT(std::filesystem::file_size(f), 0u) << f;
    if (!have_fst2vcd) continue;
    const std::string vcd = dir + "/t.vcd";
    ASSERT_EQ(std::system(("fst2vcd " + f + " > " + vcd + " 2>/dev/null").c_str()), 0) << f;
    std::ifstream in(vcd);
    std::string line;
    long first = -1, last = -1;
    while (std::getline(in, line))
      if (line.size() > 1 && line[0] == '#') {
        const long t = std::stol(line.substr(1));
        if (first < 0) first = t;
        last = t;
      }
    EXPECT_EQ(first, 2 * 50) << f << ": two time steps per cycle (clock low, high), from the window's first cycle";
    EXPECT_EQ(last, 2 * 60 + 1) << f;
  }
}
}  // namespace

// Units whose outputs are all registered are evaluated once a cycle when
// untraced, twice (clock low, then high) when traced
// (systemc/rtl/rtl_model.hpp). The traced run traces every unit but the
// shading units of pipelines 1..p-1, so it mixes both ways in one frame;
// both runs give every unit's stream as golden's (the check compares them
// sample by sample), the same image and cycles.
namespace {
TEST(System, OneEvaluationACycleAsTwo) {
  Case c;
  c.effects = R"("shading": true, "cropping": {"x": [2, 8], "y": [1, 9], "combine": "cross"})";
  const auto [vol, regs] = program(c);
  sysc::SystemConfig cfg;
  cfg.p = 4;
  cfg.check = true;
  if (!sysc::rtl_available(cfg.p)) GTEST_SKIP() << "no RTL build for p = " << cfg.p;
  const sysc::SystemResult once = sysc::run_frame(regs, vol, cfg);
  const std::string dir = ::testing::TempDir() + "cube4_eval_test";
  std::filesystem::create_directories(dir);
  cfg.trace.file = dir + "/t.fst";
  cfg.trace.first = 1;
  cfg.trace.last = 2;
  const sysc::SystemResult twice = sysc::run_frame(regs, vol, cfg);
  EXPECT_FALSE(once.mismatch) << once.mismatch->describe();
  EXPECT_FALSE(twice.mismatch) << twice.mismatch->describe();
  EXPECT_EQ(once.plane.rgba, twice.plane.rgba);
  EXPECT_EQ(once.frame_cycles, twice.frame_cycles);
  EXPECT_EQ(once.plane.rgba, golden::render_fixed(vol, regs).rgba);
}
}  // namespace

// The whole exchange through the TLM-2.0 host interface, as `cube4 render`
// runs it: volume, tables and registers written as transactions, START,
// the base plane read back through the base-plane window.
namespace {
TEST(System, ThroughTheHostInterface) {
  Case c;
  c.effects = R"("shading": true, "cropping": {"x": [2, 8], "y": [1, 9], "combine": "cross"},)"
              R"( "gradient_modulation": {"opacity": true})";
  const auto [vol, regs] = program(c);
  sysc::SystemConfig cfg;
  cfg.p = 5;
  cfg.check = true;
  if (!sysc::rtl_available(cfg.p)) GTEST_SKIP() << "no RTL build for p = " << cfg.p;
  if (!sysc::host_interface_available(cfg.p))
    GTEST_SKIP() << "this process cannot build the host interface for p = 5 any more (ctest runs each test alone)";
  double bus = 0;
  const sysc::SystemResult res = sysc::render_through_host(regs, vol, cfg, {}, &bus);
  EXPECT_FALSE(res.mismatch) << res.mismatch->describe();
  const golden::BasePlane want = golden::render_fixed(vol, regs);
  EXPECT_EQ(res.plane.width, want.width);
  EXPECT_EQ(res.plane.rgba, want.rgba);
  EXPECT_EQ(res.plane.shift_x, want.shift_x);
  EXPECT_EQ(res.frame_cycles, sysc::frame_cycles(regs, 5).latency);
  EXPECT_GT(bus, 0.0) << "the host bus time is annotated";
}

// p = 4, every unit loosely timed: the host-interface tests' machine.
sysc::SystemConfig tlm_p4() {
  sysc::SystemConfig cfg;
  cfg.p = 4;
  cfg.levels = kTlm;
  return cfg;
}
const std::string kSceneDir = std::string(CUBE4_SOURCE_DIR) + "/scenes";
// A scene's volume with its voxel tags.
golden::Volume tagged_volume(const golden::Scene& sc) {
  golden::Volume vol = golden::load_volume(sc.volume, sc.precision.voxel_bits, kSceneDir);
  golden::load_tags(sc, vol, kSceneDir);
  return vol;
}

// The DMI-style load `cube4 render` uses: the volume mapped into voxel
// memory in place gives the frame, cycles and bus time of the load through
// the VOLUME window, for plain and (a process of its own: the interface is
// built once, for one precision) tagged voxels, and holds no copy; after
// the frame the subvolume reads as cleared.
TEST(System, MappedVolumeIsTheBusLoadWithoutTheCopy) {
  if (!sysc::host_interface_available(4))
    GTEST_SKIP() << "this process cannot build the host interface for p = 4 any more (ctest runs each test alone)";
  Case c;
  c.effects = R"("shading": true, "gradient_modulation": {"opacity": true})";
  const auto [vol, regs] = program(c);
  const sysc::SystemConfig cfg = tlm_p4();
  double bus = 0, mapped_bus = 0;
  const sysc::SystemResult loaded = sysc::render_through_host(regs, vol, cfg, {}, &bus);
  const sysc::SystemResult mapped =
      sysc::render_through_host(regs, vol, cfg, {}, &mapped_bus, nullptr, sysc::VolumeLoad::Mapped);
  EXPECT_EQ(mapped.plane.rgba, loaded.plane.rgba);
  EXPECT_EQ(mapped.plane.rgba, golden::render_fixed(vol, regs).rgba);
  EXPECT_EQ(mapped.frame_cycles, loaded.frame_cycles);
  EXPECT_EQ(mapped_bus, bus) << "the same bus time: the bursts are annotated, not moved";
  const golden::Volume& after = sysc::host_session(cfg, regs.p).machine.volume(0);
  EXPECT_NE(&after, &vol) << "the mapping ends with the frame";
  EXPECT_EQ(std::count(after.data.begin(), after.data.end(), 0), static_cast<std::ptrdiff_t>(vol.size()));
}

TEST(System, MappedTaggedVolumeIsTheBusLoad) {
  if (!sysc::host_interface_available(4))
    GTEST_SKIP() << "this process cannot build the host interface for p = 4 any more (ctest runs each test alone)";
  const sysc::SystemConfig cfg = tlm_p4();
  const golden::Scene sc = golden::load_scene(kSceneDir + "/tagged_spheres.json");
  const golden::Volume tagged = tagged_volume(sc);
  const golden::Registers tagged_regs = golden::program_host(sc, tagged).regs;
  double tagged_bus = 0, tagged_mapped_bus = 0;
  const auto tagged_loaded = sysc::render_through_host(tagged_regs, tagged, cfg, {}, &tagged_bus);
  const auto tagged_mapped = sysc::render_through_host(tagged_regs, tagged, cfg, {}, &tagged_mapped_bus, nullptr,
                                                       sysc::VolumeLoad::Mapped);
  EXPECT_EQ(tagged_mapped.plane.rgba, tagged_loaded.plane.rgba);
  EXPECT_EQ(tagged_mapped_bus, tagged_bus);
}

// The machine uses a mapped volume in place until a voxel is written, which
// makes the subvolume its own copy first: the host's volume never changes.
TEST(System, MachineCopiesAMappedVolumeOnItsFirstVoxelWrite) {
  Case c;
  const auto [vol, regs] = program(c);
  sysc::Machine m(tlm_p4(), vol.bits);
  m.set_volume_dims(0, vol.dim[0], vol.dim[1], vol.dim[2]);
  m.map_volume(0, vol);
  EXPECT_EQ(&m.volume(0), &vol);
  const uint16_t before = vol.at(1, 2, 3);
  const uint16_t written = static_cast<uint16_t>((before + 1) & vol.max_value());
  m.write_voxel(0, 1, 2, 3, written);
  EXPECT_EQ(vol.at(1, 2, 3), before) << "the host's volume was written";
  ASSERT_NE(&m.volume(0), &vol);
  EXPECT_EQ(m.volume(0).at(1, 2, 3), written);
  golden::Volume expected = vol;
  expected.data[expected.index(1, 2, 3)] = written;
  EXPECT_EQ(m.volume(0).data, expected.data);
  m.unmap_volume(0);  // its own copy now: unchanged
  EXPECT_EQ(m.volume(0).data, expected.data);
  m.map_volume(0, vol);
  m.unmap_volume(0);
  EXPECT_EQ(std::count(m.volume(0).data.begin(), m.volume(0).data.end(), 0), static_cast<std::ptrdiff_t>(vol.size()));
}

// Voxel tags (bela §III) through the host interface at transaction level:
// the volume window carries {tag, value} words into the voxel memory, the
// CLASS window the {tag, value} table and the MATERIAL window each tag's
// coefficients; two touching spheres told apart only by their tags, from
// all six base planes, equal golden's, in golden's cycles. At RTL only a p
// verilated with voxel tags takes them.
TEST(System, TaggedSpheresThroughTheHostInterfaceTlm) {
  if (!sysc::host_interface_available(4))
    GTEST_SKIP() << "this process cannot build the host interface for p = 4 any more (ctest runs each test alone)";
  sysc::SystemConfig cfg = tlm_p4();
  for (int view = 0; view < 6; ++view) {
    const int axis = view / 2;
    SCOPED_TRACE("base plane " + std::to_string(view));
    golden::Scene sc = golden::load_scene(kSceneDir + "/tagged_spheres.json");
    golden::Vec3 d{0, 0, 0};
    d[axis] = view % 2 ? -1 : 1;
    sc.view.direction = d;
    sc.view.up = axis == 1 ? golden::Vec3{0, 0, 1} : golden::Vec3{0, 1, 0};
    const golden::Volume vol = tagged_volume(sc);
    ASSERT_FALSE(vol.tags.empty());
    const golden::Registers regs = golden::program_host(sc, vol).regs;
    const sysc::SystemResult res = sysc::render_through_host(regs, vol, cfg, {});
    EXPECT_EQ(res.plane.rgba, golden::render_fixed(vol, regs).rgba);
    EXPECT_EQ(res.frame_cycles, sysc::frame_cycles(regs, cfg.p).latency);
    EXPECT_EQ(sysc::host_session(cfg, regs.p).machine.volume(0).tags, vol.tags);
    sysc::SystemConfig rtl = cfg;
    rtl.levels[static_cast<size_t>(sysc::Unit::Interp)] = Level::Rtl;
    const std::vector<int> tagged = sysc::rtl_tag_pipes();
    for (int p : sysc::rtl_pipes()) {
      rtl.p = p;
      if (std::find(tagged.begin(), tagged.end(), p) != tagged.end())
        EXPECT_NO_THROW(sysc::check_system_limits(regs, rtl)) << "p = " << p;
      else
        EXPECT_THROW(sysc::check_system_limits(regs, rtl), std::invalid_argument) << "p = " << p;
    }
  }
}

// Two touching spheres (the synthetic "spheres") told apart only by their
// tags, seen from base plane `view` (0 .. 5: +x, -x, +y, -y, +z, -z).
Case tagged_spheres(int view) {
  const char* dirs[6][2] = {{"[1, 0, 0]", "[0, 1, 0]"}, {"[-1, 0, 0]", "[0, 1, 0]"}, {"[0, 1, 0]", "[0, 0, 1]"},
                            {"[0, -1, 0]", "[0, 0, 1]"}, {"[0, 0, 1]", "[0, 1, 0]"}, {"[0, 0, -1]", "[0, 1, 0]"}};
  Case c;
  c.volume = R"({"synthetic": "spheres", "size": [14, 10, 9], "radius": 3.5})";
  c.direction = dirs[view][0];
  c.up = dirs[view][1];
  c.transfer = R"("transfer": {"opacity": [[0, 0], [0.3, 0], [0.5, 0.6], [1, 0.8]]})";
  c.effects = R"("shading": true, "material": {"ks": 0.4}, "precision": {"tag_bits": 2},
                 "tags": {"label": [{"tag": 1, "box": {"min": [0, 0, 0], "max": [6, 9, 8]}},
                                    {"tag": 2, "box": {"min": [7, 0, 0], "max": [13, 9, 8]}}],
                          "classes": [{"tag": 1, "color": [[0, 1, 0.1, 0.1], [1, 1, 0.1, 0.1]]},
                                      {"tag": 2, "color": [[0, 0.1, 0.1, 1], [1, 0.1, 0.1, 1]],
                                       "material": {"kd": 0.5, "ks": 0.9}}]})";
  return c;
}

// The same spheres through the transaction-level units clocked beat by
// beat: the voxel memory's words carry the tags, the interpolation unit
// gives each sample its nearest voxel's, the gradient unit passes the
// centre's on, the shading unit classifies and shades by it; every unit's
// stream (tags included) and the base plane equal golden's, from all six
// base planes.
TEST(System, TaggedSpheresTlmCycleLevelAllBasePlanes) {
  for (int view = 0; view < 6; ++view) {
    SCOPED_TRACE("base plane " + std::to_string(view));
    run(tagged_spheres(view), 4, kTlm, true);
    run(tagged_spheres(view), 3, kTlm, true);
  }
}

// The same spheres at RTL (the rings and shading unit verilated with voxel
// tags): the words {tag, value} through the interpolation ring's storage and
// links, the nearest voxel's tag per sample, the centre's through the
// gradient ring's delays, classification at {tag, value} and the material
// RAM; base plane, every unit's stream and the cycles equal golden's and the
// cycle model's (the tags cost no cycle), from all six base planes, at p = 4
// and 2.
TEST(System, TaggedSpheresRtlAllBasePlanes) {
  for (int p : {4, 2}) {
    if (!sysc::rtl_available(p)) continue;
    const std::vector<int> tagged = sysc::rtl_tag_pipes();
    if (std::find(tagged.begin(), tagged.end(), p) == tagged.end()) continue;
    for (int view = 0; view < 6; ++view) {
      SCOPED_TRACE("p = " + std::to_string(p) + ", base plane " + std::to_string(view));
      run(tagged_spheres(view), p, kRtl);
      if (::testing::Test::HasFailure()) return;
    }
  }
}

// Mixed levels: each tag-carrying unit alone at RTL among transaction-level
// ones (their tag lanes meet the other level's), all six base planes, p = 4.
TEST(System, TaggedSpheresMixedLevels) {
  if (!sysc::rtl_available(4)) GTEST_SKIP() << "no RTL build for p = 4";
  for (int view = 0; view < 6; ++view)
    for (sysc::Unit u : {sysc::Unit::Interp, sysc::Unit::Gradient, sysc::Unit::Shade}) {
      SCOPED_TRACE(std::string(sysc::unit_name(u)) + " at RTL, base plane " + std::to_string(view));
      run(tagged_spheres(view), 4, only(u));
      if (::testing::Test::HasFailure()) return;
    }
}


// Subvolumes (VolumePro §4.2) at RTL: two volumes resident in voxel memory,
// a 4-D animation of one of them by slab writes between frames (a bright
// box moving through the noise) without reloading the rest, and the other
// rendered in between, untouched: every frame equals golden's of the
// volume as updated, and the voxel memory holds exactly that volume.
TEST(System, SubvolumesAnimatedBetweenFrames) {
  Case a, b;
  a.volume = R"({"synthetic": "noise", "size": [16, 14, 12], "seed": 21})";
  b.volume = R"({"synthetic": "sphere", "size": [12, 12, 12]})";
  b.direction = "[-0.2, 1, 0.3]";
  b.up = "[0, 0, 1]";
  Programmed pa = program(a);
  const Programmed pb = program(b);
  sysc::SystemConfig cfg;
  cfg.p = 4;
  cfg.check = true;
  if (!sysc::rtl_available(cfg.p)) GTEST_SKIP() << "no RTL build for p = 4";
  if (!sysc::host_interface_available(cfg.p))
    GTEST_SKIP() << "this process cannot build the host interface for p = 4 any more (ctest runs each test alone)";
  const sysc::HostSession host = sysc::host_session(cfg, pa.regs.p);
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
  sysc::load_subvolume_over_tlm(host.target, 0, pa.vol, delay);
  sysc::load_subvolume_over_tlm(host.target, 1, pb.vol, delay);
  auto frame = [&](int k, const Programmed& f, const std::string& what) {
    SCOPED_TRACE(what);
    sysc::write_tables_over_tlm(host.target, f.regs, delay);
    sysc::write_view_over_tlm(host.target, f.regs, delay);
    sysc::select_subvolume_over_tlm(host.target, k, delay);
    sysc::start_frame_over_tlm(host.target, delay);
    ASSERT_TRUE(host.machine.last());
    EXPECT_FALSE(host.machine.last()->mismatch) << host.machine.last()->mismatch->describe();
    const golden::BasePlane got = sysc::read_base_plane_over_tlm(host.target, f.regs, delay);
    EXPECT_EQ(got.rgba, golden::render_fixed(f.vol, f.regs).rgba);
    EXPECT_EQ(host.machine.volume(k).data, f.vol.data);
  };
  frame(0, pa, "subvolume 0 as loaded");
  const std::array<int, 3> box{4, 4, 3};
  const std::vector<uint16_t> bright(static_cast<size_t>(box[0]) * box[1] * box[2],
                                     static_cast<uint16_t>(pa.vol.max_value()));
  for (int t = 0; t < 3; ++t) {
    const std::array<int, 3> at{2 + 4 * t, 5, 4};
    sysc::write_slab_over_tlm(host.target, 0, at, box, bright, delay);
    for (int z = 0; z < box[2]; ++z)
      for (int y = 0; y < box[1]; ++y)
        for (int x = 0; x < box[0]; ++x) pa.vol.data[pa.vol.index(at[0] + x, at[1] + y, at[2] + z)] = bright[0];
    frame(0, pa, "subvolume 0, animation frame " + std::to_string(t + 1));
    frame(1, pb, "subvolume 1 after frame " + std::to_string(t + 1));
    if (::testing::Test::HasFailure()) return;
  }
}
}  // namespace

// Every register narrower than its bus word, at each end of its hardware
// field, written through the host interface: the RTL system's base plane is
// golden's (the register file refuses what the RTL would truncate). One
// frame per register and end, the others as the scene programs them, plus
// the falloff and its reciprocal at their maxima together.
namespace {
TEST(System, RegistersAtTheirLimitsThroughTheHostInterface) {
  if (!sysc::rtl_available(4)) GTEST_SKIP() << "no RTL build for p = 4";
  if (!sysc::host_interface_available(4))
    GTEST_SKIP() << "this process cannot build the host interface for p = 4 any more (ctest runs each test alone)";
  Case c;
  c.effects = R"("shading": true, "lights": [{"direction": [0.3, 0.5, 1], "intensity": 0.8}],)"
              R"( "material": {"ks": 0.6, "exponent": 12}, "gradient_modulation": {"opacity": true},)"
              R"( "cropping": {"x": [2, 8], "y": [1, 9], "combine": "cross"},)"
              R"( "cut_plane": {"normal": [1, 0.5, 1], "dmin": 5, "dmax": 9, "falloff": 2.5})";
  const Programmed programmed = program(c);
  const golden::Volume& vol = programmed.vol;
  const golden::Registers& base = programmed.regs;
  sysc::SystemConfig cfg;
  cfg.p = 4;
  cfg.check = true;
  auto frame = [&](const golden::Registers& r, const std::string& what) {
    SCOPED_TRACE(what);
    const sysc::SystemResult res = sysc::render_through_host(r, vol, cfg, {});
    EXPECT_FALSE(res.mismatch) << res.mismatch->describe();
    const golden::BasePlane want = golden::render_fixed(vol, r);
    EXPECT_EQ(res.plane.rgba, want.rgba);
    return std::count_if(want.rgba.begin(), want.rgba.end(), [](uint16_t v) { return v != 0; });
  };
  ASSERT_GT(frame(base, "the scene"), 0) << "the scene renders nothing";
  namespace rm = sysc::regmap;
  const sysc::HardwareParams hw{base.p};
  int frames = 0;
  auto with = [&](golden::Registers r, const rm::Register& reg, int64_t v) {
    rm::RegisterValues values;
    values.regs = std::move(r);
    values.vol_dims[0] = vol.dim;
    reg.set(values, static_cast<uint64_t>(v));
    return values.regs;
  };
  for (const rm::Register& reg : rm::kRegisters) {
    const std::optional<rm::Limits> l = rm::limits(reg, hw);
    // Narrow fields only; DIM and SUPERSAMPLING shape the frame, not a datapath field.
    if (!rm::carries_frame_field(reg) || reg.rule != rm::Rule::Width || l->lo == INT64_MIN ||
        (reg.words == 1 && reg.width.of(hw.precision) >= 32))
      continue;
    // A window register bites only with the window on (the other bounds
    // open): a block machine's.
    golden::Registers r = base;
    if (reg.block == rm::Block::Window) {
      r.window_enabled = true;
      for (auto& range : r.window.range) range = {0, static_cast<int32_t>(l->hi)};
    }
    for (const int64_t v : {l->lo, l->hi}) {
      frame(with(r, reg, v), std::string(reg.name) + " = " + std::to_string(v));
      ++frames;
    }
  }
  EXPECT_EQ(frames, 2 * 31) << "FLIP, 7 cropping, 6 block-window, 8 cut-plane and 9 shading registers";
  const golden::Registers falloff = with(base, *rm::find_register("CUT_FALLOFF"),
                                         rm::limits(*rm::find_register("CUT_FALLOFF"), hw)->hi);
  frame(with(falloff, *rm::find_register("CUT_INV_FALLOFF"), rm::limits(*rm::find_register("CUT_INV_FALLOFF"), hw)->hi),
        "CUT_FALLOFF and CUT_INV_FALLOFF at their maxima");
}
}  // namespace

// Frames streamed back to back: the first frame's last pixel comes at the
// cycle model's latency of a followed frame, every next one exactly
// `stream` cycles later (the steady-state interval; the last one earlier by
// what the first waited for the second), and the pixel memory holds the
// frame.
namespace {
sysc::SystemConfig three_frames(std::array<Level, sysc::kUnits> levels, bool cycle_level, bool check) {
  sysc::SystemConfig cfg;
  cfg.p = 4;
  cfg.levels = levels;
  cfg.cycle_level = cycle_level;
  cfg.frames = 3;
  cfg.check = check;
  return cfg;
}
void back_to_back(std::array<Level, sysc::kUnits> levels, bool cycle_level, const Case& c = Case{}) {
  const auto [vol, regs] = program(c);
  const sysc::SystemConfig cfg = three_frames(levels, cycle_level, true);
  if (!cfg.all_tlm() && !sysc::rtl_available(cfg.p)) GTEST_SKIP() << "no RTL build for p = " << cfg.p;
  const sysc::SystemResult res = sysc::run_frame(regs, vol, cfg);
  EXPECT_FALSE(res.mismatch) << res.mismatch->describe();
  EXPECT_EQ(res.plane.rgba, golden::render_fixed(vol, regs).rgba);
  const sysc::CycleCount cc = sysc::frame_cycles(regs, 4);
  EXPECT_EQ(res.measured_interval, cc.stream);
  // The first frame waits for the second's priming pass (VolumePro's z
  // gradient), the last for no frame.
  const uint64_t wait = cc.latency_followed - cc.latency;
  EXPECT_EQ(res.simulated_cycles, res.frame_cycles + 2 * cc.stream - wait);
  if (levels == kRtl) {
    EXPECT_EQ(res.frame_cycles, cc.latency_followed);
  }
}
TEST(System, BackToBackFramesRtl) { back_to_back(kRtl, false); }
// No zero pass between the frames: the address generator starts the next
// frame in the cycle after the last read (again_i), with supersampling.
TEST(System, BackToBackFramesRtlMipS2) {
  Case c;
  c.effects = R"("shading": false, "blend": "mip")";
  c.S = 2;
  back_to_back(kRtl, false, c);
}
TEST(System, BackToBackFramesMixed) { back_to_back(only(sysc::Unit::Gradient), false); }
TEST(System, BackToBackFramesTlmClocked) { back_to_back(kTlm, true); }

// VolumePro's z gradient (z_gradient voxel_differences): the rings with
// HasZDiff and HasVoxelZ, and the clocked TLM units, stream one slice ahead
// after a priming pass per frame (docs/rtl-interp-zdiff.md); bit-exact
// base plane and streams, and the cycles of the cycle model, at S = 1, 2
// and 3, alone at RTL and mixed, and frames back to back.
Case voxel_z_case(int S) {
  Case c;
  c.effects = R"("shading": true, "z_gradient": "voxel_differences")";
  c.S = S;
  return c;
}
// GTEST_SKIP only leaves the function it is in: the tests call it themselves.
bool has_zdiff_rtl(int p) {
  const std::vector<int> built = sysc::rtl_zdiff_pipes();
  return std::find(built.begin(), built.end(), p) != built.end();
}
TEST(System, VoxelZGradientRtlP4) {
  if (!has_zdiff_rtl(4)) GTEST_SKIP() << "no z-difference RTL for p = 4";
  for (int S : {1, 2, 3}) run(voxel_z_case(S), 4, kRtl);
}
TEST(System, VoxelZGradientRtlP1) {
  if (!has_zdiff_rtl(1)) GTEST_SKIP() << "no z-difference RTL for p = 1";
  run(voxel_z_case(2), 1, kRtl);
}
TEST(System, VoxelZGradientMixedLevels) {
  if (!has_zdiff_rtl(4)) GTEST_SKIP() << "no z-difference RTL for p = 4";
  run(voxel_z_case(3), 4, only(sysc::Unit::Interp));
  run(voxel_z_case(3), 4, only(sysc::Unit::Gradient));
}
TEST(System, VoxelZGradientClockedTlm) {
  for (int p : {3, 5}) run(voxel_z_case(2), p, kTlm, true);
}
TEST(System, VoxelZGradientBackToBackFrames) {
  back_to_back(kTlm, true, voxel_z_case(2));
  if (!has_zdiff_rtl(4)) GTEST_SKIP() << "no z-difference RTL for p = 4";
  back_to_back(kRtl, false, voxel_z_case(2));
}

// Unchecked clocked TLM: the gradient and shading units skip the samples of
// rays the compositor has stopped, as the golden renderer does (RayStop).
// An opaque sphere stops most rays at their first samples; three frames
// back to back on a volume three slices deep, so that each frame's first
// slices are shaded while the frame before is still composited (its stopped
// rays must not stop the next frame's); a block's partial image keeps its
// accumulators, whose rays stop only at full α.
TEST(System, ClockedTlmSkipsTheSamplesOfStoppedRaysFrameByFrame) {
  for (const bool accumulators : {false, true}) {
    for (const char* size : {"[13, 11, 9]", "[9, 7, 3]"}) {
      SCOPED_TRACE(std::string("size ") + size + (accumulators ? ", accumulators" : ""));
      Case c;
      c.volume = std::string(R"({"synthetic": "sphere", "size": )") + size + "}";
      c.transfer = R"("transfer": {"color": [[0, 1, 0.2, 0], [1, 0.1, 0, 1]], "opacity": [[0, 0], [0.2, 1], [1, 1]]})";
      const auto [vol, regs] = program(c);
      sysc::SystemConfig cfg = three_frames(kTlm, true, false);
      cfg.accumulators = accumulators;
      const sysc::SystemResult res = sysc::run_frame(regs, vol, cfg);
      golden::FixedOptions o;
      o.accumulators = accumulators;
      const golden::BasePlane want = golden::render_fixed(vol, regs, o);
      EXPECT_EQ(res.plane.rgba, want.rgba);
      EXPECT_EQ(res.plane.acc.size(), want.acc.size());
      for (size_t i = 0; i < want.acc.size() && i < res.plane.acc.size(); ++i)
        ASSERT_TRUE(res.plane.acc[i].r == want.acc[i].r && res.plane.acc[i].g == want.acc[i].g &&
                    res.plane.acc[i].b == want.acc[i].b && res.plane.acc[i].a == want.acc[i].a)
            << "accumulator of ray " << i;
      EXPECT_EQ(res.measured_interval, sysc::frame_cycles(regs, 4).stream);
    }
  }
}
}  // namespace

// A parallel view's DDA registers outside what the machine is built for
// (rays moving backwards, or more than a voxel a slice, or starting before
// 0; golden::dda_out_of_range()) are refused by the golden
// renderer and the system model naming the field and its value; a negative
// shear once read and wrote outside the ray memory. The host interface
// refuses them at START (FieldRange, test_host_if).
TEST(System, ParallelShearsOutsideTheMachinesRangeAreRefusedNamingTheField) {
  const test::Setup s = setup(R"({"volume": {"synthetic": "sphere", "size": [21, 17, 13]}, "shading": true,
      "output": {"width": 48, "height": 48}})");
  const int64_t one = int64_t{1} << s.host.regs.p.dda_frac_bits;
  struct Bad {
    const char* field;
    int64_t golden::Registers::*reg;
    int64_t value;
  };
  for (const Bad& b : {Bad{"x_step", &golden::Registers::x_step, -one / 2}, Bad{"y_step", &golden::Registers::y_step, one + 1},
                       Bad{"x_start", &golden::Registers::x_start, -1}, Bad{"y_start", &golden::Registers::y_start, -one}}) {
    SCOPED_TRACE(b.field);
    golden::Registers r = s.host.regs;
    r.*b.reg = b.value;
    EXPECT_STREQ(golden::dda_out_of_range(r), b.field);
    const std::string want = std::string("registers: ") + b.field + " = " + std::to_string(b.value);
    try {
      golden::render_fixed(s.volume, r);
      ADD_FAILURE() << "golden rendered";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(want, 0), 0u) << e.what();
    }
    sysc::SystemConfig cfg;
    cfg.levels = kTlm;
    EXPECT_THROW(sysc::run_frame(r, s.volume, cfg), std::invalid_argument);
  }
  // The edges are in range: a shear of exactly a voxel a slice, a start deep in x.
  golden::Registers r = s.host.regs;
  r.x_step = one;
  r.y_start = 5 * one;
  EXPECT_EQ(golden::dda_out_of_range(r), nullptr);
  // Perspective: ray 0's DDA would overflow 64 bits (fuzz_host found it in
  // START's own base-plane check).
  const test::Setup ps = setup(R"({"volume": {"synthetic": "sphere", "size": [21, 17, 13]}, "shading": true,
      "view": {"projection": "perspective", "fov": 50, "eye": [10, 8, -20]}, "output": {"width": 48, "height": 48}})");
  golden::Registers pr = ps.host.regs;
  ASSERT_TRUE(pr.perspective);
  EXPECT_EQ(golden::dda_out_of_range(pr), nullptr);
  pr.x_step = int64_t{1} << 61;
  EXPECT_STREQ(golden::dda_out_of_range(pr), "x_step");
  EXPECT_THROW(golden::render_fixed(ps.volume, pr), std::invalid_argument);
  pr = ps.host.regs;
  pr.y_start = -(int64_t{1} << 62);
  EXPECT_STREQ(golden::dda_out_of_range(pr), "y_start");
}
