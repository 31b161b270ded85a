// Shared by the system test suites (test_system.cpp, test_system_slow.cpp):
// a small scene description and run(), which renders it through the system
// model and checks the base plane bit for bit against golden render_fixed(),
// every unit's stream (--check), and the cycles against the cycle model.
#pragma once
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <vector>
#include <sstream>
#include <string>

#include "golden/host_driver.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "systemc/core/system.hpp"
#include "systemc/rtl/rtl_factory.hpp"

namespace cube4::test {

using sysc::Level;

inline const char* kTransfer =
    R"("transfer": {"color": [[0, 1, 0.2, 0], [0.5, 0, 1, 0.3], [1, 0.1, 0, 1]],)"
    R"( "opacity": [[0, 0.0], [0.3, 0.05], [0.6, 0.2], [1, 0.5]]})";

struct Case {
  std::string volume = R"({"synthetic": "sphere", "size": [13, 11, 9]})";
  std::string direction = "[0.3, -0.2, 1]";
  std::string up = "[0, 1, 0]";
  std::string effects = R"("shading": true)";
  int S = 1;
  std::string transfer = kTransfer;
};

inline std::string scene_json(const Case& c) {
  std::ostringstream s;
  s << R"({"volume": )" << c.volume << R"(, "view": {"direction": )" << c.direction << R"(, "up": )" << c.up
    << R"(}, "supersampling": )" << c.S << ", " << c.transfer << ", " << c.effects << "}";
  return s.str();
}

// A case as the host programs it.
struct Programmed {
  golden::Volume vol;
  golden::Registers regs;
};
inline Programmed program(const Case& c) {
  const golden::Scene scene = golden::parse_scene(scene_json(c), "test_system.json");
  Programmed f{golden::load_volume(scene.volume, scene.precision.voxel_bits, CUBE4_SOURCE_DIR), {}};
  golden::load_tags(scene, f.vol, CUBE4_SOURCE_DIR);
  f.regs = golden::program_host(scene, f.vol).regs;
  return f;
}

// The RTL's random-reset seeds a system test runs with: CUBE4_SYSTEM_SEED_COUNT
// of them (2 in the default suite, more in the slow one), from CUBE4_SEED
// (else 1) on, so that an X-dependence shows as a difference between runs.
#ifndef CUBE4_SYSTEM_SEED_COUNT
#define CUBE4_SYSTEM_SEED_COUNT 2
#endif
inline std::vector<uint32_t> system_seeds() {
  const char* env = std::getenv("CUBE4_SEED");
  const uint32_t base = env && *env ? static_cast<uint32_t>(std::strtoul(env, nullptr, 10)) : 1u;
  std::vector<uint32_t> seeds;
  for (uint32_t i = 0; i < CUBE4_SYSTEM_SEED_COUNT; ++i) seeds.push_back(base + i);
  return seeds;
}

inline void run_seeded(const Case& c, int p, std::array<Level, sysc::kUnits> levels, bool cycle_level,
                       sysc::Kernel kernel, bool simulate_unneeded, uint32_t seed, bool check);

// Renders the case through the system at `levels` with p pipelines, once per
// seed of system_seeds() when a unit runs at RTL. Clocked runs are checked
// stream by stream; clocked TLM runs also once without the check, where
// the TLM units skip what only the check reads (docs/system.md).
inline void run(const Case& c, int p, std::array<Level, sysc::kUnits> levels, bool cycle_level = false,
                sysc::Kernel kernel = sysc::Kernel::SystemC, bool simulate_unneeded = false) {
  bool any_rtl = false;
  for (Level l : levels) any_rtl = any_rtl || l == Level::Rtl;
  for (uint32_t seed : any_rtl ? system_seeds() : std::vector<uint32_t>{1}) {
    SCOPED_TRACE("RTL random reset seed " + std::to_string(seed));
    run_seeded(c, p, levels, cycle_level, kernel, simulate_unneeded, seed, !any_rtl ? cycle_level : true);
    if (::testing::Test::HasFatalFailure() || ::testing::Test::IsSkipped()) return;
  }
  if (!any_rtl && cycle_level) {
    SCOPED_TRACE("clocked TLM without --check");
    run_seeded(c, p, levels, cycle_level, kernel, simulate_unneeded, 1, false);
  }
}

// One run: checks the base plane and the cycle count.
inline void run_seeded(const Case& c, int p, std::array<Level, sysc::kUnits> levels, bool cycle_level,
                       sysc::Kernel kernel, bool simulate_unneeded, uint32_t seed, bool check) {
  const auto [vol, regs] = program(c);
  sysc::SystemConfig cfg;
  cfg.p = p;
  cfg.levels = levels;
  cfg.check = check;
  cfg.cycle_level = cycle_level;
  cfg.kernel = kernel;
  cfg.simulate_unneeded = simulate_unneeded;
  cfg.seed = seed;
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
  // A clocked run: the stream former's last voxel beat is beat number
  // `stream + flush` (one partial beam per clock, no gap).
  if (!cfg.all_tlm() || cycle_level) {
    EXPECT_EQ(res.last_beat[0], cc.stream + cc.flush) << "voxel beats per frame";
  }
  bool all_rtl = true;
  for (Level l : levels) all_rtl = all_rtl && l == Level::Rtl;
  if (all_rtl) {
    EXPECT_EQ(res.frame_cycles, cc.latency) << "RTL cycles against the cycle model";
  }
  const int B = (regs.dim[0] + p - 1) / p;
  // Passes back to back (n³/p for S = 1; VolumePro's z gradient primes
  // each frame with one pass more), then the zero pass (gradient unit on)
  // and a flush beam.
  const bool prime = simulated.gradient && regs.z_gradient == golden::ZGradient::VoxelDifferences;
  EXPECT_EQ(cc.stream, static_cast<uint64_t>(regs.sample_slices() + (prime ? 1 : 0)) *
                           static_cast<uint64_t>(regs.dim[1]) * static_cast<uint64_t>(B));
  EXPECT_EQ(cc.flush, static_cast<uint64_t>(simulated.gradient ? regs.dim[1] + 1 : 1) * static_cast<uint64_t>(B));
}

constexpr std::array<Level, sysc::kUnits> kRtl{Level::Rtl, Level::Rtl, Level::Rtl, Level::Rtl, Level::Rtl};
constexpr std::array<Level, sysc::kUnits> kTlm{Level::Tlm, Level::Tlm, Level::Tlm, Level::Tlm, Level::Tlm};
inline std::array<Level, sysc::kUnits> only(sysc::Unit u) {
  std::array<Level, sysc::kUnits> l = kTlm;
  l[static_cast<size_t>(u)] = Level::Rtl;
  return l;
}

}  // namespace cube4::test
