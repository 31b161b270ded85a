// Scene JSON parser (golden/scene_io) and effect sets (golden/effects):
// defaults, the example scenes, every key's happy path and every documented
// error, whose message must name the file, the key path and the value.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <string>
#include <vector>

#include "golden/errors.hpp"
#include "golden/scene.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"

namespace cube4::golden {
namespace {

namespace fs = std::filesystem;

const char* const kFile = "t.json";

Scene parse(const std::string& text) { return parse_scene(text, kFile); }

// A valid scene with `extra` top-level members after the volume.
std::string with(const std::string& extra) {
  return R"({"volume": {"synthetic": "constant"})" + (extra.empty() ? "" : ", " + extra) + "}";
}

Scene parse_with(const std::string& extra) { return parse(with(extra)); }

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// The message must name the file and contain every fragment.
void expect_error(const std::string& text, std::initializer_list<std::string> fragments) {
  const std::string msg = error_of(text);
  SCOPED_TRACE("scene: " + text);
  EXPECT_EQ(msg.rfind(std::string(kFile) + ": ", 0), 0u) << msg;
  for (const auto& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "wanted '" << f << "' in: " << msg;
}

void expect_same(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.volume.kind, b.volume.kind);
  EXPECT_EQ(a.volume.path, b.volume.path);
  EXPECT_EQ(a.volume.spacing.has_value(), b.volume.spacing.has_value());
  EXPECT_EQ(a.volume.quantisation.mode, b.volume.quantisation.mode);
  EXPECT_EQ(a.view.rotate, b.view.rotate);
  EXPECT_EQ(a.view.direction, b.view.direction);
  EXPECT_EQ(a.view.up, b.view.up);
  EXPECT_EQ(a.view.ray_offset, b.view.ray_offset);
  EXPECT_EQ(a.view.zoom, b.view.zoom);
  EXPECT_EQ(a.view.look_at, b.view.look_at);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  ASSERT_EQ(a.color.size(), b.color.size());
  for (size_t i = 0; i < a.color.size(); ++i) {
    EXPECT_EQ(a.color[i].x, b.color[i].x);
    EXPECT_EQ(a.color[i].rgb, b.color[i].rgb);
  }
  auto same_points = [](const std::vector<ScalarPoint>& p, const std::vector<ScalarPoint>& q) {
    ASSERT_EQ(p.size(), q.size());
    for (size_t i = 0; i < p.size(); ++i) {
      EXPECT_EQ(p[i].x, q[i].x);
      EXPECT_EQ(p[i].y, q[i].y);
    }
  };
  same_points(a.opacity, b.opacity);
  same_points(a.gm_lut, b.gm_lut);
  ASSERT_EQ(a.lights.size(), b.lights.size());
  for (size_t i = 0; i < a.lights.size(); ++i) {
    EXPECT_EQ(a.lights[i].direction, b.lights[i].direction);
    EXPECT_EQ(a.lights[i].intensity, b.lights[i].intensity);
  }
  EXPECT_EQ(a.material.ke, b.material.ke);
  EXPECT_EQ(a.material.kd, b.material.kd);
  EXPECT_EQ(a.material.ks, b.material.ks);
  EXPECT_EQ(a.material.specular_color, b.material.specular_color);
  EXPECT_EQ(a.material.exponent, b.material.exponent);
  EXPECT_EQ(a.shading, b.shading);
  EXPECT_EQ(a.blend, b.blend);
  EXPECT_EQ(a.gm.opacity, b.gm.opacity);
  EXPECT_EQ(a.gm.diffuse, b.gm.diffuse);
  EXPECT_EQ(a.gm.specular, b.gm.specular);
  EXPECT_EQ(a.supersampling, b.supersampling);
  EXPECT_EQ(a.cropping.enabled, b.cropping.enabled);
  EXPECT_EQ(a.cut.enabled, b.cut.enabled);
  EXPECT_EQ(a.pipelines, b.pipelines);
  EXPECT_EQ(a.clock_mhz, b.clock_mhz);
  EXPECT_EQ(a.precision.voxel_bits, b.precision.voxel_bits);
  EXPECT_EQ(a.precision.alpha_bits, b.precision.alpha_bits);
  EXPECT_EQ(a.polygons.size(), b.polygons.size());
}

std::string scene_path(const std::string& name) {
  return std::string(CUBE4_SOURCE_DIR) + "/scenes/" + name;
}

// A file under the system temp folder, removed at the end of the test.
struct TempFile {
  explicit TempFile(const std::string& text) {
    path = (fs::temp_directory_path() /
            ("cube4_test_scene_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
             "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".json"))
               .string();
    std::ofstream(path) << text;
  }
  ~TempFile() { std::remove(path.c_str()); }
  std::string path;
};

// ---- defaults -------------------------------------------------------------

TEST(SceneDefaults, DefaultSceneIsShadedCompositeOfBrainsmall) {
  const Scene s = default_scene();
  EXPECT_EQ(s.file, "");
  EXPECT_EQ(s.volume.kind, "den");
  EXPECT_EQ(s.volume.path, default_brainsmall_path());
  EXPECT_EQ(s.view.rotate, (Vec3{20, 60, 180}));
  EXPECT_FALSE(s.view.direction.has_value());
  EXPECT_TRUE(s.shading);
  EXPECT_EQ(s.blend, Blend::Composite);
  EXPECT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.opacity.size(), 4u);
}

TEST(SceneDefaults, MinimalSceneGetsEveryDefault) {
  const Scene s = parse_with("");
  EXPECT_EQ(s.file, kFile);
  EXPECT_EQ(s.volume.kind, "constant");
  EXPECT_EQ(s.view.rotate, (Vec3{0, 0, 0}));
  EXPECT_EQ(s.width, 256);
  EXPECT_EQ(s.height, 256);
  ASSERT_EQ(s.color.size(), 2u);
  EXPECT_EQ(s.color[0].x, 0);
  EXPECT_EQ(s.color[1].x, 1);
  EXPECT_EQ(s.color[1].rgb, (Vec3{1, 1, 1}));
  ASSERT_EQ(s.opacity.size(), 4u);
  EXPECT_DOUBLE_EQ(s.opacity[1].x, 0.094);
  EXPECT_DOUBLE_EQ(s.opacity[2].x, 0.16);
  EXPECT_DOUBLE_EQ(s.opacity[2].y, 0.6);
  EXPECT_DOUBLE_EQ(s.opacity[3].y, 0.8);
  ASSERT_EQ(s.gm_lut.size(), 2u);
  EXPECT_EQ(s.gm_lut[1].y, 1);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].direction, (Vec3{0.3, 0.3, 1}));
  EXPECT_EQ(s.lights[0].intensity, 1);
  EXPECT_EQ(s.material.ks, Material{}.ks);
  EXPECT_TRUE(s.shading);
  EXPECT_EQ(s.blend, Blend::Composite);
  EXPECT_EQ(s.supersampling, 1);
  EXPECT_FALSE(s.cropping.enabled);
  EXPECT_FALSE(s.cut.enabled);
  EXPECT_EQ(s.pipelines, 4);
  EXPECT_EQ(s.clock_mhz, 125);
  EXPECT_EQ(s.precision.voxel_bits, Precision{}.voxel_bits);
}

TEST(SceneDefaults, FinishSceneKeepsGivenLists) {
  Scene s;
  s.opacity = {{0, 0.5}};
  finish_scene(s);
  EXPECT_EQ(s.opacity.size(), 1u);
  EXPECT_EQ(s.color.size(), 2u);
}

// ---- example scenes -------------------------------------------------------

TEST(SceneExamples, EveryExampleParses) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(std::string(CUBE4_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(load_scene(entry.path().string()));
    ++n;
  }
  EXPECT_GE(n, 4);
}

TEST(SceneExamples, DefaultJsonEqualsDefaultScene) {
  Scene s = load_scene(scene_path("default.json"));
  EXPECT_EQ(s.file, scene_path("default.json"));
  const Scene d = default_scene();
  // Where brainsmall is only installed gzipped, the default scene names the .gz.
  if (d.volume.path != s.volume.path && d.volume.path == s.volume.path + ".gz") s.volume.path = d.volume.path;
  expect_same(s, d);
}

// Meshes (tb/tests/test_mesh.cpp) add to a scene and change nothing else:
// without them, or with an empty list, every example is what it was.
TEST(SceneExamples, EmptyPolygonsChangeNothing) {
  for (const auto& e : fs::directory_iterator(std::string(CUBE4_SOURCE_DIR) + "/scenes")) {
    if (e.path().extension() != ".json") continue;
    SCOPED_TRACE(e.path().string());
    Scene s = load_scene(e.path().string());
    if (!s.polygons.empty()) continue;  // brain_probe.json
    std::ifstream in(e.path());
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t brace = text.find('{');
    ASSERT_NE(brace, std::string::npos);
    text.insert(brace + 1, R"("polygons": [], )");
    const Scene t = parse_scene(text, e.path().string());
    EXPECT_TRUE(t.polygons.empty());
    expect_same(s, t);
  }
  expect_same(parse(with("")), parse(with(R"("polygons": [])")));
}

TEST(SceneExamples, SphereScenes) {
  const Scene shaded = load_scene(scene_path("sphere.json"));
  EXPECT_EQ(shaded.volume.kind, "sphere");
  EXPECT_EQ(shaded.volume.size, (std::array<int, 3>{64, 64, 64}));
  EXPECT_TRUE(effects_of(shaded).shading);
  const Scene mip = load_scene(scene_path("sphere_mip.json"));
  EXPECT_EQ(mip.blend, Blend::Mip);
  EXPECT_FALSE(effects_of(mip).gradient);
}

TEST(SceneExamples, BrainCutHasCroppingAndCutPlane) {
  const Scene s = load_scene(scene_path("brain_cut.json"));
  EXPECT_EQ(s.volume.kind, "den");
  EXPECT_TRUE(s.cropping.enabled);
  EXPECT_TRUE(s.cut.enabled);
  EXPECT_FALSE(s.cut.keep_inside);
}

// ---- happy paths ----------------------------------------------------------

TEST(SceneVolume, FileKindFromExtension) {
  auto kind = [](const std::string& file) {
    return parse(R"({"volume": {"file": ")" + file + R"("}})").volume.kind;
  };
  EXPECT_EQ(kind("a/head.den"), "den");
  EXPECT_EQ(kind("brainsmall.den.gz"), "den");
  EXPECT_EQ(kind("head.nii"), "nifti");
  EXPECT_EQ(kind("head.nii.gz"), "nifti");
  EXPECT_EQ(kind("HEAD.NII.GZ"), "nifti");
  const Scene s = parse(R"({"volume": {"file": "rel/head.den"}})");
  EXPECT_EQ(s.volume.path, "rel/head.den");
}

TEST(SceneVolume, ExplicitFormatWins) {
  const Scene s = parse(R"({"volume": {"file": "head.bin", "format": "nifti"}})");
  EXPECT_EQ(s.volume.kind, "nifti");
}

TEST(SceneVolume, RawLayout) {
  const Scene s = parse(
      R"({"volume": {"file": "v.raw", "dim": [10, 20, 30], "type": "int16", "endian": "big", "header": 512}})");
  EXPECT_EQ(s.volume.kind, "raw");
  EXPECT_EQ(s.volume.dim, (std::array<int, 3>{10, 20, 30}));
  EXPECT_EQ(s.volume.type, "int16");
  EXPECT_EQ(s.volume.endian, "big");
  EXPECT_EQ(s.volume.header_bytes, 512u);
  const Scene d = parse(R"({"volume": {"file": "v.raw", "dim": [1, 1, 1]}})");
  EXPECT_EQ(d.volume.type, "uint8");
  EXPECT_EQ(d.volume.endian, "little");
  EXPECT_EQ(d.volume.header_bytes, 0u);
}

TEST(SceneVolume, EverySyntheticKind) {
  const Scene sphere = parse(
      R"({"volume": {"synthetic": "sphere", "size": [32, 40, 48], "radius": 10.5, "center": [16, 20, 24.5]}})");
  EXPECT_EQ(sphere.volume.kind, "sphere");
  EXPECT_EQ(sphere.volume.size, (std::array<int, 3>{32, 40, 48}));
  EXPECT_EQ(sphere.volume.radius, 10.5);
  EXPECT_EQ(sphere.volume.center, (Vec3{16, 20, 24.5}));
  EXPECT_EQ(parse(R"({"volume": {"synthetic": "field", "field": "ramp_y"}})").volume.field, "ramp_y");
  EXPECT_EQ(parse(R"({"volume": {"synthetic": "noise", "seed": 4294967295}})").volume.seed, 4294967295u);
  EXPECT_EQ(parse(R"({"volume": {"synthetic": "constant", "value": 0.25}})").volume.value, 0.25);
  const Scene one = parse(R"({"volume": {"synthetic": "single_voxel", "size": [8, 8, 8], "at": [1, 2, 7], "value": 0.5}})");
  EXPECT_EQ(one.volume.at, (std::array<int, 3>{1, 2, 7}));
  EXPECT_EQ(one.volume.value, 0.5);
}

TEST(SceneVolume, SpacingAndMap) {
  const Scene s = parse(R"({"volume": {"synthetic": "constant", "spacing": [1, 1, 2.5], "map": [-100, 3000]}})");
  EXPECT_EQ(s.volume.spacing, (Vec3{1, 1, 2.5}));
  EXPECT_EQ(s.volume.quantisation.mode, Quantisation::Mode::Window);
  EXPECT_EQ(s.volume.quantisation.lo, -100);
  EXPECT_EQ(s.volume.quantisation.hi, 3000);
  EXPECT_EQ(parse(R"({"volume": {"synthetic": "constant", "map": "minmax"}})").volume.quantisation.mode,
            Quantisation::Mode::MinMax);
  EXPECT_EQ(parse(R"({"volume": {"synthetic": "constant", "map": "full"}})").volume.quantisation.mode,
            Quantisation::Mode::Full);
}

TEST(SceneView, RotateAndRayOffset) {
  const Scene s = parse_with(R"("view": {"rotate": [-400, 30.5, 720], "ray_offset": [0, 0.999]})");
  EXPECT_EQ(s.view.rotate, (Vec3{-400, 30.5, 720}));
  EXPECT_EQ(s.view.ray_offset, (std::array<double, 2>{0, 0.999}));
}

TEST(SceneView, ZoomAndLookAt) {
  const Scene d = parse_with(R"("view": {"rotate": [0, 0, 0]})");
  EXPECT_EQ(d.view.zoom, 1.0);
  EXPECT_FALSE(d.view.look_at.has_value());
  const Scene s = parse_with(R"("view": {"direction": [0, 0, -1], "zoom": 2.5, "look_at": [3, -4.5, 100]})");
  EXPECT_EQ(s.view.zoom, 2.5);
  EXPECT_EQ(s.view.look_at, (Vec3{3, -4.5, 100}));
}

TEST(SceneView, DirectionAndUp) {
  const Scene s = parse_with(R"("view": {"direction": [0, 0, -2], "up": [1, 0, 0]})");
  EXPECT_EQ(s.view.direction, (Vec3{0, 0, -2}));
  EXPECT_EQ(s.view.up, (Vec3{1, 0, 0}));
  EXPECT_EQ(parse_with(R"("view": {"direction": [1, 0, 0]})").view.up, (Vec3{0, 1, 0}));
}

TEST(SceneOutput, WidthHeight) {
  const Scene s = parse_with(R"("output": {"width": 8192, "height": 1})");
  EXPECT_EQ(s.width, 8192);
  EXPECT_EQ(s.height, 1);
}

TEST(SceneTransfer, ColorOpacityAndGmLut) {
  const Scene s = parse_with(
      R"("transfer": {"color": [[0, 1, 0, 0], [0.5, 0, 1, 0], [1, 0, 0, 1]], "opacity": [[0.2, 0.7]]},
         "gm_lut": [[0, 0.1], [0.3, 0.9], [1, 1]])");
  ASSERT_EQ(s.color.size(), 3u);
  EXPECT_EQ(s.color[1].x, 0.5);
  EXPECT_EQ(s.color[1].rgb, (Vec3{0, 1, 0}));
  ASSERT_EQ(s.opacity.size(), 1u);
  EXPECT_EQ(s.opacity[0].y, 0.7);
  ASSERT_EQ(s.gm_lut.size(), 3u);
  EXPECT_EQ(s.gm_lut[1].x, 0.3);
}

TEST(SceneLights, SeveralLightsDefaultIntensity) {
  const Scene s = parse_with(R"("lights": [{"direction": [1, 0, 0]}, {"direction": [0, -1, 0], "intensity": 0.5}])");
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].intensity, 1);
  EXPECT_EQ(s.lights[1].direction, (Vec3{0, -1, 0}));
  EXPECT_EQ(s.lights[1].intensity, 0.5);
}

