// The frame registers of each RTL unit, bound to its ports once: the system's
// RTL wrappers (rtl_composite.hpp, rtl_shade.hpp) and the units' testbenches
// (tb/rtl) drive them through these, so a port the RTL adds or widens is
// bound in one place. Header-only, on any verilated model with the ports
// (cube4_composite / _unit / _ring; cube4_shade_unit, cube4_shade and its
// table-holding parts).
#pragma once
#include <cstdint>
#include <vector>

#include "golden/fixed.hpp"
#include "golden/registers.hpp"
#include "systemc/rtl/vl_bits.hpp"

namespace cube4::rtl {

// The compositing unit's registers: blend mode, cropping, block window and cut plane.
template <class M>
void drive_composite_registers(M& m, const golden::Registers& r, bool polygons = false) {
  const golden::Precision& p = r.p;
  auto put = [](auto& port, int bits, auto v) { put_bits(port, 0, bits, static_cast<uint64_t>(v)); };
  put(m.blend_mode_i, 2, static_cast<uint8_t>(r.blend));
  m.crop_enabled_i = r.crop_enabled;
  put(m.crop_x_lo_i, golden::kPositionBits, r.crop.slab[0][0]);
  put(m.crop_x_hi_i, golden::kPositionBits, r.crop.slab[0][1]);
  put(m.crop_y_lo_i, golden::kPositionBits, r.crop.slab[1][0]);
  put(m.crop_y_hi_i, golden::kPositionBits, r.crop.slab[1][1]);
  put(m.crop_z_lo_i, golden::kPositionBits, r.crop.slab[2][0]);
  put(m.crop_z_hi_i, golden::kPositionBits, r.crop.slab[2][1]);
  put(m.crop_mask_i, 8, r.crop.mask);
  m.window_enabled_i = r.window_enabled;
  put(m.window_x_lo_i, golden::kPositionBits, r.window.range[0][0]);
  put(m.window_x_hi_i, golden::kPositionBits, r.window.range[0][1]);
  put(m.window_y_lo_i, golden::kPositionBits, r.window.range[1][0]);
  put(m.window_y_hi_i, golden::kPositionBits, r.window.range[1][1]);
  put(m.window_z_lo_i, golden::kPositionBits, r.window.range[2][0]);
  put(m.window_z_hi_i, golden::kPositionBits, r.window.range[2][1]);
  m.cut_enabled_i = r.cut_enabled;
  put(m.cut_a_i, golden::kCutCoefBits, r.cut.a);
  put(m.cut_b_i, golden::kCutCoefBits, r.cut.b);
  put(m.cut_c_i, golden::kCutCoefBits, r.cut.c);
  put(m.cut_dmin_i, p.cut_bits, r.cut.dmin);
  put(m.cut_dmax_i, p.cut_bits, r.cut.dmax);
  put(m.cut_falloff_i, p.cut_bits, r.cut.falloff);
  put(m.cut_inv_falloff_i, p.alpha_bits + golden::kCutInvShift, r.cut.inv_falloff);
  m.cut_keep_inside_i = r.cut.keep_inside;
  m.poly_enabled_i = polygons;  // a PolygonFrame with the frame (polygon_streams.hpp)
}

// The shading unit's mode bits, coefficients and eye vector.
template <class M>
void drive_shade_registers(M& m, const golden::Registers& r) {
  const golden::Precision& p = r.p;
  auto put = [](auto& port, int bits, auto v) { put_bits(port, 0, bits, static_cast<uint64_t>(v)); };
  m.magnitude_i = r.magnitude;
  m.shading_i = r.shading;
  m.specular_i = r.specular;
  m.gm_opacity_i = r.gm_opacity;
  m.gm_diffuse_i = r.gm_diffuse;
  m.gm_specular_i = r.gm_specular;
  put(m.ke_i, p.coef_bits, r.coefs.ke);
  put(m.kd_i, p.coef_bits, r.coefs.kd);
  put(m.ks_i, p.coef_bits, r.coefs.ks);
  put(m.spec_red_i, p.alpha_bits, r.coefs.specular[0]);
  put(m.spec_green_i, p.alpha_bits, r.coefs.specular[1]);
  put(m.spec_blue_i, p.alpha_bits, r.coefs.specular[2]);
  put(m.eye_x_i, p.eye_bits, r.eye[0]);
  put(m.eye_y_i, p.eye_bits, r.eye[1]);
  put(m.eye_z_i, p.eye_bits, r.eye[2]);
}

// A classification entry as its table's write port takes it: {r, g, b, a}.
inline uint64_t class_word(const golden::ClassEntry& e, const golden::Precision& p) {
  return ((((uint64_t{e.r} << p.color_bits | e.g) << p.color_bits) | e.b) << p.alpha_bits) | e.a;
}

// Writes table entries through a write port, one per tick() (which clocks the model).
template <class We, class Addr, class Data, class Table, class Word, class Tick>
void load_table(We& we, Addr& addr, int addr_bits, Data& data, int data_bits, const Table& table, Word&& word,
                Tick&& tick) {
  for (size_t i = 0; i < table.size(); ++i) {
    we = 1;
    put_bits(addr, 0, addr_bits, i);
    put_bits(data, 0, data_bits, word(table[i]));
    tick();
  }
  we = 0;
}

// The classification table (cube4_shade_classify and up).
template <class M, class Tick>
void load_class_table(M& m, const golden::Precision& p, const std::vector<golden::ClassEntry>& table, Tick&& tick) {
  // The address is {tag, value} (golden class_address).
  load_table(m.class_we_i, m.class_waddr_i, p.voxel_bits + p.tag_bits, m.class_wdata_i, 3 * p.color_bits + p.alpha_bits, table,
             [&p](const golden::ClassEntry& e) { return class_word(e, p); }, tick);
}

// Each tag's material (cube4_shade with VoxelTagBits > 0, golden
// Registers::tag_coefs): {ke, kd, ks, spec r, g, b}, ke in the top bits.
template <class M, class Tick>
void load_materials(M& m, const golden::Precision& p, const std::vector<golden::ShadeCoefs>& mats, Tick&& tick) {
  const int a = p.alpha_bits, c = p.coef_bits;
  for (size_t t = 0; t < mats.size(); ++t) {
    const golden::ShadeCoefs& k = mats[t];
    m.mat_we_i = 1;
    put_bits(m.mat_waddr_i, 0, p.tag_bits, t);
    put_bits(m.mat_wdata_i, 0, a, k.specular[2]);
    put_bits(m.mat_wdata_i, a, a, k.specular[1]);
    put_bits(m.mat_wdata_i, 2 * a, a, k.specular[0]);
    put_bits(m.mat_wdata_i, 3 * a, c, k.ks);
    put_bits(m.mat_wdata_i, 3 * a + c, c, k.kd);
    put_bits(m.mat_wdata_i, 3 * a + 2 * c, c, k.ke);
    tick();
  }
  m.mat_we_i = 0;
}

// The GmLUT (cube4_shade_classify and up).
template <class M, class Tick>
void load_gm_lut(M& m, const golden::Precision& p, const std::vector<uint16_t>& table, Tick&& tick) {
  load_table(m.gmlut_we_i, m.gmlut_waddr_i, p.magnitude_bits, m.gmlut_wdata_i, p.gmlut_bits, table,
             [](uint16_t v) { return uint64_t{v}; }, tick);
}

// One reflectance map (cube4_shade_reflectance and up): `which` selects the
// diffuse (dmap_*) or specular (smap_*) port.
enum class Map { Diffuse, Specular };
template <class M, class Tick>
void load_map(M& m, const golden::Precision& p, Map which, const std::vector<uint32_t>& map, Tick&& tick) {
  const int addr_bits = golden::bit_length(6 * p.map_face_res * p.map_face_res - 1);
  auto word = [](uint32_t v) { return uint64_t{v}; };
  if (which == Map::Diffuse)
    load_table(m.dmap_we_i, m.dmap_waddr_i, addr_bits, m.dmap_wdata_i, p.map_bits, map, word, tick);
  else
    load_table(m.smap_we_i, m.smap_waddr_i, addr_bits, m.smap_wdata_i, p.map_bits, map, word, tick);
}

}  // namespace cube4::rtl
