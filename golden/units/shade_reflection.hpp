// Reflection vector R = 2(N·E)N - (N·N)E from the unnormalised gradient N and
// the eye vector E: the direction of the mirror reflection without a square
// root or divider. Only its direction matters (it indexes a cube map), so it
// is brought back to gradient width by a common right shift.
#pragma once
#include <array>
#include <cstdint>

#include "golden/fixed.hpp"
#include "golden/precision.hpp"
#include "golden/units/gradient.hpp"

namespace cube4::golden {

using Eye = std::array<int32_t, 3>;  // eye_bits signed, towards the viewer

// Smallest common shift that fits every |component| into ±(2^(bits-1)-1);
// magnitudes are shifted, signs kept, so the direction is kept up to rounding.
inline Gradient reduce_vector(int64_t x, int64_t y, int64_t z, int bits) {
  auto mag = [](int64_t v) { return v < 0 ? -v : v; };
  int64_t m = mag(x);
  if (mag(y) > m) m = mag(y);
  if (mag(z) > m) m = mag(z);
  // The smallest such shift leaves m with bits-1 significant bits.
  const int s = m > max_signed(bits) ? bit_length(static_cast<uint64_t>(m)) - (bits - 1) : 0;
  auto shrink = [&](int64_t v) { return static_cast<int32_t>(v < 0 ? -((-v) >> s) : v >> s); };
  return {shrink(x), shrink(y), shrink(z)};
}

inline Gradient reflection_vector(const Gradient& n, const Eye& e, const Precision& p) {
  const int64_t ne = int64_t{n.x} * e[0] + int64_t{n.y} * e[1] + int64_t{n.z} * e[2];
  const int64_t nn = int64_t{n.x} * n.x + int64_t{n.y} * n.y + int64_t{n.z} * n.z;
  return reduce_vector(2 * ne * n.x - nn * e[0], 2 * ne * n.y - nn * e[1], 2 * ne * n.z - nn * e[2],
                       p.gradient_bits);
}

}  // namespace cube4::golden
