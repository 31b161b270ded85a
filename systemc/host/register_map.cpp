#include "systemc/host/register_map.hpp"

#include <cstdio>

#include "golden/fixed.hpp"

namespace cube4::sysc::regmap {
namespace {

std::string hex(uint64_t a) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%llx", static_cast<unsigned long long>(a));
  return buf;
}

std::string offset(uint64_t a) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%03llX", static_cast<unsigned long long>(a));
  return buf;
}

std::string indexed(const char* window, uint64_t index, const char* part) {
  return std::string(window) + "[" + std::to_string(index) + "]" + part;
}

std::string word_name(const Register& r, uint64_t a) {
  if (r.words == 1) return r.name;
  return std::string(r.name) + (a == r.addr ? "_LO" : "_HI");
}

std::string width_text(const Register& r) {
  std::string w = r.width.plus ? "`" + std::string(golden::precision_field(r.width.plus).key) + "`" : "";
  if (r.width.plus && r.width.bits) w += "+" + std::to_string(r.width.bits);
  if (!r.width.plus) w = std::to_string(r.width.bits);
  if (r.sign == Sign::Signed) w += " signed";
  if (r.sign == Sign::Symmetric) w += " symmetric";
  return w;
}

std::string range_text(const Register& r, const HardwareParams& hw) {
  if (r.access == Access::R || r.block == Block::Control) return "—";
  switch (r.rule) {
    case Rule::Dim: return "1..max dim";
    case Rule::Supersampling: return "1.." + std::to_string(kMaxSupersampling);
    case Rule::Permutation: return "a permutation";
    case Rule::Mode: return "bits below, blend ≤ 2";
    case Rule::Width: break;
  }
  const int full = 32 * r.words;
  if (r.width.bits >= full && r.sign != Sign::Symmetric) return "any";
  if (r.width.plus) {
    const char* lo = r.sign == Sign::Unsigned ? "0" : (r.sign == Sign::Signed ? "−2^(w−1)" : "−(2^(w−1)−1)");
    const char* hi = r.sign == Sign::Unsigned ? "2^w−1" : "2^(w−1)−1";
    return std::string(lo) + ".." + hi;
  }
  const Limits l = *limits(r, hw);
  return std::to_string(l.lo) + ".." + std::to_string(l.hi);
}

std::string reset_text(const Register& r, const HardwareParams& hw) {
  if (!r.get || r.block == Block::Identification || r.block == Block::Precision) return "—";
  const int64_t v = field_value(r, reset_value(r, hw));
  return v >= 0 && v < 10 ? std::to_string(v) : hex(static_cast<uint64_t>(v));
}

const char* access_text(Access a) {
  switch (a) {
    case Access::R: return "R";
    case Access::W: return "W";
    case Access::RW: return "RW";
  }
  return "?";
}

// Identifiers in code font; none: a dash.
std::string code(const std::string& s) {
  if (s.empty()) return "—";
  return (s[0] >= 'a' && s[0] <= 'z') || (s[0] >= 'A' && s[0] <= 'Z') ? "`" + s + "`" : s;
}

struct Section {
  Block block;
  const char* title;
};
constexpr Section kSections[] = {
    {Block::Control, "Control and status"}, {Block::Identification, "Identification, read-only"},
    {Block::Precision, "Precision, read-only"}, {Block::View, "View and DDA"}, {Block::Mode, "Mode"},
    {Block::Cropping, "Cropping"}, {Block::Window, "Block window"}, {Block::CutPlane, "Cut plane"}, {Block::Shading, "Shading"},
    {Block::Volume, "Volume"}, {Block::Polygons, "Polygons (Cube-5)"},
};

}  // namespace

std::optional<Limits> limits(const Register& r, const HardwareParams& hw) {
  switch (r.rule) {
    case Rule::Dim: return Limits{1, hw.max_dim};
    case Rule::Supersampling: return Limits{1, kMaxSupersampling};
    case Rule::Permutation:
    case Rule::Mode: return std::nullopt;
    case Rule::Width: break;
  }
  const int w = r.width.of(hw.precision);
  switch (r.sign) {
    case Sign::Unsigned: return Limits{0, w >= 63 ? INT64_MAX : static_cast<int64_t>(golden::max_unsigned(w))};
    case Sign::Signed:
      return w >= 64 ? Limits{INT64_MIN, INT64_MAX} : Limits{-golden::max_signed(w) - 1, golden::max_signed(w)};
    case Sign::Symmetric: return Limits{-golden::max_signed(w), golden::max_signed(w)};
  }
  return std::nullopt;
}

