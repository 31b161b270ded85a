// Sub-cubes (golden/blocks.hpp): the plan, the blocks' registers and
// volumes, and the composed image against the one-pass render.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "golden/blocks.hpp"
#include "golden/errors.hpp"
#include "systemc/core/compose_network.hpp"
#include "tb/tests/test_support.hpp"

using namespace cube4;

namespace {

std::string view_dir(double x, double y, double z) {
  const bool vertical = std::fabs(y) > std::fabs(x) && std::fabs(y) > std::fabs(z);
  return R"("view": {"direction": [)" + std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(z) +
         R"(], "up": )" + (vertical ? "[0, 0, 1]" : "[0, 1, 0]") + "}";
}

// Oblique views near each of the six base planes, so that every permutation
// and flip runs with a shear in both directions.
const double kViews[][3] = {{0.3, 0.2, 1}, {-0.25, 0.3, -1}, {1, -0.3, 0.2},
                            {-1, 0.2, -0.35}, {0.2, 1, 0.3}, {-0.3, -1, -0.2}};

std::string noise_scene(const std::string& view, const std::string& extra) {
  return R"({"volume": {"synthetic": "noise", "size": [23, 19, 17], "seed": 11},
             "transfer": {"color": [[0, 0, 0.5, 1], [1, 1, 1, 0]], "opacity": [[0, 0.1], [1, 0.9]]},
             "output": {"width": 48, "height": 48}, )" +
         view + extra + "}";
}

std::string sphere_scene(const std::string& view, const std::string& extra) {
  return R"({"volume": {"synthetic": "sphere", "size": [26, 22, 20]},
             "output": {"width": 48, "height": 48}, )" +
         view + extra + "}";
}

golden::BasePlane partitioned(const test::Setup& s, const std::array<int, 3>& counts) {
  const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, counts, "--blocks");
  return golden::render_blocks_fixed(s.volume, plan, golden::FixedOptions{});
}

// The largest channel difference between two base planes, in LSBs.
int max_difference(const golden::BasePlane& a, const golden::BasePlane& b) {
  int worst = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) worst = std::max(worst, std::abs(int{a.rgba[i]} - int{b.rgba[i]}));
  return worst;
}

// The derived bound on |partitioned - one pass| per channel, in base-plane
// LSBs, for rays of at most N samples through a composition tree of depth d
// (docs/fixed-point.md, "Partitioned compositing"): in accumulator LSBs
// one pass is within 2N of exact arithmetic on the same samples (colour; N
// for α), the partitioned image within 2N + d(N + d) + d, and pixel_of()
// turns an accumulator difference D into at most ceil(D / 2^g) + 1.
int partition_bound(const golden::Precision& p, int samples, int blocks) {
  const int d = static_cast<int>(std::ceil(std::log2(std::max(blocks, 1))));
  const double acc = 2.0 * samples + (2.0 * samples + d * (samples + d) + d);
  return static_cast<int>(std::ceil(acc / std::ldexp(1.0, p.acc_guard_bits))) + 1;
}

// Every block's partial image (golden), and pointers to them in plan order.
struct Partials {
  std::vector<golden::BasePlane> planes;
  std::vector<const golden::BasePlane*> ptrs;
};
Partials render_partials(const golden::Volume& vol, const golden::BlockPlan& plan) {
  Partials p;
  for (const golden::Block& b : plan.blocks) p.planes.push_back(golden::render_block_fixed(golden::block_volume(vol, b), b, {}));
  for (const auto& x : p.planes) p.ptrs.push_back(&x);
  return p;
}

}  // namespace

TEST(Blocks, OneBlockIsTheOnePassRender) {
  const auto s = test::setup(sphere_scene(view_dir(0.3, 0.2, 1), ""));
  const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, {1, 1, 1}, "--blocks");
  ASSERT_EQ(plan.blocks.size(), 1u);
  const golden::Block& b = plan.blocks[0];
  EXPECT_FALSE(b.regs.window_enabled);
  EXPECT_EQ(b.regs.x_start, s.host.regs.x_start);
  EXPECT_EQ(b.regs.dim, s.host.regs.dim);
  EXPECT_EQ(b.u0, 0);
  EXPECT_EQ(b.v0, 0);
  const golden::BasePlane one = golden::render_fixed(s.volume, s.host.regs);
  EXPECT_EQ(partitioned(s, {1, 1, 1}).rgba, one.rgba);
}

