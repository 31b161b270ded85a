#include "systemc/host/register_file.hpp"

#include <stdexcept>
#include <string>

#include "golden/fixed.hpp"

namespace cube4::sysc {
namespace rm = regmap;
using rm::ErrorCode;

namespace {

// The precision block's order (docs/registers.md).
constexpr int golden::Precision::*kPrecisionFields[rm::kPrecisionFields] = {
    &golden::Precision::voxel_bits,     &golden::Precision::weight_bits,
    &golden::Precision::dda_frac_bits,  &golden::Precision::gradient_bits,
    &golden::Precision::gradient_shift, &golden::Precision::magnitude_bits,
    &golden::Precision::nr_iterations,  &golden::Precision::color_bits,
    &golden::Precision::alpha_bits,     &golden::Precision::gmlut_bits,
    &golden::Precision::map_face_res,   &golden::Precision::map_bits,
    &golden::Precision::map_frac_bits,  &golden::Precision::coef_bits,
    &golden::Precision::coef_frac_bits, &golden::Precision::eye_bits,
    &golden::Precision::cut_bits,       &golden::Precision::acc_guard_bits,
};

bool fits_unsigned(uint32_t v, int bits) { return bits >= 32 || v < (uint32_t{1} << bits); }

bool fits_symmetric(uint32_t v, int bits) {
  const int64_t s = static_cast<int32_t>(v);
  return s <= golden::max_signed(bits) && s >= -golden::max_signed(bits);
}

bool in_range(uint32_t v, int lo, int hi) {
  return v >= static_cast<uint32_t>(lo) && v <= static_cast<uint32_t>(hi);
}

// 64-bit registers are two words; each write replaces its half.
template <class T>
void set_half(T& field, bool high, uint32_t w) {
  uint64_t u = static_cast<uint64_t>(field);
  u = high ? (u & 0xFFFF'FFFFull) | (uint64_t{w} << 32) : (u & ~0xFFFF'FFFFull) | w;
  field = static_cast<T>(u);
}

template <class T>
uint32_t get_half(T field, bool high) {
  const uint64_t u = static_cast<uint64_t>(field);
  return static_cast<uint32_t>(high ? u >> 32 : u);
}

size_t class_entries(const golden::Precision& p) { return size_t{1} << p.voxel_bits; }
size_t gm_entries(const golden::Precision& p) { return size_t{1} << p.magnitude_bits; }
size_t map_entries(const golden::Precision& p) { return size_t{6} * p.map_face_res * p.map_face_res; }

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("host interface: " + what);
}

}  // namespace

void check_hardware_params(const HardwareParams& hw) {
  auto in_range = [](const std::string& name, int v, int lo, int hi) {
    require(v >= lo && v <= hi, name + " = " + std::to_string(v) + " is out of range " + std::to_string(lo) + ".." +
                                    std::to_string(hi));
  };
  const golden::Precision& p = hw.precision;
  in_range("pipelines", hw.pipelines, 1, rm::kMaxPipelines);
  in_range("max_dim", hw.max_dim, 2, rm::kMaxDimLimit);
  // The windows and packings of docs/registers.md bound these widths.
  in_range("precision.voxel_bits", p.voxel_bits, 1, 16);
  in_range("precision.magnitude_bits", p.magnitude_bits, 1, 16);
  in_range("precision.color_bits", p.color_bits, 1, 8);
  in_range("precision.alpha_bits", p.alpha_bits, 1, 16);
  in_range("precision.acc_guard_bits", p.acc_guard_bits, 0, p.alpha_bits);
  in_range("precision.gmlut_bits", p.gmlut_bits, 1, 16);
  in_range("precision.map_face_res", p.map_face_res, 2, 64);
  in_range("precision.map_bits", p.map_bits, 1, 32);
  in_range("precision.coef_bits", p.coef_bits, 1, 32);
  in_range("precision.eye_bits", p.eye_bits, 2, 32);
}

RegisterFile::RegisterFile(const HardwareParams& hw) : hw_(hw) {
  check_hardware_params(hw);
  reset();
}

void RegisterFile::reset() {
  regs_ = golden::Registers{};
  regs_.p = hw_.precision;
  regs_.classification.assign(class_entries(hw_.precision), golden::ClassEntry{});
  regs_.gm_lut.assign(gm_entries(hw_.precision), 0);
  regs_.diffuse_map.assign(map_entries(hw_.precision), 0);
  regs_.specular_map.assign(map_entries(hw_.precision), 0);
  vol_dim_ = {0, 0, 0};
}

uint64_t RegisterFile::table_bytes(rm::Region r) const {
  const golden::Precision& p = hw_.precision;
  switch (r) {
    case rm::Region::Class: return 8 * class_entries(p);
    case rm::Region::GmLut: return 4 * gm_entries(p);
    case rm::Region::Diffuse:
    case rm::Region::Specular: return 4 * map_entries(p);
    default: return 0;
  }
}

