#include "systemc/host/register_file.hpp"

#include <stdexcept>
#include <string>

#include "golden/fixed.hpp"

namespace cube4::sysc {
namespace rm = regmap;
using rm::ErrorCode;

namespace {

using rm::class_entries;
using rm::gm_entries;
using rm::map_entries;

bool fits_unsigned(uint32_t v, int bits) { return bits >= 32 || v < (uint32_t{1} << bits); }

// 64-bit registers are two words; each write replaces its half.
uint64_t with_half(uint64_t value, bool high, uint32_t w) {
  return high ? (value & 0xFFFF'FFFFull) | (uint64_t{w} << 32) : (value & ~0xFFFF'FFFFull) | w;
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("host interface: " + what);
}

}  // namespace

void check_hardware_params(const HardwareParams& hw) {
  auto in_range = [](const std::string& name, int v, int lo, int hi) {
    require(v >= lo && v <= hi, name + " = " + std::to_string(v) + " is out of range " + std::to_string(lo) + ".." +
                                    std::to_string(hi));
  };
  in_range("pipelines", hw.pipelines, 1, rm::kMaxPipelines);
  in_range("max_dim", hw.max_dim, 2, rm::kMaxDimLimit);
  // The windows and packings of docs/registers.md bound these widths.
  using P = golden::Precision;
  const struct {
    int P::*member;
    int lo, hi;
  } bounds[] = {{&P::voxel_bits, 1, 16}, {&P::magnitude_bits, 1, 16}, {&P::color_bits, 1, 8},
                {&P::alpha_bits, 1, 16}, {&P::gmlut_bits, 1, 16},     {&P::map_face_res, 2, 64},
                {&P::map_bits, 1, 32},   {&P::coef_bits, 1, 32},      {&P::eye_bits, 2, 32},
                {&P::acc_guard_bits, 0, hw.precision.alpha_bits}};
  for (const auto& b : bounds)
    in_range(std::string("precision.") + golden::precision_field(b.member).key, hw.precision.*b.member, b.lo, b.hi);
}

RegisterFile::RegisterFile(const HardwareParams& hw) : hw_(hw) {
  check_hardware_params(hw);
  reset();
}

void RegisterFile::reset() {
  values_ = rm::RegisterValues{};
  golden::Registers& r = values_.regs;
  r.p = hw_.precision;
  r.classification.assign(rm::class_entries(hw_.precision), golden::ClassEntry{});
  r.gm_lut.assign(rm::gm_entries(hw_.precision), 0);
  r.diffuse_map.assign(rm::map_entries(hw_.precision), 0);
  r.specular_map.assign(rm::map_entries(hw_.precision), 0);
  r.tag_coefs.assign(rm::material_entries(hw_.precision), golden::ShadeCoefs{});
}

uint64_t RegisterFile::table_bytes(rm::Region r) const {
  const golden::Precision& p = hw_.precision;
  switch (r) {
    case rm::Region::Class: return 8 * class_entries(p);
    case rm::Region::GmLut: return 4 * gm_entries(p);
    case rm::Region::Diffuse:
    case rm::Region::Specular: return 4 * map_entries(p);
    case rm::Region::Material: return 4 * rm::kMaterialWords * rm::material_entries(p);
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
    case rm::Region::Material: {
      if (addr - rm::kMaterialBase >= table_bytes(r)) return ErrorCode::Unmapped;
      // ke, kd, ks: coef_bits; the specular colour: alpha_bits; the rest zero.
      const uint64_t word = (addr - rm::kMaterialBase) / 4 % rm::kMaterialWords;
      const int bits = word < 3 ? p.coef_bits : word < 6 ? p.alpha_bits : 0;
      return fits_unsigned(v, bits) ? ErrorCode::None : ErrorCode::FieldRange;
    }
    default: return ErrorCode::Unmapped;
  }
}

namespace {

// Word `word` of a MATERIAL window entry (6, 7: none).
uint32_t* material_word(golden::ShadeCoefs& k, uint64_t word) {
  switch (word) {
    case 0: return &k.ke;
    case 1: return &k.kd;
    case 2: return &k.ks;
    case 3: case 4: case 5: return &k.specular[word - 3];
    default: return nullptr;
  }
}

}  // namespace

ErrorCode RegisterFile::check_register(uint64_t a, uint32_t v) const {
  const rm::Register* reg = rm::register_at(a);
  if (!reg || reg->block == rm::Block::Control) return ErrorCode::Unmapped;
  if (reg->access != rm::Access::RW) return ErrorCode::ReadOnly;
  if (reg->words == 2) return ErrorCode::None;  // wide_value_out_of_range, at START
  if (!rm::fits(*reg, v, hw_)) return ErrorCode::FieldRange;
  // Every resident subvolume (all three dimensions set) shares the voxel
  // memory: a new size must leave room for the others.
  if (reg->rule == rm::Rule::Dim && reg->block == rm::Block::Volume) {
    uint64_t used = 0;
    for (int k = 0; k < rm::kSubvolumes; ++k) {
      std::array<int, 3> d = values_.vol_dims[static_cast<size_t>(k)];
      if (k == values_.vol_index) d[(a - rm::kVolDim) / 4] = static_cast<int>(v);
      used += uint64_t(d[0]) * uint64_t(d[1]) * uint64_t(d[2]);
    }
    if (used > hw_.voxel_memory) return ErrorCode::VoxelMemoryFull;
  }
  return ErrorCode::None;
}

const rm::Register* RegisterFile::wide_value_out_of_range() const {
  for (const rm::Register& reg : rm::kRegisters)
    if (reg.words == 2 && reg.set && !rm::fits(reg, reg.get(values_, hw_), hw_)) return &reg;
  return nullptr;
}

void RegisterFile::write(uint64_t addr, uint32_t v) {
  switch (rm::region_of(addr)) {
    case rm::Region::Registers: write_register(addr, v); return;
    case rm::Region::Class: {
      golden::ClassEntry& e = values_.regs.classification[(addr - rm::kClassBase) / 8];
      if (addr & 4) {
        e.a = static_cast<uint16_t>(v);
      } else {
        e.r = static_cast<uint16_t>(v & 0xFF);
        e.g = static_cast<uint16_t>(v >> 8 & 0xFF);
        e.b = static_cast<uint16_t>(v >> 16 & 0xFF);
      }
      return;
    }
    case rm::Region::GmLut: values_.regs.gm_lut[(addr - rm::kGmLutBase) / 4] = static_cast<uint16_t>(v); return;
    case rm::Region::Diffuse: values_.regs.diffuse_map[(addr - rm::kDiffuseBase) / 4] = v; return;
    case rm::Region::Specular: values_.regs.specular_map[(addr - rm::kSpecularBase) / 4] = v; return;
    case rm::Region::Material: {
      const uint64_t off = (addr - rm::kMaterialBase) / 4;
      if (uint32_t* w = material_word(values_.regs.tag_coefs[off / rm::kMaterialWords], off % rm::kMaterialWords)) *w = v;
      return;
    }
    default: return;
  }
}

void RegisterFile::write_register(uint64_t a, uint32_t v) {
  const rm::Register& reg = *rm::register_at(a);  // check_write found it
  const uint64_t value = reg.words == 2 ? with_half(reg.get(values_, hw_), a != reg.addr, v)
                                        : static_cast<uint64_t>(rm::field_value(reg, v));
  reg.set(values_, value);
}

// False where register space has no register (or only the control block's).
bool RegisterFile::read_register(uint64_t a, uint32_t& v) const {
  const rm::Register* reg = rm::register_at(a);
  if (!reg || !reg->get) return false;
  const uint64_t value = reg->get(values_, hw_);
  v = static_cast<uint32_t>(a == reg->addr ? value : value >> 32);
  return true;
}

ErrorCode RegisterFile::read(uint64_t addr, uint32_t& v) const {
  const rm::Region r = rm::region_of(addr);
  if (r == rm::Region::Registers) return read_register(addr, v) ? ErrorCode::None : ErrorCode::Unmapped;
  switch (r) {
    case rm::Region::Class: {
      const uint64_t off = addr - rm::kClassBase;
      if (off >= table_bytes(r)) return ErrorCode::Unmapped;
      const golden::ClassEntry& e = values_.regs.classification[off / 8];
      v = (off & 4) ? e.a : (uint32_t{e.r} | uint32_t{e.g} << 8 | uint32_t{e.b} << 16);
      return ErrorCode::None;
    }
    case rm::Region::GmLut:
      if (addr - rm::kGmLutBase >= table_bytes(r)) return ErrorCode::Unmapped;
      v = values_.regs.gm_lut[(addr - rm::kGmLutBase) / 4];
      return ErrorCode::None;
    case rm::Region::Diffuse:
      if (addr - rm::kDiffuseBase >= table_bytes(r)) return ErrorCode::Unmapped;
      v = values_.regs.diffuse_map[(addr - rm::kDiffuseBase) / 4];
      return ErrorCode::None;
    case rm::Region::Specular:
      if (addr - rm::kSpecularBase >= table_bytes(r)) return ErrorCode::Unmapped;
      v = values_.regs.specular_map[(addr - rm::kSpecularBase) / 4];
      return ErrorCode::None;
    case rm::Region::Material: {
      if (addr - rm::kMaterialBase >= table_bytes(r)) return ErrorCode::Unmapped;
      const uint64_t off = (addr - rm::kMaterialBase) / 4;
      golden::ShadeCoefs k = values_.regs.tag_coefs[off / rm::kMaterialWords];
      const uint32_t* w = material_word(k, off % rm::kMaterialWords);
      v = w ? *w : 0;
      return ErrorCode::None;
    }
    default: return ErrorCode::Unmapped;
  }
}

golden::Registers RegisterFile::decoded() const {
  golden::Registers r = values_.regs;
  if (!r.magnitude) r.gm_lut.clear();
  if (!r.shading) r.diffuse_map.clear();
  if (!r.specular) r.specular_map.clear();
  if (!r.shading) r.tag_coefs.clear();  // as program_host: the materials shade
  return r;
}

}  // namespace cube4::sysc
