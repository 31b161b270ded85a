// The perspective dataflow of the rings (docs/perspective.md, "The
// dataflow"): where the pipelines form a ray's sample, and how far the
// rings must reach for its box, its gradient's neighbours and its
// accumulator. The pipelines hold the voxel columns (x = j * p + k); a
// ray's sample is formed at its home, the voxel column and row its
// position lies in, so that every unit keeps the parallel units' near-
// neighbour links and a pass keeps its ny beams.
#pragma once
#include <cstdint>

#include "golden/registers.hpp"

namespace cube4::golden {

// A ray's home on a slice along one axis: the cell floor(pos) its position
// lies in. Rays at least one voxel apart have distinct homes, and a ray
// that samples the slice (0 <= pos < n) has its home in the volume.
constexpr int64_t home_cell(int64_t pos, int frac_bits) { return pos >> frac_bits; }

// The range of cell offsets, relative to the sample's own home, at which
// one kind of operand lies over a frame, along one axis. An empty range
// (lo > hi) means the frame has no such operand.
struct CellRange {
  int64_t lo = INT64_MAX, hi = INT64_MIN;
  bool empty() const { return lo > hi; }
  void add(int64_t d) {
    lo = d < lo ? d : lo;
    hi = d > hi ? d : hi;
  }
};

struct AxisReach {
  CellRange box;     // the cells the box filter weighs (overlap > 0)
  CellRange next;    // the next ray's home on the same slice (the gradient's +1 neighbour)
  CellRange behind;  // the homes of the two rays of slice k - 1 around the point straight behind
  CellRange ahead;   // and of slice k + 1 around the point straight ahead
  CellRange drift;   // the same ray's home on slice k + 1 (its accumulator's move)
};
struct PerspectiveReach {
  AxisReach x, y;
  uint64_t samples = 0;  // perspective_samples()
};

// The samples of a perspective frame: the rays sampling each slice, summed
// over the slices (a parallel frame has nx * ny per slice). Fewer than the
// voxels the frame reads: the rays spread behind the first slice.
uint64_t perspective_samples(const Registers& r);

// The largest move of a ray's home from one slice to the next, along
// either axis: the compositor's reach the frame needs (0 without moves).
inline int64_t largest_home_move(const PerspectiveReach& r) {
  int64_t m = 0;
  for (const CellRange* d : {&r.x.drift, &r.y.drift})
    if (!d->empty()) {
      m = -d->lo > m ? -d->lo : m;
      m = d->hi > m ? d->hi : m;
    }
  return m;
}

// Every offset of a perspective frame's registers, over all sample slices
// and every ray that samples them (rays that miss a slice read zero and
// have no home there).
PerspectiveReach perspective_reach(const Registers& r);

}  // namespace cube4::golden
