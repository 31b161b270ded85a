// The perspective dataflow's claims (golden/perspective_dataflow.hpp;
// docs/perspective.md, "The dataflow"), on which the rings' sizes rest: a
// ray's box lies within one cell before and two after its home, rays of a
// slice have distinct homes 1 to 3 cells apart, the gradient's realigned
// neighbours lie within 3 cells, and a ray's home moves by what its slope
// gives, which only the viewing direction and S bound.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "golden/perspective_dataflow.hpp"
#include "golden/renderers.hpp"
#include "tb/tests/test_support.hpp"

using namespace cube4;

namespace {

constexpr int F = 20;

std::string view(const std::string& camera, int S = 1, const std::string& size = "[40,40,40]") {
  return R"({"volume": {"synthetic": "sphere", "size": )" + size + R"(}, "supersampling": )" + std::to_string(S) +
         R"(, "view": {"projection": "perspective", )" + camera + "}}";
}

}  // namespace

TEST(PerspectiveDataflow, TheBoxLiesWithinOneCellBeforeAndTwoAfterTheHome) {
  std::mt19937_64 rng(11);
  for (int w : {2, 8, 14}) {
    for (int i = 0; i < 200000; ++i) {
      // Spacings 1, 3 and their neighbours, the limits, and anything between.
      const int64_t one = int64_t{1} << F;
      const int64_t spacing = i % 5 == 0   ? one
                              : i % 5 == 1 ? 3 * one
                              : i % 5 == 2 ? 3 * one - 1
                                           : one + static_cast<int64_t>(rng() % (2 * one + 1));
      // Positions on cell edges, just below them, and anywhere.
      const int64_t cell = static_cast<int64_t>(rng() % 300) - 100;
      const int64_t pos = i % 3 == 0 ? cell * one : i % 3 == 1 ? cell * one + one - 1
                                                               : cell * one + static_cast<int64_t>(rng() % one);
      const golden::BoxAxis b = golden::box_axis(pos, spacing, F, w);
      const int64_t home = golden::home_cell(pos, F);
      ASSERT_EQ(home, cell);
      for (int j = 0; j < 4; ++j) {
        if (b.overlap[static_cast<size_t>(j)] == 0) continue;
        ASSERT_GE(b.first + j, home - 1) << "w " << w << " pos " << pos << " spacing " << spacing;
        ASSERT_LE(b.first + j, home + 2) << "w " << w << " pos " << pos << " spacing " << spacing;
      }
    }
  }
}

TEST(PerspectiveDataflow, HomesAreDistinctOneToThreeCellsApartAndNeighboursWithinThree) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> angle(-180, 179);
  for (int i = 0; i < 60; ++i) {
    const std::string rotate = "[" + std::to_string(angle(rng)) + "," + std::to_string(angle(rng)) + "," +
                               std::to_string(angle(rng)) + "]";
    const std::string fov = std::to_string(10 + 79 * (i % 4) / 3);
    const auto s = test::setup(view(R"("fov": )" + fov + R"(, "rotate": )" + rotate, 1 + i % 3));
    const golden::PerspectiveReach r = golden::perspective_reach(s.host.regs);
    for (const golden::AxisReach* a : {&r.x, &r.y}) {
      const std::string where = "fov " + fov + " rotate " + rotate;
      EXPECT_GE(a->box.lo, -1) << where;
      EXPECT_LE(a->box.hi, 2) << where;
      EXPECT_GE(a->next.lo, 1) << where;
      EXPECT_LE(a->next.hi, 3) << where;
      for (const golden::CellRange& z : {a->behind, a->ahead}) {
        EXPECT_GE(z.lo, -3) << where;
        EXPECT_LE(z.hi, 3) << where;
      }
    }
  }
}

TEST(PerspectiveDataflow, AlongAnAxisRaysMoveAtMostOneCellASliceWhateverTheField) {
  // With the eye on the axis the rays are under 45 degrees from it.
  for (const char* fov : {"10", "45", "89"}) {
    const auto s = test::setup(view(std::string(R"("fov": )") + fov));
    EXPECT_EQ(golden::largest_home_move(golden::perspective_reach(s.host.regs)), 1) << "fov " << fov;
  }
}

TEST(PerspectiveDataflow, ObliqueWideViewsMoveFurtherAndSupersamplingHalvesTheMoves) {
  // A diagonal view with a wide field: the outer rays are far steeper than
  // 45 degrees from the principal axis (the table in docs/perspective.md).
  const std::string camera = R"("fov": 80, "rotate": [35, 45, 0])";
  const int64_t s1 = golden::largest_home_move(golden::perspective_reach(test::setup(view(camera, 1)).host.regs));
  const int64_t s2 = golden::largest_home_move(golden::perspective_reach(test::setup(view(camera, 2)).host.regs));
  EXPECT_GE(s1, 2);
  EXPECT_LT(s2, s1);
}

TEST(PerspectiveDataflow, TheSamplesAreTheRenderersOwn) {
  for (const char* camera : {R"("fov": 30)", R"("fov": 70, "rotate": [20, -30, 10])"}) {
    const auto s = test::setup(view(camera, 2, "[24,30,20]"));
    golden::RenderStats stats;
    golden::FixedOptions opt;
    opt.stats = &stats;
    golden::render_fixed(s.volume, s.host.regs, opt);
    EXPECT_EQ(golden::perspective_reach(s.host.regs).samples, stats.samples) << camera;
  }
}