TEST(SceneLights, SixteenLightsAllowed) {
  std::string lights;
  for (int i = 0; i < 16; ++i) lights += std::string(i ? "," : "") + R"({"direction": [0, 0, 1]})";
  EXPECT_EQ(parse_with(R"("lights": [)" + lights + "]").lights.size(), 16u);
}

TEST(SceneMaterial, AllKeys) {
  const Scene s = parse_with(
      R"("material": {"ke": 0, "kd": 3.99, "ks": 1.5, "specular_color": [1, 0.5, 0], "exponent": 128})");
  EXPECT_EQ(s.material.ke, 0);
  EXPECT_EQ(s.material.kd, 3.99);
  EXPECT_EQ(s.material.ks, 1.5);
  EXPECT_EQ(s.material.specular_color, (Vec3{1, 0.5, 0}));
  EXPECT_EQ(s.material.exponent, 128);
}

TEST(SceneFlags, ShadingBlendGradientModulationSupersampling) {
  const Scene s = parse_with(
      R"("shading": false, "blend": "minip", "supersampling": 8,
         "gradient_modulation": {"opacity": true, "diffuse": false, "specular": true})");
  EXPECT_FALSE(s.shading);
  EXPECT_EQ(s.blend, Blend::MinIp);
  EXPECT_EQ(s.supersampling, 8);
  EXPECT_TRUE(s.gm.opacity);
  EXPECT_FALSE(s.gm.diffuse);
  EXPECT_TRUE(s.gm.specular);
  EXPECT_EQ(parse_with(R"("blend": "mip")").blend, Blend::Mip);
  EXPECT_EQ(parse_with(R"("blend": "composite")").blend, Blend::Composite);
}

