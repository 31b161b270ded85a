// Weight generator, perspective projection (Cube-4 §3; docs/perspective.md).
// The rays leave one eye, so they spread: on sample slice k they are m_k
// voxels apart and ray 0 lies at c_k, both integer DDAs over the slices
// (start + k * step, like dda_position), and ray u at c_k + u * m_k, a third
// DDA along the beam. All positions have dda_frac_bits of fraction. On the
// first slice m = 1: one ray per base-plane pixel.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>

namespace cube4::golden {

// ceil(a / b) for b > 0.
constexpr int64_t ceil_div(int64_t a, int64_t b) { return a >= 0 ? (a + b - 1) / b : -((-a) / b); }
// floor(a / b) for b > 0, wide numerator.
constexpr int64_t floor_div(__int128 a, int64_t b) {
  return static_cast<int64_t>(a >= 0 ? a / b : -((-a + b - 1) / b));
}

constexpr int64_t ray_position(int64_t ray0, int64_t spacing, int64_t u) { return ray0 + u * spacing; }

// The rays u whose sample on a slice lies in [0, n) along one axis, the
// columns of voxels the pipelines hold: [lo, hi). A ray samples a slice iff
// it is in the ranges of both axes; as the positions move linearly with k,
// a ray is inside for one run of slices, enters once and leaves once.
struct RayRange {
  int64_t lo = 0, hi = 0;
  bool empty() const { return lo >= hi; }
};
constexpr RayRange rays_inside(int64_t ray0, int64_t spacing, int n, int frac_bits) {
  return {ceil_div(-ray0, spacing), ceil_div((int64_t{n} << frac_bits) - ray0, spacing)};
}

// The box filter's reach along one axis for a sample at `pos` with ray
// spacing `spacing`: the box is spacing wide, centred on the sample, over
// voxel cells (cell i is where voxel i is nearest: [i - 1/2, i + 1/2)).
// Start and extent are truncated to weight_bits of fraction, the extent
// once per slice (box_extent), so every box of a slice has the same width.
// overlap[j] is the part of cell first + j the box covers, weight_bits of
// fraction; for extents up to 3 (spacing <= 3) four cells always suffice.
// An extent of exactly 1 gives linear interpolation between voxels first
// and first + 1 (overlaps 1 - f and f).
struct BoxAxis {
  int32_t first = 0;
  std::array<uint32_t, 4> overlap{};
};

constexpr int64_t box_extent(int64_t spacing, int frac_bits, int weight_bits) {
  return spacing >> (frac_bits - weight_bits);
}

constexpr BoxAxis box_axis(int64_t pos, int64_t spacing, int frac_bits, int weight_bits) {
  const int shift = frac_bits - weight_bits;
  const int64_t one = int64_t{1} << weight_bits;
  // Cell-edge coordinates: the box starts at pos + 1/2 - spacing/2.
  const int64_t start = (pos + (int64_t{1} << (frac_bits - 1)) - (spacing >> 1)) >> shift;
  const int64_t a = start & (one - 1), e = a + box_extent(spacing, frac_bits, weight_bits);
  BoxAxis b;
  b.first = static_cast<int32_t>(start >> weight_bits);
  for (int j = 0; j < 4; ++j) {
    const int64_t lo = std::max(a, j * one), hi = std::min(e, (j + 1) * one);
    b.overlap[static_cast<size_t>(j)] = hi > lo ? static_cast<uint32_t>(hi - lo) : 0u;
  }
  return b;
}

// The tag's voxel: the one nearest the sample (ties up, as sample_tag()).
constexpr int32_t nearest_voxel(int64_t pos, int frac_bits) {
  return static_cast<int32_t>((pos + (int64_t{1} << (frac_bits - 1))) >> frac_bits);
}

// A point of a neighbouring slice in that slice's ray grid: the ray index
// (integer part) and the weight between it and the next ray.
struct RayPoint {
  int64_t ray = 0;
  uint32_t weight = 0;
};

// The gradient's ahead and behind samples are taken straight ahead of and
// behind the sample, like the parallel 12-neighbourhood's, but the point
// lands between rays of the other slice at a place that varies per ray:
// ray u's position c_k + u m_k is ray (c_k - c_j + u m_k) / m_j of slice j,
// a DDA along the beam with start (c_k - c_j) / m_j and step m_k / m_j
// (per-slice divisions, floor, frac_bits of fraction).
struct RealignDda {
  int64_t start = 0, step = 0;
};
constexpr RealignDda realign_dda(int64_t ray0_here, int64_t spacing_here, int64_t ray0_there, int64_t spacing_there,
                                 int frac_bits) {
  // Scaled by multiplying: a left shift of a negative value is undefined.
  const __int128 one = static_cast<__int128>(1) << frac_bits;
  return {floor_div(static_cast<__int128>(ray0_here - ray0_there) * one, spacing_there),
          floor_div(static_cast<__int128>(spacing_here) * one, spacing_there)};
}
constexpr RayPoint realigned_ray(const RealignDda& d, int64_t u, int frac_bits, int weight_bits) {
  const int64_t pos = d.start + u * d.step;
  return {pos >> frac_bits,
          static_cast<uint32_t>((pos & ((int64_t{1} << frac_bits) - 1)) >> (frac_bits - weight_bits))};
}

}  // namespace cube4::golden
