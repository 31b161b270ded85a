// The perspective dataflow of the rings (docs/perspective.md, "The
// dataflow"): where the pipelines form a ray's sample, and how far the
// rings must reach for its box, its gradient's neighbours and its
// accumulator. The pipelines hold the voxel columns (x = j * p + k); a
// ray's sample is formed at its home, the voxel column and row its
// position lies in, so that every unit keeps the parallel units' near-
// neighbour links and a pass keeps its ny beams.
#pragma once
#include <array>
#include <cstdint>

#include "golden/perspective.hpp"
#include "golden/registers.hpp"
#include "golden/units/dda.hpp"
#include "golden/units/dda_perspective.hpp"

namespace cube4::golden {

// A ray's home on a slice along one axis: the cell floor(pos) its position
// lies in. Rays at least one voxel apart have distinct homes, and a ray
// that samples the slice (0 <= pos < n) has its home in the volume.
constexpr int64_t home_cell(int64_t pos, int frac_bits) { return pos >> frac_bits; }

// Which ray has its home in a given cell of one axis, the question the
// rings' lanes ask (cube4_persp_lanes: lane k of step j holds cell
// j * lanes + k; along x the steps are a beam's partial beams and the lanes
// the p pipelines, along y the steps are a pass's beams, one lane). The
// ray's box (box_axis()) starts at the home or one cell before it.
struct HomeLane {
  bool valid = false;     // a ray of `rays` has its home in the cell
  int64_t ray = 0;        // that ray
  bool box_left = false;  // its box starts at home - 1 (else at home)
  BoxAxis box;            // box_axis() of its position
  uint32_t weight = 0;    // its position's fraction, weight_bits (dda_split(): sample_place())
};
inline HomeLane home_lane(int64_t ray0, int64_t spacing, RayRange rays, int64_t cell, int frac_bits,
                          int weight_bits) {
  HomeLane h;
  // The first ray at or after the cell's start (spacing >= 1: no earlier
  // ray can have its home there).
  const int64_t u = ceil_div(cell * (int64_t{1} << frac_bits) - ray0, spacing);
  if (u < rays.lo || u >= rays.hi) return h;
  const int64_t pos = ray_position(ray0, spacing, u);
  if (home_cell(pos, frac_bits) != cell) return h;
  h.valid = true;
  h.ray = u;
  h.box = box_axis(pos, spacing, frac_bits, weight_bits);
  h.box_left = h.box.first < cell;
  h.weight = dda_split(pos, frac_bits, weight_bits).weight;
  return h;
}

// Where the interpolation ring forms a sample (docs/perspective.md, "The
// dataflow"): a stream of passes back to back, ny beams of `row` = B * p
// positions each (position j * p + k: pipeline k's column in partial beam
// j), forms at each position the cell two columns back in the beam two
// back, so a pass's last cells spill into the next pass's (or the flush
// beams') first positions. formed_cell(position) is that cell: its pass
// (counted from the stream's first), column and row; invalid where the
// cell lies before the stream or in a beam's padding (x >= nx).
struct FormedCell {
  bool valid = false;
  int64_t pass = 0, x = 0, y = 0;
};
// The cell of a pass that a unit works on at `position` when it works on
// each cell `beams` beams and `columns` columns after the stream reads it.
inline FormedCell cell_behind(int64_t position, int64_t beams, int64_t columns, int64_t row, int nx, int ny) {
  FormedCell c;
  const int64_t q = position - beams * row - columns;
  if (q < 0) return c;
  const int64_t beam = q / row;
  c.x = q % row;
  c.pass = beam / ny;
  c.y = beam % ny;
  c.valid = c.x < nx;
  return c;
}
constexpr int kFormedAfterColumns = 2, kFormedAfterBeams = 2;
inline FormedCell formed_cell(int64_t position, int64_t row, int nx, int ny) {
  return cell_behind(position, kFormedAfterBeams, kFormedAfterColumns, row, nx, ny);
}
// Its inverse: the stream position that forms cell (x, y) of a pass.
constexpr int64_t forming_position(int64_t pass, int64_t x, int64_t y, int64_t row, int ny) {
  return (pass * ny + y + kFormedAfterBeams) * row + x + kFormedAfterColumns;
}

// Where the gradient ring is to form a ray's gradient (docs/perspective.md,
// "Gradient"): at its home cell + (5, 5) in the next pass. The operands
// straight ahead have their homes at most three cells further on in each
// axis and are formed two cells after those (formed_cell()), so by then
// every operand has been formed; one gradient per cell keeps the passes
// back to back. gradient_cell(position) is the cell, of the pass before
// the one streaming at `position`, whose gradient that position forms; a
// stream's last slice spills up to six beams past the pass after it.
constexpr int kGradientAfterColumns = 5, kGradientAfterBeams = 5;
inline FormedCell gradient_cell(int64_t position, int64_t row, int nx, int ny) {
  FormedCell c = cell_behind(position, kGradientAfterBeams, kGradientAfterColumns, row, nx, ny);
  c.valid = c.valid && c.pass >= 1;
  c.pass -= 1;
  return c;
}
// Its inverse: the stream position that forms the gradient of cell (x, y) of a pass.
constexpr int64_t gradient_forming_position(int64_t pass, int64_t x, int64_t y, int64_t row, int ny) {
  return ((pass + 1) * ny + y + kGradientAfterBeams) * row + x + kGradientAfterColumns;
}

// The homes, along one axis, of ray u's gradient operands
// (docs/perspective.md, "The plan for the ring's RTL"): a ray's home column
// depends on u alone and its home row on v alone, so the question is asked
// once per axis, and the gradient ring's per-lane selection (along x) and
// its rows per beam (along y) are its two uses. cube4_gradient_persp_homes
// computes it bit for bit. kNoRow: that ray misses its slice along the
// axis (the operand reads zero; nothing is stored for it).
constexpr int64_t kNoRow = INT64_MIN;
struct AxisSlice {  // one axis of a PerspectiveSlice
  int64_t ray0 = 0, spacing = 0;
  RayRange rays;
};
inline AxisSlice axis_slice(const PerspectiveSlice& s, int axis) {
  return axis == 0 ? AxisSlice{s.ray0_x, s.spacing, s.rays_x} : AxisSlice{s.ray0_y, s.spacing, s.rays_y};
}
// Ray a's home on a slice along the axis, or kNoRow where it misses it.
inline int64_t ray_home(const AxisSlice& on, int64_t a, int frac_bits) {
  return a >= on.rays.lo && a < on.rays.hi ? home_cell(ray_position(on.ray0, on.spacing, a), frac_bits) : kNoRow;
}
struct OperandHomes {
  int64_t home = 0;                                                       // ray u's own, on slice k
  std::array<int64_t, 2> side{kNoRow, kNoRow};                            // rays u - 1, u + 1 on slice k
  std::array<int64_t, 2> behind{kNoRow, kNoRow}, ahead{kNoRow, kNoRow};  // rays q, q + 1 of slices k -/+ 1
  uint32_t behind_weight = 0, ahead_weight = 0;  // the realigned points' weights between q and q + 1
};
// u: a ray of `here` along the axis; `behind`, `ahead`: slices k -/+ 1 along
// it, or null at the frame's ends; `to_behind`, `to_ahead`: slice k's
// realignments into them (PerspectiveSlice::behind_x and so on).
OperandHomes gradient_operand_homes(const AxisSlice& here, const AxisSlice* behind, const RealignDda& to_behind,
                                    const AxisSlice* ahead, const RealignDda& to_ahead, int64_t u, int frac_bits,
                                    int weight_bits);

// The rows of slices k - 1, k and k + 1 that the gradients of one beam read:
// every gradient of slice k whose home row is Y reads the same rows
// (gradient_operand_homes() along y).
struct GradientRows {
  bool valid = false;  // a ray of slice k has its home row at Y
  int64_t v = 0;       // that ray
  int64_t up = kNoRow, down = kNoRow;  // home rows of rays v - 1 and v + 1 on slice k
  std::array<int64_t, 2> behind{kNoRow, kNoRow}, ahead{kNoRow, kNoRow};  // of rays py, py + 1 on slices k -/+ 1
};
// `behind` and `ahead`: slices k - 1 and k + 1, or null at the frame's ends.
GradientRows gradient_rows(const Registers& r, const PerspectiveSlice& s, const PerspectiveSlice* behind,
                           const PerspectiveSlice* ahead, int64_t Y);

// Where the gradient of ray u of slice s finds its operands in the ring's
// window (docs/perspective.md, "The plan for the ring's RTL"): the lane of
// each operand's stored sample (its home column + 2), counted back from the
// lane that forms the gradient (the ray's home column + 5), so 0 .. 6 (the
// window's own packet and the six to its left); -1 where the operand's ray
// misses its slice (it reads zero). left, right: rays u -/+ 1 of slice s;
// behind, ahead: rays px, px + 1 of slices k -/+ 1 (null at the frame's ends).
struct GradientWindow {
  int left = -1, right = -1;
  std::array<int, 2> behind{-1, -1}, ahead{-1, -1};
};
GradientWindow gradient_window(const Registers& r, const PerspectiveSlice& s, const PerspectiveSlice* behind,
                               const PerspectiveSlice* ahead, int64_t u);

// Where the compositing ring is to blend a ray's sample (docs/perspective.md,
// "The plan for the compositing ring"): the accumulator of a ray's sample
// of slice k is stored on the lane of its home + 5 (its gradient's lane),
// and the ray's accumulator of slice k - 1 lies at its home there, at most
// `reach` cells away in either axis (largest_home_move()). So the sample is
// blended `reach` columns after its gradient, where the 2 reach + 1 lanes
// home + 5 - reach .. home + 5 + reach that may store its accumulator lie
// at or before the blending lane (the window, 0 .. 2 reach back), and the
// new accumulator goes back `reach` lanes to be stored: the one link
// against the ring's direction, as Cube-4's compositing units have.
constexpr int64_t composite_after_columns(int reach) { return kGradientAfterColumns + reach; }
inline FormedCell composite_cell(int64_t position, int64_t row, int nx, int ny, int reach) {
  FormedCell c = cell_behind(position, kGradientAfterBeams, composite_after_columns(reach), row, nx, ny);
  c.valid = c.valid && c.pass >= 1;
  c.pass -= 1;
  return c;
}
// Its inverse: the stream position that blends the sample of cell (x, y) of a pass.
constexpr int64_t composite_position(int64_t pass, int64_t x, int64_t y, int64_t row, int ny, int reach) {
  return gradient_forming_position(pass, x, y, row, ny) + reach;
}

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
