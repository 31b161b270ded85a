// The fixed-point renderer's traversal: base planes, symmetry, effect
// skipping and hard numerical cases, with the float renderer as a check.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tb/tests/test_support.hpp"

using namespace cube4;

namespace {

std::string sphere_scene(const std::string& view, const std::string& extra = "", int size = 24) {
  const std::string n = std::to_string(size);
  return R"({"volume": {"synthetic": "sphere", "size": [)" + n + "," + n + "," + n + R"(]},
             "view": )" + view + extra + "}";
}

std::string direction(double x, double y, double z) {
  const bool vertical = std::fabs(y) > std::fabs(x) && std::fabs(y) > std::fabs(z);
  return R"({"direction": [)" + std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(z) +
         R"(], "up": )" + (vertical ? "[0, 0, 1]" : "[0, 1, 0]") + "}";
}

int64_t alpha_sum(const golden::BasePlane& bp) {
  int64_t s = 0;
  for (size_t i = 3; i < bp.rgba.size(); i += 4) s += bp.rgba[i];
  return s;
}

}  // namespace

TEST(RenderFixed, SixAxisViewsOfASymmetricSphereGiveIdenticalBasePlanes) {
  // Unshaded, so the lights (fixed in world space) cannot break the symmetry;
  // the sphere is symmetric under every flip and axis permutation, so every
  // base plane's permuted volume is the same and so must its image be.
  const golden::BasePlane ref =
      golden::render_fixed(test::setup(sphere_scene(direction(0, 0, 1), R"(, "shading": false)")).volume,
                           test::setup(sphere_scene(direction(0, 0, 1), R"(, "shading": false)")).host.regs);
  EXPECT_GT(alpha_sum(ref), 0);
  for (auto d : {std::array<double, 3>{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, -1}}) {
    const auto s = test::setup(sphere_scene(direction(d[0], d[1], d[2]), R"(, "shading": false)"));
    const golden::BasePlane bp = golden::render_fixed(s.volume, s.host.regs);
    ASSERT_EQ(bp.width, ref.width);
    ASSERT_EQ(bp.height, ref.height);
    EXPECT_EQ(bp.rgba, ref.rgba) << "direction " << d[0] << "," << d[1] << "," << d[2];
  }
}

