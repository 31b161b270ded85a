// Cube-4's perspective projection in the golden model: the weight
// generator's ray DDA and realignment, the box-filter stages, the gradient's
// lateral scale, the camera's checks, and the renderers against each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "golden/errors.hpp"
#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/units/dda.hpp"
#include "golden/units/gradient.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "tb/image_io.hpp"
#include "tb/tests/cli_support.hpp"
#include "tb/tests/test_support.hpp"

using namespace cube4;
using golden::BoxAxis;

namespace {

constexpr int F = 20;

std::string sphere(const std::string& view, const std::string& extra = "", const std::string& size = "[24,24,24]") {
  return R"({"volume": {"synthetic": "sphere", "size": )" + size + R"(}, "view": )" + view + extra + "}";
}

int64_t alpha_sum(const golden::BasePlane& bp) {
  int64_t s = 0;
  for (size_t i = 3; i < bp.rgba.size(); i += 4) s += bp.rgba[i];
  return s;
}

// The message of the InputError `f` throws ("" if none).
template <class Fn>
std::string error_of(Fn&& f) {
  try {
    f();
  } catch (const golden::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(PerspectiveUnits, ABoxOneVoxelWideIsLinearInterpolation) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 100000; ++i) {
    const int64_t pos = static_cast<int64_t>(rng() % (int64_t{200} << F)) - (int64_t{50} << F);
    const BoxAxis b = golden::box_axis(pos, int64_t{1} << F, F, 8);
    const uint32_t f = static_cast<uint32_t>((pos >> (F - 8)) & 255);
    ASSERT_EQ(b.first, pos >> F) << pos;
    ASSERT_EQ(b.overlap[0], 256 - f) << pos;
    ASSERT_EQ(b.overlap[1], f) << pos;
    ASSERT_EQ(b.overlap[2] + b.overlap[3], 0u) << pos;
  }
}

TEST(PerspectiveUnits, OverlapsCoverTheBoxExactlyForExtentsUpToThree) {
  std::mt19937_64 rng(2);
  for (int w : {2, 8, 14}) {
    for (int i = 0; i < 100000; ++i) {
      // Extents 1, 2 and 3 exactly, and anything between.
      const int64_t spacing = i % 4 < 3 ? (int64_t{1 + i % 4 % 3} << F)
                                        : (int64_t{1} << F) + static_cast<int64_t>(rng() % (int64_t{2} << F) + 1);
      const int64_t pos = static_cast<int64_t>(rng() % (int64_t{300} << F)) - (int64_t{100} << F);
      const BoxAxis b = golden::box_axis(pos, spacing, F, w);
      uint64_t sum = 0;
      for (uint32_t o : b.overlap) sum += o;
      ASSERT_EQ(sum, static_cast<uint64_t>(golden::box_extent(spacing, F, w))) << "w " << w << " pos " << pos;
      // The box is centred on the sample: it starts within m/2 + 1/2 before it.
      const double centre = std::ldexp(static_cast<double>(pos), -F);
      ASSERT_LE(b.first, std::floor(centre + 0.5)) << pos;
      ASSERT_GE(b.first, std::floor(centre + 0.5 - std::ldexp(static_cast<double>(spacing), -F) / 2) - 1) << pos;
    }
  }
}

TEST(PerspectiveUnits, TheBoxFilterKeepsAConstantFieldExactly) {
  std::mt19937_64 rng(3);
  for (int vb : {8, 12, 16})
    for (int wb : {2, 8, 14}) {
      golden::Precision p;
      p.voxel_bits = vb;
      p.weight_bits = wb;
      const int q = golden::box_recip_bits(p);
      for (int i = 0; i < 30000; ++i) {
        const int64_t spacing = (int64_t{1} << F) + static_cast<int64_t>(rng() % ((int64_t{2} << F) + 1));
        const int64_t px = static_cast<int64_t>(rng() % (int64_t{64} << F)), py = static_cast<int64_t>(rng() % (int64_t{64} << F));
        const uint32_t value = i == 0 ? static_cast<uint32_t>(golden::max_unsigned(vb))
                                      : static_cast<uint32_t>(rng() % (golden::max_unsigned(vb) + 1));
        std::array<std::array<uint32_t, 4>, 4> v{};
        for (auto& row : v) row.fill(value);
        const uint64_t recip = golden::box_reciprocal(golden::box_extent(spacing, F, wb), q);
        ASSERT_EQ(golden::box_filter(v, golden::box_axis(px, spacing, F, wb), golden::box_axis(py, spacing, F, wb),
                                     recip, q),
                  value)
            << "voxel_bits " << vb << " weight_bits " << wb << " spacing " << spacing;
      }
    }
}

namespace {
// docs/perspective.md: the reciprocal's error is below a quarter of an LSB,
// the final rounding adds half; for voxels in [lo, hi] of type T.
template <class T>
void check_box_filter_bound(int64_t lo, int64_t hi, unsigned seed) {
  std::mt19937_64 rng(seed);
  golden::Precision p;
  const int q = golden::box_recip_bits(p);
  for (int i = 0; i < 1000000; ++i) {
    const int64_t spacing = (int64_t{1} << F) + static_cast<int64_t>(rng() % ((int64_t{2} << F) + 1));
    const BoxAxis bx = golden::box_axis(static_cast<int64_t>(rng() % (int64_t{64} << F)), spacing, F, p.weight_bits);
    const BoxAxis by = golden::box_axis(static_cast<int64_t>(rng() % (int64_t{64} << F)), spacing, F, p.weight_bits);
    std::array<std::array<T, 4>, 4> v{};
    double exact = 0;
    for (size_t j = 0; j < 4; ++j)
      for (size_t k = 0; k < 4; ++k) {
        v[j][k] = static_cast<T>(lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1)));
        exact += static_cast<double>(bx.overlap[k]) * by.overlap[j] * static_cast<double>(v[j][k]);
      }
    const double e = static_cast<double>(golden::box_extent(spacing, F, p.weight_bits));
    exact /= e * e;
    const T got = golden::box_filter_t<T>(v, bx, by, golden::box_reciprocal(golden::box_extent(spacing, F, p.weight_bits), q), q);
    ASSERT_LT(std::fabs(static_cast<double>(got) - exact), 0.75) << i;
  }
}
}  // namespace

