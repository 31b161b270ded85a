// A partitioned volume on several machines and the composition network
// (systemc/core/partitioned.hpp, compose_network.hpp): every block's
// partial image and the composed base plane bit for bit against golden
// (golden/blocks.hpp), at RTL and TLM, and the cycles against the models.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "golden/blocks.hpp"
#include "systemc/core/compose_network.hpp"
#include "systemc/core/machine.hpp"
#include "systemc/core/partitioned.hpp"
#include "tb/tests/system_support.hpp"
#include "tb/tests/test_support.hpp"

using namespace cube4;
using test::Case;
using test::kRtl;
using test::kTlm;
using sysc::Level;

namespace {

// Renders case `c` as `counts` blocks on machines of p pipelines at
// `levels`, the network at `net_level`, and checks everything against
// golden: each block's partial image (pixels and accumulators), the
// composed image, no unit stream mismatch, and at RTL the cycle counts.
void run_partitioned(const Case& c, const std::array<int, 3>& counts, int p, std::array<Level, sysc::kUnits> levels,
                     Level net_level, bool one_pass_equal = false) {
  const auto [vol, regs] = test::program(c);
  const golden::BlockPlan plan = golden::plan_blocks(regs, vol.dim, counts, "test");
  sysc::SystemConfig cfg;
  cfg.p = p;
  cfg.levels = levels;
  cfg.check = true;
  cfg.cycle_level = true;  // at TLM too: the machines clocked beat by beat
  if (!cfg.all_tlm() && !sysc::rtl_available(p)) GTEST_SKIP() << "no RTL build for p = " << p;
  if (!sysc::host_interface_available(p)) GTEST_SKIP() << "the host interface of this process is built for another p";
  sysc::NetworkConfig net;
  net.level = net_level;
  net.cycle_level = true;
  bool any_rtl = net_level == Level::Rtl;
  for (Level l : levels) any_rtl = any_rtl || l == Level::Rtl;
  for (uint32_t seed : any_rtl ? test::system_seeds() : std::vector<uint32_t>{1}) {
    SCOPED_TRACE("RTL random reset seed " + std::to_string(seed));
    cfg.seed = net.seed = seed;
    const sysc::PartitionedResult res = sysc::render_partitioned(plan, vol, cfg, net);
    EXPECT_FALSE(res.mismatch) << *res.mismatch;
    const golden::BasePlane want = golden::render_blocks_fixed(vol, plan, golden::FixedOptions{});
    ASSERT_EQ(res.network.plane.width, want.width);
    ASSERT_EQ(res.network.plane.height, want.height);
    EXPECT_EQ(res.network.plane.rgba, want.rgba) << "the composed base plane differs from golden";
    if (one_pass_equal) {
      EXPECT_EQ(res.network.plane.rgba, golden::render_fixed(vol, regs).rgba) << "selecting blends are exact";
    }
    size_t lit = 0;
    for (size_t i = 3; i < want.rgba.size(); i += 4) lit += want.rgba[i] != 0;
    EXPECT_GT(lit, want.rgba.size() / 40) << "the test scene renders almost nothing";
    // Cycles: each machine's against the cycle model (all at RTL), the
    // network's against network_cycles(), the frame the slowest machine's
    // plus the network's.
    ASSERT_EQ(res.blocks.size(), plan.blocks.size());
    uint64_t slowest = 0;
    for (size_t i = 0; i < plan.blocks.size(); ++i) {
      const sysc::CycleCount cc = sysc::frame_cycles(plan.blocks[i].regs, p);
      if (levels == kRtl) {
        EXPECT_EQ(res.blocks[i].frame_cycles, cc.latency) << "block " << i;
      }
      slowest = std::max(slowest, res.blocks[i].frame_cycles);
    }
    const sysc::NetworkCycles nc =
        sysc::network_cycles(want.width, want.height, static_cast<int>(plan.blocks.size()));
    EXPECT_EQ(res.network.cycles, nc.latency);
    EXPECT_EQ(res.network.nodes, static_cast<int>(plan.blocks.size()) - 1);
    EXPECT_EQ(res.frame_cycles, slowest + nc.latency);
    if (::testing::Test::HasFailure()) return;
  }
}

Case noise(const std::string& direction, const std::string& effects) {
  Case c;
  c.volume = R"({"synthetic": "noise", "size": [19, 17, 16], "seed": 5})";
  c.direction = direction;
  c.effects = effects;
  return c;
}

}  // namespace

TEST(SystemBlocks, ShadedBlocksAtRtlWithTheNetworkAtRtl) {
  run_partitioned(noise("[0.3, -0.2, 1]", R"("shading": true)"), {2, 2, 2}, 4, kRtl, Level::Rtl);
}

// MIP selects and never rounds: the composed image is the one pass image.
TEST(SystemBlocks, MipBlocksFromAnotherBasePlaneEqualOnePass) {
  run_partitioned(noise("[-1, 0.25, -0.3]", R"("shading": false, "blend": "mip")"), {2, 1, 3}, 4, kRtl, Level::Rtl,
                  true);
}

