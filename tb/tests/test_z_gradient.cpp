// VolumePro's z gradient (interpolated voxel differences, golden/units/
// gradient.hpp): the renderer's slice-wide path against the per-sample unit
// functions, its agreement with the 12-neighbourhood where the two must
// agree and its difference where they must not, threads and skipping, and
// the scene key's errors.
#include <gtest/gtest.h>
#include <algorithm>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "golden/perspective.hpp"
#include "golden/permuted_volume.hpp"
#include "tb/tests/cli_support.hpp"
#include "tb/tests/test_support.hpp"
#include "systemc/rtl/rtl_factory.hpp"

using namespace cube4;

namespace {

std::string sphere(const std::string& rest) {
  return R"({"volume": {"synthetic": "sphere", "size": [24, 20, 28]}, )" + rest + "}";
}

std::string brainsmall(const std::string& rest) {
  return R"({"volume": {"file": ")" + golden::default_brainsmall_path() + R"("}, )" + rest + "}";
}

// Checks every sample's z component against interpolated_z_difference() of
// its own eight voxel differences, read straight from the volume.
struct ZDifferenceChecker : golden::SampleProbe {
  const golden::Registers& r;
  std::vector<uint32_t> permuted;  // the volume in permuted order, beam by beam
  int samples = 0, nonzero = 0, mismatches = 0;
  ZDifferenceChecker(const golden::Volume& v, const golden::Registers& regs)
      : r(regs), permuted(static_cast<size_t>(regs.dim[0]) * regs.dim[1] * regs.dim[2]) {
    const golden::PermutedVolume pv(v, regs.perm, regs.flip);
    for (int z = 0; z < r.dim[2]; ++z)
      for (int y = 0; y < r.dim[1]; ++y) pv.load_beam(y, z, &permuted[(static_cast<size_t>(z) * r.dim[1] + y) * r.dim[0]]);
  }
  uint32_t voxel(int x, int y, int z) const {
    if (x < 0 || y < 0 || z < 0 || x >= r.dim[0] || y >= r.dim[1] || z >= r.dim[2]) return 0;
    return permuted[(static_cast<size_t>(z) * r.dim[1] + y) * r.dim[0] + x];
  }
  void sample(int x, int y, const golden::SliceControl& c, uint32_t, const golden::Gradient& g) override {
    std::array<int32_t, 8> d{};
    for (int i = 0; i < 8; ++i) {
      const int vx = x + (i & 1), vy = y + (i >> 1 & 1), vz = c.z_voxel + (i >> 2);
      d[static_cast<size_t>(i)] = golden::voxel_z_difference(voxel(vx, vy, vz + 1), voxel(vx, vy, vz - 1));
    }
    const int32_t want = golden::gradient_component(
        golden::interpolated_z_difference(d, c.wx, c.wy, c.wz, r.p.weight_bits), r.p);
    ++samples;
    if (want != 0) ++nonzero;
    if (g.z != want && mismatches++ == 0)
      ADD_FAILURE() << "first mismatch: sample (" << x << ", " << y << ") of slice " << c.k << ": z component "
                    << g.z << ", its voxel differences give " << want;
  }
};

golden::BasePlane render(const test::Setup& s, int threads, bool skip) {
  golden::FixedOptions o;
  o.threads = threads;
  o.skip_empty = skip;
  return golden::render_fixed(s.volume, s.host.regs, o);
}

}  // namespace

