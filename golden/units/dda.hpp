// Weight generator: the integer DDA that gives every sample slice its ray
// offset, and the per-slice trilinear and ABC re-alignment weights. One set
// of weights serves a whole slice because all rays are parallel.
#pragma once
#include <cstdint>

#include "golden/fixed.hpp"

namespace cube4::golden {

// Ray offset of sample slice k: the start value advanced k times by the step.
// Integer addition, so golden and RTL agree for any run length.
constexpr int64_t dda_position(int64_t start, int64_t step, int k) { return start + step * k; }

struct SliceOffset {
  int32_t integer;  // whole voxels the rays have moved
  uint32_t weight;  // fraction, weight_bits wide (truncated)
};

constexpr SliceOffset dda_split(int64_t pos, int frac_bits, int weight_bits) {
  const int64_t frac = pos & max_unsigned(frac_bits);
  return {static_cast<int32_t>(pos >> frac_bits),
          static_cast<uint32_t>(frac >> (frac_bits - weight_bits))};
}

// Sample slice k of S per voxel slice lies between voxel slices k/S and k/S+1
// at weight floor((k mod S) * 2^W / S).
constexpr int32_t z_voxel_slice(int k, int supersampling) { return k / supersampling; }
constexpr uint32_t z_weight(int k, int supersampling, int weight_bits) {
  return static_cast<uint32_t>((static_cast<int64_t>(k % supersampling) << weight_bits) / supersampling);
}

// 12-neighbourhood ABC gradient: the point straight ahead of (or behind) a
// sample, in the neighbouring sample slice's own grid, lies at x + base +
// weight/2^W. `w_here` and `w_there` are the two slices' DDA weights.
struct Realign {
  int32_t base;     // -1 or 0
  uint32_t weight;  // 0 .. 2^W - 1
};

constexpr Realign realign(uint32_t w_here, uint32_t w_there, int weight_bits) {
  const int64_t d = static_cast<int64_t>(w_here) - static_cast<int64_t>(w_there);
  if (d >= 0) return {0, static_cast<uint32_t>(d)};
  return {-1, static_cast<uint32_t>(d + (int64_t{1} << weight_bits))};
}

}  // namespace cube4::golden
