#include "systemc/host/register_map.hpp"

#include <cstdio>

namespace cube4::sysc::regmap {
namespace {

struct Named {
  uint64_t addr;
  const char* name;
};

// The register-space names used by docs/registers.md.
constexpr Named kNames[] = {
    {kCtrl, "CTRL"}, {kStatus, "STATUS"}, {kLastError, "LAST_ERROR"},
    {kErrorAddrLo, "ERROR_ADDR_LO"}, {kErrorAddrHi, "ERROR_ADDR_HI"},
    {kFrameCountLo, "FRAME_COUNT_LO"}, {kFrameCountHi, "FRAME_COUNT_HI"},
    {kCyclesLo, "CYCLES_LO"}, {kCyclesHi, "CYCLES_HI"},
    {kBaseWidth, "BASE_WIDTH"}, {kBaseHeight, "BASE_HEIGHT"},
    {kIdMagic, "ID_MAGIC"}, {kIdVersion, "ID_VERSION"}, {kIdPipelines, "ID_PIPELINES"},
    {kIdMaxDim, "ID_MAX_DIM"}, {kIdVoxelBits, "ID_VOXEL_BITS"},
    {kIdClassEntries, "ID_CLASS_ENTRIES"}, {kIdGmLutEntries, "ID_GMLUT_ENTRIES"},
    {kIdMapEntries, "ID_MAP_ENTRIES"}, {kIdBaseMax, "ID_BASE_MAX"},
    {kPrecision + 0x00, "P_VOXEL_BITS"}, {kPrecision + 0x04, "P_WEIGHT_BITS"},
    {kPrecision + 0x08, "P_DDA_FRAC_BITS"}, {kPrecision + 0x0C, "P_GRADIENT_BITS"},
    {kPrecision + 0x10, "P_GRADIENT_SHIFT"}, {kPrecision + 0x14, "P_MAGNITUDE_BITS"},
    {kPrecision + 0x18, "P_NR_ITERATIONS"}, {kPrecision + 0x1C, "P_COLOR_BITS"},
    {kPrecision + 0x20, "P_ALPHA_BITS"}, {kPrecision + 0x24, "P_GMLUT_BITS"},
    {kPrecision + 0x28, "P_MAP_FACE_RES"}, {kPrecision + 0x2C, "P_MAP_BITS"},
    {kPrecision + 0x30, "P_MAP_FRAC_BITS"}, {kPrecision + 0x34, "P_COEF_BITS"},
    {kPrecision + 0x38, "P_COEF_FRAC_BITS"}, {kPrecision + 0x3C, "P_EYE_BITS"},
    {kPrecision + 0x40, "P_CUT_BITS"}, {kPrecision + 0x44, "P_ACC_GUARD_BITS"},
    {kDimX, "DIM_X"}, {kDimY, "DIM_Y"}, {kDimZ, "DIM_Z"}, {kPerm, "PERM"}, {kFlip, "FLIP"},
    {kSupersampling, "SUPERSAMPLING"},
    {kXStartLo, "X_START_LO"}, {kXStartHi, "X_START_HI"}, {kXStepLo, "X_STEP_LO"},
    {kXStepHi, "X_STEP_HI"}, {kYStartLo, "Y_START_LO"}, {kYStartHi, "Y_START_HI"},
    {kYStepLo, "Y_STEP_LO"}, {kYStepHi, "Y_STEP_HI"},
    {kMode, "MODE"},
    {kCropSlab + 0x00, "CROP_X_LO"}, {kCropSlab + 0x04, "CROP_X_HI"},
    {kCropSlab + 0x08, "CROP_Y_LO"}, {kCropSlab + 0x0C, "CROP_Y_HI"},
    {kCropSlab + 0x10, "CROP_Z_LO"}, {kCropSlab + 0x14, "CROP_Z_HI"}, {kCropMask, "CROP_MASK"},
    {kCutA, "CUT_A"}, {kCutB, "CUT_B"}, {kCutC, "CUT_C"}, {kCutFlags, "CUT_FLAGS"},
    {kCutDminLo, "CUT_DMIN_LO"}, {kCutDminHi, "CUT_DMIN_HI"},
    {kCutDmaxLo, "CUT_DMAX_LO"}, {kCutDmaxHi, "CUT_DMAX_HI"},
    {kCutFalloffLo, "CUT_FALLOFF_LO"}, {kCutFalloffHi, "CUT_FALLOFF_HI"},
    {kCutInvFalloffLo, "CUT_INV_FALLOFF_LO"}, {kCutInvFalloffHi, "CUT_INV_FALLOFF_HI"},
    {kKe, "KE"}, {kKd, "KD"}, {kKs, "KS"},
    {kSpecularColor + 0x0, "SPEC_R"}, {kSpecularColor + 0x4, "SPEC_G"}, {kSpecularColor + 0x8, "SPEC_B"},
    {kEye + 0x0, "EYE_X"}, {kEye + 0x4, "EYE_Y"}, {kEye + 0x8, "EYE_Z"},
    {kVolDim + 0x0, "VOL_DIM_X"}, {kVolDim + 0x4, "VOL_DIM_Y"}, {kVolDim + 0x8, "VOL_DIM_Z"},
};

std::string hex(uint64_t a) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%llx", static_cast<unsigned long long>(a));
  return buf;
}

std::string indexed(const char* window, uint64_t index, const char* part) {
  return std::string(window) + "[" + std::to_string(index) + "]" + part;
}

}  // namespace

std::string describe_address(uint64_t a) {
  std::string name;
  switch (region_of(a)) {
    case Region::Registers:
      name = "unnamed register";
      for (const Named& n : kNames)
        if (n.addr == (a & ~uint64_t{3})) name = n.name;
      break;
    case Region::Class: {
      const uint64_t off = a - kClassBase;
      name = indexed("CLASS", off / 8, (off & 4) ? ".a" : ".rgb");
      break;
    }
    case Region::GmLut: name = indexed("GMLUT", (a - kGmLutBase) / 4, ""); break;
    case Region::Diffuse: name = indexed("DIFFUSE_MAP", (a - kDiffuseBase) / 4, ""); break;
    case Region::Specular: name = indexed("SPECULAR_MAP", (a - kSpecularBase) / 4, ""); break;
    case Region::Base: {
      const uint64_t off = a - kBaseBase;
      name = indexed("BASE_PLANE", off / 8, (off & 4) ? ".ba" : ".rg");
      break;
    }
    case Region::Volume: name = indexed("VOLUME", (a - kVolumeBase) / 2, " (voxel index)"); break;
    case Region::None: name = "unmapped"; break;
  }
  return name + " (" + hex(a) + ")";
}

uint32_t mode_word(const golden::Registers& r) {
  uint32_t m = static_cast<uint32_t>(r.blend) << kModeBlendShift;
  if (r.gradient) m |= kModeGradient;
  if (r.magnitude) m |= kModeMagnitude;
  if (r.shading) m |= kModeShading;
  if (r.specular) m |= kModeSpecular;
  if (r.gm_opacity) m |= kModeGmOpacity;
  if (r.gm_diffuse) m |= kModeGmDiffuse;
  if (r.gm_specular) m |= kModeGmSpecular;
  if (r.crop_enabled) m |= kModeCrop;
  if (r.cut_enabled) m |= kModeCut;
  return m;
}

}  // namespace cube4::sysc::regmap
