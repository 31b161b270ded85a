// Cropping (VolumePro §4.3): three slabs, combined by an 8-entry truth table.
// Positions and slabs are in permuted voxel coordinates (the host permutes
// the user's object-space slabs and the table's bits).
#pragma once
#include <array>
#include <cstdint>

namespace cube4::golden {

// The hardware's unsigned width of permuted positions and crop slabs (the
// RTL's PosBits); golden compares with any int32.
constexpr int kPositionBits = 16;

struct CropRegs {
  std::array<std::array<int32_t, 2>, 3> slab{{{0, 0}, {0, 0}, {0, 0}}};  // inclusive [lo, hi]
  uint8_t mask = 0x80;  // visible iff bit (inX | inY<<1 | inZ<<2) is set
};

constexpr bool crop_visible(int32_t x, int32_t y, int32_t z, const CropRegs& c) {
  const int in_x = c.slab[0][0] <= x && x <= c.slab[0][1];
  const int in_y = c.slab[1][0] <= y && y <= c.slab[1][1];
  const int in_z = c.slab[2][0] <= z && z <= c.slab[2][1];
  return (c.mask >> (in_x | (in_y << 1) | (in_z << 2))) & 1;
}

}  // namespace cube4::golden