TEST(PerspectiveUnits, TheBoxFilterIsWithinThreeQuartersOfAnLsbOfTheExactMean) {
  const int64_t top = (int64_t{1} << golden::Precision{}.voxel_bits) - 1;
  check_box_filter_bound<uint32_t>(0, top, 4);
  // VolumePro's voxel z differences (V + 1 bits, signed) through the same stage.
  check_box_filter_bound<int32_t>(-top, top, 5);
}

TEST(PerspectiveUnits, RaysInsideAreThoseWhosePositionIsInTheVolume) {
  std::mt19937_64 rng(5);
  for (int i = 0; i < 2000; ++i) {
    const int64_t spacing = (int64_t{1} << F) + static_cast<int64_t>(rng() % ((int64_t{2} << F) + 1));
    const int64_t ray0 = static_cast<int64_t>(rng() % (int64_t{400} << F)) - (int64_t{200} << F);
    const int n = 1 + static_cast<int>(rng() % 100);
    const golden::RayRange r = golden::rays_inside(ray0, spacing, n, F);
    for (int64_t u = -300; u < 300; ++u) {
      const int64_t x = golden::ray_position(ray0, spacing, u);
      ASSERT_EQ(x >= 0 && x < (int64_t{n} << F), u >= r.lo && u < r.hi) << "ray " << u;
    }
  }
}

TEST(PerspectiveUnits, RealignedPointsLieStraightBehindTheSample) {
  std::mt19937_64 rng(6);
  for (int i = 0; i < 100000; ++i) {
    const int64_t m_here = (int64_t{1} << F) + static_cast<int64_t>(rng() % ((int64_t{2} << F) + 1));
    const int64_t m_there = m_here - static_cast<int64_t>(rng() % 5000);
    const int64_t c_here = static_cast<int64_t>(rng() % (int64_t{40} << F)) - (int64_t{20} << F);
    const int64_t c_there = c_here + static_cast<int64_t>(rng() % (int64_t{2} << F)) - (int64_t{1} << F);
    const golden::RealignDda d = golden::realign_dda(c_here, m_here, c_there, m_there, F);
    const int64_t u = static_cast<int64_t>(rng() % 600) - 300;
    const int64_t pos = d.start + u * d.step;  // ray index of the other slice, F fraction bits
    const long double there = static_cast<long double>(c_there) + static_cast<long double>(pos) * m_there / (1 << F);
    const long double here = static_cast<long double>(golden::ray_position(c_here, m_here, u));
    // Two floors, the start's and the step's (times |u|), each under one LSB of a ray index.
    ASSERT_LE(std::fabs(static_cast<double>(there - here)), static_cast<double>((std::llabs(u) + 1) * m_there) / (1 << F))
        << i;
  }
}

TEST(PerspectiveUnits, TheLateralScaleOfUnitSpacingLeavesTheParallelGradient) {
  std::mt19937_64 rng(7);
  golden::Precision p;
  const int64_t unit = golden::lateral_reciprocal(int64_t{1} << F, F, golden::lateral_recip_bits(p));
  for (int i = 0; i < 100000; ++i) {
    uint32_t s[6];
    for (uint32_t& x : s) x = static_cast<uint32_t>(rng() % 4096);
    ASSERT_EQ(golden::gradient_perspective(s[0], s[1], s[2], s[3], s[4], s[5], 2, unit, p),
              golden::gradient_12n(s[0], s[1], s[2], s[3], s[4], s[5], 2, p));
  }
}

