// Random perspective frame registers for the RTL tests of the weight
// generator (test_persp_slice.cpp, test_persp_ray.cpp): as the host makes
// them, spacing from 1 at the first slice to at most 3 at the last, rays
// meeting at an eye anywhere in x and y, volumes up to 1023 x 1023 x 300.
#pragma once
#include <array>

#include "golden/registers.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace cube4::rtl {

// `min_dim` and `max_dim` bound the volume (the rings' tests take small ones).
inline golden::Registers random_perspective_registers(Random& rng, int frac_bits,
                                                      std::array<int, 3> max_dim = {1023, 1023, 300},
                                                      std::array<int, 3> min_dim = {1, 1, 1}, int max_s = 4) {
  golden::Registers r;
  r.perspective = true;
  r.p.dda_frac_bits = frac_bits;
  const int64_t one = int64_t{1} << frac_bits;
  for (size_t i = 0; i < 3; ++i) r.dim[i] = static_cast<int>(rng.range(min_dim[i], max_dim[i]));
  r.supersampling = static_cast<int>(rng.range(1, max_s));
  const int K = r.sample_slices();
  r.scale_start = one;
  r.scale_step = rng.range(0, K > 1 ? 2 * one / (K - 1) : 2 * one);
  const int64_t ex = rng.range(-2000, 3000), ey = rng.range(-2000, 3000);
  r.x_start = rng.range(0, one - 1);
  r.y_start = rng.range(0, one - 1);
  // x_step = (ray_offset - eye) * scale_step, give or take the host's rounding.
  r.x_step = (r.x_start - ex * one) / one * r.scale_step + rng.range(-1000, 1000);
  r.y_step = (r.y_start - ey * one) / one * r.scale_step + rng.range(-1000, 1000);
  return r;
}

}  // namespace cube4::rtl
