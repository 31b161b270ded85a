// bela's projection (render_splat, golden/splat_footprint.hpp): the
// footprint tables, where a voxel lands, what a slice covers, occlusion,
// elliptical footprints for unequal spacing, symmetry, and the sphere against
// the reference ray caster within a bound derived from the geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "golden/errors.hpp"
#include "golden/shading_model.hpp"
#include "golden/splat_footprint.hpp"
#include "tb/tests/test_support.hpp"

using namespace cube4;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A scene (its volume key is ignored) with a volume made by a function of
// the voxel, and the view factorised for that volume.
struct Made {
  golden::Scene scene;
  golden::Volume volume;
  golden::ViewFactorisation view;
};

using VoxelValue = std::function<double(int, int, int)>;

Made make(const std::string& json, std::array<int, 3> dim, const VoxelValue& value,
          std::array<double, 3> spacing = {1, 1, 1}) {
  Made m;
  m.scene = golden::parse_scene(json, "test.json");
  m.volume.dim = dim;
  m.volume.spacing = spacing;
  m.volume.data.resize(m.volume.size());
  for (int z = 0; z < dim[2]; ++z)
    for (int y = 0; y < dim[1]; ++y)
      for (int x = 0; x < dim[0]; ++x)
        m.volume.data[m.volume.index(x, y, z)] =
            static_cast<uint16_t>(std::lround(value(x, y, z) * m.volume.max_value()));
  m.view = golden::factorise_view(m.scene, m.volume);
  return m;
}

// The same volume's principal (slice) axis for a view: the factorisation
// does not depend on the voxels.
int principal_axis(const std::string& json, std::array<int, 3> dim, std::array<double, 3> spacing = {1, 1, 1}) {
  return make(json, dim, [](int, int, int) { return 0.0; }, spacing).view.perm[2];
}

golden::ImageF splat(const Made& m) { return golden::render_splat(m.volume, m.scene, m.view); }

double alpha(const golden::ImageF& img, int x, int y) { return img.pixel(x, y)[3]; }

