// Voxel tags (bela §III): the nearest-voxel rule, the slice form of it,
// the scene keys and their errors, and the golden renderers on tagged
// volumes; a scene whose tags are all 0 renders as one without tags.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <random>
#include <string>

#include "golden/errors.hpp"
#include "golden/slice_steps.hpp"
#include "golden/volume_io.hpp"
#include "tb/tests/test_support.hpp"

using namespace cube4;

namespace {

std::string error_of(const std::string& json, const std::string& dir = ".") {
  try {
    test::setup_parsed(golden::parse_scene(json, "t.json"), dir);
  } catch (const golden::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

void expect_has(const std::string& msg, std::initializer_list<std::string> parts) {
  for (const std::string& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "wanted '" << p << "' in: " << msg;
}

const std::string kSpheres = R"("volume": {"synthetic": "spheres", "size": [16, 16, 16]})";

// Pixels whose colour is mostly red, and mostly blue.
std::array<int, 2> red_and_blue(const golden::BasePlane& bp) {
  std::array<int, 2> n{0, 0};
  for (size_t i = 0; i < bp.rgba.size(); i += 4) {
    const int r = bp.rgba[i], b = bp.rgba[i + 2];
    if (bp.rgba[i + 3] == 0) continue;
    if (r > 2 * b) ++n[0];
    if (b > 2 * r) ++n[1];
  }
  return n;
}

}  // namespace

TEST(Tags, NearestCornerIsTheUpperVoxelFromHalfOn) {
  const int W = 8;
  EXPECT_EQ(golden::upper_corner(0, W), 0);
  EXPECT_EQ(golden::upper_corner(127, W), 0);
  EXPECT_EQ(golden::upper_corner(128, W), 1);  // the tie goes up
  EXPECT_EQ(golden::upper_corner(255, W), 1);
  EXPECT_EQ(golden::upper_corner(256, W), 1);  // the weight's end: the upper voxel itself
  const std::array<uint32_t, 8> t{0, 1, 2, 3, 4, 5, 6, 7};
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(golden::sample_tag(t, i & 1 ? 200 : 50, i & 2 ? 128 : 127, i & 4 ? 255 : 0, W), uint32_t(i));
}

TEST(Tags, SliceFormEqualsSampleTagPerSample) {
  std::mt19937 gen(11);
  const int nx = 9, ny = 7, W = 6;
  golden::Plane lo(nx, ny, 1), hi(nx, ny, 1), out(nx, ny, 1);
  for (auto* p : {&lo, &hi})
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) p->row(y)[x] = static_cast<int32_t>(gen() % 16);
  golden::SliceInterp interp(nx, ny, W);
  for (int trial = 0; trial < 200; ++trial) {
    golden::SliceControl c;
    c.wx = gen() % (1u << W);
    c.wy = gen() % (1u << W);
    c.wz = gen() % (1u << W);
    std::vector<golden::Span> whole(ny, golden::Span{0, nx});
    interp.tags(lo, hi, c, out, 0, ny, whole.data());
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        std::array<uint32_t, 8> t{};
        for (int i = 0; i < 8; ++i) t[i] = (i & 4 ? hi : lo).at(x + (i & 1), y + (i >> 1 & 1));
        ASSERT_EQ(out.at(x, y), golden::sample_tag(t, c.wx, c.wy, c.wz, W)) << x << "," << y;
      }
  }
}

TEST(Tags, ClassificationAddressIsTagThenValue) {
  golden::Precision p;
  p.tag_bits = 2;
  EXPECT_EQ(golden::class_address(0, 5, p), 5u);
  EXPECT_EQ(golden::class_address(3, 4095, p), (3u << 12) | 4095u);
}

TEST(Tags, SceneKeysAndTheTableTheHostBuilds) {
  const test::Setup s = test::setup_file(std::string(CUBE4_SOURCE_DIR) + "/scenes/tagged_spheres.json");
  EXPECT_EQ(s.scene.precision.tag_bits, 2);
  ASSERT_EQ(s.scene.tags.label.size(), 2u);
  EXPECT_EQ(s.scene.tags.label[1].key, "tags.label[1]");
  const golden::Registers& r = s.host.regs;
  EXPECT_EQ(r.classification.size(), size_t{4} << 12);
  ASSERT_EQ(r.tag_coefs.size(), 4u);
  EXPECT_NE(r.tag_coefs[2].ks, r.tag_coefs[1].ks);  // tag 2's own material
  EXPECT_EQ(r.tag_coefs[1].ke, r.tag_coefs[0].ke);  // tag 1's is the scene's
  // Tag 1 red, tag 2 blue at full value.
  const golden::ClassEntry& a = r.classification[golden::class_address(1, 4095, r.p)];
  const golden::ClassEntry& b = r.classification[golden::class_address(2, 4095, r.p)];
  EXPECT_GT(a.r, a.b);
  EXPECT_GT(b.b, b.r);
  EXPECT_EQ(s.volume.tag_at(7, 15, 15), 1);
  EXPECT_EQ(s.volume.tag_at(24, 15, 15), 2);
  EXPECT_EQ(s.volume.tag_at(7, 0, 0), 0);
  EXPECT_NE(golden::effects_of(s.scene).names().back(), "polygons");
  EXPECT_EQ(golden::effects_of(s.scene).names().back(), "tags");
}

TEST(Tags, EveryLabellingRule) {
  const test::Setup s = test::setup(R"({"volume": {"synthetic": "field", "field": "ramp_x", "size": [8, 8, 8]},
      "precision": {"tag_bits": 3},
      "tags": {"label": [{"tag": 1, "threshold": [0.5, 1]}, {"tag": 2, "box": {"min": [0, 0, 0], "max": [1, 7, 7]}},
                         {"tag": 3, "sphere": {"center": [7, 7, 7], "radius": 1}}]}})");
  EXPECT_EQ(s.volume.tag_at(2, 3, 3), 0);
  EXPECT_EQ(s.volume.tag_at(6, 3, 3), 1);
  EXPECT_EQ(s.volume.tag_at(1, 5, 5), 2);  // a later rule wins
  EXPECT_EQ(s.volume.tag_at(7, 7, 7), 3);
  EXPECT_EQ(s.volume.tag_at(6, 7, 7), 3);
  EXPECT_EQ(s.volume.tag_at(6, 6, 7), 1);
}