TEST(RenderFixed, ExactFortyFiveDegreeViewsAreSymmetricToo) {
  const auto first = test::setup(sphere_scene(direction(1, 0, 1), R"(, "shading": false)"));
  const golden::BasePlane ref = golden::render_fixed(first.volume, first.host.regs);
  EXPECT_EQ(std::max(ref.width, ref.height), 24 + 23);  // one voxel of shear per slice
  for (auto d : {std::array<double, 3>{-1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, {0, 1, 1}, {0, -1, -1}}) {
    const auto s = test::setup(sphere_scene(direction(d[0], d[1], d[2]), R"(, "shading": false)"));
    const golden::BasePlane bp = golden::render_fixed(s.volume, s.host.regs);
    EXPECT_EQ(std::max(bp.width, bp.height), std::max(ref.width, ref.height));
    EXPECT_EQ(alpha_sum(bp), alpha_sum(ref)) << d[0] << "," << d[1] << "," << d[2];
  }
}

TEST(RenderFixed, SkippedUnitsDoNotChangeTheImage) {
  // An unshaded MIP needs no gradient: computing it anyway must not matter.
  auto s = test::setup(sphere_scene(direction(0.3, 0.2, 1), R"(, "shading": false, "blend": "mip")"));
  EXPECT_FALSE(s.host.regs.gradient);
  const golden::BasePlane skipped = golden::render_fixed(s.volume, s.host.regs);
  s.host.regs.gradient = true;
  s.host.regs.magnitude = true;
  s.host.regs.gm_lut.assign(size_t{1} << s.scene.precision.magnitude_bits, 0);
  EXPECT_EQ(golden::render_fixed(s.volume, s.host.regs).rgba, skipped.rgba);
}

TEST(RenderFixed, CountsSupersampledSamples) {
  for (int S : {1, 2, 8}) {
    const auto s = test::setup(sphere_scene(direction(0.2, 0.1, 1), R"(, "supersampling": )" + std::to_string(S), 16));
    golden::RenderStats st;
    golden::render_fixed(s.volume, s.host.regs, &st);
    EXPECT_EQ(st.samples, static_cast<uint64_t>(S) * 16 * 16 * 16);
    EXPECT_EQ(st.slices, 16 * S);
  }
}

TEST(RenderFixed, TinyVolumes) {
  for (int n : {1, 2}) {
    const std::string size = std::to_string(n);
    for (const std::string& view : {direction(0, 0, 1), direction(0.6, -0.5, 0.7)}) {
      const auto s = test::setup(R"({"volume": {"synthetic": "constant", "size": [)" + size + "," + size + "," +
                                 size + R"(], "value": 1}, "view": )" + view + "}");
      const golden::BasePlane bp = golden::render_fixed(s.volume, s.host.regs);
      EXPECT_GE(bp.width, n);
      EXPECT_LE(bp.width, 2 * n);
      EXPECT_GT(alpha_sum(bp), 0);
    }
  }
}

TEST(RenderFixed, MaximumVoxelsAtFullOpacityGiveExactlyOpaqueRays) {
  const auto s = test::setup(R"({"volume": {"synthetic": "constant", "size": [8, 8, 8], "value": 1},
      "transfer": {"opacity": [[0, 1], [1, 1]]}, "shading": false, "view": {"direction": [0, 0, 1]}})");
  const golden::BasePlane bp = golden::render_fixed(s.volume, s.host.regs);
  // Rays through the interior (x, y < 7 sample with their +1 neighbours inside).
  for (int y = 0; y < 7; ++y)
    for (int x = 0; x < 7; ++x) {
      const uint16_t* px = &bp.rgba[(static_cast<size_t>(y) * bp.width + x) * 4];
      ASSERT_EQ(px[3], (1 << bp.bits) - 1);
      ASSERT_EQ(px[0], (1 << bp.bits) - 1);
    }
}

TEST(RenderFixed, VeryLowOpacityOverHundredsOfSamplesStaysCloseAtVolumeProWidths) {
  // 300 samples of α = 0.0005 per unit step: fixed α LUT = round(0.0005·4095)
  // = 2; accumulated exactly 1-(1-α)^300 in float. (The default widths are
  // tested against their own, much tighter bound in test_translucency.)
  const auto s = test::setup(R"({"volume": {"synthetic": "constant", "size": [4, 4, 300], "value": 0.5},
      "transfer": {"opacity": [[0, 0.0005], [1, 0.0005]]}, "shading": false, "view": {"direction": [0, 0, 1]},
      "precision": {"alpha_bits": 12, "acc_guard_bits": 0}})");
  const golden::BasePlane bp = golden::render_fixed(s.volume, s.host.regs);
  const golden::BasePlaneF fp = golden::render_float(s.volume, s.scene, s.host.view);
  const double fixed_alpha = bp.rgba[3] / 4095.0, float_alpha = fp.image.rgba[3];
  EXPECT_NEAR(float_alpha, 1 - std::pow(1 - 0.0005, 300), 1e-6);
  // Bound (docs/fixed-point.md): LUT rounding |2/4095 - 0.0005| per sample,
  // plus half an LSB of rounding per step: 300·(0.000012 + 0.5/4095) ≈ 0.040.
  EXPECT_NEAR(fixed_alpha, float_alpha, 300 * (std::fabs(2 / 4095.0 - 0.0005) + 0.5 / 4095));
  EXPECT_GT(bp.rgba[3], 250);  // not lost to rounding
}

TEST(RenderFixed, EightTimesSupersamplingMatchesFloat) {
  const auto s = test::setup(sphere_scene(direction(0.4, 0.3, 1), R"(, "supersampling": 8)", 20));
  const auto e = test::compare(test::final_fixed(s), test::final_float(s));
  EXPECT_GT(e.psnr, 35.0);
}