ErrorCode RegisterFile::check_write(uint64_t addr, uint32_t value) const {
  const rm::Region r = rm::region_of(addr);
  if (r == rm::Region::Registers) return check_register(addr, value);
  if (addr % 4 != 0) return ErrorCode::Alignment;
  return check_table(r, addr, value);
}

ErrorCode RegisterFile::check_table(rm::Region r, uint64_t addr, uint32_t v) const {
  const golden::Precision& p = hw_.precision;
  switch (r) {
    case rm::Region::Class:
      if (addr - rm::kClassBase >= table_bytes(r)) return ErrorCode::Unmapped;
      if (addr & 4) return fits_unsigned(v, p.alpha_bits) ? ErrorCode::None : ErrorCode::FieldRange;
      for (int c = 0; c < 3; ++c)
        if (!fits_unsigned(v >> (8 * c) & 0xFF, p.color_bits)) return ErrorCode::FieldRange;
      return (v >> 24) == 0 ? ErrorCode::None : ErrorCode::FieldRange;
    case rm::Region::GmLut:
      if (addr - rm::kGmLutBase >= table_bytes(r)) return ErrorCode::Unmapped;
      return fits_unsigned(v, p.gmlut_bits) ? ErrorCode::None : ErrorCode::FieldRange;
    case rm::Region::Diffuse:
    case rm::Region::Specular: {
      const uint64_t base = r == rm::Region::Diffuse ? rm::kDiffuseBase : rm::kSpecularBase;
      if (addr - base >= table_bytes(r)) return ErrorCode::Unmapped;
      return fits_unsigned(v, p.map_bits) ? ErrorCode::None : ErrorCode::FieldRange;
    }
    default: return ErrorCode::Unmapped;
  }
}

ErrorCode RegisterFile::check_register(uint64_t a, uint32_t v) const {
  const golden::Precision& p = hw_.precision;
  auto range = [](bool ok) { return ok ? ErrorCode::None : ErrorCode::FieldRange; };
  uint32_t dummy = 0;
  if (!read_register(a, dummy)) return ErrorCode::Unmapped;
  if (a >= rm::kIdMagic && a < rm::kDimX) return ErrorCode::ReadOnly;  // identification, precision
  switch (a) {
    case rm::kDimX: case rm::kDimY: case rm::kDimZ:
    case rm::kVolDim: case rm::kVolDim + 4: case rm::kVolDim + 8:
      return range(in_range(v, 1, hw_.max_dim));
    case rm::kPerm: {
      if (v >> 6) return ErrorCode::FieldRange;
      uint32_t seen = 0;
      for (int i = 0; i < 3; ++i) seen |= 1u << (v >> (2 * i) & 3);
      return range(seen == 7);  // each axis exactly once
    }
    case rm::kFlip: return range(v <= 7);
    case rm::kSupersampling: return range(in_range(v, 1, rm::kMaxSupersampling));
    case rm::kMode:
      return range((v & ~rm::kModeMask) == 0 && (v & rm::kModeBlendMask) >> rm::kModeBlendShift <= 2);
    case rm::kCropMask: return range(v <= 0xFF);
    case rm::kCutFlags: return range((v & ~rm::kCutKeepInside) == 0);
    case rm::kKe: case rm::kKd: case rm::kKs: return range(fits_unsigned(v, p.coef_bits));
    case rm::kSpecularColor: case rm::kSpecularColor + 4: case rm::kSpecularColor + 8:
      return range(fits_unsigned(v, p.alpha_bits));
    case rm::kEye: case rm::kEye + 4: case rm::kEye + 8: return range(fits_symmetric(v, p.eye_bits));
    default: return ErrorCode::None;  // full-width fields: every value is one
  }
}

void RegisterFile::write(uint64_t addr, uint32_t v) {
  switch (rm::region_of(addr)) {
    case rm::Region::Registers: write_register(addr, v); return;
    case rm::Region::Class: {
      golden::ClassEntry& e = regs_.classification[(addr - rm::kClassBase) / 8];
      if (addr & 4) {
        e.a = static_cast<uint16_t>(v);
      } else {
        e.r = static_cast<uint16_t>(v & 0xFF);
        e.g = static_cast<uint16_t>(v >> 8 & 0xFF);
        e.b = static_cast<uint16_t>(v >> 16 & 0xFF);
      }
      return;
    }
    case rm::Region::GmLut: regs_.gm_lut[(addr - rm::kGmLutBase) / 4] = static_cast<uint16_t>(v); return;
    case rm::Region::Diffuse: regs_.diffuse_map[(addr - rm::kDiffuseBase) / 4] = v; return;
    case rm::Region::Specular: regs_.specular_map[(addr - rm::kSpecularBase) / 4] = v; return;
    default: return;
  }
}

