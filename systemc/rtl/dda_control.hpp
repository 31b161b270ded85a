// A slice's control as cube4_dda's outputs show it, read into golden's
// SliceControl (parallel projection) or PerspectiveSlice: by the system's
// wrapper (rtl_dda.hpp) and the unit's test (tb/rtl/test_dda.cpp) alike.
// No SystemC.
#pragma once
#include <cstdint>

#include "golden/perspective.hpp"
#include "golden/pipeline.hpp"

namespace cube4::rtl {

// int_bits: the unit's IntBits (PosBits - FracBits), the width of its
// signed whole-voxel outputs.
template <class M>
golden::SliceControl read_dda_control(const M& m, int int_bits) {
  auto whole = [&](uint64_t v) {
    return static_cast<int>(static_cast<int64_t>(v << (64 - int_bits)) >> (64 - int_bits));
  };
  auto realign = [](uint32_t base, uint32_t weight) { return golden::Realign{base ? -1 : 0, weight}; };
  golden::SliceControl c;
  c.k = static_cast<int>(m.k_o);
  c.z_voxel = static_cast<int>(m.z_voxel_o);
  c.wx = m.wx_o;
  c.wy = m.wy_o;
  c.wz = m.wz_o;
  c.ix = whole(m.ix_o);
  c.iy = whole(m.iy_o);
  c.dx = whole(m.dx_o);
  c.dy = whole(m.dy_o);
  c.behind_x = realign(m.behind_x_base_o, m.behind_x_weight_o);
  c.behind_y = realign(m.behind_y_base_o, m.behind_y_weight_o);
  c.ahead_x = realign(m.ahead_x_base_o, m.ahead_x_weight_o);
  c.ahead_y = realign(m.ahead_y_base_o, m.ahead_y_weight_o);
  return c;
}

// The divided constants as cube4_persp_slice's outputs show them (the
// weight generator's perspective part, and the unit's own test), into `s`.
// pos_bits: the unit's PosBits, the width of its outputs.
template <class M>
void read_divided_constants(const M& m, int pos_bits, golden::PerspectiveSlice& s) {
  auto get = [&](uint64_t v) { return static_cast<int64_t>(v << (64 - pos_bits)) >> (64 - pos_bits); };
  s.rays_x = {get(m.rays_x_lo_o), get(m.rays_x_hi_o)};
  s.rays_y = {get(m.rays_y_lo_o), get(m.rays_y_hi_o)};
  s.box_reciprocal = static_cast<uint64_t>(get(m.box_recip_o));
  s.lateral_reciprocal = get(m.lateral_recip_o);
  s.behind_x = {get(m.behind_start_x_o), get(m.behind_step_o)};
  s.behind_y = {get(m.behind_start_y_o), get(m.behind_step_o)};
  s.ahead_x = {get(m.ahead_start_x_o), get(m.ahead_step_o)};
  s.ahead_y = {get(m.ahead_start_y_o), get(m.ahead_step_o)};
}

// A perspective slice's constants as cube4_dda's outputs show them.
template <class M>
golden::PerspectiveSlice read_perspective_slice(const M& m, int pos_bits) {
  auto get = [&](uint64_t v) { return static_cast<int64_t>(v << (64 - pos_bits)) >> (64 - pos_bits); };
  golden::PerspectiveSlice s;
  s.k = static_cast<int>(m.k_o);
  s.z_voxel = static_cast<int>(m.z_voxel_o);
  s.wz = m.wz_o;
  s.spacing = get(m.spacing_o);
  s.ray0_x = get(m.ray0_x_o);
  s.ray0_y = get(m.ray0_y_o);
  read_divided_constants(m, pos_bits, s);
  return s;
}

}  // namespace cube4::rtl
