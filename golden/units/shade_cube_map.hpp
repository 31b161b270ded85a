// Reflectance-map lookup: an unnormalised vector picks a cube face and a
// position on it; four map entries are bilinearly interpolated (VolumePro
// §3.5: 6 faces, 8x8 entries each by default).
#pragma once
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "golden/fixed.hpp"
#include "golden/precision.hpp"
#include "golden/units/interp.hpp"

namespace cube4::golden {

struct CubeCoord {
  bool valid = false;  // false for the zero vector: no direction, no light
  int face = 0;        // 2*axis + (component < 0): +x,-x,+y,-y,+z,-z
  uint32_t u = 0, v = 0;    // grid cell, 0 .. res-2
  uint32_t wu = 0, wv = 0;  // weights, 0 .. 2^weight_bits inclusive
};

// The face's in-plane axes: x -> (y, z), y -> (z, x), z -> (x, y). The host
// builds the maps with the same convention.
constexpr int face_axis_u(int axis) { return (axis + 1) % 3; }
constexpr int face_axis_v(int axis) { return (axis + 2) % 3; }

// Position (s + m) / 2m along the face, m = |major| > 0, scaled to the grid
// (res - 1 cells) with weight_bits of fraction, by truncating division.
// The far edge (s = m) is cell res-2 at full weight so u+1 stays on the face.
constexpr void face_position(int64_t s, int64_t m, int res, int weight_bits, uint32_t& cell,
                             uint32_t& weight) {
  const int64_t pos = ((s + m) * (res - 1) << weight_bits) / (2 * m);
  int64_t c = pos >> weight_bits;
  int64_t w = pos & max_unsigned(weight_bits);
  if (c >= res - 1) { c = res - 2; w = int64_t{1} << weight_bits; }
  cell = static_cast<uint32_t>(c);
  weight = static_cast<uint32_t>(w);
}

// face_position() for every |s| <= m <= mmax, filled by calling it: a
// software renderer's substitute for the hardware divider, equal by
// construction (and tested exhaustively).
class FacePositionTable {
 public:
  FacePositionTable(int mmax, int res, int weight_bits) : mmax_(mmax), entries_(offset(mmax + 1)) {
    for (int m = 1; m <= mmax; ++m)
      for (int s = -m; s <= m; ++s) {
        uint32_t c = 0, w = 0;
        face_position(s, m, res, weight_bits, c, w);
        entries_[offset(m) + s + m] = {static_cast<uint16_t>(c), static_cast<uint16_t>(w)};
      }
  }
  void operator()(int64_t s, int64_t m, uint32_t& cell, uint32_t& weight) const {
    const Entry& e = entries_[offset(static_cast<int>(m)) + s + m];
    cell = e.cell;
    weight = e.weight;
  }
  int mmax() const { return mmax_; }

 private:
  struct Entry { uint16_t cell, weight; };
  static size_t offset(int m) { return static_cast<size_t>(m) * m - 1; }  // sum of 2k+1 for 0 < k < m
  int mmax_;
  std::vector<Entry> entries_;
};

// Ties pick the lower axis (x before y before z), so every vector has one
// face. `position(s, m, cell, weight)` is face_position at this precision.
template <class FacePosition>
constexpr CubeCoord cube_coordinates_with(int32_t x, int32_t y, int32_t z, const FacePosition& position) {
  const int64_t c[3] = {x, y, z};
  const int64_t a[3] = {x < 0 ? -int64_t{x} : x, y < 0 ? -int64_t{y} : y, z < 0 ? -int64_t{z} : z};
  CubeCoord r;
  if (a[0] == 0 && a[1] == 0 && a[2] == 0) return r;
  const int axis = (a[0] >= a[1] && a[0] >= a[2]) ? 0 : (a[1] >= a[2] ? 1 : 2);
  r.valid = true;
  r.face = 2 * axis + (c[axis] < 0 ? 1 : 0);
  position(c[face_axis_u(axis)], a[axis], r.u, r.wu);
  position(c[face_axis_v(axis)], a[axis], r.v, r.wv);
  return r;
}

constexpr CubeCoord cube_coordinates(int32_t x, int32_t y, int32_t z, const Precision& p) {
  return cube_coordinates_with(x, y, z, [&p](int64_t s, int64_t m, uint32_t& cell, uint32_t& weight) {
    face_position(s, m, p.map_face_res, p.weight_bits, cell, weight);
  });
}

constexpr size_t map_index(int face, uint32_t u, uint32_t v, int res) {
  return (static_cast<size_t>(face) * res + v) * res + u;
}

// Bilinear in the map (map_bits entries); zero for an invalid coordinate.
inline uint32_t reflectance_lookup(const std::vector<uint32_t>& map, const CubeCoord& c,
                                   const Precision& p) {
  if (!c.valid) return 0;
  const int res = p.map_face_res;
  return static_cast<uint32_t>(bilerp(map[map_index(c.face, c.u, c.v, res)],
                                      map[map_index(c.face, c.u + 1, c.v, res)],
                                      map[map_index(c.face, c.u, c.v + 1, res)],
                                      map[map_index(c.face, c.u + 1, c.v + 1, res)], c.wu, c.wv,
                                      p.weight_bits));
}

}  // namespace cube4::golden