// An unshaded scene: value 0 transparent, values from 0.5 up of opacity
// `a`; colour (1, 1, 1) up to 0.6, `far` (0 .. 1) from 0.7, so that two
// materials can be told apart.
std::string scene_json(const std::string& view, int image, double a = 1, const std::string& far = "1, 1, 1") {
  return R"({"volume": {"synthetic": "constant"}, "view": )" + view + R"(, "shading": false,
             "output": {"width": )" + std::to_string(image) + R"(, "height": )" + std::to_string(image) + R"(},
             "transfer": {"color": [[0, 1, 1, 1], [0.6, 1, 1, 1], [0.7, )" + far + "], [1, " + far + R"(]],
                          "opacity": [[0, 0], [0.49, 0], [0.5, )" + std::to_string(a) + "], [1, " +
         std::to_string(a) + "]]}}";
}

std::string rotated(const std::string& rotate, double zoom) {
  return R"({"rotate": )" + rotate + R"(, "zoom": )" + std::to_string(zoom) + "}";
}

const std::string kAlongZ = R"({"direction": [0, 0, 1], "zoom": 0.5})";

// The volume 24×24×12 has a diagonal of exactly 36 voxel spacings: on a
// 72-pixel image at zoom 0.5 a voxel spacing is exactly one pixel, bela's
// magnification 1 (§IV).
constexpr std::array<int, 3> kUnitDim{24, 24, 12};
constexpr int kUnitImage = 72;

// Permuted slice coordinates (x, y) of the image point (X, Y) on slice z:
// the inverse of the splat renderer's projection, for choosing pixels well
// inside a slice.
std::array<double, 2> on_slice(const golden::ViewFactorisation& f, double X, double Y, double z) {
  auto at = [&](const golden::Vec3& p) { return f.image_of(f.to_object(p)); };
  const auto o = at({0, 0, z}), px = at({1, 0, z}), py = at({0, 1, z});
  const double a = px[0] - o[0], b = py[0] - o[0], c = px[1] - o[1], d = py[1] - o[1];
  const double det = a * d - b * c, u = X - o[0], v = Y - o[1];
  return {(d * u - b * v) / det, (a * v - c * u) / det};
}

// The lattice-sum ripple of the kernel itself: the largest relative
// departure from one of Σ g(u - p) over the unit lattice of centres p,
// g the truncated Gaussian normalised to unit integral, over a grid of u.
double kernel_ripple(const golden::SplatKernel& k) {
  const double s2 = k.sigma * k.sigma, r2 = k.width * k.width;
  const double integral = 2 * kPi * s2 * (1 - std::exp(-r2 / (2 * s2)));
  const int reach = static_cast<int>(std::ceil(k.width)) + 1, n = 64;
  double worst = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      double sum = 0;
      for (int i = -reach; i <= reach; ++i)
        for (int j = -reach; j <= reach; ++j) {
          const double dx = static_cast<double>(a) / n - i, dy = static_cast<double>(b) / n - j;
          const double d2 = dx * dx + dy * dy;
          if (d2 <= r2) sum += std::exp(-d2 / (2 * s2));
        }
      worst = std::max(worst, std::fabs(sum / integral - 1));
    }
  return worst;
}

// How far a slice of equal voxels may depart from covering a pixel once
// (relative): the kernel's own ripple, plus what quantising every centre of
// projection to a sub-pixel centre (at most √2/4 pixel away) can change.
// Moving one footprint by e changes it by at most |e|·|∇g| pointwise, and
// the footprints of a slice sum |∇g| to about ∫|∇g| = √(π/2)/σ per unit
// energy (σ the footprint's smallest standard deviation in pixels), times
// the ripple again for the lattice.
double coverage_tolerance(const golden::FootprintTables& t, const golden::SplatKernel& k) {
  const double mean = (t.covariance[0] + t.covariance[2]) / 2;
  const double dev =
      std::sqrt(std::max(0.0, mean * mean - t.covariance[0] * t.covariance[2] + t.covariance[1] * t.covariance[1]));
  const double sigma_px = std::sqrt(mean - dev);
  const double ripple = kernel_ripple(k);
  return ripple + std::sqrt(2.0) / 4 * std::sqrt(kPi / 2) / sigma_px * (1 + ripple);
}

}  // namespace

TEST(SplatFootprint, EveryTableSumsToOneAndMirrorsItsOpposite) {
  // Energy conservation is the tables' contract: whatever the view, the
  // spacing or the magnification, each sub-pixel's footprint sums to one.
  // The kernel is symmetric about its centre, so the opposite sub-pixel's
  // table is the same table turned by 180°.
  for (const auto& spacing : {std::array<double, 3>{1, 1, 1}, {1, 1, 3}, {0.5, 2, 1}})
    for (const char* rotate : {"[0, 0, 0]", "[20, 30, 0]", "[20, 60, 180]", "[45, 45, 10]"})
      for (double zoom : {0.3, 1.0, 2.5}) {
        const Made m = make(scene_json(rotated(rotate, zoom), 64), {20, 24, 16}, [](int, int, int) { return 0.0; },
                            spacing);
        const golden::FootprintTables t = golden::footprint_tables(m.view, {});
        const int w = t.extent, h = w / 2;
        ASSERT_EQ(w % 2, 1);
        for (int q = 0; q < 4; ++q) {
          double sum = 0;
          for (double x : t.weight[q]) {
            EXPECT_GE(x, 0);
            sum += x;
          }
          EXPECT_NEAR(sum, 1.0, 1e-12) << rotate << " zoom " << zoom << " sub-pixel " << q;
          for (int j = -h; j <= h; ++j)
            for (int i = -h; i <= h; ++i)
              ASSERT_NEAR(t.weight[q][(j + h) * w + (i + h)], t.weight[3 - q][(h - j) * w + (h - i)], 1e-12);
        }
      }
}