TEST(RenderFixed, CroppingAndCutPlaneAgreeWithFloat) {
  for (const std::string& extra :
       {std::string(R"(, "cropping": {"x": [0, 11], "combine": "intersection"})"),
        std::string(R"(, "cropping": {"x": [6, 17], "y": [6, 17], "z": [6, 17], "combine": "cross", "invert": true})"),
        std::string(R"(, "cut_plane": {"normal": [1, 1, 0], "dmin": 14, "dmax": 20, "falloff": 2})"),
        std::string(R"(, "cut_plane": {"normal": [0, 0, 1], "dmin": 8, "dmax": 14, "keep": "outside"})")}) {
    // A direction whose ray offsets never land exactly on integers: at such a
    // tie the fixed DDA (rounded step) and the real one can put the same
    // sample in neighbouring grid cells, and a crop decision made on the grid
    // cell then flips for that sample (seen with shear 0.3/0.2: 0.2·10 = 2 in
    // float, 2 - 2^-19 in the DDA).
    const auto s = test::setup(sphere_scene(direction(0.31, 0.17, 1), extra));
    const auto e = test::compare(test::final_fixed(s), test::final_float(s));
    EXPECT_GT(e.psnr, 35.0) << extra << " max error " << e.max_error;
    // And the effect is really there: the image differs from the uncut one.
    const auto plain = test::setup(sphere_scene(direction(0.31, 0.17, 1)));
    EXPECT_LT(test::compare(test::final_fixed(s), test::final_fixed(plain)).psnr, 30.0) << extra;
  }
}

TEST(RenderFixed, AnisotropicSpacingMatchesTheIsotropicVolume) {
  // Every other z slice of an isotropic sphere, with z spacing 2, is the same
  // object: once the warp undoes the spacing the images must agree up to the
  // lost resolution in z.
  const auto iso = test::setup(sphere_scene(direction(0.3, 0.2, 1), R"(, "shading": false)", 33));
  golden::Volume half = iso.volume;
  half.dim[2] = 17;
  half.spacing[2] = 2;
  half.data.clear();
  for (int z = 0; z < 33; z += 2)
    for (int y = 0; y < 33; ++y)
      for (int x = 0; x < 33; ++x) half.data.push_back(iso.volume.at(x, y, z));
  test::Setup aniso = iso;
  aniso.volume = half;
  aniso.host = golden::program_host(aniso.scene, half);
  EXPECT_GT(test::compare(test::final_fixed(iso), test::final_fixed(aniso)).psnr, 25.0);
}

namespace {
struct NullProbe : golden::SampleProbe {
  uint64_t seen = 0;
  void sample(int, int, const golden::SliceControl&, uint32_t, const golden::Gradient&) override { ++seen; }
};
}  // namespace

TEST(RenderFixed, SkippingSamplesThatCannotChangeTheRayIsExact) {
  // A probe makes the renderer shade every sample; without one it skips the
  // composited samples of classified α = 0 and those behind opaque rays.
  for (const char* extra : {"", R"(, "transfer": {"opacity": [[0, 0], [0.5, 0], [0.55, 1], [1, 1]]})",
                            R"(, "gradient_modulation": {"opacity": true, "diffuse": true, "specular": true})"}) {
    const auto s = test::setup(sphere_scene(direction(0.4, -0.3, 1), extra, 20));
    NullProbe probe;
    const golden::BasePlane all = golden::render_fixed(s.volume, s.host.regs, nullptr, {}, &probe);
    EXPECT_EQ(probe.seen, 20u * 20 * 20);
    EXPECT_EQ(golden::render_fixed(s.volume, s.host.regs).rgba, all.rgba) << extra;
  }
}