// One weight generator for both projections (docs/perspective.md, "Not
// yet"): with rays one voxel apart (SCALE_START one, SCALE_STEP zero) the
// perspective generator puts ray u of slice k where parallel projection's
// DDA puts base-plane column u, with the same whole voxel and weights, so
// its samples would be parallel projection's. Its realignment of the
// neighbouring slices is not: it truncates the exact difference of the two
// slices' positions, where parallel projection (golden realign()) takes the
// difference of the two truncated weights, and the two differ by one LSB
// about half the time. A merged unit must keep parallel projection's rule
// for it, or every parallel image would change.
TEST(PerspectiveUnits, AtSpacingOneTheSamplesAreParallelProjectionsButNotTheRealignment) {
  std::mt19937_64 gen(3);
  golden::Precision p;
  const int F = p.dda_frac_bits, W = p.weight_bits;
  const int64_t one = int64_t{1} << F;
  int differ = 0, n = 0;
  for (int i = 0; i < 20000; ++i) {
    const int64_t start = static_cast<int64_t>(gen() % (uint64_t{1} << (F + 6))),
                  step = static_cast<int64_t>(gen() % static_cast<uint64_t>(one));
    const int k = 1 + static_cast<int>(gen() % 200);
    const int64_t u = static_cast<int64_t>(gen() % 300);
    const int64_t here = golden::dda_position(start, step, k), there = golden::dda_position(start, step, k - 1);
    const golden::SliceOffset parallel = golden::dda_split(here, F, W);
    const golden::SliceOffset persp = golden::dda_split(golden::ray_position(here, one, u), F, W);
    ASSERT_EQ(persp.integer, parallel.integer + u);
    ASSERT_EQ(persp.weight, parallel.weight);
    const golden::BoxAxis box = golden::box_axis(golden::ray_position(here, one, u), one, F, W);
    ASSERT_EQ(box.first, parallel.integer + u);
    ASSERT_EQ(box.overlap[0], (1u << W) - parallel.weight);
    ASSERT_EQ(box.overlap[1], parallel.weight);
    const golden::Realign par = golden::realign(parallel.weight, golden::dda_split(there, F, W).weight, W);
    const golden::RayPoint pr = golden::realigned_ray(golden::realign_dda(here, one, there, one, F), u, F, W);
    ++n;
    if (pr.weight != par.weight) ++differ;
  }
  EXPECT_GT(differ, n / 4);
  EXPECT_LT(differ, 3 * n / 4);
}

TEST(PerspectiveCamera, BadCamerasNameTheKeyAndValue) {
  const std::string persp = R"({"rotate": [10, 20, 0], "projection": "perspective")";
  auto message = [](const std::string& json) { return error_of([&] { test::setup(json); }); };
  EXPECT_NE(message(sphere(persp + R"(, "fov": 90})")).find("\"view.fov\" = 90"), std::string::npos);
  EXPECT_NE(message(sphere(persp + R"(, "fov": 0})")).find("\"view.fov\" = 0"), std::string::npos);
  EXPECT_NE(message(sphere(R"({"fov": 30})")).find("needs \"view.projection\": \"perspective\""), std::string::npos);
  EXPECT_NE(message(sphere(persp + R"(, "distance": 5})")).find("\"view.distance\" = 5 puts the eye inside the volume"),
            std::string::npos);
  const std::string close = message(sphere(persp + R"(, "distance": 20})"));
  EXPECT_NE(close.find("\"view.distance\" = 20 puts the eye"), std::string::npos) << close;
  EXPECT_NE(close.find("at most 3"), std::string::npos) << close;
  EXPECT_NE(message(sphere(R"({"projection": "perspective", "eye": [11.5, 11.5, -40], "rotate": [0,0,0]})")).find("\"view.eye\""),
            std::string::npos);
  EXPECT_NE(message(sphere(R"({"projection": "perspective", "eye": [11.5, 11.5, -40], "distance": 50})")).find("both place the eye"),
            std::string::npos);
  EXPECT_NE(message(sphere(R"({"projection": "perspective", "eye": [11.5, 11.5, 11.5]})")).find("is the point looked at"),
            std::string::npos);
  EXPECT_NE(message(sphere(R"({"projection": "perspective", "eye": [11.5, 40, 11.5]})")).find("parallel"), std::string::npos);
  EXPECT_NE(message(sphere(R"({"projection": "perspective", "eye": [11.5, 11.5, 2]})")).find("\"view.eye\" = [11.5,11.5,2]"),
            std::string::npos);
  EXPECT_EQ(message(sphere(persp + R"(, "distance": 60})")), "");
}

TEST(PerspectiveCamera, TheFirstSliceHasOneRayPerPixelAndTheRaysSpreadBehindIt) {
  const auto s = test::setup(sphere(R"({"rotate": [10, 20, 0], "projection": "perspective", "distance": 40})"));
  const golden::Registers& r = s.host.regs;
  ASSERT_TRUE(r.perspective);
  EXPECT_EQ(r.ray_spacing(0), int64_t{1} << r.p.dda_frac_bits);
  EXPECT_GT(r.ray_spacing(r.sample_slices() - 1), r.ray_spacing(0));
  EXPECT_LE(r.ray_spacing(r.sample_slices() - 1), 3 * r.ray_spacing(0));
  // The base plane holds every ray that meets the volume, and no more.
  const golden::RayRange a = r.rays_in_slice(0, 0), b = r.rays_in_slice(0, r.sample_slices() - 1);
  EXPECT_EQ(r.base_width(), std::max(a.hi, b.hi) - std::min(a.lo, b.lo));
}