TEST(ZGradient, EverySampleIsItsVoxelDifferencesInterpolated) {
  for (const std::string& json :
       {sphere(R"("z_gradient": "voxel_differences", "view": {"direction": [0.6, -0.5, 0.7]})"),
        sphere(R"("z_gradient": "voxel_differences", "supersampling": 3, "view": {"rotate": [30, 200, 10]})"),
        brainsmall(R"("z_gradient": "voxel_differences", "supersampling": 2, "view": {"rotate": [20, 60, 180]},
                      "precision": {"voxel_bits": 16, "weight_bits": 14})")}) {
    const test::Setup s = test::setup(json);
    ASSERT_EQ(s.host.regs.z_gradient, golden::ZGradient::VoxelDifferences);
    ZDifferenceChecker check(s.volume, s.host.regs);
    golden::Registers r = s.host.regs;
    r.gradient = true;
    golden::render_fixed(s.volume, r, nullptr, {}, &check);
    EXPECT_EQ(check.samples, r.dim[0] * r.dim[1] * r.sample_slices()) << json;
    EXPECT_GT(check.nonzero, check.samples / 100) << json << ": too few surfaces to test anything";
    EXPECT_EQ(check.mismatches, 0) << json;
  }
}

// Axis-aligned, one sample slice per voxel slice: every weight is zero, so
// the 12-neighbourhood's ahead and behind samples are the voxels above and
// below, and the two methods are one.
TEST(ZGradient, EqualsTheTwelveNeighbourhoodAxisAlignedAtOneSlicePerVoxel) {
  const test::Setup abc = test::setup(sphere(R"("view": {"rotate": [0, 0, 0]})"));
  const test::Setup vd = test::setup(sphere(R"("view": {"rotate": [0, 0, 0]}, "z_gradient": "voxel_differences")"));
  const golden::BasePlane a = render(abc, 1, true), b = render(vd, 1, true);
  EXPECT_EQ(a.rgba, b.rgba);
  // ... and differ once the rays are sheared.
  const test::Setup abc2 = test::setup(sphere(R"("view": {"rotate": [25, 35, 0]})"));
  const test::Setup vd2 = test::setup(sphere(R"("view": {"rotate": [25, 35, 0]}, "z_gradient": "voxel_differences")"));
  EXPECT_NE(render(abc2, 1, true).rgba, render(vd2, 1, true).rgba);
}

TEST(ZGradient, EveryThreadCountAndSkippingGiveTheSameImage) {
  for (const std::string& json :
       {brainsmall(R"("z_gradient": "voxel_differences", "view": {"rotate": [20, 60, 180]})"),
        brainsmall(R"("z_gradient": "voxel_differences", "supersampling": 3, "view": {"rotate": [45, 45, 45]})"),
        sphere(R"("z_gradient": "voxel_differences", "view": {"direction": [1, 0, 1], "up": [0, 1, 0]})")}) {
    const test::Setup s = test::setup(json);
    const golden::BasePlane one = render(s, 1, false);
    for (int threads : {1, 2, 3, 7})
      for (bool skip : {true, false})
        EXPECT_EQ(render(s, threads, skip).rgba, one.rgba) << json << ", " << threads << " threads, skip " << skip;
  }
}

// In perspective (docs/perspective.md): the voxel differences go through
// each ray's own box filters and z lerp. A probe sees each sample's gradient:
// its z is gradient_component() of perspective_z_difference() over the
// differences read straight from the volume; the float model agrees as it
// does with the 12-neighbourhood; and the two methods give other images.
TEST(ZGradient, PerspectiveFiltersTheVoxelDifferencesWithEachRaysBox) {
  for (const char* S : {"1", "3"}) {
    const std::string view = R"("view": {"rotate": [25, 35, 0], "projection": "perspective", "fov": 50},
        "output": {"width": 64, "height": 64}, "supersampling": )" + std::string(S);
    const test::Setup vd = test::setup(sphere(view + R"(, "z_gradient": "voxel_differences")"));
    const test::Setup abc = test::setup(sphere(view));
    ASSERT_TRUE(vd.host.regs.perspective);
    const golden::Registers& r = vd.host.regs;
    const golden::PermutedVolume pv(vd.volume, r.perm, r.flip);
    struct Checker : golden::SampleProbe {
      const golden::Registers& r;
      const golden::PermutedVolume& pv;
      int calls = 0, samples = 0, nonzero = 0, mismatches = 0;
      Checker(const golden::Registers& regs, const golden::PermutedVolume& v) : r(regs), pv(v) {}
      void sample(int x, int y, const golden::SliceControl& c, uint32_t, const golden::Gradient& g) override {
        ++calls;
        // The probe gives the sample's cell and weights; find its ray by position.
        const golden::PerspectiveSlice s = golden::perspective_slice(r, c.k);
        for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
          for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
            const golden::SamplePlace p = golden::sample_place(r, s, u, v);
            if (p.x != x || p.y != y || p.wx != c.wx || p.wy != c.wy) continue;
            const int32_t d = golden::perspective_z_difference(r, s, u, v, [&](int i, int j, int dz) {
              const int z = s.z_voxel + dz;
              return golden::voxel_z_difference(pv.at(i, j, z + 1), pv.at(i, j, z - 1));
            });
            ++samples;
            nonzero += d != 0;
            if (g.z != golden::gradient_component(d, r.p)) ++mismatches;
            return;
          }
      }
    } check(r, pv);
    golden::FixedOptions o;
    o.probe = &check;
    const golden::BasePlane with_probe = golden::render_fixed(vd.volume, r, o);
    EXPECT_EQ(check.samples, check.calls) << "S " << S << ": samples whose ray was not found";
    EXPECT_GT(check.samples, 5000) << "S " << S;
    EXPECT_GT(check.nonzero, 1000) << "S " << S;
    EXPECT_EQ(check.mismatches, 0) << "S " << S;
    EXPECT_NE(with_probe.rgba, golden::render_fixed(abc.volume, abc.host.regs).rgba) << "S " << S;
    const test::ImageError e = test::compare(test::final_fixed(vd), test::final_float(vd));
    EXPECT_GT(e.psnr, 35.0) << "S " << S << ", max " << e.max_error;
  }
}

