// Towards-scalable §3, Fig. 2: mean angular error of ABC gradient estimators
// of 6, 10, 12 and 26 samples and of zero-order central differences, at the
// first sample above half density on each ray of a volume-sampled sphere
// rotated 0°..90° about the vertical axis; fixed point and float. The
// estimators: golden/units/gradient_neighbourhoods.hpp; the table and plot:
// scripts/gradient_neighbourhoods.sh, docs/accuracy.md.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "golden/slice_steps.hpp"
#include "golden/units/gradient_neighbourhoods.hpp"
#include "tb/tests/sphere_normals.hpp"

using namespace cube4;
using golden::Vec3;

namespace {

// "26b": the 26-neighbourhood's Sobel block re-aligned bilinearly (40
// samples), to tell its smoothing from its nearest-sample re-alignment.
constexpr int kEstimators = 6;
constexpr const char* kNames[kEstimators] = {"zero-order", "6", "10", "12", "26", "26b"};
enum { kZeroOrder, kSix, kTen, kTwelve, kTwentySix, kSobelBilinear };
// Where two estimators read the same samples (axis-aligned views), double
// rounding may still tell their means apart by this much.
constexpr double kRounding = 1e-9;

// The estimators of one sample, in kNames' order.
template <class M, class Plane, class Voxels>
std::array<golden::GradientOf<M>, kEstimators> estimates(const M& m, const Plane& behind, const Plane& current,
                                                         const Plane& ahead, const Voxels& voxels, int x, int y,
                                                         int z, const std::array<typename M::Weight, 3>& w,
                                                         const golden::SliceAlignment<typename M::Weight>& a) {
  return {golden::gradient_zero_order(m, voxels, x, y, z, w[0], w[1], w[2]),
          golden::abc_gradient<golden::StraightNearest>(m, behind, current, ahead, x, y, a),
          golden::abc_gradient<golden::StraightTriangle>(m, behind, current, ahead, x, y, a),
          golden::abc_gradient<golden::StraightBilinear>(m, behind, current, ahead, x, y, a),
          golden::gradient_3x3x3<golden::StraightNearest>(m, behind, current, ahead, x, y, a),
          golden::gradient_3x3x3<golden::StraightBilinear>(m, behind, current, ahead, x, y, a)};
}

struct MeanAngles {
  std::array<double, kEstimators> sum{};
  std::array<int, kEstimators> count{};
  template <class G>
  void add(const golden::ViewFactorisation& view, const Vec3& position, const std::array<G, kEstimators>& g) {
    for (int e = 0; e < kEstimators; ++e) {
      double degrees;
      if (!test::angle_to_normal(view, test::kSphereCentre, position,
                                 {double(g[e][0]), double(g[e][1]), double(g[e][2])}, degrees))
        continue;
      sum[e] += degrees;
      ++count[e];
    }
  }
  double mean(int e) const { return sum[e] / count[e]; }
};

// Walks sample slices k = 0 .. K-1 with the slices behind and ahead, as the
// renderer does, and calls hit(k, x, y, behind, current, ahead) for each
// ray's first sample at or above the threshold, in the renderer's order.
// samples(k, plane) makes slice k (zeros outside 0 .. K-1); ray(k, x, y)
// names the ray through sample (x, y) of slice k.
template <class Plane, class Samples, class Ray, class Hit>
void first_hits(int K, Plane blank, double threshold, Samples&& samples, Ray&& ray, Hit&& hit) {
  Plane behind = blank, current = blank, ahead = blank;
  samples(0, current);
  samples(1, ahead);
  std::set<std::pair<int, int>> seen;
  for (int k = 0; k < K; ++k) {
    for (int y = 0; y < blank.ny; ++y)
      for (int x = 0; x < blank.nx; ++x)
        if (current.at(x, y) >= threshold && seen.insert(ray(k, x, y)).second) hit(k, x, y, behind, current, ahead);
    std::swap(behind, current);
    std::swap(current, ahead);
    samples(k + 2, ahead);
  }
}

// Sample slices in double, zeros beyond the grid as Plane's border.
struct RealPlane {
  static constexpr int kPad = 2;
  int nx = 0, ny = 0;
  std::vector<double> v;
  RealPlane(int nx_, int ny_) : nx(nx_), ny(ny_), v(static_cast<size_t>(nx_ + 2 * kPad) * (ny_ + 2 * kPad), 0.0) {}
  double& at(int x, int y) { return v[static_cast<size_t>(y + kPad) * (nx + 2 * kPad) + x + kPad]; }
  double at(int x, int y) const { return v[static_cast<size_t>(y + kPad) * (nx + 2 * kPad) + x + kPad]; }
};

struct RotationResult {
  MeanAngles fixed, real;
  MeanAngles probe;  // the renderer's 12-neighbourhood through a SampleProbe
  int hits = 0, renderer_hits = 0, mismatches = 0;
};

// Fixed point: the renderer's sample slices and control, and its own
// gradient at every hit beside the estimators'.
void measure_fixed(const test::Setup& s, RotationResult& out) {
  golden::Registers r = s.host.regs;
  r.gradient = true;
  const int nx = r.dim[0], ny = r.dim[1], W = r.p.weight_bits;
  const golden::PermutedVolume voxels(s.volume, r.perm, r.flip);
  golden::SliceInterp interp(nx, ny, W);
  golden::Plane lo(nx, ny, 1), hi(nx, ny, 1);
  auto samples = [&](int k, golden::Plane& out) {
    if (k < 0 || k >= r.sample_slices()) return out.clear();
    const golden::SliceControl c = golden::slice_control(r, k);
    golden::load_voxel_slice(voxels, c.z_voxel, lo);
    golden::load_voxel_slice(voxels, c.z_voxel + 1, hi);
    interp.slice(lo, hi, c, out);
  };
  auto ray = [&](int k, int x, int y) {
    const golden::SliceControl c = golden::slice_control(r, k);
    return std::pair{x - c.ix, y - c.iy};
  };
  test::FirstHitProbe probe(s.host.view, test::kSphereCentre, test::kSphereHalfDensity, W);
  golden::render_fixed(s.volume, r, nullptr, {}, &probe);
  out.probe.sum[kTwelve] = probe.angle_sum;
  out.probe.count[kTwelve] = probe.count;
  out.renderer_hits = static_cast<int>(probe.hits.size());
  const golden::FixedGradientMath m{r.p};
  first_hits(r.sample_slices(), golden::Plane(nx, ny, RealPlane::kPad), test::kSphereHalfDensity, samples, ray,
             [&](int k, int x, int y, const golden::Plane& b, const golden::Plane& cur, const golden::Plane& a) {
               const golden::SliceControl c = golden::slice_control(r, k);
               const golden::SliceAlignment<uint32_t> al{{c.behind_x.base, c.behind_x.weight},
                                                          {c.behind_y.base, c.behind_y.weight},
                                                          {c.ahead_x.base, c.ahead_x.weight},
                                                          {c.ahead_y.base, c.ahead_y.weight},
                                                          r.supersampling};
               const auto g = estimates(m, b, cur, a, voxels, x, y, c.z_voxel, {c.wx, c.wy, c.wz}, al);
               golden::Neighbourhood n;
               golden::gather_neighbourhood(b, cur, a, c, x, y, n);
               const golden::Gradient renderer = golden::sample_gradient(r, c, n);
               const auto& h = probe.hits;
               const size_t i = static_cast<size_t>(out.hits++);
               if (i >= h.size() || h[i].x != x || h[i].y != y || h[i].k != k || !(h[i].g == renderer) ||
                   !(golden::Gradient{g[kTwelve][0], g[kTwelve][1], g[kTwelve][2]} == renderer))
                 ++out.mismatches;
               out.fixed.add(s.host.view, test::sample_position(x, y, c, W), g);
             });
}

// Float: the float model's exact DDA, trilinear weights and arithmetic.
void measure_real(const test::Setup& s, RotationResult& out) {
  const golden::ViewFactorisation& view = s.host.view;
  const int S = s.scene.supersampling, nx = view.pdim[0], ny = view.pdim[1], K = view.pdim[2] * S;
  const golden::PermutedVolume voxels(s.volume, view.perm, view.flip);
  const golden::RealGradientMath m{s.scene.precision};
  struct Offset {
    int integer;
    double frac;
  };
  auto offset = [&](int axis, int k) {
    const double shear = axis == 0 ? view.shear_x : view.shear_y;
    const double v = s.scene.view.ray_offset[axis] + k * shear / S, i = std::floor(v);
    return Offset{static_cast<int>(i), v - i};
  };
  auto samples = [&](int k, RealPlane& out) {
    const bool inside = k >= 0 && k < K;
    const double fx = offset(0, k).frac, fy = offset(1, k).frac, wz = double(k % S) / S;
    const int z = k / S;
    auto bilinear = [&](int x, int y, int zz) {
      return m.lerp(m.lerp(voxels.at(x, y, zz), voxels.at(x + 1, y, zz), fx),
                    m.lerp(voxels.at(x, y + 1, zz), voxels.at(x + 1, y + 1, zz), fx), fy);
    };
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) out.at(x, y) = inside ? m.lerp(bilinear(x, y, z), bilinear(x, y, z + 1), wz) : 0;
  };
  auto ray = [&](int k, int x, int y) { return std::pair{x - offset(0, k).integer, y - offset(1, k).integer}; };
  first_hits(K, RealPlane(nx, ny), test::kSphereHalfDensity, samples, ray,
             [&](int k, int x, int y, const RealPlane& b, const RealPlane& cur, const RealPlane& a) {
               const Offset ox = offset(0, k), oy = offset(1, k);
               const golden::SliceAlignment<double> al{golden::realign_real(ox.frac, offset(0, k - 1).frac),
                                                        golden::realign_real(oy.frac, offset(1, k - 1).frac),
                                                        golden::realign_real(ox.frac, offset(0, k + 1).frac),
                                                        golden::realign_real(oy.frac, offset(1, k + 1).frac), S};
               const double wz = double(k % S) / S;
               const auto g = estimates(m, b, cur, a, voxels, x, y, k / S, {ox.frac, oy.frac, wz}, al);
               out.real.add(view, {x + ox.frac, y + oy.frac, k / S + wz}, g);
             });
}