TEST(Blocks, CoresTileTheVolumeAndBordersStayInside) {
  const auto s = test::setup(sphere_scene(view_dir(-1, 0.2, -0.35), ""));
  const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, {3, 2, 4}, "--blocks");
  ASSERT_EQ(plan.blocks.size(), 24u);
  std::vector<int> owner(size_t{64} * 64 * 64, 0);  // permuted axes below 64
  for (const golden::Block& b : plan.blocks) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_LE(b.store_lo[i], b.core_lo[i]);
      EXPECT_GE(b.store_hi[i], b.core_hi[i]);
      EXPECT_GE(b.core_hi[i] - b.core_lo[i], golden::kMinBlockCore);
      EXPECT_EQ(b.regs.dim[i], b.store_hi[i] - b.store_lo[i]);
    }
    EXPECT_TRUE(b.regs.window_enabled);
    // Count each permuted voxel's owners through the object box of the core.
    for (int z = b.core_lo[2]; z < b.core_hi[2]; ++z)
      for (int y = b.core_lo[1]; y < b.core_hi[1]; ++y)
        for (int x = b.core_lo[0]; x < b.core_hi[0]; ++x) ++owner[(static_cast<size_t>(z) * 64 + y) * 64 + x];
  }
  // Every voxel of the permuted volume is in exactly one core.
  const auto& d = s.host.regs.dim;
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x) ASSERT_EQ(owner[(static_cast<size_t>(z) * 64 + y) * 64 + x], 1);
}

TEST(Blocks, BlockVolumeHoldsTheVolumesVoxels) {
  const auto s = test::setup(noise_scene(view_dir(-0.3, -1, -0.2), R"(, "shading": false)"));
  const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, {2, 3, 2}, "--blocks");
  for (const golden::Block& b : plan.blocks) {
    const golden::Volume v = golden::block_volume(s.volume, b);
    ASSERT_EQ(v.dim, b.object_dim);
    for (int z = 0; z < v.dim[2]; ++z)
      for (int y = 0; y < v.dim[1]; ++y)
        for (int x = 0; x < v.dim[0]; ++x)
          ASSERT_EQ(v.at(x, y, z), s.volume.at(x + b.object_lo[0], y + b.object_lo[1], z + b.object_lo[2]));
  }
}

// MIP and MinIP select and never round, so a partitioned render is the one
// pass render exactly: a sample composited twice cannot show, but one
// missing or a wrong merge order does (ties keep the front block).
TEST(Blocks, MipAndMinIpEqualOnePassFromEveryBasePlane) {
  for (const char* blend : {"mip", "minip"})
    for (const char* shading : {R"(, "shading": false)", ""})
      for (const auto& v : kViews) {
        const auto s = test::setup(noise_scene(view_dir(v[0], v[1], v[2]),
                                               std::string(R"(, "blend": ")") + blend + "\"" + shading));
        const golden::BasePlane one = golden::render_fixed(s.volume, s.host.regs);
        for (const std::array<int, 3>& counts : {std::array<int, 3>{2, 2, 2}, {3, 1, 2}, {1, 4, 1}})
          ASSERT_EQ(partitioned(s, counts).rgba, one.rgba)
              << blend << shading << " view " << v[0] << "," << v[1] << "," << v[2] << " blocks " << counts[0]
              << "x" << counts[1] << "x" << counts[2];
      }
}