TEST(SceneCropping, SlabsAndWholeAxes) {
  const Scene s = parse_with(R"("cropping": {"x": [2, 10], "z": [5, 5]})");
  EXPECT_TRUE(s.cropping.enabled);
  EXPECT_EQ(s.cropping.slab[0], (std::array<int, 2>{2, 10}));
  EXPECT_EQ(s.cropping.slab[1], (std::array<int, 2>{0, 1 << 30}));
  EXPECT_EQ(s.cropping.slab[2], (std::array<int, 2>{5, 5}));
  EXPECT_EQ(s.cropping.mask, 0x80);
  EXPECT_TRUE(parse_with(R"("cropping": {})").cropping.enabled);
}

TEST(SceneCropping, CombineMaskInvert) {
  auto mask = [](const std::string& c) { return parse_with(R"("cropping": )" + c).cropping.mask; };
  EXPECT_EQ(mask(R"({"combine": "intersection"})"), 0x80);
  EXPECT_EQ(mask(R"({"combine": "union"})"), 0xFE);
  EXPECT_EQ(mask(R"({"combine": "cross"})"), 0xE8);
  EXPECT_EQ(mask(R"({"mask": 0})"), 0x00);
  EXPECT_EQ(mask(R"({"mask": 255})"), 0xFF);
  EXPECT_EQ(mask(R"({"combine": "union", "invert": true})"), 0x01);
  EXPECT_EQ(mask(R"({"mask": 15, "invert": true})"), 0xF0);
  EXPECT_EQ(mask(R"({"invert": false})"), 0x80);
}

