// Interpolation unit, perspective: Cube-4's box-filter stages (§3). A ray's
// sample on a voxel slice is the mean of the slice's nearest-voxel field
// over a box as wide as the rays are apart there (box_axis(): up to four
// voxels per axis), so that rays further apart than a voxel still see every
// voxel between them. The weighted sum is exact; one multiplication by the
// slice's reciprocal of the box's area normalises it, rounded half up. The
// z step between the two voxel slices is the trilinear unit's lerp().
#pragma once
#include <array>
#include <cstdint>

#include "golden/precision.hpp"
#include "golden/units/dda_perspective.hpp"

namespace cube4::golden {

// Fraction bits of the reciprocal: with extents below 4 (weight_bits of
// fraction) the area E^2 is below 2^(2W+4), so Q = V + 2W + 5 keeps the
// product's error below a quarter of the sample's LSB, and a constant field
// comes out exactly its value (docs/perspective.md derives it).
constexpr int box_recip_bits(const Precision& p) { return p.voxel_bits + 2 * p.weight_bits + 5; }

// round(2^Q / extent^2), once per slice.
constexpr uint64_t box_reciprocal(int64_t extent, int recip_bits) {
  const unsigned __int128 area = static_cast<unsigned __int128>(extent) * static_cast<unsigned __int128>(extent);
  return static_cast<uint64_t>(((static_cast<unsigned __int128>(1) << recip_bits) + area / 2) / area);
}

// The filter in two stages, as the rings compute it (docs/perspective.md,
// "The dataflow"): each voxel column's four cells weighed by the y
// overlaps (at the column's own pipeline), then the four column sums
// weighed by the x overlaps (at the ray's home), both box_taps(), then the
// mean (box_mean). Both sums are exact, so the order of the axes does not
// change the sample. T is the voxels' type: unsigned for the samples,
// signed for VolumePro's voxel z differences (V + 1 bits), which the same
// stages filter with the same weights for the voxel-difference z gradient
// (docs/fixed-point.md); the rounding is half up (towards +infinity)
// either way.
template <class T>
constexpr int64_t box_taps(const std::array<T, 4>& d, const BoxAxis& axis) {
  int64_t sum = 0;
  for (size_t i = 0; i < 4; ++i) sum += static_cast<int64_t>(axis.overlap[i]) * d[i];
  return sum;
}
// The weighted sum times the slice's reciprocal of the box's area, rounded.
template <class T>
constexpr T box_mean(int64_t sum, uint64_t reciprocal, int recip_bits) {
  const __int128 half = static_cast<__int128>(1) << (recip_bits - 1);
  return static_cast<T>((static_cast<__int128>(sum) * static_cast<__int128>(reciprocal) + half) >> recip_bits);
}

// The whole filter of a 4 x 4 window: v[j][i] is voxel (x.first + i,
// y.first + j) of the slice.
template <class T>
constexpr T box_filter_t(const std::array<std::array<T, 4>, 4>& v, const BoxAxis& x, const BoxAxis& y,
                         uint64_t reciprocal, int recip_bits) {
  std::array<int64_t, 4> col{};
  for (size_t i = 0; i < 4; ++i) col[i] = box_taps<T>({v[0][i], v[1][i], v[2][i], v[3][i]}, y);
  return box_mean<T>(box_taps(col, x), reciprocal, recip_bits);
}
constexpr uint32_t box_filter(const std::array<std::array<uint32_t, 4>, 4>& v, const BoxAxis& x, const BoxAxis& y,
                              uint64_t reciprocal, int recip_bits) {
  return box_filter_t<uint32_t>(v, x, y, reciprocal, recip_bits);
}

}  // namespace cube4::golden
