// Cut plane (VolumePro §4.3): samples whose plane distance d = A·X + B·Y + C·Z
// lies in [Dmin, Dmax] keep their α; within `falloff` outside it α ramps
// linearly to zero; beyond, α is zero. "Keep outside" inverts the factor.
// X, Y, Z are sample positions in permuted voxel units with weight_bits of
// fraction; A, B, C, D and the falloff are integers in the same scale.
#pragma once
#include <cstdint>

#include "golden/fixed.hpp"
#include "golden/precision.hpp"

namespace cube4::golden {

struct CutRegs {
  int32_t a = 0, b = 0, c = 0;          // plane normal, signed
  int64_t dmin = 0, dmax = 0;           // distance units of d
  int64_t falloff = 0;                  // 0: hard cut
  uint64_t inv_falloff = 0;             // round((2^alpha_bits - 1) * 2^24 / falloff), host computed
  bool keep_inside = true;
};

constexpr int kCutInvShift = 24;
// The hardware holds the normal in signed registers of this width (the RTL's
// CutCoefBits); golden computes with any int32.
constexpr int kCutCoefBits = 12;

constexpr int64_t cut_distance(const CutRegs& r, int64_t x, int64_t y, int64_t z, const Precision& p) {
  return sat_signed(int64_t{r.a} * x + int64_t{r.b} * y + int64_t{r.c} * z, p.cut_bits);
}

// Factor at alpha_bits unit (max = keep α unchanged).
constexpr uint32_t cut_factor(int64_t d, const CutRegs& r, const Precision& p) {
  const int64_t one = max_unsigned(p.alpha_bits);
  const int64_t outside = d < r.dmin ? r.dmin - d : (d > r.dmax ? d - r.dmax : 0);
  int64_t inside_factor = 0;
  if (outside == 0) {
    inside_factor = one;
  } else if (outside >= r.falloff) {
    inside_factor = 0;
  } else {
    // One minus the distance into the transition, as a fraction of its width,
    // rounded half up. Exact in 128 bits: with the falloff and its reciprocal
    // both at their register limits the product passes 2^63 (the RTL's is exact).
    const unsigned __int128 ramp =
        (static_cast<unsigned __int128>(r.falloff - outside) * r.inv_falloff + (uint64_t{1} << (kCutInvShift - 1))) >>
        kCutInvShift;
    inside_factor = ramp > static_cast<unsigned __int128>(one) ? one : static_cast<int64_t>(ramp);
  }
  return static_cast<uint32_t>(r.keep_inside ? inside_factor : one - inside_factor);
}

}  // namespace cube4::golden

namespace cube4::golden {

constexpr uint32_t cut_alpha(uint32_t alpha, uint32_t factor, const Precision& p) {
  return static_cast<uint32_t>(mul_frac(alpha, factor, p.alpha_bits));
}

}  // namespace cube4::golden