TEST(Blocks, MipWithCroppingAndCutPlaneEqualsOnePass) {
  const auto s = test::setup(noise_scene(
      view_dir(0.3, 0.2, 1), R"(, "blend": "mip", "shading": false,
      "cropping": {"x": [3, 15], "y": [2, 12], "combine": "union"},
      "cut_plane": {"normal": [1, 2, 1], "dmin": 8, "dmax": 20, "falloff": 3})"));
  ASSERT_TRUE(s.host.regs.crop_enabled && s.host.regs.cut_enabled);
  const golden::BasePlane one = golden::render_fixed(s.volume, s.host.regs);
  EXPECT_EQ(partitioned(s, {2, 2, 2}).rgba, one.rgba);
  EXPECT_EQ(partitioned(s, {3, 4, 1}).rgba, one.rgba);
}

// Front-to-back compositing rounds at every merge: the partitioned image
// stays within the derived bound of the one pass image, for shaded and
// translucent material, supersampling, cropping and the cut plane.
TEST(Blocks, CompositeStaysWithinTheDerivedBoundOfOnePass) {
  const std::string cases[] = {"", R"(, "supersampling": 2)",
                               R"(, "cropping": {"x": [3, 15], "z": [2, 12], "combine": "cross"})",
                               R"(, "cut_plane": {"normal": [1, -1, 2], "dmin": 4, "dmax": 14, "falloff": 2})"};
  for (const std::string& extra : cases)
    for (const auto& v : kViews) {
      for (bool sphere : {true, false}) {
        const auto s = test::setup(sphere ? sphere_scene(view_dir(v[0], v[1], v[2]), extra)
                                          : noise_scene(view_dir(v[0], v[1], v[2]), extra));
        const golden::BasePlane one = golden::render_fixed(s.volume, s.host.regs);
        for (const std::array<int, 3>& counts : {std::array<int, 3>{2, 2, 2}, {4, 1, 3}}) {
          const int blocks = counts[0] * counts[1] * counts[2];
          const int bound = partition_bound(s.host.regs.p, s.host.regs.sample_slices(), blocks);
          EXPECT_LE(max_difference(partitioned(s, counts), one), bound) << extra << " view " << v[0] << "," << v[1];
        }
      }
    }
}

// The composed image puts each block where the plan says: a plan whose
// blocks are composed in the reverse order shows a front block behind a
// back one, far beyond the rounding bound.
TEST(Blocks, ReversedOrderIsFarFromOnePass) {
  const auto s = test::setup(noise_scene(view_dir(0.3, 0.2, 1), R"(, "shading": false)"));
  const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, {1, 1, 2}, "--blocks");
  golden::BlockPlan reversed = plan;
  std::reverse(reversed.blocks.begin(), reversed.blocks.end());
  const Partials parts = render_partials(s.volume, reversed);
  const std::vector<const golden::BasePlane*>& ptrs = parts.ptrs;
  const golden::BasePlane one = golden::render_fixed(s.volume, s.host.regs);
  EXPECT_LE(max_difference(golden::compose_blocks(plan, {ptrs.rbegin(), ptrs.rend()}), one),
            partition_bound(s.host.regs.p, s.host.regs.sample_slices(), 2));
  EXPECT_GT(max_difference(golden::compose_blocks(reversed, ptrs), one), 1000);
}

