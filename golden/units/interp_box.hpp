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

// v[j][i] is voxel (x.first + i, y.first + j) of the slice (0 outside it).
constexpr uint32_t box_filter(const std::array<std::array<uint32_t, 4>, 4>& v, const BoxAxis& x, const BoxAxis& y,
                              uint64_t reciprocal, int recip_bits) {
  unsigned __int128 sum = 0;
  for (size_t j = 0; j < 4; ++j) {
    uint64_t row = 0;
    for (size_t i = 0; i < 4; ++i) row += static_cast<uint64_t>(x.overlap[i]) * v[j][i];
    sum += static_cast<unsigned __int128>(y.overlap[j]) * row;
  }
  const unsigned __int128 half = static_cast<unsigned __int128>(1) << (recip_bits - 1);
  return static_cast<uint32_t>((sum * reciprocal + half) >> recip_bits);
}

}  // namespace cube4::golden
