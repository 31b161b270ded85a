// The published gradient check (Towards-scalable §3, Fig. 2): a
// volume-sampled sphere rotated about the vertical axis, and the angle
// between a gradient at the first sample above half density on each ray and
// the sphere's analytic normal there.
#pragma once
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "golden/pipeline.hpp"
#include "golden/renderers.hpp"
#include "golden/view.hpp"
#include "tb/tests/test_support.hpp"

namespace cube4::test {

constexpr uint32_t kSphereHalfDensity = 2048;
inline const golden::Vec3 kSphereCentre{31.5, 31.5, 31.5};

// 64³, radius 24, unshaded, turned `degrees` about the vertical axis
// (after tilting it `tilt` about the horizontal one).
inline Setup rotated_sphere(int degrees, int tilt = 0) {
  return setup(R"({"volume": {"synthetic": "sphere", "size": [64, 64, 64], "radius": 24},
      "shading": false, "view": {"rotate": [)" + std::to_string(tilt) + ", " + std::to_string(degrees) +
               R"(, 0]}})");
}

// Degrees between `gradient` at `position` (both permuted voxel space) and
// the sphere's outward normal; the gradient points up the density, inwards.
// False if either vector is zero.
inline bool angle_to_normal(const golden::ViewFactorisation& view, const golden::Vec3& centre,
                            const golden::Vec3& position, const golden::Vec3& gradient, double& degrees) {
  const golden::Vec3 pos = view.to_object(position);
  const golden::Vec3 grad = view.direction_to_object(gradient);
  double dot = 0, gn = 0, nn = 0;
  for (int i = 0; i < 3; ++i) {
    const double n = pos[i] - centre[i];
    dot += -grad[i] * n;
    gn += grad[i] * grad[i];
    nn += n * n;
  }
  if (gn == 0 || nn == 0) return false;
  degrees = std::acos(std::clamp(dot / std::sqrt(gn * nn), -1.0, 1.0)) * 180 / 3.14159265358979323846;
  return true;
}

// Permuted voxel position of sample (x, y) of slice c.k in fixed point.
inline golden::Vec3 sample_position(int x, int y, const golden::SliceControl& c, int weight_bits) {
  const double one = std::ldexp(1.0, weight_bits);
  return {x + c.wx / one, y + c.wy / one, c.z_voxel + c.wz / one};
}

// What render_fixed() shows a probe: for every ray its first sample above a
// threshold, with the renderer's gradient there, and the mean angle to the
// sphere's normal.
struct FirstHitProbe : golden::SampleProbe {
  struct Hit {
    int x, y, k;
    golden::Gradient g;
  };
  const golden::ViewFactorisation& view;
  golden::Vec3 centre;
  uint32_t threshold;
  int weight_bits;
  std::set<std::pair<int, int>> hit;
  std::vector<Hit> hits;
  double angle_sum = 0;
  int count = 0;
  FirstHitProbe(const golden::ViewFactorisation& v, golden::Vec3 c, uint32_t t, int w)
      : view(v), centre(c), threshold(t), weight_bits(w) {}
  void sample(int x, int y, const golden::SliceControl& c, uint32_t value, const golden::Gradient& g) override {
    if (value < threshold) return;
    if (!hit.insert({x - c.ix, y - c.iy}).second) return;
    hits.push_back({x, y, c.k, g});
    double degrees;
    if (!angle_to_normal(view, centre, sample_position(x, y, c, weight_bits), {double(g.x), double(g.y), double(g.z)},
                         degrees))
      return;
    angle_sum += degrees;
    ++count;
  }
};

}  // namespace cube4::test
