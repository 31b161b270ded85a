// Gradient unit: central differences of samples in x and y, and in z either
// Cube-4's 12-neighbourhood ABC method (ahead and behind slices bilinearly
// re-aligned to the current ray) or VolumePro's interpolated voxel
// differences; signed and saturating.
#pragma once
#include <array>
#include <cstdint>

#include "golden/fixed.hpp"
#include "golden/precision.hpp"
#include "golden/units/interp.hpp"

namespace cube4::golden {

struct Gradient {
  int32_t x = 0, y = 0, z = 0;
  friend constexpr bool operator==(const Gradient& a, const Gradient& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  }
};

// A full central difference (twice the gradient in sample units per voxel)
// scaled down by gradient_shift with rounding and saturated to ±(2^(b-1)-1).
constexpr int32_t gradient_component(int64_t full_difference, const Precision& p) {
  return static_cast<int32_t>(sat_signed(round_shift(full_difference, p.gradient_shift), p.gradient_bits));
}

// The ahead/behind sample straight in z: bilinear in the 2x2 samples around
// the re-aligned position (weights from realign()).
constexpr uint32_t abc_sample(uint32_t s00, uint32_t s10, uint32_t s01, uint32_t s11,
                              uint32_t wx, uint32_t wy, int weight_bits) {
  return static_cast<uint32_t>(bilerp(s00, s10, s01, s11, wx, wy, weight_bits));
}

// Sample slices are 1/S voxel apart in z, so the z difference is scaled by
// S to stay in per-voxel units like x and y.
constexpr Gradient gradient_12n(uint32_t left, uint32_t right, uint32_t up, uint32_t down,
                                uint32_t behind, uint32_t ahead, int supersampling,
                                const Precision& p) {
  return {gradient_component(static_cast<int64_t>(right) - left, p),
          gradient_component(static_cast<int64_t>(down) - up, p),
          gradient_component((static_cast<int64_t>(ahead) - behind) * supersampling, p)};
}

// How the z component is estimated (scene key "z_gradient"):
//  Abc: Cube-4's 12-neighbourhood, the sample slices just ahead and behind
//    re-aligned to the ray; they are 2/S voxels apart at supersampling S.
//  VoxelDifferences: VolumePro §3.2, central differences of voxels in z
//    (two voxel slices apart, like x and y) interpolated to the sample with
//    its own trilinear weights: the span stays 2 voxels at every S. The
//    hardware interpolates one more (signed) value per sample.
enum class ZGradient { Abc, VoxelDifferences };

// The voxel one slice above minus the one below: voxel_bits + 1 bits, signed.
constexpr int32_t voxel_z_difference(uint32_t above, uint32_t below) {
  return static_cast<int32_t>(above) - static_cast<int32_t>(below);
}

// d[i]: voxel_z_difference() at trilinear_t()'s corner i; the same lerps
// (and rounding) as the sample's value, so the result needs no saturation
// and keeps voxel_bits + 1 signed bits.
constexpr int64_t interpolated_z_difference(const std::array<int32_t, 8>& d, uint32_t wx, uint32_t wy, uint32_t wz,
                                            int weight_bits) {
  return trilinear_t(d, wx, wy, wz, weight_bits);
}

// The interpolated voxel difference already spans two voxels, as right -
// left does: no scaling by S.
constexpr Gradient gradient_voxel_z(uint32_t left, uint32_t right, uint32_t up, uint32_t down, int64_t z_difference,
                                    const Precision& p) {
  return {gradient_component(static_cast<int64_t>(right) - left, p),
          gradient_component(static_cast<int64_t>(down) - up, p), gradient_component(z_difference, p)};
}

// Perspective: the rays beside a sample are `spacing` voxels away, not one,
// so the x and y differences are scaled by the slice's reciprocal
// lateral_reciprocal(spacing) before the same rounding and saturation (the
// z difference is the parallel one: ahead and behind are realigned straight
// in z). The reciprocal has lateral_recip_bits of fraction: V + 2 keeps the
// scaled difference within half an LSB of exact.
constexpr int lateral_recip_bits(const Precision& p) { return p.voxel_bits + 2; }
constexpr int64_t lateral_reciprocal(int64_t spacing, int frac_bits, int recip_bits) {
  return static_cast<int64_t>(((static_cast<__int128>(1) << (recip_bits + frac_bits)) + spacing / 2) / spacing);
}
constexpr int64_t scale_lateral(int64_t full_difference, int64_t reciprocal, int recip_bits) {
  return round_shift(full_difference * reciprocal, recip_bits);
}
// `z_full`: the z difference spanning two voxels, (ahead - behind)·S for the
// 12-neighbourhood, the filtered voxel difference for VolumePro's.
constexpr Gradient gradient_perspective_z(uint32_t left, uint32_t right, uint32_t up, uint32_t down, int64_t z_full,
                                          int64_t reciprocal, const Precision& p) {
  const int q = lateral_recip_bits(p);
  return {gradient_component(scale_lateral(static_cast<int64_t>(right) - left, reciprocal, q), p),
          gradient_component(scale_lateral(static_cast<int64_t>(down) - up, reciprocal, q), p),
          gradient_component(z_full, p)};
}
constexpr Gradient gradient_perspective(uint32_t left, uint32_t right, uint32_t up, uint32_t down, uint32_t behind,
                                        uint32_t ahead, int supersampling, int64_t reciprocal, const Precision& p) {
  return gradient_perspective_z(left, right, up, down, (static_cast<int64_t>(ahead) - behind) * supersampling,
                                reciprocal, p);
}

}  // namespace cube4::golden
