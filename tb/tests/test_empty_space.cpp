// The fixed renderer's empty-space skipping and threads: neither may change
// a single bit of the base plane (golden/empty_space.hpp,
// golden/render_fixed.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tb/tests/test_support.hpp"

using namespace cube4;

namespace {

// Every sample computed and shaded: the probe turns all skipping off.
struct SeeAll : golden::SampleProbe {
  void sample(int, int, const golden::SliceControl&, uint32_t, const golden::Gradient&) override {}
};

golden::BasePlane render(const test::Setup& s, int threads, bool skip) {
  golden::FixedOptions o;
  o.threads = threads;
  o.skip_empty = skip;
  return golden::render_fixed(s.volume, s.host.regs, o);
}

int64_t alpha_sum(const golden::BasePlane& bp) {
  int64_t a = 0;
  for (size_t i = 3; i < bp.rgba.size(); i += 4) a += bp.rgba[i];
  return a;
}

// The fraction of the frame's cells the skip map keeps.
double kept_fraction(const test::Setup& s) {
  const golden::BlockRanges ranges = golden::block_ranges(s.volume);
  const golden::SkipMap map(s.host.regs, &ranges);
  if (!map.skipping()) return 1.0;
  const auto& d = s.host.regs.dim;
  double kept = 0;
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y) kept += map.visible(z, y).size();
  return kept / (static_cast<double>(d[0]) * d[1] * d[2]);
}

void expect_exact(const test::Setup& s, const std::string& what, bool expect_skipping = true) {
  SeeAll all;
  const golden::BasePlane every = golden::render_fixed(s.volume, s.host.regs, nullptr, {}, &all);
  const golden::BasePlane skipped = render(s, 1, true);
  EXPECT_GT(alpha_sum(every), 0) << what;
  EXPECT_EQ(skipped.rgba, every.rgba) << what;
  const double kept = kept_fraction(s);
  if (expect_skipping) {
    EXPECT_LT(kept, 0.75) << what << ": the test needs empty space to skip";
  }
  std::printf("%s: %.1f %% of the cells kept\n", what.c_str(), 100 * kept);
}

std::string brainsmall(const std::string& rest) {
  return R"({"volume": {"file": ")" + golden::default_brainsmall_path() + R"("}, )" + rest + "}";
}

}  // namespace

TEST(EmptySpace, SkippingIsExactOnBrainsmall) {
  const std::vector<std::string> views = {R"("view": {"rotate": [20, 60, 180]})", R"("view": {"rotate": [0, 0, 0]})",
                                          R"("view": {"rotate": [90, 0, 0]})", R"("view": {"rotate": [-35, 10, 75]})",
                                          R"("view": {"rotate": [170, -80, 33]})"};
  for (const std::string& v : views) expect_exact(test::setup(brainsmall(v)), "brainsmall " + v);
  // Supersampled, a narrow opacity band, gradient-modulated opacity, cut and crop.
  expect_exact(test::setup(brainsmall(R"("view": {"rotate": [45, 45, 45]}, "supersampling": 2)")),
               "brainsmall S = 2");
  expect_exact(test::setup(brainsmall(R"("view": {"rotate": [30, 100, 10]},
      "transfer": {"color": [[0, 1, 0.5, 0.2], [1, 0.3, 0.6, 1]], "opacity": [[0, 0], [0.6, 0], [0.62, 0.05], [1, 0.05]]},
      "gradient_modulation": {"opacity": true, "diffuse": true, "specular": true})")),
               "brainsmall narrow band, modulated");
  expect_exact(test::setup(brainsmall(R"("view": {"rotate": [-15, 130, 0]},
      "cropping": {"x": [0, 63], "y": [40, 127], "combine": "intersection", "invert": true},
      "cut_plane": {"normal": [1, 0, 1], "dmin": 60, "dmax": 90, "falloff": 4, "keep": "outside"})")),
               "brainsmall cropped and cut");
}

TEST(EmptySpace, SkippingIsExactOnSmoothFieldsWithEmptyNeighbours) {
  // A Gaussian blob: the outside is empty but not zero, so the gradients of
  // the visible shell read samples of skipped blocks; a missing or stale one
  // would change them.
  for (const std::string view : {R"({"rotate": [20, 30, 0]})", R"({"rotate": [-50, 200, 15]})",
                                  R"({"direction": [1, 1, 1], "up": [0, 1, 0]})"})
    for (int S : {1, 3})
      expect_exact(test::setup(R"({"volume": {"synthetic": "field", "field": "gaussian", "size": [45, 38, 52]},
          "view": )" + view + R"(, "supersampling": )" + std::to_string(S) + R"(,
          "transfer": {"opacity": [[0, 0], [0.55, 0], [0.6, 0.3], [1, 0.9]]}})"),
                   "gaussian " + view + " S = " + std::to_string(S));
}

TEST(EmptySpace, BlocksOfInvisibleValuesWhoseInterpolationIsVisibleAreKept) {
  // 8-voxel blocks of 0 and full scale, only the middle of the range
  // visible: no voxel is visible, but samples between two blocks are. The
  // blocks overlap by one voxel for exactly this.
  auto s = test::setup(R"({"volume": {"synthetic": "constant", "size": [32, 24, 40], "value": 0},
      "view": {"rotate": [17, 29, 3]},
      "transfer": {"opacity": [[0, 0], [0.3, 0], [0.4, 1], [0.6, 1], [0.7, 0], [1, 0]]}})");
  const uint16_t full = static_cast<uint16_t>(s.volume.max_value());
  for (int z = 0; z < s.volume.dim[2]; ++z)
    for (int y = 0; y < s.volume.dim[1]; ++y)
      for (int x = 0; x < s.volume.dim[0]; ++x)
        s.volume.data[s.volume.index(x, y, z)] = ((x / 8 + y / 8 + z / 8) & 1) ? full : 0;
  s.host = golden::program_host(s.scene, s.volume);
  expect_exact(s, "checkerboard of blocks", false);
}

