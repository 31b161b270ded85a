// Cube-5's polygons in Cube-4's perspective (docs/fixed-point.md,
// "Polygons: the host rasteriser"): the rasteriser's perspective-correct
// depth against the exact crossing of each ray with the triangle's plane,
// the near plane, and the renderers with polygons in perspective (skipping
// exact, fixed against float against the reference).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "golden/polygons.hpp"
#include "golden/rasterise.hpp"
#include "tb/tests/test_support.hpp"

using namespace cube4;

namespace {

const char* const kViews[] = {
    R"({"direction": [0.4, -0.3, 1], "projection": "perspective", "fov": 40})",
    R"({"direction": [-1, 0.2, 0.1], "up": [0, 0, 1], "projection": "perspective", "fov": 60})",
    R"({"direction": [0.1, 1, -0.2], "up": [0, 0, 1], "projection": "perspective", "fov": 30, "zoom": 1.5})",
};

// Depth (sample slices) at which the ray of base-plane pixel (u, v) meets
// the plane through permuted points a, b, c, solved exactly in doubles: the
// ray is x = x0 + d·sx + (u - origin_x)·w(d), y likewise, z = d / S.
double ray_plane_depth(const golden::BaseFrame& f, const golden::Vec3& a, const golden::Vec3& b, const golden::Vec3& c,
                       double u, double v) {
  const golden::Vec3 e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const golden::Vec3 n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  const double rhs = n[0] * a[0] + n[1] * a[1] + n[2] * a[2];
  const double pu = u - f.origin_x, pv = v - f.origin_y;
  const double at0 = n[0] * (f.x0 + pu) + n[1] * (f.y0 + pv);
  const double slope = n[0] * (f.sx + pu * f.ms) + n[1] * (f.sy + pv * f.ms) + n[2] / f.S;
  return (rhs - at0) / slope;
}

golden::BaseFrame perspective_frame() {
  const test::Setup s = test::setup(test::sphere_with_polygons(kViews[0]));
  EXPECT_TRUE(s.host.regs.perspective);
  return golden::base_frame(s.host.regs);
}

}  // namespace

// Random triangles in front of the eye: in doubles the depth is the ray's
// crossing with the plane up to rounding. In integers (snapped corners) the
// depth is a perspective-weighted mean of the corners' (weights in [0, 1]),
// so its error is at most the rounding (1/512 slice) plus the largest
// corner's: its depth snapped by up to 1/512 slice, its position by up to
// 1/512 pixel in u and v, which moves the plane's depth there by the
// plane's slope times that, and h by up to 2^-21 of 2^20 / w, which shifts
// the weights by a relative 2^-20 w at most, so the mean by that much of the
// corners' depth range. First order; the test reports the worst ratio.
TEST(PolygonsPerspective, DepthIsTheRayPlaneCrossing) {
  const golden::BaseFrame f = perspective_frame();
  ASSERT_GT(f.ms, 0);
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> pos(-4, 28), depth(-8, 40);
  int triangles = 0, pixels = 0;
  double worst_ratio = 0;
  while (triangles < 300) {
    golden::Vec3 p[3];
    for (auto& q : p) q = {pos(gen), pos(gen), depth(gen)};
    golden::BaseCorner corner[3];
    int pieces = 0;
    golden::project_triangle(f, p[0], p[1], p[2], [&](const golden::BaseCorner(&k)[3]) {
      ++pieces;
      std::copy(k, k + 3, corner);
    });
    if (pieces != 1) continue;  // clipped: DepthBehindTheNearPlane
    const auto plane_depth = [&](double u, double v) { return ray_plane_depth(f, p[0], p[1], p[2], u, v); };
    double bound = 0.5 / 256, lo = 1e300, hi = -1e300, w_max = 0;
    for (const golden::BaseCorner& k : corner) {
      const double u = k.uvd[0], v = k.uvd[1], e = 1e-4;
      const double su = (plane_depth(u + e, v) - plane_depth(u - e, v)) / (2 * e),
                   sv = (plane_depth(u, v + e) - plane_depth(u, v - e)) / (2 * e);
      lo = std::min(lo, k.uvd[2]);
      hi = std::max(hi, k.uvd[2]);
      w_max = std::max(w_max, 1 / k.h);
      bound = std::max(bound, 0.5 / 256 + (1 + std::fabs(su) + std::fabs(sv)) / 512);
    }
    bound += (hi - lo) * w_max * std::ldexp(1.0, -20);
    if (bound > 0.25) continue;  // nearly edge-on: the plane's slope makes a snapped corner meaningless
    ++triangles;
    golden::BaseVertex<double> real[3];
    golden::BaseVertex<int64_t> snapped[3];
    for (int i = 0; i < 3; ++i) {
      const golden::Vec3& b = corner[i].uvd;
      real[i] = {b[0], b[1], b[2], corner[i].h};
      snapped[i] = {std::llround(std::floor(b[0] * 256 + 0.5)), std::llround(std::floor(b[1] * 256 + 0.5)),
                    std::llround(std::floor(b[2] * 256 + 0.5)),
                    std::llround(std::floor(std::ldexp(corner[i].h, golden::kInverseSpacingBits) + 0.5))};
    }
    golden::scan_triangle<double>(real[0], real[1], real[2], 1.0, 64, 64, [&](int u, int v, double d) {
      ++pixels;
      const double want = plane_depth(u, v);
      ASSERT_NEAR(d, want, 1e-9 * std::max(1.0, std::fabs(want))) << "pixel (" << u << ", " << v << ")";
    });
    golden::scan_triangle<int64_t>(snapped[0], snapped[1], snapped[2], 256, 64, 64, [&](int u, int v, int64_t d) {
      const double err = std::fabs(d / 256.0 - plane_depth(u, v));
      worst_ratio = std::max(worst_ratio, err / bound);
      ASSERT_LE(err, bound) << "triangle " << triangles << ", pixel (" << u << ", " << v << ")";
    });
  }
  EXPECT_GT(pixels, 5000);
  std::printf("worst integer depth error: %.3f of its bound\n", worst_ratio);
}

