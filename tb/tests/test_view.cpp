// View factorisation: permutation, flips, shear and the base-plane warp.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tb/tests/test_support.hpp"

using namespace cube4;
using golden::Vec3;

namespace {

golden::ViewFactorisation view_for(const Vec3& dir, const std::array<int, 3>& dim = {16, 16, 16},
                                   const Vec3& spacing = {1, 1, 1}) {
  golden::Scene s = golden::default_scene();
  s.view.direction = dir;
  s.view.up = std::fabs(dir[1]) > 0.9 ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
  golden::Volume v;
  v.dim = dim;
  v.spacing = spacing;
  return golden::factorise_view(s, v);
}

}  // namespace

TEST(View, SixBasePlanes) {
  const struct { Vec3 dir; int axis; bool flip; } cases[] = {
      {{1, 0, 0}, 0, false}, {{-1, 0, 0}, 0, true}, {{0, 1, 0}, 1, false},
      {{0, -1, 0}, 1, true}, {{0, 0, 1}, 2, false}, {{0, 0, -1}, 2, true}};
  for (const auto& c : cases) {
    const auto f = view_for(c.dir);
    EXPECT_EQ(f.perm[2], c.axis);
    EXPECT_EQ(f.flip[2], c.flip);
    EXPECT_EQ(f.shear_x, 0.0);
    EXPECT_EQ(f.shear_y, 0.0);
    // The eye looks back along -z in permuted space.
    EXPECT_NEAR(f.eye_perm[2], -1.0, 1e-12);
  }
}

TEST(View, ExactFortyFiveDegreesShearsOneVoxelPerSlice) {
  const auto f = view_for({1, 0, 1});
  EXPECT_NEAR(f.shear_x + f.shear_y, 1.0, 1e-12);
  golden::Scene s = golden::default_scene();
  s.view.direction = Vec3{1, 1, 1};
  s.supersampling = 4;
  golden::Volume v;
  v.dim = {8, 8, 8};
  v.data.assign(512, 0);
  const auto h = golden::program_host(s, v);
  // Diagonal view: the DDA steps exactly 1/S voxel per sample slice in x and y.
  EXPECT_EQ(h.regs.x_step, int64_t{1} << (s.precision.dda_frac_bits - 2));
  EXPECT_EQ(h.regs.y_step, int64_t{1} << (s.precision.dda_frac_bits - 2));
  EXPECT_EQ(h.regs.base_width(), 8 + 7);
}

TEST(View, RandomDirectionsKeepShearWithinOneAndRoundTrip) {
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 d{u(gen), u(gen), u(gen)};
    if (std::fabs(d[0]) + std::fabs(d[1]) + std::fabs(d[2]) < 1e-3) continue;
    const auto f = view_for(d, {12, 9, 7}, {1.0, 0.5, 2.5});
    ASSERT_GE(f.shear_x, 0.0);
    ASSERT_LE(f.shear_x, 1.0);
    ASSERT_GE(f.shear_y, 0.0);
    ASSERT_LE(f.shear_y, 1.0);
    const Vec3 p{3, 4, 5};
    const Vec3 q = f.to_object(f.to_permuted(p));
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(q[k], p[k], 1e-12);
  }
}

TEST(View, AnisotropicSpacingChoosesTheAxisInVoxelSpace) {
  // 30° from z towards x in physical space, but z voxels are 4x thicker:
  // in voxel space x dominates, so x must be the principal axis (else shear > 1).
  const double a = 30 * 3.14159265358979 / 180;
  const auto f = view_for({std::sin(a), 0, std::cos(a)}, {16, 16, 16}, {1, 1, 4});
  EXPECT_EQ(f.perm[2], 0);
  EXPECT_LE(f.shear_x, 1.0);
  EXPECT_LE(f.shear_y, 1.0);
}

TEST(View, VolumeCentreProjectsToImageCentreAndWarpIsConsistent) {
  const auto f = view_for({0.3, -0.2, 0.9}, {20, 16, 12});
  const auto c = f.image_of({9.5, 7.5, 5.5});
  EXPECT_NEAR(c[0], f.image_width / 2.0 - 0.5, 1e-9);
  EXPECT_NEAR(c[1], f.image_height / 2.0 - 0.5, 1e-9);
  // Base plane (u, v) and the permuted front-face point it stands for land on
  // the same image position.
  const golden::Affine2 a = f.base_to_image(2.25, 1.5);
  const auto via_affine = a.apply(5, 7);
  const auto direct = f.image_of(f.to_object({5 - 2.25, 7 - 1.5, 0}));
  EXPECT_NEAR(via_affine[0], direct[0], 1e-9);
  EXPECT_NEAR(via_affine[1], direct[1], 1e-9);
  const auto back = a.inverse().apply(via_affine[0], via_affine[1]);
  EXPECT_NEAR(back[0], 5, 1e-9);
  EXPECT_NEAR(back[1], 7, 1e-9);
}