TEST(EmptySpace, NothingIsSkippedForMipOrMinIp) {
  // An α = 0 sample still competes for the maximum (it is only invisible
  // once cropped or cut), so the skip map keeps everything.
  for (const char* blend : {"mip", "minip"}) {
    const auto s = test::setup(brainsmall(std::string(R"("blend": ")") + blend + R"(", "shading": false,
        "transfer": {"opacity": [[0, 0.2], [1, 1]]})"));
    EXPECT_EQ(kept_fraction(s), 1.0) << blend;
    expect_exact(s, blend, false);
  }
}

TEST(EmptySpace, StoppedRaysAreExactAndSaveShading) {
  // Thin translucent material everywhere above a low threshold: rays keep a
  // little transparency over long stretches, where their pixel is settled
  // long before their α is full.
  for (const char* view : {R"([20, 60, 180])", R"([-35, 10, 75])"}) {
    const auto s = test::setup(brainsmall(std::string(R"("view": {"rotate": )") + view + R"(},
        "transfer": {"opacity": [[0, 0], [0.05, 0], [0.1, 0.2], [0.3, 0.6], [1, 0.7]]})"));
    SeeAll all;
    golden::FixedOptions every;
    every.probe = &all;
    every.accumulators = true;
    const golden::BasePlane reference = golden::render_fixed(s.volume, s.host.regs, every);
    golden::RenderStats full_alpha, settled;
    golden::FixedOptions o;
    o.accumulators = true;  // only rays of full α may stop: their accumulators are final
    o.stats = &full_alpha;
    const golden::BasePlane with_acc = golden::render_fixed(s.volume, s.host.regs, o);
    EXPECT_EQ(with_acc.acc, reference.acc) << view;
    EXPECT_EQ(with_acc.rgba, reference.rgba) << view;
    o.accumulators = false;  // rays stop once their pixel is settled
    o.stats = &settled;
    EXPECT_EQ(golden::render_fixed(s.volume, s.host.regs, o).rgba, reference.rgba) << view;
    o.threads = 3;
    EXPECT_EQ(golden::render_fixed(s.volume, s.host.regs, o).rgba, reference.rgba) << view;
    EXPECT_GT(settled.shaded, 0u);
    EXPECT_LT(settled.shaded, full_alpha.shaded) << view;
    EXPECT_LT(full_alpha.shaded, full_alpha.samples) << view;
    std::printf("%s: %llu samples shaded with rays stopped at full alpha, %llu at a settled pixel\n", view,
                static_cast<unsigned long long>(full_alpha.shaded), static_cast<unsigned long long>(settled.shaded));
  }
}

TEST(EmptySpace, EveryThreadCountGivesTheSameImage) {
  const std::vector<test::Setup> scenes = {
      test::setup(brainsmall(R"("view": {"rotate": [20, 60, 180]})")),
      test::setup(brainsmall(R"("view": {"rotate": [45, 45, 45]}, "supersampling": 2, "blend": "mip")")),
      test::setup(R"({"volume": {"synthetic": "sphere", "size": [24, 20, 28]},
          "view": {"direction": [1, 0, 1], "up": [0, 1, 0]}})"),
      test::setup(R"({"volume": {"synthetic": "constant", "size": [2, 2, 2], "value": 1},
          "view": {"direction": [0.6, -0.5, 0.7]}})"),
  };
  for (size_t i = 0; i < scenes.size(); ++i) {
    const golden::BasePlane one = render(scenes[i], 1, true);
    EXPECT_GT(alpha_sum(one), 0) << i;
    for (int threads : {2, 3, 4, 7, 16, 1000})
      for (bool skip : {true, false})
        EXPECT_EQ(render(scenes[i], threads, skip).rgba, one.rgba)
            << "scene " << i << ", " << threads << " threads, skipping " << skip;
  }
}

TEST(EmptySpace, BlockRangesGivenOnceAreTheOnesUsed) {
  // A caller rendering many frames of one volume builds its ranges once
  // (FixedOptions::ranges, as `cube4 render --repeat` and bench_golden
  // --ranges volume do): the same image as ranges built inside the frame.
  const auto s = test::setup(brainsmall(R"("view": {"rotate": [20, 60, 180]})"));
  const golden::BlockRanges once = golden::block_ranges(s.volume);
  golden::FixedOptions o;
  o.threads = 1;
  o.ranges = &once;
  const golden::BasePlane given = golden::render_fixed(s.volume, s.host.regs, o);
  EXPECT_GT(alpha_sum(given), 0);
  EXPECT_EQ(given.rgba, render(s, 1, true).rgba);
  // And they are used, not rebuilt: a volume of zeros of the same size has
  // no block that can change a ray, so its ranges skip everything.
  golden::Volume zeros = s.volume;
  std::fill(zeros.data.begin(), zeros.data.end(), uint16_t{0});
  const golden::BlockRanges empty = golden::block_ranges(zeros);
  o.ranges = &empty;
  EXPECT_EQ(alpha_sum(golden::render_fixed(s.volume, s.host.regs, o)), 0);
}