TEST(SplatFootprint, BelasThreeByThreeTablesWithSixValuesAtMagnificationOne) {
  // bela §III.B: at one voxel spacing per pixel a 3×3 extent covers the
  // kernel from all four sub-pixel centres, and by symmetry the four tables
  // of nine entries hold six different values.
  for (const std::string& view : {std::string(kAlongZ), rotated("[20, 30, 0]", 0.5), rotated("[35, -70, 15]", 0.5)}) {
    const Made m = make(scene_json(view, kUnitImage), kUnitDim, [](int, int, int) { return 0.0; });
    const golden::FootprintTables t = golden::footprint_tables(m.view, {});
    EXPECT_EQ(t.extent, 3) << view;
    std::vector<double> values;
    for (const auto& table : t.weight) values.insert(values.end(), table.begin(), table.end());
    std::sort(values.begin(), values.end());
    int distinct = 1;
    for (size_t i = 1; i < values.size(); ++i) distinct += values[i] - values[i - 1] > 1e-9;
    EXPECT_EQ(distinct, 6) << view;
  }
}

TEST(Splat, ASingleVoxelLandsAtItsProjection) {
  // Its energy (α times the area a voxel of the slice stands for) is spread
  // around the pixel its centre of projection falls in; the centroid lies
  // between that pixel's centre and the chosen sub-pixel centre, so within
  // half a pixel of the exact projection on each axis.
  for (const char* rotate : {"[20, 30, 0]", "[20, 60, 180]", "[-40, 10, 75]"})
    for (const std::array<int, 3> at : {std::array<int, 3>{5, 9, 14}, {13, 2, 7}}) {
      const Made m = make(scene_json(rotated(rotate, 1.7), 96, 0.5), {20, 24, 16},
                          [&](int x, int y, int z) { return x == at[0] && y == at[1] && z == at[2] ? 1.0 : 0.0; });
      const golden::ImageF img = splat(m);
      const auto p = m.view.image_of({double(at[0]), double(at[1]), double(at[2])});
      double sum = 0, cx = 0, cy = 0, peak = 0;
      int px = -1, py = -1;
      for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
          const double a = alpha(img, x, y);
          sum += a;
          cx += a * x;
          cy += a * y;
          if (a > peak) { peak = a; px = x; py = y; }
        }
      ASSERT_LT(peak, 1) << "no pixel clamped, so the energy is all there";
      const golden::FootprintTables t = golden::footprint_tables(m.view, {});
      const double energy = golden::correct_alpha(0.5, golden::sample_step_ratio(m.view, 1)) * t.cell_area;
      EXPECT_NEAR(sum, energy, 1e-6 * energy) << rotate << " (a single-precision image)";
      EXPECT_EQ(px, static_cast<int>(std::lround(p[0]))) << rotate;
      EXPECT_EQ(py, static_cast<int>(std::lround(p[1]))) << rotate;
      EXPECT_LE(std::fabs(cx / sum - p[0]), 0.5) << rotate;
      EXPECT_LE(std::fabs(cy / sum - p[1]), 0.5) << rotate;
    }
}