RotationResult measure(int degrees, int tilt = 0) {
  const auto s = test::rotated_sphere(degrees, tilt);
  RotationResult r;
  measure_fixed(s, r);
  measure_real(s, r);
  return r;
}

void print_row(const char* tag, int degrees, const char* model, const MeanAngles& m) {
  std::printf("%s %2d %-5s", tag, degrees, model);
  for (int e = 0; e < kEstimators; ++e) std::printf(" %7.3f", m.mean(e));
  std::printf("\n");
}

// The harness is the renderer: the same first hits, and its 12-neighbourhood
// gradient at each, so the same mean as
// Accuracy.TwelveNeighbourhoodGradientOnAVolumeSampledSphere.
void expect_renderers_hits(const RotationResult& r, int degrees) {
  EXPECT_EQ(r.hits, r.renderer_hits) << degrees;
  EXPECT_EQ(r.mismatches, 0) << degrees;
  EXPECT_EQ(r.fixed.count[kTwelve], r.probe.count[kTwelve]) << degrees;
  EXPECT_EQ(r.fixed.mean(kTwelve), r.probe.mean(kTwelve)) << degrees;
}

}  // namespace

// The orderings below are what the measurement found (docs/accuracy.md,
// "Gradient neighbourhoods"), not thresholds fitted to it.
TEST(GradientNeighbourhoods, MeanAngularErrorOnARotatedSphere) {
  std::printf("GN rotation model");
  for (const char* n : kNames) std::printf(" %s", n);
  std::printf("\n");
  std::array<std::array<double, kEstimators>, 2> total{};  // over the rotations: fixed, float
  for (int deg = 0; deg <= 90; deg += 5) {
    const RotationResult r = measure(deg);
    ASSERT_GT(r.hits, 1000);
    expect_renderers_hits(r, deg);
    print_row("GN", deg, "fixed", r.fixed);
    print_row("GN", deg, "float", r.real);
    for (const MeanAngles* m : {&r.fixed, &r.real}) {
      const auto& a = *m;
      // About the vertical axis only x shears: the 2x2's y weight is zero,
      // where the triangle and the bilinear interpolation are one lerp.
      if (m == &r.fixed) {
        EXPECT_EQ(a.mean(kTen), a.mean(kTwelve)) << deg;
      } else {
        EXPECT_NEAR(a.mean(kTen), a.mean(kTwelve), kRounding) << deg;
      }
      EXPECT_LE(a.mean(kTwelve), a.mean(kSix) + kRounding) << deg;
      EXPECT_LT(a.mean(kSobelBilinear), a.mean(kTwelve)) << deg;
      for (int e = 0; e < kEstimators; ++e) total[m == &r.fixed ? 0 : 1][e] += a.mean(e);
    }
  }
  for (const auto& a : total) {
    EXPECT_LT(a[kSobelBilinear], a[kTwelve]);
    EXPECT_LT(a[kTwelve], a[kZeroOrder]);
    EXPECT_LT(a[kZeroOrder], a[kTwentySix]);
    EXPECT_LT(a[kTwentySix], a[kSix]);
  }
}

// Tilted 20° first, so that both x and y shear: the triangle and the
// bilinear re-alignment now differ.
TEST(GradientNeighbourhoods, TiltedSphere) {
  bool ten_differs = false;
  for (int deg = 0; deg <= 90; deg += 15) {
    const RotationResult r = measure(deg, 20);
    ASSERT_GT(r.hits, 1000);
    expect_renderers_hits(r, deg);
    print_row("GT", deg, "fixed", r.fixed);
    print_row("GT", deg, "float", r.real);
    for (const MeanAngles* m : {&r.fixed, &r.real}) {
      EXPECT_LE(m->mean(kTwelve), m->mean(kSix) + kRounding) << deg;
      EXPECT_LT(m->mean(kSobelBilinear), m->mean(kTwelve)) << deg;
      ten_differs |= m->mean(kTen) != m->mean(kTwelve);
    }
  }
  EXPECT_TRUE(ten_differs);
}