TEST(Blocks, BlocksThatDoNotDivideSensiblyAreRefused) {
  const auto s = test::setup(sphere_scene(view_dir(0.3, 0.2, 1), ""));
  auto message = [&](const std::array<int, 3>& counts) {
    try {
      golden::plan_blocks(s.host.regs, s.volume.dim, counts, "--blocks");
    } catch (const golden::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({0, 1, 1}).find("x 0 blocks"), std::string::npos);
  EXPECT_NE(message({1, 6, 1}).find("at least 4"), std::string::npos);  // 22 / 6 = 3 voxels
  EXPECT_NE(message({1, 6, 1}).find("at most 5 blocks along y"), std::string::npos);
  EXPECT_EQ(message({1, 5, 1}), "");
}

// The composition network's clocked TLM nodes (golden compose() with the
// RTL's latencies) against golden compose_blocks() and the cycle model, for
// trees of every shape up to nine images (unequal halves need the skew
// registers), on the plain loop and on the SystemC kernel.
TEST(ComposeNetwork, ClockedTlmEqualsGoldenForEveryTreeShape) {
  const auto s = test::setup(noise_scene(view_dir(0.3, 0.2, 1), ""));
  const std::array<int, 3> shapes[] = {{1, 1, 1}, {2, 1, 1}, {3, 1, 1}, {2, 2, 1}, {5, 1, 1},
                                       {3, 2, 1}, {2, 2, 2}, {3, 3, 1}};
  for (sysc::Kernel kernel : {sysc::Kernel::PlainLoop, sysc::Kernel::SystemC})
    for (const auto& counts : shapes) {
      const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, counts, "test");
      const Partials parts = render_partials(s.volume, plan);
      const std::vector<const golden::BasePlane*>& ptrs = parts.ptrs;
      sysc::NetworkConfig net;
      net.cycle_level = true;
      net.kernel = kernel;
      net.check = true;
      const sysc::NetworkResult r = sysc::run_network(plan, ptrs, net);
      const int n = static_cast<int>(plan.blocks.size());
      SCOPED_TRACE(std::to_string(n) + " images");
      EXPECT_FALSE(r.mismatch) << *r.mismatch;
      EXPECT_EQ(r.plane.rgba, golden::compose_blocks(plan, ptrs).rgba);
      EXPECT_EQ(r.nodes, n - 1);
      EXPECT_EQ(r.cycles, sysc::network_cycles(r.plane.width, r.plane.height, n).latency);
      EXPECT_EQ(r.depth, static_cast<int>(std::ceil(std::log2(n))));
    }
}

TEST(ComposeNetwork, PartialImagesThatDoNotFitThePlanAreRefused) {
  const auto s = test::setup(noise_scene(view_dir(0.3, 0.2, 1), ""));
  const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, {2, 1, 1}, "test");
  const golden::BasePlane one = golden::render_block_fixed(golden::block_volume(s.volume, plan.blocks[0]),
                                                           plan.blocks[0], {});
  // One image for two blocks, and an image without its accumulators.
  golden::BasePlane pixels_only = one;
  pixels_only.acc.clear();
  EXPECT_THROW(sysc::run_network(plan, {&one}, {}), std::invalid_argument);
  EXPECT_THROW(sysc::run_network(plan, {&one, &pixels_only}, {}), std::invalid_argument);
}

// ---- perspective (golden/blocks.hpp, "Perspective") ----

namespace {

// Eyes in front of each face of the 23 x 19 x 17 volumes, a little off its
// middle. The view's flips put the eye on the low side of the middle (most
// rays move towards +x and +y); the rays between the eye and a block
// boundary below it move the other way and cross it: every quadrant's block
// order runs.
const char* const kEyes[6] = {"[13, 11, -22]", "[13, 11, 40]", "[-26, 11, 10]", "[50, 11, 10]", "[13, -24, 10]", "[13, 44, 10]"};
// As near as the box filter allows (the last slice's rays almost 3 voxels
// apart): the widest reach of a core sample's reads.
const char* const kNearEyes[3] = {"[13, 11, -8.6]", "[-11.6, 11, 10]", "[13, 28, 10]"};
std::string eye_view(const char* eye) {
  return std::string(R"("view": {"projection": "perspective", "fov": 50, "eye": )") + eye + R"(, "up": [1, 1, 1]})";
}

}  // namespace

TEST(BlocksPerspective, OneBlockIsTheOnePassRender) {
  const auto s = test::setup(sphere_scene(eye_view(kEyes[0]), ""));
  ASSERT_TRUE(s.host.regs.perspective);
  const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, {1, 1, 1}, "--blocks");
  EXPECT_EQ(plan.blocks[0].regs.scale_start, s.host.regs.scale_start);
  EXPECT_EQ(plan.blocks[0].u0, 0);
  EXPECT_EQ(partitioned(s, {1, 1, 1}).rgba, golden::render_fixed(s.volume, s.host.regs).rgba);
}