TEST(ZGradient, SceneErrorsNameTheKey) {
  auto error_of = [](const std::string& json) {
    try {
      test::setup(json);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string bad = error_of(sphere(R"("z_gradient": "sobel")"));
  EXPECT_NE(bad.find("z_gradient"), std::string::npos) << bad;
  EXPECT_NE(bad.find("sobel"), std::string::npos) << bad;
}

// The wood-grain mechanism, on a field quadratic in z (V = c z²): its exact
// full z difference (twice the derivative, in per-voxel units) at depth z is
// 4cz. Voxel differences interpolate D(z) = V(z+1) - V(z-1) = 4cz, linear in
// z, so they are exact at every sample slice. The 12-neighbourhood at S = 4
// differences samples a quarter voxel either side; trilinear samples are
// linear within a voxel cell, so inside a cell it sees the cell's slope,
// 2c(2n+1) for the whole difference: exact on the voxel slices and half way
// between them, c off a quarter voxel from either. A ring per voxel slice.
TEST(ZGradient, VoxelDifferencesAreExactOnAQuadraticFieldWhereTheTwelveNeighbourhoodSteps) {
  constexpr int kC = 16, kNz = 16, kS = 4;
  for (const char* method : {"voxel_differences", "abc"}) {
    test::Setup s = test::setup(R"({"volume": {"synthetic": "constant", "size": [6, 6, 16], "value": 1},
        "view": {"direction": [0, 0, 1], "up": [0, 1, 0]}, "supersampling": 4, "z_gradient": ")" +
                                std::string(method) + R"(", "precision": {"gradient_shift": 0, "gradient_bits": 16}})");
    for (int z = 0; z < kNz; ++z)
      for (int i = 0; i < 36; ++i) s.volume.data[static_cast<size_t>(z * 36 + i)] = static_cast<uint16_t>(kC * z * z);
    s.host = golden::program_host(s.scene, s.volume, s.meshes);
    golden::Registers r = s.host.regs;
    ASSERT_EQ(r.perm, (std::array<int, 3>{0, 1, 2}));
    ASSERT_EQ(r.flip, (std::array<bool, 3>{false, false, false}));
    ASSERT_EQ(r.supersampling, kS);
    struct Column : golden::SampleProbe {
      int worst = 0, checked = 0;
      void sample(int x, int y, const golden::SliceControl& c, uint32_t, const golden::Gradient& g) override {
        // Inside the volume, away from its first and last voxel slices.
        if (x != 2 || y != 2 || c.z_voxel < 1 || c.z_voxel > kNz - 3) return;
        const int exact = 4 * kC * (4 * c.z_voxel + c.k % kS) / kS;  // 4c z, z = z_voxel + (k mod S)/S
        worst = std::max(worst, std::abs(g.z - exact));
        ++checked;
      }
    } column;
    golden::render_fixed(s.volume, r, nullptr, {}, &column);
    EXPECT_EQ(column.checked, (kNz - 3) * kS) << method;
    if (std::string(method) == "voxel_differences") {
      EXPECT_EQ(column.worst, 0) << method;
    } else {
      EXPECT_EQ(column.worst, kC) << method;
    }
  }
}

using ZGradientCli = test::Cli;

// The host's MODE register carries the choice to the system model: the
// loosely timed level renders the golden frame, and so do the RTL rings
// built with VolumePro's z gradient (--check on); a p without them, and
// voxel tags with the z gradient at RTL, are refused naming the limit.
TEST_F(ZGradientCli, EveryModelRendersTheFixedFrameAndMissingRtlIsRefusedSayingWhy) {
  const std::string scene = write("z.json", sphere(R"("z_gradient": "voxel_differences", "supersampling": 2,
      "view": {"rotate": [25, 35, 0]}, "output": {"width": 64, "height": 64})"));
  std::vector<std::string> models = {"fixed", "tlm"};
  const std::vector<int> built = sysc::rtl_zdiff_pipes();
  const bool p4 = std::find(built.begin(), built.end(), 4) != built.end();
  if (p4) models.insert(models.end(), {"rtl", "mixed:gradient"});
  for (const std::string& model : models) {
    const test::CliResult r = run("render " + scene + " -q --pipes 4 --model " + model + " --report " +
                                  path(model + ".json") + " -o " + path(model + ".png"));
    ASSERT_EQ(r.code, 0) << model << ": " << r.err;
  }
  auto hash = [&](const std::string& model) {
    nlohmann::json j;
    std::ifstream(path(model + ".json")) >> j;
    return j.value("baseplane_hash_fnv1a64", std::string());
  };
  EXPECT_EQ(hash("fixed").size(), 16u);
  for (const std::string& model : models) EXPECT_EQ(hash(model), hash("fixed")) << model;
  if (!sysc::rtl_available(5) || !p4) return;
  if (std::find(built.begin(), built.end(), 5) == built.end()) {
    const test::CliResult r = run("render " + scene + " -q --pipes 5 --model rtl -o " + path("no.png"));
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("pipelines: 5 has no RTL interpolation and gradient rings for z_gradient voxel_differences"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("CUBE4_SYSTEM_ZDIFF_PIPES"), std::string::npos) << r.err;
    EXPECT_FALSE(test::fs::exists(path("no.png")));
  }
}
