// Gradient magnitude: sum of squares, then a fixed number of integer
// Newton–Raphson steps for the square root (VolumePro §3.3).
#pragma once
#include <cstdint>

#include "golden/fixed.hpp"
#include "golden/precision.hpp"
#include "golden/units/gradient.hpp"

namespace cube4::golden {

// Starts at 2^ceil(bits(q)/2) >= sqrt(q), so the iteration descends; each
// step is x <- (x + floor(q / x)) >> 1. After enough steps it settles on
// floor(sqrt(q)) (or alternates with floor+1 when q = (r+1)^2 - 1).
constexpr uint32_t newton_sqrt(uint64_t q, int iterations) {
  if (q == 0) return 0;
  uint64_t x = uint64_t{1} << ((bit_length(q) + 1) / 2);
  for (int i = 0; i < iterations; ++i) x = (x + q / x) >> 1;
  return static_cast<uint32_t>(x);
}

constexpr uint32_t gradient_magnitude(const Gradient& g, const Precision& p) {
  const uint64_t q = static_cast<uint64_t>(int64_t{g.x} * g.x + int64_t{g.y} * g.y + int64_t{g.z} * g.z);
  return static_cast<uint32_t>(sat_unsigned(newton_sqrt(q, p.nr_iterations), p.magnitude_bits));
}

}  // namespace cube4::golden