TEST(SystemBlocks, CroppedAndCutBlocksOfFivePipelines) {
  run_partitioned(noise("[0.2, 1, 0.35]", R"("shading": true, "cropping": {"x": [2, 14], "combine": "union"},
      "cut_plane": {"normal": [1, 1, 0], "dmin": 6, "dmax": 20, "falloff": 3})"),
                  {3, 1, 2}, 5, kRtl, Level::Rtl);
}

// The machines at TLM, clocked, and the network's clocked TLM nodes.
TEST(SystemBlocks, ClockedTlmMachinesAndNetwork) {
  Case c = noise("[0.3, -0.2, 1]", R"("shading": true)");
  c.S = 2;
  run_partitioned(c, {2, 2, 1}, 4, kTlm, Level::Tlm);
}

// Only the network at RTL (mixed:compose): loosely timed machines feed it.
TEST(SystemBlocks, NetworkAloneAtRtl) {
  const Case c = noise("[0.3, -0.2, 1]", R"("shading": true)");
  const auto [vol, regs] = test::program(c);
  if (!sysc::rtl_available(4)) GTEST_SKIP() << "no RTL build";
  const golden::BlockPlan plan = golden::plan_blocks(regs, vol.dim, {3, 3, 1}, "test");
  std::vector<golden::BasePlane> parts;
  for (const golden::Block& b : plan.blocks) parts.push_back(golden::render_block_fixed(golden::block_volume(vol, b), b, {}));
  std::vector<const golden::BasePlane*> ptrs;
  for (const auto& p : parts) ptrs.push_back(&p);
  for (sysc::Kernel k : {sysc::Kernel::SystemC, sysc::Kernel::PlainLoop}) {
    sysc::NetworkConfig net;
    net.level = Level::Rtl;
    net.kernel = k;
    net.check = true;
    const sysc::NetworkResult r = sysc::run_network(plan, ptrs, net);
    EXPECT_FALSE(r.mismatch) << *r.mismatch;
    EXPECT_EQ(r.plane.rgba, golden::compose_blocks(plan, ptrs).rgba);
    EXPECT_EQ(r.depth, 4);  // nine images: ceil(log2 9)
    EXPECT_EQ(r.cycles, sysc::network_cycles(r.plane.width, r.plane.height, 9).latency);
  }
}

// A volume with an axis beyond what one machine's RTL rings hold (256)
// is refused in one pass and renders as blocks (a supervolume).
TEST(SystemBlocks, VolumeBeyondTheRtlLimitRendersAsBlocks) {
  Case c;
  c.volume = R"({"synthetic": "noise", "size": [300, 18, 14], "seed": 9})";
  c.direction = "[0.1, 0.2, 1]";
  c.effects = R"("shading": true)";
  const auto [vol, regs] = test::program(c);
  ASSERT_GT(regs.dim[0], sysc::kRtlMaxDim);
  sysc::SystemConfig cfg;
  cfg.p = 4;
  cfg.levels = kRtl;
  if (!sysc::rtl_available(4)) GTEST_SKIP() << "no RTL build";
  EXPECT_THROW(sysc::check_system_limits(regs, cfg), std::invalid_argument);
  run_partitioned(c, {2, 1, 1}, 4, kRtl, Level::Rtl);
}

// Perspective (golden/blocks.hpp, "Perspective"): loosely timed machines,
// each programmed with its block's registers (SCALE_START the spacing of
// its first slice) through the host interface, and the network's leaves
// routed per pixel by the ray's quadrant, clocked at TLM and at RTL.
TEST(SystemBlocks, PerspectiveBlocksWithTheNetworkClockedAndAtRtl) {
  if (!sysc::host_interface_available(4)) GTEST_SKIP() << "the host interface of this process is built for another p";
  const test::Setup s = test::setup(R"({"volume": {"synthetic": "noise", "size": [19, 17, 16], "seed": 5},
      "shading": true, "output": {"width": 48, "height": 48},
      "view": {"projection": "perspective", "fov": 50, "eye": [11, 10, -9], "up": [0, 1, 0]}})");
  ASSERT_TRUE(s.host.regs.perspective);
  const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, {3, 2, 2}, "test");
  const golden::BasePlane want = golden::render_blocks_fixed(s.volume, plan, golden::FixedOptions{});
  sysc::SystemConfig cfg;
  cfg.p = 4;
  cfg.levels = kTlm;
  cfg.check = true;
  for (Level net_level : {Level::Tlm, Level::Rtl}) {
    if (net_level == Level::Rtl && !sysc::rtl_available(4)) continue;
    SCOPED_TRACE(net_level == Level::Rtl ? "network at RTL" : "network at clocked TLM");
    sysc::NetworkConfig net;
    net.level = net_level;
    net.cycle_level = true;
    net.check = true;
    const sysc::PartitionedResult res = sysc::render_partitioned(plan, s.volume, cfg, net);
    EXPECT_FALSE(res.mismatch) << *res.mismatch;
    EXPECT_EQ(res.network.plane.rgba, want.rgba) << "the composed base plane differs from golden";
  }
}