TEST(Splat, ASliceOfEqualVoxelsCoversEveryPixelOnceOnAverage) {
  // One slice of translucent voxels (α 0.2: no pixel can reach one). Its
  // energy is exactly the voxels' α times their projected area; away from
  // its edges it covers each pixel by α times the footprints' sum there.
  // At magnification 1 seen along the slice normal every pixel gets one
  // whole table: exactly α.
  {
    const Made m = make(scene_json(kAlongZ, kUnitImage, 0.2), kUnitDim,
                        [](int, int, int z) { return z == 6 ? 1.0 : 0.0; });
    const golden::ImageF img = splat(m);
    for (int y = 0; y < kUnitImage; ++y)
      for (int x = 0; x < kUnitImage; ++x) {
        const auto s = on_slice(m.view, x, y, 6);
        if (s[0] >= 2 && s[0] <= 21 && s[1] >= 2 && s[1] <= 21) {
          ASSERT_NEAR(alpha(img, x, y), 0.2, 1e-7);  // 0.2 in single precision
        }
      }
  }
  for (const char* rotate : {"[20, 30, 0]", "[20, 60, 180]", "[0, 0, 0]"})
    for (int image : {64, 128, 256}) {  // 1.2, 2.3 and 4.6 pixels per voxel spacing
      const std::string json = scene_json(rotated(rotate, 1), image, 0.2);
      const std::array<int, 3> dim{32, 32, 32};
      const int axis = principal_axis(json, dim);
      const Made m = make(json, dim, [&](int x, int y, int z) { return std::array<int, 3>{x, y, z}[axis] == 16; });
      const golden::ImageF img = splat(m);
      const golden::FootprintTables t = golden::footprint_tables(m.view, {});
      const double a = golden::correct_alpha(0.2, golden::sample_step_ratio(m.view, 1));
      const double slice_z = m.view.flip[2] ? 15 : 16;
      double sum = 0, lo = 1e9, hi = 0;
      for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
          sum += alpha(img, x, y);
          const auto s = on_slice(m.view, x, y, slice_z);
          if (s[0] < 4 || s[0] > 27 || s[1] < 4 || s[1] > 27) continue;
          lo = std::min(lo, alpha(img, x, y) / a);
          hi = std::max(hi, alpha(img, x, y) / a);
        }
      EXPECT_NEAR(sum, 32 * 32 * a * t.cell_area, 1e-6 * sum) << rotate << " image " << image;
      const double tol = coverage_tolerance(t, {});
      std::printf("slice coverage %s, %d² image: %.4f .. %.4f (tolerance ±%.3f, kernel ripple %.4f)\n", rotate,
                  image, lo, hi, tol, kernel_ripple({}));
      EXPECT_GE(lo, 1 - tol) << rotate << " image " << image;
      EXPECT_LE(hi, 1 + tol) << rotate << " image " << image;
    }
}

TEST(Splat, AnOpaqueSlabHidesWhatIsBehindIt) {
  // Front to back, a pixel's colour is the slab's plus (1 - the slab's α)
  // times what lies behind; the slab's α is 1 - Π(1 - sₖ) over its slices'
  // coverages sₖ (slice images composited, not voxels). White material
  // (0.5) lies behind a green slab (1.0).
  auto compare = [](const std::string& json, std::array<int, 3> dim, std::vector<int> slab, double margin) -> double {
    const Made probe = make(json, dim, [](int, int, int) { return 0.0; });
    const int axis = probe.view.perm[2], n = dim[axis];
    // Depth in permuted z: slices are taken front to back in it.
    auto depth = [&](int x, int y, int z) {
      const int d = std::array<int, 3>{x, y, z}[axis];
      return probe.view.flip[2] ? n - 1 - d : d;
    };
    auto in_slab = [&](int d) { return std::find(slab.begin(), slab.end(), d) != slab.end(); };
    const Made front = make(json, dim, [&](int x, int y, int z) { return in_slab(depth(x, y, z)) ? 1.0 : 0.0; });
    const Made both = make(json, dim, [&](int x, int y, int z) {
      const int d = depth(x, y, z);
      return in_slab(d) ? 1.0 : d > n / 2 ? 0.5 : 0.0;
    });
    std::vector<golden::ImageF> slices;
    for (int d : slab)
      slices.push_back(splat(make(json, dim, [&](int x, int y, int z) { return depth(x, y, z) == d ? 1.0 : 0.0; })));
    const golden::ImageF a = splat(front), b = splat(both);
    double worst_leak = 0, alpha_error = 0, excess = 0;
    int interior = 0;
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) {
        double through = 1;
        for (const golden::ImageF& s : slices) through *= 1 - std::min(1.0, alpha(s, x, y));
        alpha_error = std::max(alpha_error, std::fabs(alpha(a, x, y) - (1 - through)));
        for (int c = 0; c < 4; ++c) excess = std::max(excess, std::fabs(b.pixel(x, y)[c] - a.pixel(x, y)[c]) - through);
        bool inside = true;
        for (int d : slab) {
          const auto s = on_slice(front.view, x, y, d);
          inside = inside && s[0] >= margin && s[0] <= front.view.pdim[0] - 1 - margin && s[1] >= margin &&
                   s[1] <= front.view.pdim[1] - 1 - margin;
        }
        if (!inside) continue;
        ++interior;
        worst_leak = std::max(worst_leak, through);
      }
    EXPECT_LT(alpha_error, 1e-6) << "the slab's α is not its slices' composited";
    EXPECT_LT(excess, 1e-6) << "more shows through the slab than its slices let through";
    EXPECT_GT(interior, 100);
    return worst_leak;
  };
  // Magnification 1 along the slab's normal: one slice covers every pixel
  // exactly once, so a single opaque slice hides everything.
  EXPECT_LT(compare(scene_json(kAlongZ, kUnitImage, 1, "0, 1, 0"), kUnitDim, {2}, 2), 1e-12);
  // Oblique: four slices, each covering at least 1 - tolerance (the
  // previous test): at most tolerance⁴ gets through.
  const std::string json = scene_json(rotated("[20, 30, 0]", 1), 128, 1, "0, 1, 0");
  const Made probe = make(json, {32, 32, 32}, [](int, int, int) { return 0.0; });
  const double tol = coverage_tolerance(golden::footprint_tables(probe.view, {}), {});
  const double leak = compare(json, {32, 32, 32}, {3, 4, 5, 6}, 4);
  std::printf("oblique slab of four slices: at most %.2e of what is behind shows (bound %.2e)\n", leak,
              std::pow(tol, 4));
  EXPECT_LE(leak, std::pow(tol, 4));
}

