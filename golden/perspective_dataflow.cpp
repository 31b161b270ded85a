#include "golden/perspective_dataflow.hpp"

#include "golden/perspective.hpp"

namespace cube4::golden {

OperandHomes gradient_operand_homes(const AxisSlice& here, const AxisSlice* behind, const RealignDda& to_behind,
                                    const AxisSlice* ahead, const RealignDda& to_ahead, int64_t u, int frac_bits,
                                    int weight_bits) {
  auto home = [&](const AxisSlice& on, int64_t a) { return ray_home(on, a, frac_bits); };
  OperandHomes out;
  out.home = home(here, u);
  out.side = {home(here, u - 1), home(here, u + 1)};
  auto realigned = [&](const AxisSlice* there, const RealignDda& d, std::array<int64_t, 2>& homes, uint32_t& weight) {
    if (!there) return;
    const RayPoint q = realigned_ray(d, u, frac_bits, weight_bits);
    homes = {home(*there, q.ray), home(*there, q.ray + 1)};
    weight = q.weight;
  };
  realigned(behind, to_behind, out.behind, out.behind_weight);
  realigned(ahead, to_ahead, out.ahead, out.ahead_weight);
  return out;
}

namespace {
// gradient_operand_homes() of ray u of slice s along `axis`.
OperandHomes operand_homes(const Registers& r, const PerspectiveSlice& s, const PerspectiveSlice* behind,
                           const PerspectiveSlice* ahead, int axis, int64_t u) {
  const AxisSlice b = behind ? axis_slice(*behind, axis) : AxisSlice{}, a = ahead ? axis_slice(*ahead, axis) : AxisSlice{};
  return gradient_operand_homes(axis_slice(s, axis), behind ? &b : nullptr, axis == 0 ? s.behind_x : s.behind_y,
                                ahead ? &a : nullptr, axis == 0 ? s.ahead_x : s.ahead_y, u, r.p.dda_frac_bits,
                                r.p.weight_bits);
}

// One axis's offsets (axis 0: x, 1: y).
void reach_along(const Registers& r, int axis, AxisReach& out) {
  const int F = r.p.dda_frac_bits, W = r.p.weight_bits, K = r.sample_slices();
  auto add = [](CellRange& range, int64_t h, int64_t home) {
    if (home != kNoRow) range.add(home - h);
  };
  PerspectiveSlice behind, here = perspective_slice(r, 0), ahead;
  for (int k = 0; k < K; ++k) {
    if (k + 1 < K) ahead = perspective_slice(r, k + 1);
    const AxisSlice on = axis_slice(here, axis);
    for (int64_t u = on.rays.lo; u < on.rays.hi; ++u) {
      const OperandHomes o = operand_homes(r, here, k > 0 ? &behind : nullptr, k + 1 < K ? &ahead : nullptr, axis, u);
      const int64_t h = o.home;
      const BoxAxis box = box_axis(ray_position(on.ray0, on.spacing, u), on.spacing, F, W);
      for (int j = 0; j < 4; ++j)
        if (box.overlap[static_cast<size_t>(j)] > 0) out.box.add(box.first + j - h);
      add(out.next, h, o.side[1]);
      for (size_t i = 0; i < 2; ++i) {
        add(out.behind, h, o.behind[i]);
        add(out.ahead, h, o.ahead[i]);
      }
      if (k + 1 < K) add(out.drift, h, ray_home(axis_slice(ahead, axis), u, F));
    }
    behind = here;
    here = ahead;
  }
}

}  // namespace

PerspectiveReach perspective_reach(const Registers& r) {
  PerspectiveReach out;
  reach_along(r, 0, out.x);
  reach_along(r, 1, out.y);
  out.samples = perspective_samples(r);
  return out;
}

GradientRows gradient_rows(const Registers& r, const PerspectiveSlice& s, const PerspectiveSlice* behind,
                           const PerspectiveSlice* ahead, int64_t Y) {
  GradientRows out;
  const HomeLane h = home_lane(s.ray0_y, s.spacing, s.rays_y, Y, r.p.dda_frac_bits, r.p.weight_bits);
  if (!h.valid) return out;
  const OperandHomes o = operand_homes(r, s, behind, ahead, 1, h.ray);
  out.valid = true;
  out.v = h.ray;
  out.up = o.side[0];
  out.down = o.side[1];
  out.behind = o.behind;
  out.ahead = o.ahead;
  return out;
}

GradientWindow gradient_window(const Registers& r, const PerspectiveSlice& s, const PerspectiveSlice* behind,
                               const PerspectiveSlice* ahead, int64_t u) {
  const OperandHomes o = operand_homes(r, s, behind, ahead, 0, u);
  // The lane back from the forming one (home + 5) that stores an operand
  // homed at h (lane h + 2).
  const int64_t forming = o.home + kGradientAfterColumns;
  auto lane = [&](int64_t h) { return h == kNoRow ? -1 : static_cast<int>(forming - (h + kFormedAfterColumns)); };
  GradientWindow out;
  out.left = lane(o.side[0]);
  out.right = lane(o.side[1]);
  out.behind = {lane(o.behind[0]), lane(o.behind[1])};
  out.ahead = {lane(o.ahead[0]), lane(o.ahead[1])};
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
