// A slice's control as cube4_dda's outputs show it, read into golden's
// SliceControl: by the system's wrapper (rtl_dda.hpp) and the unit's test
// (tb/rtl/test_dda.cpp) alike. No SystemC.
#pragma once
#include <cstdint>

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

}  // namespace cube4::rtl