TEST(Splat, UnequalSpacingGivesAnEllipseAlongTheProjectedLongAxis) {
  // A voxel three times longer in z: its kernel is a sphere in index space,
  // an ellipsoid with semi-axes σ, σ, 3σ in object space. Seen in a view its
  // footprint is σ²r²(I + 8ppᵀ), p the projection of the unit z direction
  // (|p| = sin of its angle to the view), r pixels per unit length: major
  // axis along p, variances in the ratio 1 + 8|p|². Truncation at a
  // Mahalanobis radius scales both variances alike; integrating over pixels
  // adds 1/12 to both.
  for (const char* rotate : {"[30, 40, 0]", "[60, 10, 20]", "[10, 75, 0]"}) {
    const Made m = make(scene_json(rotated(rotate, 1), 160, 0.5), {9, 9, 9},
                        [](int x, int y, int z) { return x == 4 && y == 4 && z == 4 ? 1.0 : 0.0; }, {1, 1, 3});
    const golden::ImageF img = splat(m);
    double sum = 0, mx = 0, my = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        sum += alpha(img, x, y);
        mx += alpha(img, x, y) * x;
        my += alpha(img, x, y) * y;
      }
    mx /= sum;
    my /= sum;
    double cxx = 0, cxy = 0, cyy = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const double a = alpha(img, x, y) / sum;
        cxx += a * (x - mx) * (x - mx);
        cxy += a * (x - mx) * (y - my);
        cyy += a * (y - my) * (y - my);
      }
    const double mean = (cxx + cyy) / 2, dev = std::sqrt(std::max(0.0, mean * mean - cxx * cyy + cxy * cxy));
    const double major = mean + dev, minor = mean - dev;
    const double angle = 0.5 * std::atan2(2 * cxy, cxx - cyy);
    // Expected, from the view alone.
    const auto o = m.view.image_of({4, 4, 4}), e = m.view.image_of({4, 4, 5});
    const double r = 1 / m.view.pixel_size;  // pixels per unit length; a z step is 3 of them
    const double px = (e[0] - o[0]) / (3 * r), py = (e[1] - o[1]) / (3 * r);
    const golden::SplatKernel k;
    const double R2 = (k.width / k.sigma) * (k.width / k.sigma);
    const double truncation = 1 - (R2 / 2) * std::exp(-R2 / 2) / (1 - std::exp(-R2 / 2));
    const double s2 = truncation * k.sigma * k.sigma * r * r;
    const double ratio = (s2 * (1 + 8 * (px * px + py * py)) + 1.0 / 12) / (s2 + 1.0 / 12);
    double off = std::fabs(angle - std::atan2(py, px)) * 180 / kPi;
    off = std::min(std::fmod(off, 180.0), 180 - std::fmod(off, 180.0));
    std::printf("%s: major axis %.3f° off the projected z axis; variance ratio %.4f, expected %.4f\n",
                rotate, off, major / minor, ratio);
    EXPECT_LT(off, 0.5) << rotate;
    EXPECT_NEAR(major / minor, ratio, 0.02 * ratio) << rotate;
  }
}