// The rasteriser's integer depth with differing h: the incremental
// numerator and denominator give the rounded quotient of each pixel's own
// sums, computed here afresh.
TEST(PolygonsPerspective, SteppedDepthEqualsEachPixelsOwnQuotient) {
  std::mt19937 gen(11);
  std::uniform_int_distribution<int64_t> coord(-2000, 10000), d(-5000, 50000), h(1 << 18, 1 << 23);
  int pixels = 0;
  for (int t = 0; t < 300; ++t) {
    golden::BaseVertex<int64_t> v[3];
    for (auto& q : v) q = {coord(gen), coord(gen), d(gen), h(gen)};
    const auto edge = [&](const golden::BaseVertex<int64_t>& a, const golden::BaseVertex<int64_t>& b, __int128 pu,
                          __int128 pv) { return (__int128{b.u} - a.u) * (pv - a.v) - (__int128{b.v} - a.v) * (pu - a.u); };
    golden::scan_triangle<int64_t>(v[0], v[1], v[2], 256, 40, 40, [&](int u, int w, int64_t got) {
      ++pixels;
      const __int128 pu = __int128{u} * 256, pv = __int128{w} * 256;
      __int128 e[3] = {edge(v[1], v[2], pu, pv), edge(v[2], v[0], pu, pv), edge(v[0], v[1], pu, pv)};
      if (e[0] + e[1] + e[2] < 0)
        for (auto& x : e) x = -x;
      __int128 N = 0, D = 0;
      for (int i = 0; i < 3; ++i) {
        N += e[i] * v[i].h * v[i].d;
        D += e[i] * v[i].h;
      }
      const __int128 num = 2 * N + D, den = 2 * D;
      __int128 q = num / den;
      if (num % den != 0 && num < 0) --q;
      ASSERT_EQ(static_cast<__int128>(got), q) << "triangle " << t << ", pixel (" << u << ", " << w << ")";
    });
  }
  EXPECT_GT(pixels, 10000);
}