TEST(SceneCutPlane, AllKeys) {
  const Scene s = parse_with(
      R"("cut_plane": {"normal": [1, 2, 0], "dmin": -3.5, "dmax": 7, "falloff": 2, "keep": "outside"})");
  EXPECT_TRUE(s.cut.enabled);
  EXPECT_EQ(s.cut.normal, (Vec3{1, 2, 0}));
  EXPECT_EQ(s.cut.dmin, -3.5);
  EXPECT_EQ(s.cut.dmax, 7);
  EXPECT_EQ(s.cut.falloff, 2);
  EXPECT_FALSE(s.cut.keep_inside);
  EXPECT_TRUE(parse_with(R"("cut_plane": {"keep": "inside"})").cut.keep_inside);
}

TEST(SceneMachine, PipelinesAndClock) {
  const Scene s = parse_with(R"("pipelines": 256, "clock_mhz": 0.5)");
  EXPECT_EQ(s.pipelines, 256);
  EXPECT_EQ(s.clock_mhz, 0.5);
  EXPECT_EQ(parse_with(R"("clock_mhz": 10000)").clock_mhz, 10000);
}

TEST(ScenePrecision, EveryKey) {
  const Scene s = parse_with(R"("precision": {
      "voxel_bits": 16, "weight_bits": 14, "dda_frac_bits": 14, "gradient_bits": 4,
      "gradient_shift": 0, "magnitude_bits": 16, "nr_iterations": 8, "color_bits": 4,
      "alpha_bits": 16, "gmlut_bits": 4, "map_face_res": 64, "map_bits": 32,
      "map_frac_bits": 31, "coef_bits": 16, "coef_frac_bits": 15, "eye_bits": 4, "cut_bits": 40})");
  const Precision& p = s.precision;
  EXPECT_EQ(p.voxel_bits, 16);
  EXPECT_EQ(p.weight_bits, 14);
  EXPECT_EQ(p.dda_frac_bits, 14);
  EXPECT_EQ(p.gradient_bits, 4);
  EXPECT_EQ(p.gradient_shift, 0);
  EXPECT_EQ(p.magnitude_bits, 16);
  EXPECT_EQ(p.nr_iterations, 8);
  EXPECT_EQ(p.color_bits, 4);
  EXPECT_EQ(p.alpha_bits, 16);
  EXPECT_EQ(p.gmlut_bits, 4);
  EXPECT_EQ(p.map_face_res, 64);
  EXPECT_EQ(p.map_bits, 32);
  EXPECT_EQ(p.map_frac_bits, 31);
  EXPECT_EQ(p.coef_bits, 16);
  EXPECT_EQ(p.coef_frac_bits, 15);
  EXPECT_EQ(p.eye_bits, 4);
  EXPECT_EQ(p.cut_bits, 40);
}

