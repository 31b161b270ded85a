// Exact empty-space skipping for the fixed-point renderer: which samples of
// a frame can change a ray at all, found from the voxel ranges of blocks.
//
// Why it is exact. A composited sample whose classified α is 0 leaves its
// ray unchanged (blend_front_to_back adds mul_frac(T, 0) = 0), and every
// later step (GmLUT modulation, cut plane, cropping) only lowers α or hides
// the sample. A trilinear sample lies between the smallest and the largest of
// its eight voxels (lerp never leaves its operands' interval), so if no value
// in the range of the voxels around a cell has a non-zero α in the
// classification table, no sample inside that cell can change a ray.
// Blocks overlap by one voxel so that every cell (2x2x2 voxels) lies inside
// one block. Samples that cannot change a ray are still computed where a
// sample that can needs them: its gradient reads the samples one step away
// in x, y and the neighbouring sample slices (docs/fixed-point.md).
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "golden/registers.hpp"
#include "golden/volume.hpp"

namespace cube4::golden {

// A half-open range of x in one beam; empty when begin >= end.
struct Span {
  int32_t begin = 0, end = 0;
  bool empty() const { return begin >= end; }
  int32_t size() const { return empty() ? 0 : end - begin; }
};

inline Span hull(Span a, Span b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.begin, b.begin), std::max(a.end, b.end)};
}

// The smallest and largest voxel of every block of the volume, in object
// axes. Block b along an axis holds voxels kBlock·b .. kBlock·b + kBlock
// (one voxel shared with the next block). Blocks on the volume's faces count
// the zero outside it too, since a cell there reads it.
struct BlockRanges {
  static constexpr int kBlock = 8;
  std::array<int, 3> dim{0, 0, 0};     // voxels
  std::array<int, 3> blocks{0, 0, 0};  // blocks per axis
  std::vector<uint16_t> lo, hi;        // x fastest
  size_t index(int bx, int by, int bz) const {
    return (static_cast<size_t>(bz) * blocks[1] + by) * blocks[0] + bx;
  }
};

BlockRanges block_ranges(const Volume& vol);

// For one frame: per voxel slice z and beam y, the cells that may hold a
// sample that changes its ray, and from them the samples and voxels the
// renderer has to compute. Without skipping (MIP, MinIP, a probe that sees
// every sample) every span is the whole beam.
class SkipMap {
 public:
  // `ranges` == nullptr: no skipping.
  SkipMap(const Registers& r, const BlockRanges* ranges);

  bool skipping() const { return skipping_; }
  // Samples of sample slices in voxel slice z, beam y, that may change their ray.
  Span visible(int z, int y) const {
    if (!skipping_) return {0, nx_};
    if (z < 0 || z >= nz_ || y < 0 || y >= ny_) return {};
    return spans_[bz_[static_cast<size_t>(z)] * by_count_ + by_[static_cast<size_t>(y)]];
  }
  // Samples of sample slice k, beam y, to interpolate: the visible ones and
  // what their gradients read.
  Span samples_needed(int k, int y) const;
  // Voxels of voxel slice z, beam y, to load: what the needed samples of the
  // sample slices between z - 1 and z + 1 read.
  Span voxels_needed(int z, int y) const;

 private:
  // Hull of visible(z, y') over y' within the gradient's reach of y.
  Span rows(int z, int y) const {
    if (y < 0 || y >= ny_) return {};
    return rows_[bz_[static_cast<size_t>(z)] * static_cast<size_t>(ny_) + y];
  }
  Span grown(Span s, int left, int right) const {
    if (s.empty()) return {};
    return {std::max(s.begin - left, 0), std::min(s.end + right, nx_)};
  }
  bool skipping_ = false;
  int nx_ = 0, ny_ = 0, nz_ = 0, supersampling_ = 1, reach_ = 0;
  int by_count_ = 0;
  std::vector<int> by_, bz_;  // block of the cells of beam y / voxel slice z
  std::vector<Span> spans_;   // per (block z, block y): hull of possibly visible cells
  std::vector<Span> rows_;    // per (block z, beam y): rows() precomputed
};

}  // namespace cube4::golden