TEST(Splat, SixAxisViewsOfASymmetricSphereGiveTheSameImage) {
  // The sphere is symmetric under every flip and axis permutation, and each
  // view's image axes are volume axes: all six base planes must give one
  // image. Unshaded, so the lights (fixed in world space) cannot break the
  // symmetry. Slices are summed in different orders: single-precision rounding.
  auto image = [](const std::string& direction, const std::string& up) {
    const test::Setup s = test::setup(R"({"volume": {"synthetic": "sphere", "size": [24, 24, 24]},
        "view": {"direction": )" + direction + R"(, "up": )" + up + R"(}, "shading": false,
        "output": {"width": 64, "height": 64}})");
    return golden::render_splat(s.volume, s.scene, s.host.view);
  };
  const golden::ImageF ref = image("[0, 0, 1]", "[0, 1, 0]");
  double coverage = 0;
  for (size_t i = 3; i < ref.rgba.size(); i += 4) coverage += ref.rgba[i];
  EXPECT_GT(coverage, 100);
  for (const auto& [direction, up] : std::vector<std::pair<std::string, std::string>>{{"[1, 0, 0]", "[0, 1, 0]"},
                                                                                    {"[-1, 0, 0]", "[0, 1, 0]"},
                                                                                    {"[0, 1, 0]", "[0, 0, 1]"},
                                                                                    {"[0, -1, 0]", "[0, 0, 1]"},
                                                                                    {"[0, 0, -1]", "[0, 1, 0]"}}) {
    const golden::ImageF img = image(direction, up);
    double worst = 0;
    for (size_t i = 0; i < img.rgba.size(); ++i) worst = std::max(worst, std::fabs(double(img.rgba[i]) - ref.rgba[i]));
    EXPECT_LT(worst, 1e-6) << direction;
  }
}