// The integer range the host admits in perspective (corners within ±2^24
// pixels and ±2^20 sample slices, h from 1 to 2^24 units of 2^-20): the
// depth's numerator and denominator stay within 128 bits, so every covered
// pixel's depth is a mean of the corners' (perspective weights in [0, 1]),
// never a wrapped value. Triangles with corners at the extremes, their
// footprints crossing the 64 x 64 window scanned.
TEST(PolygonsPerspective, CornersAtTheRangesLimitsStayWithin128Bits) {
  std::mt19937_64 gen(29);
  const int64_t uv = int64_t{1} << (24 + golden::kSubpixelBits), d = int64_t{1} << (20 + golden::kZFracBits);
  const int64_t h_max = int64_t{1} << 24;
  auto extreme = [&](int64_t limit) {
    switch (gen() % 4) {
      case 0: return limit;
      case 1: return -limit;
      case 2: return static_cast<int64_t>(gen() % static_cast<uint64_t>(2 * limit + 1)) - limit;
      default: return static_cast<int64_t>(gen() % (64 * 256));  // inside the window
    }
  };
  int triangles = 0, pixels = 0;
  for (int t = 0; t < 4000; ++t) {
    golden::BaseVertex<int64_t> v[3];
    for (auto& q : v) q = {extreme(uv), extreme(uv), extreme(d), gen() % 2 ? h_max : 1 + static_cast<int64_t>(gen() % static_cast<uint64_t>(h_max))};
    const int64_t lo = std::min({v[0].d, v[1].d, v[2].d}), hi = std::max({v[0].d, v[1].d, v[2].d});
    bool any = false;
    golden::scan_triangle<int64_t>(v[0], v[1], v[2], 256, 64, 64, [&](int u, int w, int64_t depth) {
      any = true;
      ++pixels;
      ASSERT_GE(depth, lo) << "triangle " << t << ", pixel (" << u << ", " << w << ")";
      ASSERT_LE(depth, hi) << "triangle " << t << ", pixel (" << u << ", " << w << ")";
    });
    triangles += any;
  }
  EXPECT_GT(triangles, 200);
  EXPECT_GT(pixels, 100000);
}

// A triangle reaching behind the eye is drawn beyond the near plane only:
// one or two pieces whose corners all lie on or beyond it, sharing their
// diagonal (no pixel twice), each pixel at the plane's true depth; wholly
// nearer than the near plane, nothing.
TEST(PolygonsPerspective, DepthBehindTheNearPlane) {
  const golden::BaseFrame f = perspective_frame();
  const double near_depth = (golden::kNearSpacing - 1) / f.ms;  // sample slices, negative: in front of the volume
  const double behind_eye = -1.5 / f.ms / f.S;                  // permuted z beyond the eye
  auto pieces_of = [&](const golden::Vec3& a, const golden::Vec3& b, const golden::Vec3& c) {
    std::vector<std::array<golden::BaseCorner, 3>> out;
    golden::project_triangle(f, a, b, c, [&](const golden::BaseCorner(&k)[3]) { out.push_back({k[0], k[1], k[2]}); });
    return out;
  };
  EXPECT_TRUE(pieces_of({0, 0, behind_eye}, {9, 0, behind_eye}, {0, 9, behind_eye}).empty());
  struct Case {
    golden::Vec3 a, b, c;
    size_t pieces;
  };
  for (const Case& t : {Case{{4, 4, behind_eye}, {20, 6, 10}, {8, 20, 12}, 2},  // one corner nearer: a quadrilateral
                        Case{{4, 4, behind_eye}, {20, 6, behind_eye}, {8, 20, 12}, 1}}) {  // two: a triangle
    const auto pieces = pieces_of(t.a, t.b, t.c);
    ASSERT_EQ(pieces.size(), t.pieces);
    std::vector<int> count(64 * 64, 0);
    int drawn = 0;
    for (const auto& k : pieces) {
      golden::BaseVertex<double> v[3];
      for (int i = 0; i < 3; ++i) {
        EXPECT_GE(k[static_cast<size_t>(i)].uvd[2], near_depth - 1e-9);
        v[i] = {k[static_cast<size_t>(i)].uvd[0], k[static_cast<size_t>(i)].uvd[1], k[static_cast<size_t>(i)].uvd[2],
                k[static_cast<size_t>(i)].h};
      }
      golden::scan_triangle<double>(v[0], v[1], v[2], 1.0, 64, 64, [&](int u, int w, double d) {
        ++drawn;
        ++count[static_cast<size_t>(w) * 64 + u];
        EXPECT_GE(d, near_depth - 1e-9);
        EXPECT_NEAR(d, ray_plane_depth(f, t.a, t.b, t.c, u, w), 1e-7);
      });
    }
    EXPECT_GT(drawn, 20);
    EXPECT_LE(*std::max_element(count.begin(), count.end()), 1) << "a pixel drawn by both pieces";
  }
}

