// The pipeline's bit widths: one struct. The defaults are VolumePro's but
// for the compositing channels (see volumepro_precision()).
// Every golden unit function and every RTL unit takes its widths from here.
#pragma once

namespace cube4::golden {

struct Precision {
  int voxel_bits = 12;      // voxel and sample datapath (VolumePro: 12)
  int weight_bits = 8;      // interpolation weight fraction bits
  int dda_frac_bits = 20;   // fraction bits of the ray-offset DDA
  int gradient_bits = 8;    // signed gradient components, ±(2^(b-1)-1) (VolumePro: ±127)
  int gradient_shift = 5;   // full central difference >> shift = component
  int magnitude_bits = 8;   // |g| (VolumePro: 0..220)
  int nr_iterations = 3;    // Newton–Raphson square-root iterations
  int color_bits = 8;       // classification RGB (VolumePro: 8)
  int alpha_bits = 16;      // classification α, shaded colour and base-plane channels (VolumePro: 12)
  int gmlut_bits = 8;       // GmLUT output (VolumePro: 0..255)
  int map_face_res = 8;     // reflectance-map grid per cube face: 6*8*8 = 384 entries
  int map_bits = 16;        // reflectance-map entry, map_frac_bits of them fraction
  int map_frac_bits = 8;
  int coef_bits = 10;       // ke, kd, ks: unsigned, coef_frac_bits fraction
  int coef_frac_bits = 8;
  int eye_bits = 8;         // signed eye-vector components for the reflection vector
  int cut_bits = 32;        // signed cut-plane distance, saturated
  int acc_guard_bits = 8;   // compositing accumulator: alpha_bits + these fraction bits (VolumePro: 0)
};

// VolumePro's widths (VolumePro §3, Table 1): 12-bit α and colour channels
// and a compositor that rounds every product to them. Reachable as scene
// precision {"alpha_bits": 12, "acc_guard_bits": 0}; the defaults above
// differ from it only in those two, which keep translucent material stable
// (docs/fixed-point.md, "Compositing error").
constexpr Precision volumepro_precision() {
  Precision p;
  p.alpha_bits = 12;
  p.acc_guard_bits = 0;
  return p;
}

}  // namespace cube4::golden
