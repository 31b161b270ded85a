// Interpolation unit: linear interpolation in x, then y, then z (Cube-4's
// SFG order), each step rounded back to the sample width.
#pragma once
#include <array>
#include <cstdint>

#include "golden/fixed.hpp"

namespace cube4::golden {

// a + (b - a) * w / 2^W, rounded half up; w in [0, 2^W] (both ends return a
// voxel exactly). The result lies between a and b, so it never needs
// saturation and keeps the width of its inputs. T may be any signed type
// that holds (b - a) * w + 2^(W-1): int32_t does for every allowed width
// (16-bit voxels, 14-bit weights), which lets whole beams vectorise.
template <class T>
constexpr T lerp_t(T a, T b, T w, int weight_bits) {
  return a + (((b - a) * w + (T{1} << (weight_bits - 1))) >> weight_bits);
}

constexpr int64_t lerp(int64_t a, int64_t b, int64_t w, int weight_bits) {
  return lerp_t<int64_t>(a, b, w, weight_bits);
}

constexpr int64_t bilerp(int64_t v00, int64_t v10, int64_t v01, int64_t v11,
                         int64_t wx, int64_t wy, int weight_bits) {
  return lerp(lerp(v00, v10, wx, weight_bits), lerp(v01, v11, wx, weight_bits), wy, weight_bits);
}

// v[i] is the value at (x + (i & 1), y + (i >> 1 & 1), z + (i >> 2)): voxels,
// or (signed) voxel differences for VolumePro's z gradient.
template <class T>
constexpr int64_t trilinear_t(const std::array<T, 8>& v, uint32_t wx, uint32_t wy, uint32_t wz, int weight_bits) {
  const int64_t front = bilerp(v[0], v[1], v[2], v[3], wx, wy, weight_bits);
  const int64_t back = bilerp(v[4], v[5], v[6], v[7], wx, wy, weight_bits);
  return lerp(front, back, wz, weight_bits);
}

constexpr uint32_t trilinear(const std::array<uint32_t, 8>& v, uint32_t wx, uint32_t wy,
                             uint32_t wz, int weight_bits) {
  return static_cast<uint32_t>(trilinear_t(v, wx, wy, wz, weight_bits));
}

// Voxel tags (bela §III) are labels, not quantities: a sample is never
// given a blend of tags but the tag of one of its eight voxels, the nearest.
// Per axis the upper voxel is nearer when the weight is at least half
// (w >= 2^(W-1)); at exactly half (a tie) the upper voxel wins, i.e. the
// one further along the permuted axis. In hardware: the weight's top bit.
constexpr int upper_corner(uint32_t w, int weight_bits) { return w >= (1u << (weight_bits - 1)) ? 1 : 0; }

// Index into trilinear()'s v[8] of the voxel nearest to the sample.
constexpr int nearest_corner(uint32_t wx, uint32_t wy, uint32_t wz, int weight_bits) {
  return upper_corner(wx, weight_bits) | upper_corner(wy, weight_bits) << 1 | upper_corner(wz, weight_bits) << 2;
}

// The sample's tag: that of its nearest voxel; t[i] beside v[i].
constexpr uint32_t sample_tag(const std::array<uint32_t, 8>& t, uint32_t wx, uint32_t wy, uint32_t wz,
                              int weight_bits) {
  return t[static_cast<size_t>(nearest_corner(wx, wy, wz, weight_bits))];
}

}  // namespace cube4::golden