TEST(PolygonsPerspective, SkippingStaysExactAndThePolygonsShow) {
  for (const char* view : kViews) {
    SCOPED_TRACE(view);
    const test::Setup s = test::setup(test::sphere_with_polygons(view));
    ASSERT_TRUE(s.host.regs.perspective);
    const golden::PolygonFrame frame = golden::rasterise_polygons(s.scene, s.meshes, s.host);
    EXPECT_GT(frame.counts.opaque, 0u);
    EXPECT_GT(frame.counts.in_slabs, 0u);
    EXPECT_GT(frame.counts.in_front + frame.counts.behind, 0u);
    // Without skipping (a probe sees every sample) and with it: the same plane.
    struct Counting : golden::SampleProbe {
      uint64_t seen = 0;
      void sample(int, int, const golden::SliceControl&, uint32_t, const golden::Gradient&) override { ++seen; }
    } probe;
    golden::FixedOptions all;
    all.polygons = &frame;
    all.probe = &probe;
    golden::FixedOptions skipping;
    skipping.polygons = &frame;
    const golden::BasePlane want = golden::render_fixed(s.volume, s.host.regs, all);
    EXPECT_GT(probe.seen, 1000u);
    EXPECT_EQ(golden::render_fixed(s.volume, s.host.regs, skipping).rgba, want.rgba);
    // Every pixel the polygons reach differs from the volume alone somewhere.
    EXPECT_NE(golden::render_fixed(s.volume, s.host.regs).rgba, want.rgba);
  }
}

// Fixed against float on the small hybrid scenes: the perspective
// renderer's bound without polygons (PerspectiveRender.FixedMatchesFloat...).
// Float against the reference: PolygonsPerspective.DrawnWhereThePinholeSeesThem
// and Accuracy.FloatAgainstReferenceWithPolygonsInPerspective.
TEST(PolygonsPerspective, FixedMatchesFloat) {
  for (const char* view : kViews) {
    SCOPED_TRACE(view);
    const test::Setup s = test::setup(test::sphere_with_polygons(view));
    const test::ImageError e = test::compare(test::final_fixed(s), test::final_float(s));
    EXPECT_GT(e.psnr, 35.0) << "max " << e.max_error;
  }
}


// Opaque polygons alone (an empty volume) off the view's centre in a wide
// view, and a wall reaching from behind the eye past the volume: a
// footprint misplaced by one base-plane pixel, or a wrong projection of
// the far corners, moves the centroid by more than half an image pixel or
// the covered area by more than 2 %. The reference is the pinhole ray caster.
TEST(PolygonsPerspective, DrawnWhereThePinholeSeesThem) {
  const std::string empty = R"({"volume": {"synthetic": "constant", "size": [40, 32, 48], "value": 0},
      "output": {"width": 200, "height": 160}, "view": )";
  struct Case {
    const char* name;
    std::string view, polygons;
  };
  const Case cases[] = {
      {"ball and box", R"({"rotate": [30, -40, 10], "projection": "perspective", "fov": 60})",
       R"([{"shape": "sphere", "radius": 6, "segments": 32, "rings": 16, "transform": {"translate": [8, 26, 40]}},
           {"shape": "box", "size": [10, 4, 30], "transform": {"translate": [30, 8, 20], "rotate": [20, 10, 5]}}])"},
      {"wall from behind the eye", R"({"direction": [0, 0, 1], "projection": "perspective", "fov": 50, "distance": 70})",
       R"([{"shape": "plane", "size": [400, 20], "transform": {"rotate": [0, 90, 0], "translate": [4, 15.5, 0]}}])"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const test::Setup s = test::setup(empty + c.view + R"(, "polygons": )" + c.polygons + "}");
    ASSERT_TRUE(s.host.regs.perspective);
    const auto ref = test::centroid(test::final_reference(s));
    EXPECT_GT(ref[2], 500);
    for (const auto& got : {test::centroid(test::final_fixed(s)), test::centroid(test::final_float(s))}) {
      EXPECT_NEAR(got[0], ref[0], 0.5);
      EXPECT_NEAR(got[1], ref[1], 0.5);
      EXPECT_NEAR(got[2], ref[2], 0.02 * ref[2]);
    }
  }
}