TEST(ScenePrecision, IntegralFloatIsAnInteger) {
  EXPECT_EQ(parse_with(R"("precision": {"voxel_bits": 8.0})").precision.voxel_bits, 8);
}

TEST(SceneFiles, LoadSceneReadsAFile) {
  TempFile f(with(R"("supersampling": 3)"));
  const Scene s = load_scene(f.path);
  EXPECT_EQ(s.file, f.path);
  EXPECT_EQ(s.supersampling, 3);
}

// ---- errors ---------------------------------------------------------------

TEST(SceneErrors, UnknownKeys) {
  expect_error(with(R"("supersampeling": 2)"), {"unknown key \"supersampeling\" = 2", "supersampling"});
  expect_error(with(R"("material": {"kss": 0.3})"), {"unknown key \"material.kss\" = 0.3"});
  expect_error(with(R"("lights": [{"direction": [0, 0, 1]}, {"direction": [0, 0, 1], "color": 1}])"),
               {"unknown key \"lights[1].color\""});
  expect_error(with(R"("view": {"rotate": [0, 0, 0], "zooom": 2})"), {"\"view.zooom\""});
  expect_error(with(R"("cropping": {"w": [0, 1]})"), {"\"cropping.w\""});
  expect_error(with(R"("precision": {"voxelbits": 8})"), {"\"precision.voxelbits\""});
  // Keys of another volume kind are not accepted either.
  expect_error(R"({"volume": {"synthetic": "noise", "radius": 3}})", {"unknown key \"volume.radius\" = 3"});
  expect_error(R"({"volume": {"file": "a.den", "dim": [1, 1, 1]}})", {"unknown key \"volume.dim\""});
  expect_error(R"({"volume": {"synthetic": "sphere", "format": "raw"}})", {"unknown key \"volume.format\""});
}

TEST(SceneErrors, MisspeltVolumeIsReportedAsUnknownNotMissing) {
  expect_error(R"({"volme": {"synthetic": "sphere"}})", {"unknown key \"volme\""});
}

TEST(SceneErrors, WrongTypes) {
  expect_error(with(R"("supersampling": "2")"), {"\"supersampling\" = \"2\"", "integer"});
  expect_error(with(R"("supersampling": 2.5)"), {"\"supersampling\" = 2.5", "integer"});
  expect_error(with(R"("shading": 1)"), {"\"shading\" = 1", "true or false"});
  expect_error(with(R"("blend": 0)"), {"\"blend\" = 0", "string"});
  expect_error(with(R"("material": {"ks": "high"})"), {"\"material.ks\" = \"high\"", "number"});
  expect_error(with(R"("material": [])"), {"\"material\" = []", "object"});
  expect_error(with(R"("view": {"rotate": 30})"), {"\"view.rotate\" = 30", "array"});
  expect_error(with(R"("view": {"rotate": [30, 0]})"), {"\"view.rotate\" = [30,0]", "3 entries"});
  expect_error(with(R"("view": {"rotate": [30, 0, null]})"), {"\"view.rotate[2]\" = null", "number"});
  expect_error(with(R"("lights": {"direction": [0, 0, 1]})"), {"\"lights\"", "array"});
  expect_error(with(R"("transfer": {"opacity": [[0, 0], 1]})"), {"\"transfer.opacity[1]\" = 1", "array"});
  expect_error(with(R"("transfer": {"color": [[0, 1, 1]]})"), {"\"transfer.color[0]\"", "4 entries"});
  expect_error(with(R"("cropping": {"x": [0.5, 3]})"), {"\"cropping.x[0]\" = 0.5", "integer"});
  expect_error(R"({"volume": {"file": 3}})", {"\"volume.file\" = 3", "string"});
  expect_error(R"({"volume": {"synthetic": "constant", "map": 3}})", {"\"volume.map\" = 3"});
  expect_error("[1, 2]", {"the scene = [1,2]", "object"});
}

struct RangeCase {
  const char* scene;  // a whole scene, or top-level members for with()
  const char* path;
  const char* value;
};

class SceneOutOfRange : public ::testing::TestWithParam<RangeCase> {};

TEST_P(SceneOutOfRange, NamesKeyAndValue) {
  const RangeCase& c = GetParam();
  const std::string text = c.scene[0] == '{' ? c.scene : with(c.scene);
  expect_error(text, {"\"" + std::string(c.path) + "\" = " + c.value});
}