void RegisterFile::write_register(uint64_t a, uint32_t v) {
  golden::Registers& r = regs_;
  const auto i32 = static_cast<int32_t>(v);
  switch (a) {
    case rm::kDimX: case rm::kDimY: case rm::kDimZ: r.dim[(a - rm::kDimX) / 4] = i32; return;
    case rm::kPerm: for (int i = 0; i < 3; ++i) r.perm[i] = static_cast<int>(v >> (2 * i) & 3); return;
    case rm::kFlip: for (int i = 0; i < 3; ++i) r.flip[i] = (v >> i & 1) != 0; return;
    case rm::kSupersampling: r.supersampling = i32; return;
    case rm::kXStartLo: case rm::kXStartHi: set_half(r.x_start, a & 4, v); return;
    case rm::kXStepLo: case rm::kXStepHi: set_half(r.x_step, a & 4, v); return;
    case rm::kYStartLo: case rm::kYStartHi: set_half(r.y_start, a & 4, v); return;
    case rm::kYStepLo: case rm::kYStepHi: set_half(r.y_step, a & 4, v); return;
    case rm::kMode:
      r.gradient = v & rm::kModeGradient;
      r.magnitude = v & rm::kModeMagnitude;
      r.shading = v & rm::kModeShading;
      r.specular = v & rm::kModeSpecular;
      r.gm_opacity = v & rm::kModeGmOpacity;
      r.gm_diffuse = v & rm::kModeGmDiffuse;
      r.gm_specular = v & rm::kModeGmSpecular;
      r.blend = static_cast<golden::BlendMode>((v & rm::kModeBlendMask) >> rm::kModeBlendShift);
      r.crop_enabled = v & rm::kModeCrop;
      r.cut_enabled = v & rm::kModeCut;
      return;
    case rm::kCropMask: r.crop.mask = static_cast<uint8_t>(v); return;
    case rm::kCutA: r.cut.a = i32; return;
    case rm::kCutB: r.cut.b = i32; return;
    case rm::kCutC: r.cut.c = i32; return;
    case rm::kCutFlags: r.cut.keep_inside = v & rm::kCutKeepInside; return;
    case rm::kCutDminLo: case rm::kCutDminHi: set_half(r.cut.dmin, a & 4, v); return;
    case rm::kCutDmaxLo: case rm::kCutDmaxHi: set_half(r.cut.dmax, a & 4, v); return;
    case rm::kCutFalloffLo: case rm::kCutFalloffHi: set_half(r.cut.falloff, a & 4, v); return;
    case rm::kCutInvFalloffLo: case rm::kCutInvFalloffHi: set_half(r.cut.inv_falloff, a & 4, v); return;
    case rm::kKe: r.coefs.ke = v; return;
    case rm::kKd: r.coefs.kd = v; return;
    case rm::kKs: r.coefs.ks = v; return;
    default: break;
  }
  if (a >= rm::kCropSlab && a < rm::kCropMask) {
    const uint64_t i = (a - rm::kCropSlab) / 4;
    r.crop.slab[i / 2][i % 2] = i32;
  } else if (a >= rm::kSpecularColor && a < rm::kEye) {
    r.coefs.specular[(a - rm::kSpecularColor) / 4] = v;
  } else if (a >= rm::kEye && a < rm::kEye + 12) {
    r.eye[(a - rm::kEye) / 4] = i32;
  } else if (a >= rm::kVolDim && a < rm::kVolDim + 12) {
    vol_dim_[(a - rm::kVolDim) / 4] = i32;
  }
}


