#include "golden/perspective_dataflow.hpp"

#include "golden/perspective.hpp"

namespace cube4::golden {
namespace {

// One axis's fields of a PerspectiveSlice.
struct AxisFields {
  int64_t ray0;
  RayRange rays;
  RealignDda behind, ahead;
};

// One axis's offsets: `a` picks the axis's fields of a PerspectiveSlice.
template <class Axis>
void reach_along(const Registers& r, Axis&& a, AxisReach& out) {
  const int F = r.p.dda_frac_bits, W = r.p.weight_bits, K = r.sample_slices();
  auto home = [&](const PerspectiveSlice& s, int64_t u) { return home_cell(ray_position(a(s).ray0, s.spacing, u), F); };
  auto inside = [&](const PerspectiveSlice& s, int64_t u) { return u >= a(s).rays.lo && u < a(s).rays.hi; };
  // The two rays of slice `there` around the realigned point, where they sample it.
  auto realigned = [&](const PerspectiveSlice& there, const RealignDda& d, int64_t u, int64_t h, CellRange& range) {
    const int64_t q = realigned_ray(d, u, F, W).ray;
    for (int64_t ray : {q, q + 1})
      if (inside(there, ray)) range.add(home(there, ray) - h);
  };
  PerspectiveSlice behind, here = perspective_slice(r, 0), ahead;
  for (int k = 0; k < K; ++k) {
    if (k + 1 < K) ahead = perspective_slice(r, k + 1);
    const RayRange rays = a(here).rays;
    for (int64_t u = rays.lo; u < rays.hi; ++u) {
      const int64_t pos = ray_position(a(here).ray0, here.spacing, u), h = home_cell(pos, F);
      const BoxAxis box = box_axis(pos, here.spacing, F, W);
      for (int j = 0; j < 4; ++j)
        if (box.overlap[static_cast<size_t>(j)] > 0) out.box.add(box.first + j - h);
      if (u + 1 < rays.hi) out.next.add(home(here, u + 1) - h);
      if (k > 0) realigned(behind, a(here).behind, u, h, out.behind);
      if (k + 1 < K) {
        realigned(ahead, a(here).ahead, u, h, out.ahead);
        if (inside(ahead, u)) out.drift.add(home(ahead, u) - h);
      }
    }
    behind = here;
    here = ahead;
  }
}

}  // namespace

PerspectiveReach perspective_reach(const Registers& r) {
  PerspectiveReach out;
  reach_along(r, [](const PerspectiveSlice& s) { return AxisFields{s.ray0_x, s.rays_x, s.behind_x, s.ahead_x}; }, out.x);
  reach_along(r, [](const PerspectiveSlice& s) { return AxisFields{s.ray0_y, s.rays_y, s.behind_y, s.ahead_y}; }, out.y);
  out.samples = perspective_samples(r);
  return out;
}

GradientRows gradient_rows(const Registers& r, const PerspectiveSlice& s, const PerspectiveSlice* behind,
                           const PerspectiveSlice* ahead, int64_t Y) {
  const int F = r.p.dda_frac_bits, W = r.p.weight_bits;
  GradientRows out;
  const HomeLane h = home_lane(s.ray0_y, s.spacing, s.rays_y, Y, F, W);
  if (!h.valid) return out;
  out.valid = true;
  out.v = h.ray;
  auto row = [&](const PerspectiveSlice& on, int64_t v) {
    return v >= on.rays_y.lo && v < on.rays_y.hi ? home_cell(ray_position(on.ray0_y, on.spacing, v), F) : kNoRow;
  };
  out.up = row(s, h.ray - 1);
  out.down = row(s, h.ray + 1);
  auto realigned = [&](const PerspectiveSlice* there, const RealignDda& d, std::array<int64_t, 2>& rows) {
    if (!there) return;
    const int64_t q = realigned_ray(d, h.ray, F, W).ray;
    rows = {row(*there, q), row(*there, q + 1)};
  };
  realigned(behind, s.behind_y, out.behind);
  realigned(ahead, s.ahead_y, out.ahead);
  return out;
}

GradientWindow gradient_window(const Registers& r, const PerspectiveSlice& s, const PerspectiveSlice* behind,
                               const PerspectiveSlice* ahead, int64_t u) {
  const int F = r.p.dda_frac_bits, W = r.p.weight_bits;
  const int64_t forming = home_cell(ray_position(s.ray0_x, s.spacing, u), F) + kGradientAfterColumns;
  // The lane back from the forming one that stores ray a of slice `on`.
  auto lane = [&](const PerspectiveSlice& on, int64_t a) {
    if (a < on.rays_x.lo || a >= on.rays_x.hi) return -1;
    return static_cast<int>(forming - (home_cell(ray_position(on.ray0_x, on.spacing, a), F) + kFormedAfterColumns));
  };
  GradientWindow out;
  out.left = lane(s, u - 1);
  out.right = lane(s, u + 1);
  auto realigned = [&](const PerspectiveSlice* there, const RealignDda& d, std::array<int, 2>& lanes) {
    if (!there) return;
    const int64_t q = realigned_ray(d, u, F, W).ray;
    lanes = {lane(*there, q), lane(*there, q + 1)};
  };
  realigned(behind, s.behind_x, out.behind);
  realigned(ahead, s.ahead_x, out.ahead);
  return out;
}

uint64_t perspective_samples(const Registers& r) {
  uint64_t n = 0;
  for (int k = 0; k < r.sample_slices(); ++k) {
    const RayRange x = r.rays_in_slice(0, k), y = r.rays_in_slice(1, k);
    if (!x.empty() && !y.empty()) n += static_cast<uint64_t>(x.hi - x.lo) * static_cast<uint64_t>(y.hi - y.lo);
  }
  return n;
}

}  // namespace cube4::golden