TEST(PerspectiveRender, SixAxisViewsOfASymmetricSphereGiveIdenticalBasePlanes) {
  auto view = [](const std::string& eye) {
    return sphere(R"({"projection": "perspective", "fov": 40, "eye": )" + eye + R"(, "up": [1, 1, 1]})",
                  R"(, "shading": false)");
  };
  const auto first = test::setup(view("[11.5, 11.5, -30]"));
  const golden::BasePlane ref = golden::render_fixed(first.volume, first.host.regs);
  EXPECT_GT(alpha_sum(ref), 0);
  for (const char* eye : {"[11.5, 11.5, 53]", "[-30, 11.5, 11.5]", "[53, 11.5, 11.5]", "[11.5, -30, 11.5]",
                          "[11.5, 53, 11.5]"}) {
    const auto s = test::setup(view(eye));
    const golden::BasePlane bp = golden::render_fixed(s.volume, s.host.regs);
    ASSERT_EQ(bp.width, ref.width) << eye;
    ASSERT_EQ(bp.height, ref.height) << eye;
    EXPECT_EQ(bp.rgba, ref.rgba) << eye;
  }
}

TEST(PerspectiveRender, FixedFloatAndReferenceDrawThingsInTheSamePlace) {
  // An off-centre sphere in a wide view: a ray grid misplaced by one
  // base-plane pixel, or the warp by one image pixel, moves the centroid by
  // more than half a pixel.
  const auto s = test::setup(R"({"volume": {"synthetic": "sphere", "size": [64, 48, 80], "radius": 10,
      "center": [12, 36, 60]}, "view": {"rotate": [30, -40, 10], "projection": "perspective", "fov": 60},
      "output": {"width": 256, "height": 200}})");
  const auto fixed = test::centroid(test::final_fixed(s)), flt = test::centroid(test::final_float(s)),
             ref = test::centroid(test::final_reference(s));
  EXPECT_GT(ref[2], 100);
  for (const auto& c : {fixed, flt}) {
    EXPECT_NEAR(c[0], ref[0], 0.5);
    EXPECT_NEAR(c[1], ref[1], 0.5);
  }
}

TEST(PerspectiveRender, FixedMatchesFloatAsInParallelProjection) {
  // The parallel projection's bound for the same comparison (test_renderers).
  for (const char* fov : {"20", "45", "70"}) {
    const auto s = test::setup(sphere(std::string(R"({"rotate": [20, 30, 0], "projection": "perspective", "fov": )") + fov + "}",
                                      R"(, "output": {"width": 128, "height": 128})", "[40,40,40]"));
    const auto e = test::compare(test::final_fixed(s), test::final_float(s));
    EXPECT_GT(e.psnr, 35.0) << "fov " << fov;
  }
}

TEST(PerspectiveRender, EverySampleIsCountedOnce) {
  const auto s = test::setup(sphere(R"({"rotate": [10, 20, 0], "projection": "perspective", "distance": 40})",
                                    R"(, "supersampling": 2)"));
  golden::RenderStats stats;
  golden::FixedOptions opt;
  opt.stats = &stats;
  golden::render_fixed(s.volume, s.host.regs, opt);
  const golden::Registers& r = s.host.regs;
  uint64_t expected = 0;
  for (int k = 0; k < r.sample_slices(); ++k) {
    const golden::RayRange x = r.rays_in_slice(0, k), y = r.rays_in_slice(1, k);
    expected += static_cast<uint64_t>(std::max<int64_t>(0, x.hi - x.lo) * std::max<int64_t>(0, y.hi - y.lo));
  }
  EXPECT_EQ(stats.samples, expected);
  EXPECT_EQ(stats.slices, 48);
  // At most one sample per voxel column and slice: rays are at least a voxel apart.
  EXPECT_LE(stats.samples, uint64_t{24} * 24 * 48);
}

using PerspectiveCli = test::Cli;

