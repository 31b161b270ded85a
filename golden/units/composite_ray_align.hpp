// Ray alignment: the ray through sample (x, y) of slice k came from sample
// (x - dx, y - dy) of slice k-1, one of four candidates, where (dx, dy) is the
// change of the DDA's integer offset between the slices (each 0 or 1 because
// the shear is at most one voxel per slice). A candidate outside the slice
// means the ray entered through a side face: it starts empty.
#pragma once

namespace cube4::golden {

// The multiplexer select: candidate i is the previous slice's ray at
// (x - (i & 1), y - (i >> 1)).
constexpr int predecessor_index(int dx, int dy) { return dx | (dy << 1); }

struct Predecessor {
  bool exists = false;
  int x = 0, y = 0;
};

constexpr Predecessor ray_predecessor(int x, int y, int dx, int dy) {
  if (x - dx < 0 || y - dy < 0) return {};
  return {true, x - dx, y - dy};
}

// The ray at (x, y) of slice k-1 continues at (x + dx, y + dy) of slice k,
// or leaves the volume through a side face, finishing its pixel.
constexpr bool ray_leaves(int x, int y, int dx, int dy, int nx, int ny) {
  return x + dx >= nx || y + dy >= ny;
}

}  // namespace cube4::golden