// The blocks sample the volume's rays at the volume's positions (a block
// deeper in starts at a wider spacing), read every voxel their core's
// samples and gradients read (the wider lateral border), and are merged in
// each ray's own order: MIP and MinIP equal the one-pass image exactly.
TEST(BlocksPerspective, MipAndMinIpEqualOnePassFromEveryFace) {
  for (const char* blend : {"mip", "minip"})
    for (const char* shading : {R"(, "shading": false)", ""})
      for (const char* eye : {kEyes[0], kEyes[1], kEyes[2], kEyes[3], kEyes[4], kEyes[5], kNearEyes[0], kNearEyes[1],
                              kNearEyes[2]}) {
        const auto s = test::setup(noise_scene(eye_view(eye), std::string(R"(, "blend": ")") + blend + "\"" + shading));
        ASSERT_TRUE(s.host.regs.perspective);
        const golden::BasePlane one = golden::render_fixed(s.volume, s.host.regs);
        for (const std::array<int, 3>& counts : {std::array<int, 3>{2, 2, 2}, {3, 1, 2}, {1, 4, 1}}) {
          const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, counts, "--blocks");
          for (const golden::Block& b : plan.blocks) ASSERT_GE(b.regs.scale_start, s.host.regs.scale_start);
          ASSERT_EQ(golden::render_blocks_fixed(s.volume, plan, {}).rgba, one.rgba)
              << blend << shading << " eye " << eye << " blocks " << counts[0] << "x" << counts[1] << "x" << counts[2];
        }
      }
}

TEST(BlocksPerspective, CompositeStaysWithinTheDerivedBoundOfOnePass) {
  for (const char* extra : {"", R"(, "supersampling": 2, "cut_plane": {"normal": [1, -1, 2], "dmin": 4, "dmax": 14})"})
    for (const char* eye : kEyes) {
      const auto s = test::setup(sphere_scene(eye_view(eye), extra));
      const golden::BasePlane one = golden::render_fixed(s.volume, s.host.regs);
      for (const std::array<int, 3>& counts : {std::array<int, 3>{2, 2, 2}, {4, 1, 3}}) {
        const int bound = partition_bound(s.host.regs.p, s.host.regs.sample_slices(), counts[0] * counts[1] * counts[2]);
        EXPECT_LE(max_difference(partitioned(s, counts), one), bound) << extra << " eye " << eye;
      }
    }
}

// One order for every ray, the parallel projection's, merges the blocks of
// the rays moving towards -x or -y back to front: far from the one pass.
TEST(BlocksPerspective, EachRayNeedsItsOwnOrder) {
  const auto s = test::setup(noise_scene(eye_view(kEyes[0]), R"(, "shading": false)"));
  const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, {4, 4, 1}, "--blocks");
  ASSERT_NE(plan.order[1], plan.order[0]);
  ASSERT_NE(plan.order[2], plan.order[0]);
  golden::BlockPlan one_order = plan;
  one_order.order.fill(plan.order[0]);
  const Partials parts = render_partials(s.volume, plan);
  const std::vector<const golden::BasePlane*>& ptrs = parts.ptrs;
  const golden::BasePlane one = golden::render_fixed(s.volume, s.host.regs);
  EXPECT_LE(max_difference(golden::compose_blocks(plan, ptrs), one), partition_bound(s.host.regs.p, 17, 16));
  EXPECT_GT(max_difference(golden::compose_blocks(one_order, ptrs), one), 1000);
}

// The network's leaves take the blocks in each pixel's order: clocked TLM
// equals golden for a perspective plan too.
TEST(BlocksPerspective, ClockedNetworkRoutesEachPixelsOrder) {
  const auto s = test::setup(noise_scene(eye_view(kEyes[3]), ""));
  for (const std::array<int, 3>& counts : {std::array<int, 3>{2, 2, 1}, {3, 2, 1}}) {
    const golden::BlockPlan plan = golden::plan_blocks(s.host.regs, s.volume.dim, counts, "test");
    const Partials parts = render_partials(s.volume, plan);
    const std::vector<const golden::BasePlane*>& ptrs = parts.ptrs;
    sysc::NetworkConfig net;
    net.cycle_level = true;
    net.kernel = sysc::Kernel::PlainLoop;
    net.check = true;
    const sysc::NetworkResult r = sysc::run_network(plan, ptrs, net);
    EXPECT_FALSE(r.mismatch) << *r.mismatch;
    EXPECT_EQ(r.plane.rgba, golden::compose_blocks(plan, ptrs).rgba);
  }
}