const RangeCase kRangeCases[] = {
    {R"({"volume": {"file": "v.raw", "dim": [0, 1, 1]}})", "volume.dim[0]", "0"},
    {R"({"volume": {"file": "v.raw", "dim": [1, 1, 4097]}})", "volume.dim[2]", "4097"},
    {R"({"volume": {"file": "v.raw", "dim": [1, 1, 1], "type": "int8"}})", "volume.type", "\"int8\""},
    {R"({"volume": {"file": "v.raw", "dim": [1, 1, 1], "endian": "middle"}})", "volume.endian", "\"middle\""},
    {R"({"volume": {"file": "v.raw", "dim": [1, 1, 1], "header": -1}})", "volume.header", "-1"},
    {R"({"volume": {"file": "v.den", "format": "png"}})", "volume.format", "\"png\""},
    {R"({"volume": {"file": ""}})", "volume.file", "\"\""},
    {R"({"volume": {"synthetic": "sphere", "size": [64, 1025, 64]}})", "volume.size[1]", "1025"},
    {R"({"volume": {"synthetic": "sphere", "size": [0, 1, 1]}})", "volume.size[0]", "0"},
    {R"({"volume": {"synthetic": "sphere", "radius": 0}})", "volume.radius", "0"},
    {R"({"volume": {"synthetic": "field", "field": "sinc"}})", "volume.field", "\"sinc\""},
    {R"({"volume": {"synthetic": "constant", "value": 1.5}})", "volume.value", "1.5"},
    {R"({"volume": {"synthetic": "noise", "seed": 4294967296}})", "volume.seed", "4294967296"},
    {R"({"volume": {"synthetic": "noise", "seed": -1}})", "volume.seed", "-1"},
    {R"({"volume": {"synthetic": "single_voxel", "at": [0, -1, 0]}})", "volume.at[1]", "-1"},
    {R"({"volume": {"synthetic": "single_voxel", "size": [8, 8, 8], "at": [0, 8, 0]}})", "volume.at", "[0,8,0]"},
    {R"({"volume": {"synthetic": "constant", "spacing": [1, 0, 1]}})", "volume.spacing[1]", "0"},
    {R"({"volume": {"synthetic": "constant", "map": "auto"}})", "volume.map", "\"auto\""},
    {R"({"volume": {"synthetic": "constant", "map": [5, 5]}})", "volume.map[1]", "5"},
    {R"("view": {"ray_offset": [1, 0]})", "view.ray_offset[0]", "1"},
    {R"("view": {"ray_offset": [0, -0.1]})", "view.ray_offset[1]", "-0.1"},
    {R"("xy_supersampling": 0)", "xy_supersampling", "0"},
    {R"("xy_supersampling": 5)", "xy_supersampling", "5"},
    {R"("view": {"zoom": 0})", "view.zoom", "0"},
    {R"("view": {"zoom": 2000})", "view.zoom", "2000"},
    {R"("view": {"zoom": "big"})", "view.zoom", "\"big\""},
    {R"("view": {"look_at": [1, 2]})", "view.look_at", "[1,2]"},
    {R"("view": {"look_at": [1, "a", 3]})", "view.look_at[1]", "\"a\""},
    {R"("view": {"direction": [0, 0, 0]})", "view.direction", "[0,0,0]"},
    {R"("view": {"direction": [0, 0, 1], "up": [0, 0, -3]})", "view.up", "[0,0,-3]"},
    {R"("output": {"width": 0})", "output.width", "0"},
    {R"("output": {"height": 8193})", "output.height", "8193"},
    {R"("transfer": {"color": [[0, 1, 1.5, 1]]})", "transfer.color[0][2]", "1.5"},
    {R"("transfer": {"opacity": [[-0.1, 0]]})", "transfer.opacity[0][0]", "-0.1"},
    {R"("transfer": {"opacity": []})", "transfer.opacity", "[]"},
    {R"("gm_lut": [[0, 2]])", "gm_lut[0][1]", "2"},
    {R"("lights": [{"direction": [0, 0, 0]}])", "lights[0].direction", "[0,0,0]"},
    {R"("lights": [{"direction": [0, 0, 1], "intensity": -1}])", "lights[0].intensity", "-1"},
    {R"("lights": [])", "lights", "[]"},
    {R"("material": {"ke": -0.1})", "material.ke", "-0.1"},
    {R"("material": {"kd": 4})", "material.kd", "4"},
    {R"("material": {"ks": 3.995})", "material.ks", "3.995"},
    {R"("material": {"specular_color": [1, 1, 2]})", "material.specular_color[2]", "2"},
    {R"("material": {"exponent": 0.5})", "material.exponent", "0.5"},
    {R"("material": {"exponent": 129})", "material.exponent", "129"},
    {R"("blend": "average")", "blend", "\"average\""},
    {R"("supersampling": 9)", "supersampling", "9"},
    {R"("supersampling": 0)", "supersampling", "0"},
    {R"("cropping": {"x": [-1, 3]})", "cropping.x[0]", "-1"},
    {R"("cropping": {"y": [5, 4]})", "cropping.y[1]", "4"},
    {R"("cropping": {"combine": "xor"})", "cropping.combine", "\"xor\""},
    {R"("cropping": {"mask": 256})", "cropping.mask", "256"},
    {R"("cut_plane": {"normal": [0, 0, 0]})", "cut_plane.normal", "[0,0,0]"},
    {R"("cut_plane": {"falloff": -1})", "cut_plane.falloff", "-1"},
    {R"("cut_plane": {"dmin": 5, "dmax": 4})", "cut_plane.dmax", "4"},
    {R"("cut_plane": {"dmin": 1})", "cut_plane.dmax", "0"},
    {R"("cut_plane": {"keep": "both"})", "cut_plane.keep", "\"both\""},
    {R"("pipelines": 0)", "pipelines", "0"},
    {R"("pipelines": 257)", "pipelines", "257"},
    {R"("clock_mhz": 0)", "clock_mhz", "0"},
    {R"("clock_mhz": 10001)", "clock_mhz", "10001"},
    {R"("precision": {"voxel_bits": 7})", "precision.voxel_bits", "7"},
    {R"("precision": {"voxel_bits": 17})", "precision.voxel_bits", "17"},
    {R"("precision": {"weight_bits": 15})", "precision.weight_bits", "15"},
    {R"("precision": {"weight_bits": 10, "dda_frac_bits": 9})", "precision.dda_frac_bits", "9"},
    {R"("precision": {"dda_frac_bits": 31})", "precision.dda_frac_bits", "31"},
    {R"("precision": {"gradient_bits": 3})", "precision.gradient_bits", "3"},
    {R"("precision": {"gradient_shift": 17})", "precision.gradient_shift", "17"},
    {R"("precision": {"magnitude_bits": 17})", "precision.magnitude_bits", "17"},
    {R"("precision": {"nr_iterations": 9})", "precision.nr_iterations", "9"},
    {R"("precision": {"color_bits": 9})", "precision.color_bits", "9"},
    {R"("precision": {"alpha_bits": 7})", "precision.alpha_bits", "7"},
    {R"("precision": {"gmlut_bits": 17})", "precision.gmlut_bits", "17"},
    {R"("precision": {"map_face_res": 1})", "precision.map_face_res", "1"},
    {R"("precision": {"map_bits": 33})", "precision.map_bits", "33"},
    {R"("precision": {"map_bits": 12, "map_frac_bits": 12})", "precision.map_frac_bits", "12"},
    {R"("precision": {"map_bits": 8})", "precision.map_frac_bits", "8"},  // the default 8 no longer fits
    {R"("precision": {"coef_bits": 17})", "precision.coef_bits", "17"},
    {R"("precision": {"coef_bits": 6})", "precision.coef_frac_bits", "8"},
    {R"("precision": {"coef_frac_bits": -1})", "precision.coef_frac_bits", "-1"},
    {R"("precision": {"eye_bits": 3})", "precision.eye_bits", "3"},
    {R"("precision": {"cut_bits": 15})", "precision.cut_bits", "15"},
    {R"("precision": {"cut_bits": 41})", "precision.cut_bits", "41"},
};