TEST_F(PerspectiveCli, RendersAtEveryLevelWithPerspectiveModelsAndRefusesTheOthersSayingWhy) {
  const std::string scene = write("p.json", sphere(R"({"rotate": [10, 20, 0], "projection": "perspective", "fov": 40})",
                                                   R"(, "output": {"width": 64, "height": 64})", "[16,16,16]"));
  // The perspective rings at RTL are built for CMake's
  // CUBE4_SYSTEM_PERSP_PIPES (none in a build without RTL, where the mixed
  // models and rtl are refused).
  const bool rtl = !sysc::rtl_persp_pipes().empty();
  std::string hash;
  std::vector<float> fixed_image;
  for (const char* model : {"fixed", "float", "reference", "tlm --check", "mixed:interp --check", "mixed:interp,addr",
                            "mixed:interp,shade --check", "mixed:shade", "mixed:gradient --check",
                            "mixed:interp,gradient,shade,addr --check", "rtl --check", "mixed:composite --check"}) {
    // The levels with units at RTL: every mixed one, and rtl.
    const bool mixed = std::string(model).rfind("mixed", 0) == 0 || std::string(model).rfind("rtl", 0) == 0;
    const test::CliResult r = run("render " + scene + " -q --model " + model + " -o " + path("o.png") + " --report " +
                                  path("r.json"));
    if (mixed && !rtl) {
      EXPECT_EQ(r.code, 2) << model;
      EXPECT_FALSE(test::fs::exists(path("o.png"))) << model;
      continue;
    }
    ASSERT_EQ(r.code, 0) << model << ": " << r.err;
    ASSERT_TRUE(test::fs::exists(path("o.png"))) << model;
    // Every fixed-point level's image is fixed's: the same base plane,
    // warped from the same place (the system model's plane once lay 5
    // pixels off, its image zoomed, with the base-plane hashes equal).
    const std::vector<float> image = cube4::tb::read_image(path("o.png")).rgba;
    if (fixed_image.empty()) fixed_image = image;
    if (std::string(model) != "float" && std::string(model) != "reference") {
      EXPECT_TRUE(image == fixed_image) << model << ": the image differs from --model fixed";
    }
    test::fs::remove(path("o.png"));
    // The report says what the rings' dataflow would need for the frame
    // (docs/perspective.md, "The dataflow"), the same at every level.
    std::ifstream in(path("r.json"));
    const nlohmann::json report = nlohmann::json::parse(in);
    const nlohmann::json& flow = report["view"]["dataflow"];
    const golden::PerspectiveReach reach = golden::perspective_reach(test::setup_file(scene).host.regs);
    EXPECT_EQ(flow["samples"], reach.samples) << model;
    EXPECT_EQ(flow["x"]["box"], nlohmann::json::array({-1, 2})) << model;
    EXPECT_EQ(flow["compositor_reach_needed"], golden::largest_home_move(reach)) << model;
    // The system levels say what perspective costs in cycles: nothing in
    // the steady state (a voxel per pipeline per cycle either way).
    const bool system = std::string(model).rfind("tlm", 0) == 0 || mixed;
    EXPECT_EQ(report.contains("system"), system) << model;
    if (system) {
      const nlohmann::json& cost = report["system"]["perspective_cost"];
      EXPECT_EQ(cost["extra_cycles_steady_state"], 0) << model;
      EXPECT_EQ(cost["extra_cycles_per_frame"].get<int64_t>(),
                report["system"]["cycles_per_frame"].get<int64_t>() -
                    cost["parallel_projection_cycles_per_frame"].get<int64_t>())
          << model;
    }
    // Every fixed-point level draws the golden base plane, bit for bit.
    if (std::string(model) == "float" || std::string(model) == "reference") continue;
    const std::string h = report["baseplane_hash_fnv1a64"].get<std::string>();
    if (hash.empty()) hash = h;
    EXPECT_EQ(h, hash) << model << ": the base plane differs from --model fixed";
  }
  const std::pair<const char*, const char*> refused[] = {
      {"splat", "\"view.projection\": \"perspective\": the splat model projects voxels in parallel only"}};
  for (const auto& [model, why] : refused) {
    const test::CliResult r = run("render " + scene + " -q --model " + model + " -o " + path("no.png"));
    EXPECT_EQ(r.code, 2) << model;
    if (rtl || std::string(model) == "splat") {
      EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    }
    EXPECT_FALSE(test::fs::exists(path("no.png")));
  }
}