TEST(Splat, TheSphereDiffersFromTheReferenceOnlyAlongItsSilhouette) {
  // scenes/sphere.json's sphere (64³, radius R = 24, value 1/2 + (R - d)/2
  // between d = R ± 1) and view, unshaded, so that both images are the
  // colour times their coverage and every difference is one of coverage.
  // With ρ a pixel's distance from the sphere's projected centre, in voxel
  // spacings (r pixels each):
  //  - beyond ρ_out = R + 0.2 + width + (√2/4 + √2/2)/r no voxel reaches the
  //    pixel (voxels are transparent beyond d = R + 0.2, where the value
  //    falls below 0.4; a footprint reaches `width` from its centre, which
  //    the sub-pixel moves by up to √2/4 pixel, onto pixels whose centre is
  //    up to √2/2 pixel further), and the reference's rays meet no value
  //    above 0.4 there: both images are exactly empty;
  //  - within ρ_in the reference is opaque, and the splat image is at least
  //    1 - tol³: the ray's 6 voxel spacings around its closest approach to
  //    the centre cross at least three slices (√3 apart at most), and the
  //    voxels of those slices that reach the pixel (within `reach` on the
  //    image, √3·reach in the slice) lie within sqrt(ρ² + 3²) + √3·reach of
  //    the centre, so all inside the opaque core d <= R - 0.2 when ρ < ρ_in;
  //    each of the three covers the pixel by at least 1 - tol;
  //  - in the band between, any difference up to 1.
  // So the mean error is at most mean(colour)·(band + interior·tol³) / pixels.
  const test::Setup s = test::setup(R"({"volume": {"synthetic": "sphere", "size": [64, 64, 64]},
      "view": {"rotate": [20, 30, 0]}, "shading": false,
      "transfer": {"color": [[0, 1, 0.6, 0.3], [1, 1, 0.6, 0.3]], "opacity": [[0, 0], [0.4, 0], [0.6, 1], [1, 1]]}})");
  const golden::ImageF sp = golden::render_splat(s.volume, s.scene, s.host.view);
  const golden::ImageF ref = golden::render_reference(s.volume, s.scene, s.host.view);
  const golden::SplatKernel k;
  const golden::FootprintTables t = golden::footprint_tables(s.host.view, k);
  const double R = 24, r = 1 / s.host.view.pixel_size;
  const double reach = k.width + (std::sqrt(2.0) / 4 + std::sqrt(2.0) / 2) / r;
  const double rho_out = R + 0.2 + reach;
  const double core = R - 0.2 - 0.001 - std::sqrt(3.0) * reach;  // 0.001: 12-bit values
  const double rho_in = std::sqrt(core * core - 9);
  const double tol = coverage_tolerance(t, k);
  const auto c = s.host.view.image_of({31.5, 31.5, 31.5});
  int band = 0, interior = 0, outside_hits = 0;
  double interior_min = 1, sum_error = 0;
  for (int y = 0; y < sp.height; ++y)
    for (int x = 0; x < sp.width; ++x) {
      const double rho = std::hypot(x - c[0], y - c[1]) / r;
      const float* a = sp.pixel(x, y);
      const float* b = ref.pixel(x, y);
      for (int ch = 0; ch < 3; ++ch) sum_error += std::fabs(a[ch] - b[ch]);
      if (rho > rho_out) {
        outside_hits += a[3] != 0 || b[3] != 0;
      } else if (rho < rho_in) {
        ++interior;
        EXPECT_EQ(b[3], 1.0f) << x << "," << y;
        interior_min = std::min(interior_min, double(a[3]));
      } else {
        ++band;
      }
    }
  const double mean_colour = (1 + 0.6 + 0.3) / 3, pixels = double(sp.width) * sp.height;
  const double mean_error = sum_error / (3 * pixels);
  const double bound = mean_colour * (band + interior * std::pow(tol, 3)) / pixels;
  std::printf("sphere, unshaded: mean error %.5f (bound %.5f); interior α >= %.6f (bound %.4f); %d band pixels\n",
              mean_error, bound, interior_min, 1 - std::pow(tol, 3), band);
  EXPECT_EQ(outside_hits, 0);
  EXPECT_GT(interior, 1000);
  EXPECT_GE(interior_min, 1 - std::pow(tol, 3));
  EXPECT_LE(mean_error, bound);
}

TEST(Splat, RefusesWhatItCannotRender) {
  // Energy projection sums energy: no maximum or minimum intensity; and a
  // view that would spread a voxel over more than kMaxFootprintExtent
  // pixels a side is refused by name instead of running for minutes.
  const test::Setup mip = test::setup(R"({"volume": {"synthetic": "sphere", "size": [16, 16, 16]}, "blend": "mip"})");
  try {
    golden::render_splat(mip.volume, mip.scene, mip.host.view);
    ADD_FAILURE() << "a MIP scene was rendered";
  } catch (const golden::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("test.json: \"blend\" = \"mip\""), std::string::npos) << e.what();
  }
  const test::Setup zoomed =
      test::setup(R"({"volume": {"synthetic": "sphere", "size": [16, 16, 16]}, "view": {"zoom": 64}})");
  try {
    golden::render_splat(zoomed.volume, zoomed.scene, zoomed.host.view);
    ADD_FAILURE() << "a 64x zoom was rendered";
  } catch (const golden::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"view.zoom\" = 64"), std::string::npos) << e.what();
  }
}