INSTANTIATE_TEST_SUITE_P(EveryRange, SceneOutOfRange, ::testing::ValuesIn(kRangeCases));

TEST(SceneErrors, RangeMessageFormat) {
  EXPECT_EQ(error_of(with(R"("supersampling": 9)")), "t.json: \"supersampling\" = 9 is out of range 1..8");
}

TEST(SceneErrors, TooManyLights) {
  std::string lights;
  for (int i = 0; i < 17; ++i) lights += std::string(i ? "," : "") + R"({"direction": [0, 0, 1]})";
  expect_error(with(R"("lights": [)" + lights + "]"), {"\"lights\"", "17 entries"});
}

TEST(SceneErrors, RotateAndDirectionTogether) {
  expect_error(with(R"("view": {"rotate": [0, 0, 0], "direction": [0, 0, 1]})"),
               {"\"view\"", "both \"rotate\" and \"direction\""});
  expect_error(with(R"("view": {"up": [0, 1, 0]})"), {"\"view.up\" = [0,1,0]", "view.direction"});
}

TEST(SceneErrors, TransferXMustIncreaseStrictly) {
  expect_error(with(R"("transfer": {"opacity": [[0, 0], [0.5, 1], [0.4, 1]]})"),
               {"\"transfer.opacity[2][0]\" = 0.4", "increase"});
  expect_error(with(R"("transfer": {"color": [[0, 1, 1, 1], [0, 1, 1, 1]]})"),
               {"\"transfer.color[1][0]\" = 0", "increase"});
  expect_error(with(R"("gm_lut": [[0.5, 0], [0.5, 1]])"), {"\"gm_lut[1][0]\" = 0.5"});
}

TEST(SceneErrors, VolumeStructure) {
  expect_error(R"({"view": {"rotate": [0, 0, 0]}})", {"\"volume\" is missing"});
  expect_error(R"({"volume": {}})", {"\"volume\" = {}", "\"file\" or \"synthetic\""});
  expect_error(R"({"volume": {"file": "a.den", "synthetic": "sphere"}})", {"\"volume\"", "both"});
  expect_error(R"({"volume": {"synthetic": "cube"}})", {"\"volume.synthetic\" = \"cube\"", "\"sphere\""});
  expect_error(R"({"volume": {"file": "head.png"}})", {"\"volume.file\" = \"head.png\"", "volume.format"});
  expect_error(R"({"volume": {"file": "v.raw"}})", {"\"volume.dim\" is missing"});
}

TEST(SceneErrors, LightWithoutDirection) {
  expect_error(with(R"("lights": [{"intensity": 1}])"), {"\"lights[0].direction\" is missing"});
}

TEST(SceneErrors, CombineAndMaskTogether) {
  expect_error(with(R"("cropping": {"combine": "union", "mask": 3})"), {"\"cropping\"", "both"});
}

TEST(SceneErrors, DuplicateKey) {
  expect_error(with(R"("material": {"ks": 0.1, "ks": 0.2})"), {"duplicate key \"material.ks\""});
  expect_error(with(R"("lights": [{"direction": [0, 0, 1]}, {"direction": [0, 0, 1], "direction": [1, 0, 0]}])"),
               {"duplicate key \"lights[1].direction\""});
}

TEST(SceneErrors, JsonSyntax) {
  expect_error("{\n  \"volume\": {\"synthetic\": \"sphere\"},\n  \"shading\": tru,\n  \"blend\": \"mip\"\n}",
               {"invalid JSON", "line 3", "byte 56"});
  expect_error("", {"invalid JSON"});
}