// VolumePro's voxel-difference z gradient in perspective renders at every
// level with fixed's image: the units at clocked TLM, the others at RTL,
// and the interpolation and gradient rings at RTL at a p with their
// z-gradient variants (CUBE4_SYSTEM_PERSP_PIPES and
// CUBE4_SYSTEM_ZDIFF_PIPES); at a p without them either ring at RTL is
// refused before anything is written, naming the CMake options and what to
// run instead.
TEST_F(PerspectiveCli, VoxelDifferenceZGradientRendersAtEveryLevelAndIsRefusedWhereTheRingsLackIt) {
  const std::string scene =
      write("zd.json", sphere(R"({"rotate": [10, 20, 0], "projection": "perspective", "fov": 40})",
                              R"(, "z_gradient": "voxel_differences", "output": {"width": 64, "height": 64})",
                              "[16,16,16]"));
  const bool rtl = !sysc::rtl_persp_pipes().empty();
  std::vector<float> fixed_image;
  for (const char* model : {"fixed", "tlm --check", "mixed:shade --check", "mixed:composite,addr --check",
                            "mixed:shade,composite,addr --check"}) {
    const bool mixed = std::string(model).rfind("mixed", 0) == 0;
    const test::CliResult r = run("render " + scene + " -q --model " + model + " -o " + path("o.png"));
    if (mixed && !rtl) continue;
    ASSERT_EQ(r.code, 0) << model << ": " << r.err;
    const std::vector<float> image = cube4::tb::read_image(path("o.png")).rgba;
    if (fixed_image.empty()) fixed_image = image;
    EXPECT_TRUE(image == fixed_image) << model << ": the image differs from --model fixed";
    test::fs::remove(path("o.png"));
  }
  if (!rtl) return;
  const std::vector<int> zdiff = sysc::rtl_persp_zdiff_pipes();
  for (const int p : sysc::rtl_persp_pipes()) {
    const bool built = std::find(zdiff.begin(), zdiff.end(), p) != zdiff.end();
    for (const char* model : {"mixed:interp", "mixed:gradient", "rtl"}) {
      const std::string args = std::string(model) + " --check --pipes " + std::to_string(p);
      const test::CliResult r = run("render " + scene + " -q --model " + args + " -o " + path("o.png"));
      if (built) {
        ASSERT_EQ(r.code, 0) << args << ": " << r.err;
        EXPECT_TRUE(cube4::tb::read_image(path("o.png")).rgba == fixed_image)
            << args << ": the image differs from --model fixed";
        test::fs::remove(path("o.png"));
        continue;
      }
      EXPECT_EQ(r.code, 2) << args;
      EXPECT_NE(r.err.find("z_gradient voxel_differences"), std::string::npos) << args << ": " << r.err;
      EXPECT_NE(r.err.find("CUBE4_SYSTEM_ZDIFF_PIPES"), std::string::npos) << args << ": " << r.err;
      EXPECT_FALSE(test::fs::exists(path("o.png"))) << args;
    }
  }
}

// Polygons and blocks in perspective through the command line: the TLM
// frame checked against golden (--check, through the host interface and
// POLY_* windows), the same base plane as --model fixed, and the report's
// fragment counts; clocked, the compositing unit at TLM and at RTL, the
// same image; blocks at fixed, tlm, mixed:interp and rtl alike.
TEST_F(PerspectiveCli, PolygonsAndBlocksRenderAtFixedAndTlmAlike) {
  const std::string scene = write("h.json", test::sphere_with_polygons(R"({"direction": [0.4, -0.3, 1], "projection": "perspective", "fov": 40})"));
  std::string hash;
  for (const std::string& args : {std::string("--model fixed"), std::string("--model tlm --check --pipes 5"),
                                  std::string("--model fixed --blocks 2x2x1"), std::string("--model tlm --check --blocks 2x2x1")}) {
    const bool blocks = args.find("--blocks") != std::string::npos;
    if (blocks) {
      // Polygons are not cut into blocks yet (as in parallel projection): refused, no image.
      const test::CliResult refused = run("render " + scene + " -q " + args + " -o " + path("no.png"));
      EXPECT_EQ(refused.code, 2) << args;
      EXPECT_FALSE(test::fs::exists(path("no.png"))) << args;
      continue;
    }
    const test::CliResult r = run("render " + scene + " -q " + args + " -o " + path("o.png") + " --report " + path("r.json"));
    ASSERT_EQ(r.code, 0) << args << ": " << r.err;
    const auto report = nlohmann::json::parse(std::ifstream(path("r.json")));
    EXPECT_GT(report["polygon_fragments"]["in_slabs"].get<uint64_t>(), 0u) << args;
    const std::string h = report["baseplane_hash_fnv1a64"].get<std::string>();
    if (hash.empty()) hash = h;
    EXPECT_EQ(h, hash) << args << ": the base plane differs from --model fixed";
  }
  // Clocked, the stream waits for the slab images the default connection
  // (rle) brings, at each pass's first beat: the waits the loosely timed
  // frame counts, and the same base plane.
  // The compositing ring at RTL draws them too, with its polygon hardware
  // (p = 4), the same image.
  if (!sysc::rtl_persp_pipes().empty()) {
    ASSERT_EQ(run("render " + scene + " -q --model fixed -o " + path("f.png")).code, 0);
    const std::vector<float> fixed_image = cube4::tb::read_image(path("f.png")).rgba;
    uint64_t tlm_waits = 0;
    for (const std::string model : {"tlm", "mixed:interp --check", "mixed:composite --check", "rtl --check"}) {
      const test::CliResult r = run("render " + scene + " -q --pipes 4 --model " + model + " -o " + path("c.png") +
                                    " --report " + path("rc.json"));
      ASSERT_EQ(r.code, 0) << model << ": " << r.err;
      const auto report = nlohmann::json::parse(std::ifstream(path("rc.json")));
      EXPECT_EQ(report["baseplane_hash_fnv1a64"].get<std::string>(), hash) << model;
      EXPECT_TRUE(cube4::tb::read_image(path("c.png")).rgba == fixed_image) << model;
      EXPECT_EQ(report["system"]["polygon_connection"], "rle") << model;
      const uint64_t waits = report["system"]["polygon_wait_cycles"].get<uint64_t>();
      if (model == "tlm") tlm_waits = waits;
      EXPECT_GT(waits, 0u) << model;
      EXPECT_EQ(waits, tlm_waits) << model;
    }
    // A p without the ring's polygon variant is refused by name, no image.
    const test::CliResult r = run("render " + scene + " -q --pipes 8 --model rtl -o " + path("no8.png"));
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("CUBE4_SYSTEM_POLYGON_PIPES"), std::string::npos) << r.err;
    EXPECT_FALSE(test::fs::exists(path("no8.png")));
  }
  const std::string plain = write("b.json", sphere(R"({"rotate": [10, 20, 0], "projection": "perspective", "fov": 40})",
                                                   R"(, "output": {"width": 64, "height": 64})", "[24,24,24]"));
  // Blocks at every level: each machine's units at RTL too (every ring of
  // each block's frame), the same base plane and image.
  std::string blocks_hash;
  std::vector<float> blocks_image;
  std::vector<std::string> block_models{"fixed", "tlm --check"};
  if (!sysc::rtl_persp_pipes().empty()) block_models.insert(block_models.end(), {"mixed:interp --check", "rtl --check"});
  for (const std::string& model : block_models) {
    const test::CliResult r = run("render " + plain + " -q --blocks 2x2x2 --model " + model + " -o " + path("b.png") +
                                  " --report " + path("rb.json"));
    ASSERT_EQ(r.code, 0) << model << ": " << r.err;
    const auto report = nlohmann::json::parse(std::ifstream(path("rb.json")));
    EXPECT_EQ(report["blocks"]["machines"].get<int>(), 8) << model;
    const std::string h = report["baseplane_hash_fnv1a64"].get<std::string>();
    if (blocks_hash.empty()) blocks_hash = h;
    EXPECT_EQ(h, blocks_hash) << model;
    const std::vector<float> image = cube4::tb::read_image(path("b.png")).rgba;
    if (blocks_image.empty()) blocks_image = image;
    EXPECT_TRUE(image == blocks_image) << model;
  }
}

