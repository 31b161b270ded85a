// A small volume of the permuted frame for the RTL rings' tests: nx x ny x
// nz voxels, zero outside (the volume's border, as the rings read it).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cube4::rtl {

struct VoxelGrid {
  int nx = 0, ny = 0, nz = 0;
  std::vector<uint32_t> v;
  void resize(int x, int y, int z) {
    nx = x;
    ny = y;
    nz = z;
    v.assign(static_cast<size_t>(x) * y * z, 0);
  }
  uint32_t at(int x, int y, int z) const {
    if (x < 0 || x >= nx || y < 0 || y >= ny || z < 0 || z >= nz) return 0;
    return v[(static_cast<size_t>(z) * ny + y) * nx + x];
  }
};

}  // namespace cube4::rtl