TEST(Tags, FileOfTagsAndItsErrors) {
  const std::string dir = ::testing::TempDir();
  auto write = [&](const std::string& name, size_t n, uint8_t value) {
    std::ofstream f(dir + "/" + name, std::ios::binary);
    for (size_t i = 0; i < n; ++i) f.put(static_cast<char>(i == n / 2 ? value : 1));
  };
  write("tags_ok.raw", 8 * 8 * 8, 3);
  write("tags_big.raw", 8 * 8 * 8, 9);
  write("tags_short.raw", 100, 1);
  auto scene = [](const std::string& file) {
    return R"({"volume": {"synthetic": "constant", "size": [8, 8, 8]}, "precision": {"tag_bits": 2},
               "tags": {"file": ")" + file + R"("}})";
  };
  const test::Setup s = test::setup_parsed(golden::parse_scene(scene("tags_ok.raw"), "t.json"), dir);
  EXPECT_EQ(s.volume.tag_at(0, 0, 0), 1);
  EXPECT_EQ(s.volume.tag_at(0, 0, 4), 3);  // voxel 256
  expect_has(error_of(scene("tags_big.raw"), dir), {"tags_big.raw", "tags.file", "(0,0,4)", "tag 9", "above 3",
                                                   "precision.tag_bits"});
  expect_has(error_of(scene("tags_short.raw"), dir), {"tags_short.raw", "tags.file", "512", "holds 100"});
  expect_has(error_of(scene("none.raw"), dir), {"none.raw"});
}

TEST(Tags, SceneErrorsNameTheKeyAndValue) {
  expect_has(error_of("{" + kSpheres + R"(, "tags": {"label": [{"tag": 1, "box": {"min": [0,0,0], "max": [1,1,1]}}]}})"),
             {"t.json", "\"tags\"", "precision.tag_bits"});
  expect_has(error_of("{" + kSpheres + R"(, "precision": {"tag_bits": 1},
             "tags": {"label": [{"tag": 2, "box": {"min": [0,0,0], "max": [1,1,1]}}]}})"),
             {"t.json", "tags.label[0].tag", "= 2", "0..1"});
  expect_has(error_of("{" + kSpheres + R"(, "precision": {"tag_bits": 2},
             "tags": {"classes": [{"tag": 7, "color": [[0, 1, 1, 1]]}]}})"),
             {"t.json", "tags.classes[0].tag", "= 7", "0..3"});
  expect_has(error_of("{" + kSpheres + R"(, "precision": {"tag_bits": 2},
             "tags": {"classes": [{"tag": 1, "material": {"exponent": 5}}]}})"),
             {"t.json", "tags.classes[0].material.exponent", "specular map"});
  expect_has(error_of("{" + kSpheres + R"(, "precision": {"tag_bits": 5}})"),
             {"t.json", "precision.tag_bits", "= 5", "0..4"});
  expect_has(error_of("{" + kSpheres + R"(, "precision": {"tag_bits": 1},
             "tags": {"label": [{"tag": 1, "box": {"min": [0,0,0]}}]}})"),
             {"t.json", "tags.label[0].box.max", "missing"});
  expect_has(error_of("{" + kSpheres + R"(, "precision": {"tag_bits": 1},
             "tags": {"label": [{"tag": 1, "threshold": [0, 1], "sphere": {"center": [0,0,0], "radius": 1}}]}})"),
             {"t.json", "tags.label[0]", "exactly one"});
  expect_has(error_of("{" + kSpheres + R"(, "precision": {"tag_bits": 1}, "tags": {"lable": []}})"),
             {"t.json", "unknown key \"tags.lable\""});
}

