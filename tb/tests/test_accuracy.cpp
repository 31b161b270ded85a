// Accuracy of the fixed-point model against the same algorithm in float, and
// of both against the independent image-order reference; the published
// 12-neighbourhood gradient check. Bounds and their derivation:
// docs/accuracy.md.
#include <gtest/gtest.h>

#include <cmath>

#include "golden/shading_model.hpp"
#include "tb/tests/sphere_normals.hpp"
#include "tb/tests/test_support.hpp"

using namespace cube4;

namespace {

// Largest difference between a bilinearly interpolated fixed-point map and
// the exact intensity it samples, over a fine grid of directions: the map
// resolution's share of the fixed-vs-float error budget.
double map_interpolation_error(const test::Setup& s, const std::vector<uint32_t>& map, bool specular) {
  const golden::Precision& p = s.scene.precision;
  const golden::Lighting L = golden::lighting_of(s.scene, s.host.view);
  double worst = 0;
  for (int face = 0; face < 6; ++face)
    for (int i = 0; i <= 56; ++i)
      for (int j = 0; j <= 56; ++j) {
        const golden::Vec3 d = golden::map_direction(face, i, j, 57);
        int32_t g[3];
        for (int c = 0; c < 3; ++c) g[c] = static_cast<int32_t>(std::lround(d[c] * 120));
        const double fixed = golden::reflectance_lookup(map, golden::cube_coordinates(g[0], g[1], g[2], p), p) /
                             std::ldexp(1.0, p.map_frac_bits);
        const golden::Vec3 gd{double(g[0]), double(g[1]), double(g[2])};
        const double exact = specular ? L.specular(golden::object_direction(s.host.view, gd))
                                      : L.diffuse(golden::normal_from_permuted_gradient(s.host.view, gd));
        worst = std::max(worst, std::fabs(fixed - exact));
      }
  return worst;
}

void check_fixed_against_float(const test::Setup& s, const char* name) {
  const auto e = test::compare(test::final_fixed(s), test::final_float(s));
  const double spec = s.host.regs.specular ? map_interpolation_error(s, s.host.regs.specular_map, true) : 0.0;
  const double diff = s.host.regs.shading ? map_interpolation_error(s, s.host.regs.diffuse_map, false) : 0.0;
  // Per-sample colour error budget: the maps' interpolation error times the
  // coefficients, plus 8 output LSBs for sample, gradient, α and output
  // rounding; compositing weights sum to at most one, so it bounds a pixel.
  const double budget = s.scene.material.ks * spec + s.scene.material.kd * diff + 8.0 / 255;
  std::printf("%s: fixed vs float PSNR %.2f dB, max error %.4f (budget %.4f: specular map %.4f, diffuse map %.4f)\n",
              name, e.psnr, e.max_error, budget, spec, diff);
  EXPECT_LE(e.max_error, budget) << name;
  EXPECT_GT(e.psnr, 45.0) << name;
}

}  // namespace

TEST(Accuracy, FixedAgainstFloatOnBrainsmall) {
  check_fixed_against_float(test::setup(R"({"volume": {"file": ")" CUBE4_BRAINSMALL R"("},
      "view": {"rotate": [20, 60, 180]}})"), "brainsmall");
}

TEST(Accuracy, FixedAgainstFloatOnTheSphere) {
  check_fixed_against_float(test::setup_file(CUBE4_SOURCE_DIR "/scenes/sphere.json"), "sphere");
}

// Polygons (Cube-5) add to a pixel at most their colour's and opacity's
// quantisation and a rounding per layer, a few 16-bit LSB
// (PolygonAccuracy.FixedAgainstFloatWithinTheDerivedBound): the volume's
// budget holds as it is. The box's faces, though, are lit flat, and lie
// across slice boundaries: a fragment within 2^-8 slice of a sample may
// go to the other side of it in fixed point, a difference of one
// translucent sample's share against the fragment's, inside the budget.
TEST(Accuracy, FixedAgainstFloatWithPolygons) {
  check_fixed_against_float(test::setup_file(CUBE4_SOURCE_DIR "/scenes/sphere_box.json"), "sphere in a box");
}

// In perspective (Cube-4 §3) the same budget: the rays' spacing changes
// where samples lie, not what a sample's arithmetic rounds.
TEST(Accuracy, FixedAgainstFloatWithPolygonsInPerspective) {
  check_fixed_against_float(test::setup_file(CUBE4_SOURCE_DIR "/scenes/perspective_sphere_box.json"),
                            "sphere in a box, perspective");
}