TEST(SceneErrors, JsonSyntaxInAFileNamesTheFile) {
  TempFile f("{\"volume\": ");
  try {
    load_scene(f.path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(f.path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("invalid JSON"), std::string::npos) << e.what();
  }
}

TEST(SceneErrors, MissingFile) {
  const std::string path = "/nonexistent/cube4/none.json";
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_scene(fs::temp_directory_path().string()), InputError);
}

TEST(SceneErrors, FinishSceneChecksBuiltScenes) {
  Scene s;
  s.precision.coef_bits = 8;  // the default coef_frac_bits (8) needs 9 or more
  try {
    finish_scene(s);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"precision.coef_frac_bits\" = 8"), std::string::npos) << e.what();
  }
}

// ---- effects --------------------------------------------------------------

using Names = std::vector<std::string>;

TEST(SceneEffects, UnshadedMipNeedsNoGradient) {
  const EffectSet e = effects_of(parse_with(R"("blend": "mip", "shading": false)"));
  EXPECT_EQ(e.blend, Blend::Mip);
  EXPECT_FALSE(e.gradient);
  EXPECT_FALSE(e.magnitude);
  EXPECT_FALSE(e.shading);
  EXPECT_FALSE(e.specular);
  EXPECT_EQ(e.names(), (Names{"mip"}));
}

TEST(SceneEffects, ShadedComposite) {
  const EffectSet e = effects_of(parse_with(""));
  EXPECT_TRUE(e.gradient);
  EXPECT_FALSE(e.magnitude);
  EXPECT_TRUE(e.shading);
  EXPECT_TRUE(e.specular);
  EXPECT_EQ(e.names(), (Names{"composite", "gradient", "shading", "specular"}));
}

TEST(SceneEffects, NoSpecularWithoutKs) {
  const EffectSet e = effects_of(parse_with(R"("material": {"ks": 0})"));
  EXPECT_TRUE(e.shading);
  EXPECT_FALSE(e.specular);
}

TEST(SceneEffects, GradientModulatedOpacityOnly) {
  const EffectSet e = effects_of(parse_with(R"("shading": false, "gradient_modulation": {"opacity": true})"));
  EXPECT_TRUE(e.magnitude);
  EXPECT_TRUE(e.gradient);
  EXPECT_FALSE(e.shading);
  EXPECT_EQ(e.names(), (Names{"composite", "gradient", "magnitude"}));
}

TEST(SceneEffects, ShadingModulationNeedsShading) {
  const std::string gm = R"("gradient_modulation": {"diffuse": true, "specular": true})";
  EXPECT_FALSE(effects_of(parse_with(gm + R"(, "shading": false)")).magnitude);
  EXPECT_FALSE(effects_of(parse_with(gm + R"(, "shading": false)")).gradient);
  EXPECT_TRUE(effects_of(parse_with(gm)).magnitude);
}

TEST(SceneEffects, NoLightsNoShading) {
  Scene s = parse_with("");
  s.lights.clear();
  const EffectSet e = effects_of(s);
  EXPECT_FALSE(e.shading);
  EXPECT_FALSE(e.specular);
  EXPECT_FALSE(e.gradient);
}

TEST(SceneEffects, CroppingCutPlaneSupersamplingInOrder) {
  const EffectSet e = effects_of(parse_with(
      R"("blend": "minip", "shading": false, "supersampling": 2, "cut_plane": {}, "cropping": {})"));
  EXPECT_TRUE(e.cropping);
  EXPECT_TRUE(e.cut_plane);
  EXPECT_TRUE(e.supersampling);
  EXPECT_EQ(e.names(), (Names{"minip", "cropping", "cut_plane", "supersampling"}));
  EXPECT_FALSE(effects_of(parse_with(R"("supersampling": 1)")).supersampling);
}

TEST(SceneEffects, AllNamesInOrder) {
  const EffectSet e = effects_of(parse_with(
      R"("gradient_modulation": {"opacity": true}, "supersampling": 4, "cut_plane": {}, "cropping": {})"));
  EXPECT_EQ(e.names(), (Names{"composite", "gradient", "magnitude", "shading", "specular", "cropping",
                              "cut_plane", "supersampling"}));
}

TEST(SceneMachine, PolygonEngineRatesInMillionsASecond) {
  const Scene d = parse_with("");
  EXPECT_EQ(d.polygon_engine.fill_rate, 180e6);  // Cube-5 §6's assumptions by default
  EXPECT_EQ(d.polygon_engine.triangle_rate, 6e6);
  EXPECT_EQ(d.polygon_engine.dual_fill_rate, 357e6);
  EXPECT_EQ(d.polygon_engine.rle_clock_hz, 200e6);
  const Scene s = parse_with(
      R"("polygon_engine": {"fill_rate_m": 90, "triangle_rate_m": 0.5, "dual_fill_rate_m": 1000, "rle_clock_mhz": 266})");
  EXPECT_EQ(s.polygon_engine.fill_rate, 90e6);
  EXPECT_EQ(s.polygon_engine.triangle_rate, 0.5e6);
  EXPECT_EQ(s.polygon_engine.dual_fill_rate, 1000e6);
  EXPECT_EQ(s.polygon_engine.rle_clock_hz, 266e6);
  expect_error(with(R"("polygon_engine": {"fill_rate_m": 0})"), {"\"polygon_engine.fill_rate_m\"", "out of range"});
  expect_error(with(R"("polygon_engine": {"rle_clock_mhz": -200})"), {"\"polygon_engine.rle_clock_mhz\"", "out of range"});
  expect_error(with(R"("polygon_engine": {"fill_rate": 180})"), {"unknown key \"polygon_engine.fill_rate\""});
}

}  // namespace
}  // namespace cube4::golden
