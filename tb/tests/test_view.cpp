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

// The camera of the parallel projection: zoom scales the image about its
// centre, look_at moves a point of the volume there; object_of_image stays
// the inverse of image_of on the image plane.
TEST(View, ZoomScalesAboutTheImageCentreAndLookAtCentresItsPoint) {
  golden::Scene s = golden::default_scene();
  s.view.direction = Vec3{0.3, -0.2, 0.9};
  golden::Volume v;
  v.dim = {20, 16, 12};
  const auto plain = golden::factorise_view(s, v);
  s.view.zoom = 2.5;
  const auto zoomed = golden::factorise_view(s, v);
  const double cx = plain.image_width / 2.0 - 0.5, cy = plain.image_height / 2.0 - 0.5;
  for (const Vec3& p : {Vec3{0, 0, 0}, Vec3{19, 15, 11}, Vec3{3, 12, 7}}) {
    const auto a = plain.image_of(p), b = zoomed.image_of(p);
    EXPECT_NEAR(b[0] - cx, 2.5 * (a[0] - cx), 1e-9);
    EXPECT_NEAR(b[1] - cy, 2.5 * (a[1] - cy), 1e-9);
  }
  s.view.look_at = Vec3{0, 15, 11};
  const auto aimed = golden::factorise_view(s, v);
  const auto c = aimed.image_of({0, 15, 11});
  EXPECT_NEAR(c[0], cx, 1e-9);
  EXPECT_NEAR(c[1], cy, 1e-9);
  for (const auto& f : {plain, zoomed, aimed}) {
    const auto back = f.image_of(f.object_of_image(40.25, 97.5));
    EXPECT_NEAR(back[0], 40.25, 1e-9);
    EXPECT_NEAR(back[1], 97.5, 1e-9);
  }
}

// The camera is the host's business: the registers, and so the base plane,
// are those of the default camera; only the warp differs.
TEST(View, TheCameraLeavesTheBasePlaneAlone) {
  const std::string volume = R"({"volume": {"synthetic": "sphere", "size": [12, 10, 9]}, "view": {"direction": [0.3, -0.2, 0.9])";
  const test::Setup a = test::setup(volume + "}}");
  const test::Setup b = test::setup(volume + R"(, "zoom": 3, "look_at": [2, 8, 1]}})");
  const golden::BasePlane pa = golden::render_fixed(a.volume, a.host.regs), pb = golden::render_fixed(b.volume, b.host.regs);
  EXPECT_EQ(pa.rgba, pb.rgba);
  EXPECT_EQ(pa.width, pb.width);
  EXPECT_NE(test::final_fixed(a).rgba, test::final_fixed(b).rgba);
}

// x/y supersampling's frames: n² scenes whose rays start (i, j) / n of a
// pixel after the scene's offset, wrapped into [0, 1), row by row; n = 1 is
// the scene itself. Their blend is the plain mean.
TEST(View, XySubframesOffsetTheRaysByFractionsOfAPixel) {
  golden::Scene s = golden::default_scene();
  s.view.ray_offset = {0.5, 0.25};
  const auto one = golden::xy_subframes(s);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].view.ray_offset, s.view.ray_offset);
  s.xy_supersampling = 4;
  const auto f = golden::xy_subframes(s);
  ASSERT_EQ(f.size(), 16u);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const auto& o = f[static_cast<size_t>(j * 4 + i)].view.ray_offset;
      EXPECT_DOUBLE_EQ(o[0], std::fmod(0.5 + i / 4.0, 1.0)) << i << " " << j;
      EXPECT_DOUBLE_EQ(o[1], std::fmod(0.25 + j / 4.0, 1.0)) << i << " " << j;
      EXPECT_GE(o[0], 0.0);
      EXPECT_LT(o[0], 1.0);
    }
  golden::ImageF a, b;
  a.width = b.width = 2;
  a.height = b.height = 1;
  a.rgba = {0, 1, 0.5f, 1, 0.25f, 0, 0, 0};
  b.rgba = {1, 0, 0.5f, 0, 0.75f, 1, 0, 1};
  const golden::ImageF m = golden::blend_frames({a, b});
  EXPECT_EQ(m.rgba, (std::vector<float>{0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0, 0.5f}));
  b.width = 1;
  b.rgba.resize(4);
  EXPECT_THROW(golden::blend_frames({a, b}), std::invalid_argument);
}