bool fits(const Register& r, uint64_t raw, const HardwareParams& hw) {
  if (r.words == 1 && r.sign == Sign::Unsigned && raw > 0xFFFF'FFFFull) return false;
  switch (r.rule) {
    case Rule::Permutation: {
      if (raw >> 6) return false;
      uint32_t seen = 0;
      for (int i = 0; i < 3; ++i) seen |= 1u << (raw >> (2 * i) & 3);
      return seen == 7;  // each axis exactly once
    }
    case Rule::Mode:
      return (raw & ~uint64_t{kModeMask}) == 0 && (raw & kModeBlendMask) >> kModeBlendShift <= 2;
    default: break;
  }
  const Limits l = *limits(r, hw);
  if (r.sign == Sign::Unsigned && r.words == 2 && l.hi == INT64_MAX) return true;  // the full 64 bits
  const int64_t v = field_value(r, raw);
  if (r.sign == Sign::Unsigned && r.words == 2 && v < 0) return false;
  return v >= l.lo && v <= l.hi;
}

uint64_t reset_value(const Register& r, const HardwareParams& hw) {
  RegisterValues v;
  v.regs.p = hw.precision;
  return r.get ? r.get(v, hw) : 0;
}

std::string describe_address(uint64_t a) {
  std::string name;
  switch (region_of(a)) {
    case Region::Registers: {
      const Register* r = register_at(a & ~uint64_t{3});
      name = r ? word_name(*r, a & ~uint64_t{3}) : "unnamed register";
      break;
    }
    case Region::Class: {
      const uint64_t off = a - kClassBase;
      name = indexed("CLASS", off / 8, (off & 4) ? ".a" : ".rgb");
      break;
    }
    case Region::GmLut: name = indexed("GMLUT", (a - kGmLutBase) / 4, ""); break;
    case Region::Diffuse: name = indexed("DIFFUSE_MAP", (a - kDiffuseBase) / 4, ""); break;
    case Region::Specular: name = indexed("SPECULAR_MAP", (a - kSpecularBase) / 4, ""); break;
    case Region::Material: {
      static const char* const word[kMaterialWords] = {".ke", ".kd", ".ks", ".spec_r", ".spec_g", ".spec_b", ".zero",
                                                       ".zero"};
      const uint64_t off = a - kMaterialBase;
      name = indexed("MATERIAL", off / (4 * kMaterialWords), word[off / 4 % kMaterialWords]);
      break;
    }
    case Region::Base: {
      const uint64_t off = a - kBaseBase;
      name = indexed("BASE_PLANE", off / 8, (off & 4) ? ".ba" : ".rg");
      break;
    }
    case Region::Volume: name = indexed("VOLUME", (a - kVolumeBase) / 2, " (voxel index)"); break;
    case Region::Slab: name = indexed("SLAB", (a - kSlabBase) / 2, " (voxel index in the slab)"); break;
    case Region::PolyFront:
    case Region::PolyBack: {
      const bool front = region_of(a) == Region::PolyFront;
      const uint64_t off = a - (front ? kPolyFrontBase : kPolyBackBase);
      name = indexed(front ? "POLY_FRONT" : "POLY_BACK", off / 8, (off & 4) ? ".ba" : ".rg");
      break;
    }
    case Region::PolyZ: name = indexed("POLY_Z", (a - kPolyZBase) / 4, ""); break;
    case Region::PolySlab: {
      const uint64_t off = a - kPolySlabBase;
      name = indexed("POLY_SLAB", off / kPolySlabStride, (" word " + std::to_string(off % kPolySlabStride / 4)).c_str());
      break;
    }
    case Region::None: name = "unmapped"; break;
  }
  return name + " (" + hex(a) + ")";
}

std::string register_doc() {
  const HardwareParams hw;
  std::string out;
  for (const Section& s : kSections) {
    out += "### " + std::string(s.title) + "\n\n";
    out += "| offset | name | width | range | access | reset | golden field | RTL | meaning |\n";
    out += "|---|---|---|---|---|---|---|---|---|\n";
    for (const Register& r : kRegisters) {
      if (r.block != s.block) continue;
      const std::string name = r.words == 2 ? std::string(r.name) + "_LO/HI" : r.name;
      out += "| " + offset(r.addr) + " | " + name + " | " + width_text(r) + " | " + range_text(r, hw) + " | " +
             access_text(r.access) + " | " + reset_text(r, hw) + " | " + code((r.block == Block::Precision ? "p." : "") + std::string(r.golden_field)) + " | " +
             code(r.rtl_port) + " | " + r.meaning + " |\n";
    }
    out += "\n";
  }
  out.pop_back();
  return out;
}

}  // namespace cube4::sysc::regmap
