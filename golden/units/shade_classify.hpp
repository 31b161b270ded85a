// Classification: the sample indexes the RGBA table; α optionally scaled by
// GmLUT(|g|) (VolumePro §3.4). All unit-normalised products happen at
// alpha_bits, narrower operands widened by bit replication.
#pragma once
#include <cstdint>
#include <vector>

#include "golden/fixed.hpp"
#include "golden/precision.hpp"

namespace cube4::golden {

struct ClassEntry {
  uint16_t r = 0, g = 0, b = 0;  // color_bits
  uint16_t a = 0;                // alpha_bits
};

// The table's address is {tag, sample} (bela §III: "look-up-tables
// designate unshaded RGBA values according to tag and voxel value"): with
// tag_bits = 0 it is the sample alone, as in VolumePro.
constexpr uint32_t class_address(uint32_t tag, uint32_t sample, const Precision& p) {
  return tag << p.voxel_bits | sample;
}

inline const ClassEntry& classify(const std::vector<ClassEntry>& lut, uint32_t sample) {
  return lut[sample];
}

inline const ClassEntry& classify(const std::vector<ClassEntry>& lut, uint32_t tag, uint32_t sample,
                                  const Precision& p) {
  return lut[class_address(tag, sample, p)];
}

// GmLUT value (gmlut_bits) widened to alpha_bits, the unit every product uses.
constexpr uint32_t gm_unit(uint32_t gmlut_value, const Precision& p) {
  return static_cast<uint32_t>(expand_bits(gmlut_value, p.gmlut_bits, p.alpha_bits));
}

constexpr uint32_t modulate_alpha(uint32_t alpha, uint32_t gm_alpha_unit, const Precision& p) {
  return static_cast<uint32_t>(mul_frac(alpha, gm_alpha_unit, p.alpha_bits));
}

}  // namespace cube4::golden
