// The pipeline's bit widths: one struct. The defaults are VolumePro's but
// for the compositing channels (see volumepro_precision()).
// Every golden unit function and every RTL unit takes its widths from here.
#pragma once
#include <stdexcept>

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
  int tag_bits = 0;         // voxel tag (bela §III): 0 = no tags, nothing of them simulated
};

// Every consumer of the widths as a set (the scene's "precision" keys, the
// host interface's precision registers, the host's and the system's
// comparisons) walks this table, so a new width is one line here. The order
// is the precision registers' (docs/registers.md): append, never reorder.
struct PrecisionField {
  const char* key;             // scene key "precision.<key>"
  int Precision::*member;
  int lo, hi;                  // the widest range a scene may ask for; scene_io narrows the dependent ones
  const char* register_name;   // host interface precision register
  const char* rtl_parameter;   // the RTL units' parameter; nullptr: no RTL unit has the width
};

inline constexpr PrecisionField kPrecisionFields[] = {
    {"voxel_bits", &Precision::voxel_bits, 8, 16, "P_VOXEL_BITS", "VoxelBits"},
    {"weight_bits", &Precision::weight_bits, 2, 14, "P_WEIGHT_BITS", "WeightBits"},
    // The weight generator's fraction (rtl/cube4_dda.sv; the perspective units' W).
    {"dda_frac_bits", &Precision::dda_frac_bits, 2, 30, "P_DDA_FRAC_BITS", "FracBits"},
    {"gradient_bits", &Precision::gradient_bits, 4, 16, "P_GRADIENT_BITS", "GradientBits"},
    {"gradient_shift", &Precision::gradient_shift, 0, 16, "P_GRADIENT_SHIFT", "GradientShift"},
    {"magnitude_bits", &Precision::magnitude_bits, 4, 16, "P_MAGNITUDE_BITS", "MagnitudeBits"},
    {"nr_iterations", &Precision::nr_iterations, 0, 8, "P_NR_ITERATIONS", "NrIterations"},
    {"color_bits", &Precision::color_bits, 4, 8, "P_COLOR_BITS", "ColorBits"},
    {"alpha_bits", &Precision::alpha_bits, 8, 16, "P_ALPHA_BITS", "AlphaBits"},
    {"gmlut_bits", &Precision::gmlut_bits, 4, 16, "P_GMLUT_BITS", "GmlutBits"},
    {"map_face_res", &Precision::map_face_res, 2, 64, "P_MAP_FACE_RES", "MapFaceRes"},
    {"map_bits", &Precision::map_bits, 8, 32, "P_MAP_BITS", "MapBits"},
    {"map_frac_bits", &Precision::map_frac_bits, 0, 31, "P_MAP_FRAC_BITS", "MapFracBits"},
    {"coef_bits", &Precision::coef_bits, 4, 16, "P_COEF_BITS", "CoefBits"},
    {"coef_frac_bits", &Precision::coef_frac_bits, 0, 15, "P_COEF_FRAC_BITS", "CoefFracBits"},
    {"eye_bits", &Precision::eye_bits, 4, 16, "P_EYE_BITS", "EyeBits"},
    {"cut_bits", &Precision::cut_bits, 16, 40, "P_CUT_BITS", "CutBits"},
    {"acc_guard_bits", &Precision::acc_guard_bits, 0, 8, "P_ACC_GUARD_BITS", "AccGuardBits"},
    // bela's four-bit tags fit; voxel_bits + tag_bits <= 16 (scene_io) bounds the classification table.
    {"tag_bits", &Precision::tag_bits, 0, 8, "P_TAG_BITS", "VoxelTagBits"},
};

inline constexpr int kPrecisionFieldCount = sizeof kPrecisionFields / sizeof kPrecisionFields[0];
static_assert(sizeof(Precision) == kPrecisionFieldCount * sizeof(int),
              "a Precision member without its line in kPrecisionFields");

// The table's entry of a member (every member has one).
inline const PrecisionField& precision_field(int Precision::*member) {
  for (const PrecisionField& f : kPrecisionFields)
    if (f.member == member) return f;
  throw std::logic_error("golden::kPrecisionFields lacks a Precision member");
}

// The first field in which a and b differ, or nullptr; only the widths
// some RTL unit is built with if rtl_only.
inline const PrecisionField* first_difference(const Precision& a, const Precision& b, bool rtl_only = false) {
  for (const PrecisionField& f : kPrecisionFields)
    if ((!rtl_only || f.rtl_parameter) && a.*f.member != b.*f.member) return &f;
  return nullptr;
}

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
