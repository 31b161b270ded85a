#include "golden/polygons_float.hpp"

#include <algorithm>
#include <limits>

#include "golden/rasterise.hpp"
#include "golden/shading_model.hpp"

namespace cube4::golden {

PolygonsF::PolygonsF(const Scene& s, const std::vector<Mesh>& meshes, const ViewFactorisation& f,
                     const BaseFrame& frame, int width, int height)
    : hits_(static_cast<size_t>(width) * height), next_(hits_.size(), 0), done_(hits_.size(), false),
      z_(hits_.size(), std::numeric_limits<double>::infinity()), opaque_(hits_.size()) {
  for_each_drawn_triangle(s, f, meshes, [&](const Mesh& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& rgb) {
    const auto emit = [&](int u, int v, double d) {
      const size_t i = static_cast<size_t>(v) * width + u;
      if (m.opacity < 1) {
        hits_[i].push_back({d, rgb, m.opacity});
      } else if (d < z_[i]) {
        z_[i] = d;
        opaque_[i] = rgb;
      }
    };
    project_triangle(frame, f.to_permuted(a), f.to_permuted(b), f.to_permuted(c), [&](const BaseCorner(&k)[3]) {
      BaseVertex<double> v[3];
      for (int i = 0; i < 3; ++i) v[i] = {k[i].uvd[0], k[i].uvd[1], k[i].uvd[2], k[i].h};
      scan_triangle<double>(v[0], v[1], v[2], 1.0, width, height, emit);
    });
  });
  for (size_t i = 0; i < hits_.size(); ++i) {
    auto& h = hits_[i];
    h.erase(std::remove_if(h.begin(), h.end(), [&](const Hit& x) { return x.d >= z_[i]; }), h.end());
    std::stable_sort(h.begin(), h.end(), [](const Hit& x, const Hit& y) { return x.d < y.d; });
  }
}

bool PolygonsF::before_sample(size_t i, int k, AccF& acc) {
  const auto& h = hits_[i];
  while (next_[i] < h.size() && h[next_[i]].d <= k) {
    acc.over(h[next_[i]].rgb, h[next_[i]].alpha);
    ++next_[i];
  }
  return k < z_[i];
}

AccF PolygonsF::leave(size_t i, AccF acc) {
  const auto& h = hits_[i];
  for (; next_[i] < h.size(); ++next_[i]) acc.over(h[next_[i]].rgb, h[next_[i]].alpha);
  if (z_[i] < std::numeric_limits<double>::infinity()) acc.over(opaque_[i], 1.0);
  done_[i] = true;
  return acc;
}

}  // namespace cube4::golden