TEST(Accuracy, FloatAgainstReference) {
  for (const std::string& json :
       {std::string(R"({"volume": {"file": ")" CUBE4_BRAINSMALL R"("}, "view": {"rotate": [20, 60, 180]}})"),
        std::string(R"({"volume": {"synthetic": "sphere", "size": [48, 48, 48]}, "view": {"rotate": [20, 30, 0]},
                        "transfer": {"opacity": [[0, 0], [0.4, 0], [0.6, 1], [1, 1]]}})")}) {
    const auto s = test::setup(json);
    golden::ReferenceOptions opt;
    const auto e = test::compare(test::final_float(s), golden::render_reference(s.volume, s.scene, s.host.view, opt));
    const double mean = e.mean_error;
    std::printf("float vs reference: PSNR %.2f dB, max %.4f, mean %.5f\n", e.psnr, e.max_error, mean);
    // docs/accuracy.md: mean error within 1% (Towards-scalable reports 0.3%
    // for the interpolation alone; here the base-plane warp and the gradient
    // estimators differ too), PSNR above 30 dB.
    EXPECT_LT(mean, 0.01);
    EXPECT_GT(e.psnr, 30.0);
    // The largest differences sit on silhouettes, where the base plane's
    // bilinear warp and the reference's per-pixel rays cover an edge pixel
    // differently: at most half of it for a sub-pixel displacement.
    EXPECT_LT(e.max_error, 0.5);
  }
}

TEST(Accuracy, FloatAgainstReferenceWithPolygons) {
  // The same criteria as the volume's: silhouettes of polygons move by the
  // warp's resampling as the volume's do (by at most half of an edge
  // pixel's contrast), and everywhere else both renderers intersect the
  // same triangles exactly and composite them in the same depth order.
  const auto s = test::setup_file(CUBE4_SOURCE_DIR "/scenes/sphere_box.json");
  const auto e = test::compare(test::final_float(s), test::final_reference(s));
  std::printf("sphere in a box, float vs reference: PSNR %.2f dB, max %.4f, mean %.5f\n", e.psnr, e.max_error,
              e.mean_error);
  EXPECT_LT(e.mean_error, 0.01);
  EXPECT_GT(e.psnr, 30.0);
  EXPECT_LT(e.max_error, 0.5);
}

// Perspective: the reference casts a pinhole camera's rays and intersects
// them with the triangles exactly; float draws the triangles with
// perspective-correct depth on its rays from the eye. The same criteria.
TEST(Accuracy, FloatAgainstReferenceWithPolygonsInPerspective) {
  const auto s = test::setup_file(CUBE4_SOURCE_DIR "/scenes/perspective_sphere_box.json");
  ASSERT_TRUE(s.host.regs.perspective);
  const auto e = test::compare(test::final_float(s), test::final_reference(s));
  std::printf("sphere in a box, perspective, float vs reference: PSNR %.2f dB, max %.4f, mean %.5f\n", e.psnr,
              e.max_error, e.mean_error);
  EXPECT_LT(e.mean_error, 0.01);
  EXPECT_GT(e.psnr, 30.0);
  EXPECT_LT(e.max_error, 0.5);
}

TEST(Accuracy, TwelveNeighbourhoodGradientOnAVolumeSampledSphere) {
  // Towards-scalable §3, Fig. 2: mean angular error below 3° for rotations
  // about the vertical axis from 0° to 90° in 5° steps.
  for (int deg = 0; deg <= 90; deg += 5) {
    const auto s = test::rotated_sphere(deg);
    test::FirstHitProbe probe(s.host.view, test::kSphereCentre, test::kSphereHalfDensity,
                              s.scene.precision.weight_bits);
    golden::Registers r = s.host.regs;
    r.gradient = true;  // measured although this unshaded scene does not need it
    golden::render_fixed(s.volume, r, nullptr, {}, &probe);
    ASSERT_GT(probe.count, 1000);
    const double mean = probe.angle_sum / probe.count;
    std::printf("rotation %2d°: %d surface samples, mean angular error %.3f°\n", deg, probe.count, mean);
    EXPECT_LT(mean, 3.0) << "rotation " << deg;
  }
}