TEST(PerspectiveCamera, AWindowShowsThatPartOfTheViewInBothProjections) {
  // The upper right quadrant as a 32 x 24 image is the upper right quarter
  // of the whole view at 64 x 48: the same base plane sampled at the same
  // points (up to the rounding of two formulas).
  for (const std::string projection : {R"("parallel")", R"("perspective", "fov": 40)"}) {
    const std::string view = R"({"rotate": [10, 20, 0], "projection": )" + projection;
    const auto whole = test::setup(sphere(view + "}", R"(, "output": {"width": 64, "height": 48})"));
    const auto part = test::setup(sphere(view + R"(, "window": [0, 0, 1, 1]})", R"(, "output": {"width": 32, "height": 24})"));
    const golden::ImageF a = test::final_fixed(whole), b = test::final_fixed(part);
    double worst = 0, sum = 0;
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 32; ++x)
        for (int c = 0; c < 4; ++c) {
          worst = std::max(worst, static_cast<double>(std::fabs(a.pixel(32 + x, y)[c] - b.pixel(x, y)[c])));
          sum += b.pixel(x, y)[c];
        }
    EXPECT_GT(sum, 1.0) << projection << ": the quadrant shows something";
    EXPECT_LT(worst, 1e-4) << projection;
  }
  auto message = [](const std::string& json) { return error_of([&] { test::setup(json); }); };
  EXPECT_NE(message(sphere(R"({"window": [0.5, 0, 0.5, 1]})")).find("\"view.window[2]\" = 0.5 is not right of x0"),
            std::string::npos);
  EXPECT_NE(message(sphere(R"({"window": [0, 0, 1, 2]})")).find("\"view.window[3]\" = 2 is out of range"),
            std::string::npos);
}

TEST(PerspectiveRender, CroppingAndCutPlaneAgreeWithFloat) {
  // The parallel projection's test (test_renderers) in perspective: the
  // crop and the cut plane see each sample at its ray's position.
  const std::string view = R"({"rotate": [20, 30, 10], "projection": "perspective", "fov": 50})";
  for (const std::string& extra :
       {std::string(R"(, "cropping": {"x": [0, 11], "combine": "intersection"})"),
        std::string(R"(, "cropping": {"x": [6, 17], "y": [6, 17], "z": [6, 17], "combine": "cross", "invert": true})"),
        std::string(R"(, "cut_plane": {"normal": [1, 1, 0], "dmin": 14, "dmax": 20, "falloff": 2})"),
        std::string(R"(, "cut_plane": {"normal": [0, 0, 1], "dmin": 8, "dmax": 14, "keep": "outside"})")}) {
    const auto s = test::setup(sphere(view, extra));
    const auto e = test::compare(test::final_fixed(s), test::final_float(s));
    EXPECT_GT(e.psnr, 35.0) << extra << " max error " << e.max_error;
    const auto plain = test::setup(sphere(view));
    EXPECT_LT(test::compare(test::final_fixed(s), test::final_fixed(plain)).psnr, 30.0) << extra;
  }
}