TEST(Tags, AllZeroTagsRenderAsNoTags) {
  // A wider classification address with every tag 0 and no class of its
  // own: the image of the scene without tags, bit for bit.
  const std::string base = "{" + kSpheres + R"(, "view": {"rotate": [10, 40, 0]})";
  const test::Setup plain = test::setup(base + "}");
  const test::Setup tagged = test::setup(base + R"(, "precision": {"tag_bits": 3}})");
  EXPECT_EQ(golden::render_fixed(plain.volume, plain.host.regs).rgba,
            golden::render_fixed(tagged.volume, tagged.host.regs).rgba);
}

TEST(Tags, TwoTouchingSpheresInTheirOwnColoursFromEveryBasePlane) {
  for (int view = 0; view < 6; ++view) {
    const int axis = view / 2, sign = view % 2 ? -1 : 1;
    SCOPED_TRACE("axis " + std::to_string(axis) + " sign " + std::to_string(sign));
    golden::Scene sc = golden::load_scene(std::string(CUBE4_SOURCE_DIR) + "/scenes/tagged_spheres.json");
    golden::Vec3 dir{0, 0, 0};
    dir[axis] = sign;
    sc.view.direction = dir;
    sc.view.up = axis == 1 ? golden::Vec3{0, 0, 1} : golden::Vec3{0, 1, 0};
    const test::Setup s = test::setup_parsed(sc, std::string(CUBE4_SOURCE_DIR) + "/scenes");
    const golden::BasePlane bp = golden::render_fixed(s.volume, s.host.regs);
    const auto n = red_and_blue(bp);
    // Along x one sphere hides the other but for a rim (the red one's
    // opacity starts at a lower value, so it looks a little larger).
    if (axis == 0) {
      EXPECT_GT(n[sign > 0 ? 0 : 1], 3 * n[sign > 0 ? 1 : 0] + 50) << n[0] << " red, " << n[1] << " blue";
    } else {
      EXPECT_GT(n[0], 50);
      EXPECT_GT(n[1], 50);
    }
    // Threads and empty-space skipping change nothing with tags either.
    golden::FixedOptions opt;
    opt.threads = 3;
    opt.skip_empty = false;
    EXPECT_EQ(golden::render_fixed(s.volume, s.host.regs, opt).rgba, bp.rgba);
  }
}

TEST(Tags, FloatReferenceAndSplatDrawTheTagsToo) {
  const test::Setup s = test::setup_file(std::string(CUBE4_SOURCE_DIR) + "/scenes/tagged_spheres.json");
  auto count = [](const golden::ImageF& img) {
    std::array<int, 2> n{0, 0};
    for (size_t i = 0; i < img.rgba.size(); i += 4) {
      if (img.rgba[i + 3] < 0.05f) continue;
      if (img.rgba[i] > 2 * img.rgba[i + 2]) ++n[0];
      if (img.rgba[i + 2] > 2 * img.rgba[i]) ++n[1];
    }
    return n;
  };
  const golden::ImageF fixed = test::final_fixed(s);
  for (const golden::ImageF& img : {fixed, test::final_float(s), test::final_reference(s),
                                    golden::render_splat(s.volume, s.scene, s.host.view)}) {
    const auto n = count(img);
    EXPECT_GT(n[0], 500);
    EXPECT_GT(n[1], 500);
  }
  // The fixed point follows the float renderer's nearest-voxel tags closely.
  EXPECT_GT(test::compare(fixed, test::final_float(s)).psnr, 30);
}
