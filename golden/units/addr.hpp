// Skewed voxel memory (Cube-4 §4, eqs (1), (2)) and the address generation
// that reads it beam by beam in any of the 48 traversal orders.
//
// Layout. A volume of object dims (nx, ny, nz) lives in p memory modules.
// Every axis is padded with zero voxels up to a multiple of p,
//   P_a = ceil(n_a / p) * p,   B_a = P_a / p,
// because every object axis is the beam axis of some view, and a partial
// beam (p consecutive voxels along the beam axis) must stay inside the
// padded volume to touch each module once. Voxel (x, y, z) of the padded
// volume is stored in
//   module(x, y, z) = (x + y + z) mod p                      (Cube-4 eq. (1))
//   index(x, y, z)  = floor(x / p) + B_x * (y + P_y * z)
// i.e. the index is the voxel's linear (x fastest) address divided by p.
// This is a bijection from the padded volume onto [0, p) x [0, B_x P_y P_z):
// for fixed (y, z) the p voxels x = p*u .. p*u+p-1 share index u and have p
// different sums mod p. Each module holds exactly P_x P_y P_z / p voxels.
// (Cube-4's eq. (2) uses floor(((x+y+z) mod n) / p) as the low part; it is a
// bijection too, but floor(x / p) needs no modulo.)
//
// Traversal. Registers perm/flip (golden/registers.hpp): permuted axis i
// walks object axis perm[i], backwards if flip[i]. Permuted coordinate v
// along axis i is object coordinate
//   o = v                              if !flip[i]
//   o = (n_{perm[i]} - 1 - v) mod P    if  flip[i]
// The flip is about the *unpadded* size, exactly as the fixed-point renderer
// reads the volume (permuted 0 is object n-1), so images do not move with
// p. For the beam axis the padded range v in [n, P) then wraps onto the
// padding voxels o in [n, P), which read zero like the renderer's border.
// The traversal visits slices z = 0 .. n_{perm[2]}-1, in each the beams
// y = 0 .. n_{perm[1]}-1, in each the partial beams j = 0 .. B_{perm[0]}-1;
// partial beam j holds permuted x = j*p .. j*p+p-1, and pipeline k
// processes x = j*p + k. Every object voxel is read exactly once per frame,
// the padding voxels along the beam axis once, other padding never.
//
// De-skew. Pipeline k's voxel comes from module
//   (rotation + k) mod p      if !reverse
//   (rotation - k) mod p      if  reverse (reverse = flip[0])
// with rotation = the module of pipeline 0's voxel: a barrel rotation,
// followed by a fixed per-frame reversal for a backwards beam axis.
#pragma once
#include <array>
#include <cstdint>

namespace cube4::golden {

// Largest p the fixed-size golden results below hold.
constexpr int kMaxSkewPipes = 32;

struct SkewLayout {
  std::array<int, 3> n{1, 1, 1};  // object dims nx, ny, nz (unpadded, >= 1)
  int p = 1;                      // memory modules = pipelines, 1 .. kMaxSkewPipes