namespace {
struct SeeEverySample : golden::SampleProbe {
  void sample(int, int, const golden::SliceControl&, uint32_t, const golden::Gradient&) override {}
};
}  // namespace

// Threads take rows of rays; a ray's work is its own, so any number of them
// gives the same base plane, accumulators and sample count: with stopping,
// tags, supersampling and MIP.
TEST(PerspectiveRender, ThreadsGiveTheSameFrame) {
  const std::string tags = R"(, "precision": {"tag_bits": 1}, "tags": {"label": [{"tag": 1, "box": {"min": [0, 0, 0],
      "max": [14, 25, 21]}}], "classes": [{"tag": 1, "color": [[0, 1, 0, 0], [1, 1, 0, 0]]}]})";
  for (const std::string& extra : {std::string(), std::string(R"(, "supersampling": 2)"), std::string(R"(, "blend": "mip")"),
                                   tags}) {
    const auto s = test::setup(sphere(R"({"rotate": [20, 30, 0], "projection": "perspective", "fov": 45})",
                                      R"(, "output": {"width": 64, "height": 64})" + extra, "[30, 26, 22]"));
    golden::RenderStats one_stats;
    golden::FixedOptions one;
    one.accumulators = true;
    one.stats = &one_stats;
    const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, one);
    EXPECT_GT(alpha_sum(want), 0) << extra;
    for (int threads : {2, 3, 7}) {
      golden::RenderStats stats;
      golden::FixedOptions o = one;
      o.threads = threads;
      o.stats = &stats;
      int progress_calls = 0;
      double last = 0;
      const std::thread::id caller = std::this_thread::get_id();
      o.progress = [&](double f) {
        ++progress_calls;
        last = f;
        EXPECT_EQ(std::this_thread::get_id(), caller) << "progress from the calling thread";
      };
      const golden::BasePlane got = golden::render_fixed(s.volume, s.host.regs, o);
      EXPECT_EQ(got.rgba, want.rgba) << extra << ", " << threads << " threads";
      EXPECT_EQ(got.acc, want.acc) << extra << ", " << threads << " threads";
      EXPECT_EQ(stats.samples, one_stats.samples);
      EXPECT_EQ(progress_calls, s.host.regs.sample_slices());
      EXPECT_EQ(last, 1.0);
    }
  }
}

// A progress callback that throws (a caller giving up) ends the frame on
// every thread: the exception reaches the caller, nothing hangs.
TEST(PerspectiveRender, AThrowingProgressEndsTheFrameOnEveryThread) {
  const auto s = test::setup(sphere(R"({"rotate": [20, 30, 0], "projection": "perspective", "fov": 45})",
                                    R"(, "output": {"width": 64, "height": 64})", "[30, 26, 22]"));
  for (int threads : {1, 2, 3}) {
    golden::FixedOptions o;
    o.threads = threads;
    int calls = 0;
    o.progress = [&](double) {
      if (++calls == 3) throw std::runtime_error("cancelled");
    };
    EXPECT_THROW(golden::render_fixed(s.volume, s.host.regs, o), std::runtime_error) << threads << " threads";
    EXPECT_EQ(calls, 3) << threads << " threads: the frame went on after the callback threw";
  }
}

TEST(PerspectiveRender, StoppingRaysIsExact) {
  // A probe makes the renderer shade every sample of every ray; without one
  // it stops rays at a settled pixel, or at full α when it is asked for the
  // accumulators (RayStop, as in the parallel renderer).
  for (const char* view : {R"({"rotate": [20, 60, 180], "projection": "perspective", "distance": 200})",
                           R"({"rotate": [-35, 10, 75], "projection": "perspective", "distance": 150, "fov": 50})"}) {
    const auto s = test::setup(R"({"volume": {"file": ")" + golden::default_brainsmall_path() +
                               R"("}, "output": {"width": 128, "height": 128}, "view": )" + view + R"(,
        "transfer": {"opacity": [[0, 0], [0.05, 0], [0.1, 0.2], [0.3, 0.6], [1, 0.7]]}})");
    SeeEverySample all;
    golden::FixedOptions every;
    every.probe = &all;
    every.accumulators = true;
    const golden::BasePlane reference = golden::render_fixed(s.volume, s.host.regs, every);
    golden::FixedOptions o;
    o.accumulators = true;
    const golden::BasePlane with_acc = golden::render_fixed(s.volume, s.host.regs, o);
    EXPECT_EQ(with_acc.acc, reference.acc) << view;
    o.accumulators = false;
    EXPECT_EQ(golden::render_fixed(s.volume, s.host.regs, o).rgba, reference.rgba) << view;
    int64_t alpha = 0;
    for (size_t i = 3; i < reference.rgba.size(); i += 4) alpha += reference.rgba[i];
    EXPECT_GT(alpha, 0) << view;
  }
}
