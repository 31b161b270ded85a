// System tests (ctest label `system`): whole frames through the system
// model at every level mix, bit-exact against golden render_fixed(), and
// the frame's cycles at RTL equal to the cycle model's count. Each test
// renders one frame: ctest runs every test in a process of its own, and
// SystemC elaborates once per process.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "golden/host_driver.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "systemc/core/system.hpp"
#include "systemc/rtl/rtl_factory.hpp"

namespace {

using namespace cube4;
using sysc::Level;

const char* kTransfer =
    R"("transfer": {"color": [[0, 1, 0.2, 0], [0.5, 0, 1, 0.3], [1, 0.1, 0, 1]],)"
    R"( "opacity": [[0, 0.0], [0.3, 0.05], [0.6, 0.2], [1, 0.5]]})";

struct Case {
  std::string volume = R"({"synthetic": "sphere", "size": [13, 11, 9]})";
  std::string direction = "[0.3, -0.2, 1]";
  std::string up = "[0, 1, 0]";
  std::string effects = R"("shading": true)";
  int S = 1;
};

std::string scene_json(const Case& c) {
  std::ostringstream s;
  s << R"({"volume": )" << c.volume << R"(, "view": {"direction": )" << c.direction << R"(, "up": )" << c.up
    << R"(}, "supersampling": )" << c.S << ", " << kTransfer << ", " << c.effects << "}";
  return s.str();
}

// Renders the case through the system at `levels` with p pipelines and
// checks the base plane and the cycle count.
void run(const Case& c, int p, std::array<Level, sysc::kUnits> levels, bool cycle_level = false,
         sysc::Kernel kernel = sysc::Kernel::SystemC, bool simulate_unneeded = false) {
  const golden::Scene scene = golden::parse_scene(scene_json(c), "test_system.json");
  const golden::Volume vol = golden::load_volume(scene.volume, scene.precision.voxel_bits, CUBE4_SOURCE_DIR);
  const golden::Registers regs = golden::program_host(scene, vol).regs;
  sysc::SystemConfig cfg;
  cfg.p = p;
  cfg.levels = levels;
  cfg.check = !cfg.all_tlm() || cycle_level;
  cfg.cycle_level = cycle_level;
  cfg.kernel = kernel;
  cfg.simulate_unneeded = simulate_unneeded;
  if (!cfg.all_tlm() && !sysc::rtl_available(p)) GTEST_SKIP() << "no RTL build for p = " << p;
  const sysc::SystemResult res = sysc::run_frame(regs, vol, cfg);
  const golden::BasePlane want = golden::render_fixed(vol, regs);
  ASSERT_EQ(res.plane.width, want.width);
  ASSERT_EQ(res.plane.height, want.height);
  EXPECT_FALSE(res.mismatch) << res.mismatch->describe();
  size_t bad = 0, first = 0;
  for (size_t i = 0; i < want.rgba.size(); ++i)
    if (res.plane.rgba[i] != want.rgba[i] && bad++ == 0) first = i;
  EXPECT_EQ(bad, 0u) << "first differing channel value at pixel (" << first / 4 % static_cast<size_t>(want.width)
                     << ", " << first / 4 / static_cast<size_t>(want.width) << ") channel " << first % 4 << ": expected "
                     << want.rgba[first] << ", got " << res.plane.rgba[first];
  // A frame that shows something: an empty base plane proves nothing.
  size_t lit = 0;
  for (size_t i = 3; i < want.rgba.size(); i += 4) lit += want.rgba[i] != 0;
  EXPECT_GT(lit, 0u) << "the test scene renders nothing";
  golden::Registers simulated = regs;
  simulated.gradient = regs.gradient || simulate_unneeded;
  EXPECT_EQ(res.simulated[1], simulated.gradient) << "the gradient unit runs exactly when needed (or forced)";
  const sysc::CycleCount cc = sysc::frame_cycles(simulated, p);
  EXPECT_EQ(res.stream_cycles, cc.stream);
  const bool all_rtl = levels[0] == Level::Rtl && levels[1] == Level::Rtl && levels[2] == Level::Rtl &&
                       levels[3] == Level::Rtl;
  if (all_rtl) EXPECT_EQ(res.frame_cycles, cc.latency) << "RTL cycles against the cycle model";
  const int B = (regs.dim[0] + p - 1) / p;
  EXPECT_EQ(cc.stream, static_cast<uint64_t>(regs.sample_slices() + (simulated.gradient ? 1 : 0)) *
                           static_cast<uint64_t>(regs.dim[1] + 1) * static_cast<uint64_t>(B));
}

constexpr std::array<Level, 4> kRtl{Level::Rtl, Level::Rtl, Level::Rtl, Level::Rtl};
constexpr std::array<Level, 4> kTlm{Level::Tlm, Level::Tlm, Level::Tlm, Level::Tlm};
std::array<Level, 4> only(sysc::Unit u) {
  std::array<Level, 4> l = kTlm;
  l[static_cast<size_t>(u)] = Level::Rtl;
  return l;
}

// Pipelines.
TEST(System, SphereP1) { run(Case{}, 1, kRtl); }
TEST(System, SphereP4) { run(Case{}, 4, kRtl); }
TEST(System, SphereP5) { run(Case{}, 5, kRtl); }
TEST(System, SphereP8) { run(Case{}, 8, kRtl); }
TEST(System, SphereTlmP4) { run(Case{}, 4, kTlm); }
TEST(System, SphereTlmP16) { run(Case{}, 16, kTlm); }
// Every unit's TLM model clocked beat by beat (the models mixed runs use).
TEST(System, SphereTlmCycleLevelP4) { run(Case{}, 4, kTlm, true); }
TEST(System, SphereTlmCycleLevelNoGradientP5) {
  Case c;
  c.effects = R"("shading": false, "blend": "mip")";
  run(c, 5, kTlm, true);
}
// The plain C++ schedule (the benchmarks' ceiling) simulates the same machine.
TEST(System, SpherePlainLoopP4) { run(Case{}, 4, kRtl, false, sysc::Kernel::PlainLoop); }

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