// False where register space has no register (or only the control block's).
bool RegisterFile::read_register(uint64_t a, uint32_t& v) const {
  const golden::Registers& r = regs_;
  const golden::Precision& p = hw_.precision;
  const auto u = [](int32_t x) { return static_cast<uint32_t>(x); };
  switch (a) {
    case rm::kIdMagic: v = rm::kMagic; return true;
    case rm::kIdVersion: v = rm::kVersion; return true;
    case rm::kIdPipelines: v = u(hw_.pipelines); return true;
    case rm::kIdMaxDim: v = u(hw_.max_dim); return true;
    case rm::kIdVoxelBits: v = u(p.voxel_bits); return true;
    case rm::kIdClassEntries: v = static_cast<uint32_t>(class_entries(p)); return true;
    case rm::kIdGmLutEntries: v = static_cast<uint32_t>(gm_entries(p)); return true;
    case rm::kIdMapEntries: v = static_cast<uint32_t>(map_entries(p)); return true;
    case rm::kIdBaseMax: v = u(2 * hw_.max_dim); return true;
    case rm::kDimX: case rm::kDimY: case rm::kDimZ: v = u(r.dim[(a - rm::kDimX) / 4]); return true;
    case rm::kPerm: v = u(r.perm[0] | r.perm[1] << 2 | r.perm[2] << 4); return true;
    case rm::kFlip: v = u(r.flip[0] | r.flip[1] << 1 | r.flip[2] << 2); return true;
    case rm::kSupersampling: v = u(r.supersampling); return true;
    case rm::kXStartLo: case rm::kXStartHi: v = get_half(r.x_start, a & 4); return true;
    case rm::kXStepLo: case rm::kXStepHi: v = get_half(r.x_step, a & 4); return true;
    case rm::kYStartLo: case rm::kYStartHi: v = get_half(r.y_start, a & 4); return true;
    case rm::kYStepLo: case rm::kYStepHi: v = get_half(r.y_step, a & 4); return true;
    case rm::kMode: v = rm::mode_word(regs_); return true;
    case rm::kCropMask: v = r.crop.mask; return true;
    case rm::kCutA: v = u(r.cut.a); return true;
    case rm::kCutB: v = u(r.cut.b); return true;
    case rm::kCutC: v = u(r.cut.c); return true;
    case rm::kCutFlags: v = r.cut.keep_inside ? rm::kCutKeepInside : 0; return true;
    case rm::kCutDminLo: case rm::kCutDminHi: v = get_half(r.cut.dmin, a & 4); return true;
    case rm::kCutDmaxLo: case rm::kCutDmaxHi: v = get_half(r.cut.dmax, a & 4); return true;
    case rm::kCutFalloffLo: case rm::kCutFalloffHi: v = get_half(r.cut.falloff, a & 4); return true;
    case rm::kCutInvFalloffLo: case rm::kCutInvFalloffHi: v = get_half(r.cut.inv_falloff, a & 4); return true;
    case rm::kKe: v = r.coefs.ke; return true;
    case rm::kKd: v = r.coefs.kd; return true;
    case rm::kKs: v = r.coefs.ks; return true;
    default: break;
  }
  if (a >= rm::kPrecision && a < rm::kPrecision + 4 * rm::kPrecisionFields) {
    v = u(p.*kPrecisionFields[(a - rm::kPrecision) / 4]);
  } else if (a >= rm::kCropSlab && a < rm::kCropMask) {
    const uint64_t i = (a - rm::kCropSlab) / 4;
    v = u(r.crop.slab[i / 2][i % 2]);
  } else if (a >= rm::kSpecularColor && a < rm::kEye) {
    v = r.coefs.specular[(a - rm::kSpecularColor) / 4];
  } else if (a >= rm::kEye && a < rm::kEye + 12) {
    v = u(r.eye[(a - rm::kEye) / 4]);
  } else if (a >= rm::kVolDim && a < rm::kVolDim + 12) {
    v = u(vol_dim_[(a - rm::kVolDim) / 4]);
  } else {
    return false;
  }
  return true;
}

ErrorCode RegisterFile::read(uint64_t addr, uint32_t& v) const {
  const rm::Region r = rm::region_of(addr);
  if (r == rm::Region::Registers) return read_register(addr, v) ? ErrorCode::None : ErrorCode::Unmapped;
  switch (r) {
    case rm::Region::Class: {
      const uint64_t off = addr - rm::kClassBase;
      if (off >= table_bytes(r)) return ErrorCode::Unmapped;
      const golden::ClassEntry& e = regs_.classification[off / 8];
      v = (off & 4) ? e.a : (uint32_t{e.r} | uint32_t{e.g} << 8 | uint32_t{e.b} << 16);
      return ErrorCode::None;
    }
    case rm::Region::GmLut:
      if (addr - rm::kGmLutBase >= table_bytes(r)) return ErrorCode::Unmapped;
      v = regs_.gm_lut[(addr - rm::kGmLutBase) / 4];
      return ErrorCode::None;
    case rm::Region::Diffuse:
      if (addr - rm::kDiffuseBase >= table_bytes(r)) return ErrorCode::Unmapped;
      v = regs_.diffuse_map[(addr - rm::kDiffuseBase) / 4];
      return ErrorCode::None;
    case rm::Region::Specular:
      if (addr - rm::kSpecularBase >= table_bytes(r)) return ErrorCode::Unmapped;
      v = regs_.specular_map[(addr - rm::kSpecularBase) / 4];
      return ErrorCode::None;
    default: return ErrorCode::Unmapped;
  }
}

golden::Registers RegisterFile::decoded() const {
  golden::Registers r = regs_;
  if (!r.magnitude) r.gm_lut.clear();
  if (!r.shading) r.diffuse_map.clear();
  if (!r.specular) r.specular_map.clear();
  return r;
}

}  // namespace cube4::sysc