TEST(RenderFixed, ConstantWidthLoopsGiveTheRunTimeWidthLoopsBits) {
  // At the default precision render_fixed() runs its loops instantiated
  // with the widths as constants (DefaultPrecisionRegisters): the same unit
  // functions, so every accumulator must be equal, with every effect the
  // compositor and shading unit have, on one thread and on three.
  for (const std::string& extra :
       {std::string(), std::string(R"(, "gradient_modulation": {"opacity": true, "diffuse": true, "specular": true})"),
        std::string(R"(, "cut_plane": {"normal": [1, 1, 0], "dmin": 14, "dmax": 20, "falloff": 2})"),
        std::string(R"(, "cropping": {"x": [6, 17], "y": [6, 17], "z": [6, 17], "combine": "cross", "invert": true})"),
        std::string(R"(, "blend": "mip")")}) {
    const auto s = test::setup(sphere_scene(direction(0.4, -0.3, 1), extra, 20));
    ASSERT_TRUE(golden::DefaultPrecisionRegisters::has_default_precision(s.host.regs));
    for (int threads : {1, 3}) {
      golden::FixedOptions constant, run_time;
      constant.accumulators = run_time.accumulators = true;
      constant.threads = run_time.threads = threads;
      run_time.constant_widths = false;
      const golden::BasePlane a = golden::render_fixed(s.volume, s.host.regs, constant);
      const golden::BasePlane b = golden::render_fixed(s.volume, s.host.regs, run_time);
      EXPECT_EQ(a.rgba, b.rgba) << extra << " threads " << threads;
      ASSERT_EQ(a.acc.size(), b.acc.size());
      size_t differ = 0;
      for (size_t i = 0; i < a.acc.size(); ++i)
        differ += a.acc[i].r != b.acc[i].r || a.acc[i].g != b.acc[i].g || a.acc[i].b != b.acc[i].b ||
                  a.acc[i].a != b.acc[i].a || a.acc[i].value != b.acc[i].value;
      EXPECT_EQ(differ, 0u) << extra << " threads " << threads;
      EXPECT_GT(alpha_sum(a), 0) << extra;
    }
  }
  // Another precision cannot take the constant loops.
  const auto v = test::setup(sphere_scene(direction(0.4, -0.3, 1), R"(, "precision": {"alpha_bits": 12})", 12));
  EXPECT_FALSE(golden::DefaultPrecisionRegisters::has_default_precision(v.host.regs));
  EXPECT_THROW(golden::DefaultPrecisionRegisters{v.host.regs}, std::logic_error);
}

TEST(RenderFixed, ConstantWidthLoopsOnBrainsmallGiveTheRunTimeWidthLoopsImage) {
  const auto s = test::setup_file(std::string(CUBE4_SOURCE_DIR) + "/scenes/default.json");
  golden::FixedOptions run_time;
  run_time.constant_widths = false;
  EXPECT_EQ(golden::render_fixed(s.volume, s.host.regs, golden::FixedOptions{}).rgba,
            golden::render_fixed(s.volume, s.host.regs, run_time).rgba);
}

namespace {
// Recomputes every shaded sample from its value and gradient with the plain
// unit functions: the renderer takes the gradient's part of the shading
// from a cache (GradientShadingCache), which must give the same bits.
struct ShadingCheck : golden::SampleProbe {
  const golden::Registers& r;
  uint32_t value = 0;
  golden::Gradient gradient;
  uint64_t checked = 0, wrong = 0;
  explicit ShadingCheck(const golden::Registers& regs) : r(regs) {}
  void sample(int, int, const golden::SliceControl&, uint32_t v, const golden::Gradient& g) override {
    value = v;
    gradient = g;
  }
  void shaded(int x, int y, const golden::SliceControl& c, const golden::ShadedSample& s) override {
    const golden::ShadedSample e = golden::crop_and_cut(r, c, x, y, golden::shade_classified(r, value, 0, gradient));
    ++checked;
    if (e.rgb != s.rgb || e.alpha != s.alpha || e.value != s.value || e.visible != s.visible) ++wrong;
  }
};
}  // namespace

