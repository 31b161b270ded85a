// Fixed-point primitives shared by every golden unit function. Each states
// its rounding; none wraps around.
#pragma once
#include <cstdint>
#include <cstdlib>

namespace cube4::golden {

constexpr int64_t max_unsigned(int bits) { return (int64_t{1} << bits) - 1; }
// Signed values are symmetric, ±(2^(bits-1) - 1): VolumePro's gradients are
// ±127, never -128, so negation cannot overflow.
constexpr int64_t max_signed(int bits) { return (int64_t{1} << (bits - 1)) - 1; }

constexpr int64_t sat_unsigned(int64_t v, int bits) {
  return v < 0 ? 0 : (v > max_unsigned(bits) ? max_unsigned(bits) : v);
}
constexpr int64_t sat_signed(int64_t v, int bits) {
  return v > max_signed(bits) ? max_signed(bits) : (v < -max_signed(bits) ? -max_signed(bits) : v);
}

// Round half up, then arithmetic shift: floor((v + 2^(s-1)) / 2^s).
constexpr int64_t round_shift(int64_t v, int s) {
  return s == 0 ? v : (v + (int64_t{1} << (s - 1))) >> s;
}

// Widens a unit-normalised value (max = 1.0) by repeating its bit pattern, so
// that 0 -> 0 and max -> max exactly (8 -> 12 bits: v<<4 | v>>4).
constexpr int64_t expand_bits(int64_t v, int from, int to) {
  if (to <= from) return v >> (from - to);
  if (to <= 2 * from) return (v << (to - from)) | (v >> (2 * from - to));
  int64_t r = 0;
  int filled = 0;
  while (filled < to) {
    int take = to - filled < from ? to - filled : from;
    r = (r << take) | (v >> (from - take));
    filled += take;
  }
  return r;
}

// x times a unit-normalised fraction f (f = 2^n - 1 means 1.0). The fraction
// is first mapped onto [0, 2^n] by f + (f >> (n-1)), so that f = max returns x
// exactly and f = 0 returns 0; then round half up. Monotonic in x and f, and
// never larger than x: products of opacities cannot exceed full opacity.
constexpr int64_t mul_frac(int64_t x, int64_t f, int n) {
  return round_shift(x * (f + (f >> (n - 1))), n);
}

constexpr int bit_length(uint64_t v) { return v == 0 ? 0 : 64 - __builtin_clzll(v); }

}  // namespace cube4::golden