  constexpr int blocks(int axis) const { return (n[axis] + p - 1) / p; }   // B_a
  constexpr int padded(int axis) const { return blocks(axis) * p; }        // P_a
  constexpr int64_t words_per_module() const {
    return int64_t{blocks(0)} * padded(1) * padded(2);
  }
};

struct SkewAddress {
  int module = 0;
  int64_t index = 0;
  friend constexpr bool operator==(const SkewAddress& a, const SkewAddress& b) {
    return a.module == b.module && a.index == b.index;
  }
};

// A layout's word strides within a module: per row (y) and per slice (z).
// shift: log2 p when p is a power of two, else -1.
struct SkewStrides {
  int p = 1;
  int64_t row = 1, slice = 1;
  int shift = -1;
};
constexpr SkewStrides skew_strides(const SkewLayout& l) {
  int shift = -1;
  if ((l.p & (l.p - 1)) == 0)
    for (shift = 0; (1 << shift) < l.p;) ++shift;
  return {l.p, l.blocks(0), int64_t{l.blocks(0)} * l.padded(1), shift};
}

// Where voxel (x, y, z) of the padded volume is stored (object coordinates,
// 0 <= x < P_x, ...). The strides' form lets a caller that places many
// voxels work them out once.
constexpr SkewAddress skew_address(const SkewStrides& s, int x, int y, int z) {
  // The coordinates are not negative, so for a power-of-two p a mask and a
  // shift are the remainder and the quotient (the divisions were most of a
  // clocked TLM frame's address generation).
  if (s.shift >= 0) return {(x + y + z) & (s.p - 1), (x >> s.shift) + s.row * y + s.slice * z};
  return {(x + y + z) % s.p, x / s.p + s.row * y + s.slice * z};
}
constexpr SkewAddress skew_address(const SkewLayout& l, int x, int y, int z) {
  return skew_address(skew_strides(l), x, y, z);
}

struct SkewTraversal {
  std::array<int, 3> perm{0, 1, 2};
  std::array<bool, 3> flip{false, false, false};
};

// Object coordinate of permuted coordinate v along permuted axis i
// (0 <= v < P for the beam axis, v < n for the others).
constexpr int skew_object_coordinate(const SkewLayout& l, const SkewTraversal& t, int i, int v) {
  const int a = t.perm[i];
  if (!t.flip[i]) return v;
  const int o = l.n[a] - 1 - v;
  return o < 0 ? o + l.padded(a) : o;
}

// Traversal extent: partial beams per beam, beams per slice, slices.
constexpr int skew_partial_beams(const SkewLayout& l, const SkewTraversal& t) { return l.blocks(t.perm[0]); }
constexpr int skew_beams(const SkewLayout& l, const SkewTraversal& t) { return l.n[t.perm[1]]; }
constexpr int skew_slices(const SkewLayout& l, const SkewTraversal& t) { return l.n[t.perm[2]]; }
constexpr int64_t skew_cycles(const SkewLayout& l, const SkewTraversal& t) {
  return int64_t{skew_partial_beams(l, t)} * skew_beams(l, t) * skew_slices(l, t);
}

struct BeamAccess {
  std::array<SkewAddress, kMaxSkewPipes> lane{};      // [k]: pipeline k's voxel, k < p
  std::array<int64_t, kMaxSkewPipes> module_index{};  // [m]: index presented to module m
  int rotation = 0;                                   // module of pipeline 0's voxel
  bool reverse = false;                               // pipeline k reads (rotation -/+ k) mod p
};

// The memory accesses of partial beam j of beam y of slice z (permuted
// coordinates), written into b: lanes and module indices 0 .. p - 1,
// rotation and reverse (entries from p on keep what they held, so that a
// simulator can reuse one BeamAccess a clock instead of clearing 32 lanes).
// Precondition: 1 <= l.p <= kMaxSkewPipes, position in range.
// s: skew_strides(l), which a caller clocking many beams works out once.
constexpr void beam_access_into(BeamAccess& b, const SkewLayout& l, const SkewStrides& s, const SkewTraversal& t,
                                int y, int z, int j) {
  std::array<int, 3> o{0, 0, 0};
  o[t.perm[1]] = skew_object_coordinate(l, t, 1, y);
  o[t.perm[2]] = skew_object_coordinate(l, t, 2, z);
  for (int k = 0; k < l.p; ++k) {
    o[t.perm[0]] = skew_object_coordinate(l, t, 0, j * l.p + k);
    b.lane[k] = skew_address(s, o[0], o[1], o[2]);
    b.module_index[b.lane[k].module] = b.lane[k].index;
  }
  b.rotation = b.lane[0].module;
  b.reverse = t.flip[0];
}
constexpr void beam_access_into(BeamAccess& b, const SkewLayout& l, const SkewTraversal& t, int y, int z, int j) {
  beam_access_into(b, l, skew_strides(l), t, y, z, j);
}
// The de-skew: lane k of out gets word[m], m the module pipeline k reads
// ((rotation +/- k) mod p), stepped lane by lane instead of divided.
template <class Word>
constexpr void deskew(const BeamAccess& b, int p, const Word* word, Word* out) {
  int m = b.rotation;
  for (int k = 0; k < p; ++k) {
    out[k] = word[m];
    if (b.reverse) m = (m == 0 ? p : m) - 1;
    else m = m + 1 == p ? 0 : m + 1;
  }
}
// The same as a value (lanes from p on zero).
constexpr BeamAccess beam_access(const SkewLayout& l, const SkewTraversal& t, int y, int z, int j) {
  BeamAccess b;
  beam_access_into(b, l, t, y, z, j);
  return b;
}

// The position of the c-th partial beam in traversal order.
struct BeamPosition {
  int j = 0, y = 0, z = 0;
};
constexpr BeamPosition skew_position(const SkewLayout& l, const SkewTraversal& t, int64_t c) {
  const int64_t nj = skew_partial_beams(l, t), ny = skew_beams(l, t);
  return {static_cast<int>(c % nj), static_cast<int>(c / nj % ny), static_cast<int>(c / (nj * ny))};
}

}  // namespace cube4::golden