TEST(RenderFixed, CachedGradientShadingEqualsTheUnitFunctions) {
  for (const char* extra : {R"("view": {"rotate": [20, 60, 180]})",
                            R"("view": {"rotate": [-35, 10, 75]}, "gradient_modulation": {"opacity": true, "diffuse": true, "specular": true})"}) {
    const auto s = test::setup(R"({"volume": {"file": ")" + golden::default_brainsmall_path() + R"("}, )" + extra + "}");
    ShadingCheck check(s.host.regs);
    golden::render_fixed(s.volume, s.host.regs, nullptr, {}, &check);
    EXPECT_GT(check.checked, 100000u) << extra;
    EXPECT_EQ(check.wrong, 0u) << extra;
  }
}

namespace {
// Checks every sample the renderer produced against trilinear() on the
// sample's own eight voxels, fetched through the view's axis mapping.
struct TrilinearCheck : golden::SampleProbe {
  const golden::Volume& vol;
  const golden::ViewFactorisation& view;
  int weight_bits;
  uint64_t checked = 0, wrong = 0;
  TrilinearCheck(const golden::Volume& v, const golden::ViewFactorisation& f, int w) : vol(v), view(f), weight_bits(w) {}
  uint32_t voxel(int x, int y, int z) const {
    const golden::Vec3 o = view.to_object({double(x), double(y), double(z)});
    for (int i = 0; i < 3; ++i)
      if (o[i] < 0 || o[i] > vol.dim[i] - 1 || x >= view.pdim[0] || y >= view.pdim[1] || z >= view.pdim[2]) return 0;
    return vol.at(int(o[0]), int(o[1]), int(o[2]));
  }
  void sample(int x, int y, const golden::SliceControl& c, uint32_t value, const golden::Gradient&) override {
    std::array<uint32_t, 8> v;
    for (int i = 0; i < 8; ++i) v[i] = voxel(x + (i & 1), y + (i >> 1 & 1), c.z_voxel + (i >> 2));
    ++checked;
    if (golden::trilinear(v, c.wx, c.wy, c.wz, weight_bits) != value) ++wrong;
  }
};
}  // namespace

TEST(RenderFixed, BeamWiseInterpolationEqualsTrilinearPerSample) {
  for (int S : {1, 3}) {
    const auto s = test::setup(R"({"volume": {"synthetic": "noise", "size": [13, 11, 9], "seed": 4},
        "supersampling": )" + std::to_string(S) + R"(, "view": )" + direction(-0.45, 0.3, -1) + "}");
    TrilinearCheck check(s.volume, s.host.view, s.scene.precision.weight_bits);
    golden::render_fixed(s.volume, s.host.regs, nullptr, {}, &check);
    EXPECT_EQ(check.checked, 13u * 11 * 9 * S);
    EXPECT_EQ(check.wrong, 0u);
  }
}

namespace {

// Found by scripts/fuzz_cli.py: a rotation of -1e308 degrees overflowed to
// -inf radians, the view became NaN and the reference ray caster's loop
// over an infinite ray never ended. Any finite angle is one turn's angle.
TEST(View, HugeFiniteAnglesAreReducedToOneTurn) {
  const auto huge = test::setup(R"({"volume": {"synthetic": "sphere", "size": [12, 10, 8]},
      "view": {"rotate": [20, -1e308, 0]}, "output": {"width": 32, "height": 32}})");
  const double turn = std::fmod(-1e308, 360.0);
  const auto same = test::setup(R"({"volume": {"synthetic": "sphere", "size": [12, 10, 8]},
      "view": {"rotate": [20, )" + std::to_string(turn) + R"(, 0]}, "output": {"width": 32, "height": 32}})");
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(std::isfinite(huge.host.view.view_dir_object[i]));
    EXPECT_NEAR(huge.host.view.view_dir_object[i], same.host.view.view_dir_object[i], 1e-9);
  }
  golden::RenderStats stats;
  golden::render_reference(huge.volume, huge.scene, huge.host.view, {}, &stats);
  EXPECT_GT(stats.samples, 0u);
}

}  // namespace
