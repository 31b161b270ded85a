// Sub-cubes: a volume rendered as blocks by several machines and their
// partial images merged by a composition network (bela §II and §III.D;
// VolumePro §4.2's supervolumes). The partitioned image is specified here
// bit for bit: which voxels each block stores, which samples it
// composites, its machine's registers, where its partial image lies in the
// volume's base plane, and the order and rounding of every merge.
//
// - Blocks: each object axis is cut into `counts` pieces as evenly as
//   possible (piece i starts at floor(i·n / count)); a block's *core* is
//   the product of its pieces. Every voxel cell, hence every sample, lies in
//   exactly one core.
// - Borders: a block stores its core plus the voxels its core's samples
//   read: one more voxel after the core on each axis for interpolation, and
//   with gradients one before and two after (the x/y central differences
//   and the 12-neighbourhood's re-aligned slices ahead and behind read the
//   samples one cell away, which read one voxel further), clipped to the
//   volume. Those voxels are duplicated from the neighbouring blocks.
// - Registers: the volume's, translated to the block's stored origin: the
//   same view, tables and widths; the DDA restarted at the block's first
//   sample slice (its integer part dropped, so the weights of every slice
//   are the volume's); crop slabs and the cut plane moved to the block's
//   coordinates; the block window (golden/units/composite_window.hpp) set
//   to the core, so the border's samples are computed for the gradients
//   but not composited.
// - One ray grid: the block's ray at base-plane pixel (u, v) is the
//   volume's ray at (u + u0, v + v0), so every partial image is a rectangle
//   of the volume's base plane. A ray's samples inside a block reach the
//   block's ray store in the same order as in one pass; a ray entering the
//   block starts empty.
// - Visibility order: rays advance towards +x, +y and +z in permuted
//   coordinates, so the blocks sorted by permuted block coordinate z, then
//   y, then x, are front to back for every ray (the order bela's object
//   space processors hand over their images, "most parallel" slices first).
// - Perspective (Cube-4 §3): the same, on the volume's rays from the eye.
//   A block's registers keep the volume's ray indices (ray 0's position and
//   the spacing moved to the block's first slice and origin, so SCALE_START
//   is that slice's spacing, not one), and its border is wider laterally:
//   a core sample's box filter reads one voxel before and two after its
//   cell, and its gradient's neighbouring rays, up to 3 voxels away, as far
//   again: 4 before and 5 after. Rays still advance towards +z, but towards
//   -x (-y) on the eye's one side, so the order is per ray: by z, then y
//   ascending or descending as the ray moves in y, then x likewise; the four
//   orders of a frame are fixed (BlockPlan::order), and a ray's quadrant
//   follows from its slope X_STEP + u·SCALE_STEP (which the composition
//   network's leaf routing selects per pixel).
// - Composition: per base-plane pixel, the blocks' ray accumulators
//   (RayAcc, the accumulator domain, with the empty ray where a block has no
//   such pixel) in visibility order through compose_tree() of
//   golden/units/compose.hpp, then pixel_of(). The empty ray is the node's
//   identity, so a pixel is the tree over the blocks its ray crosses. MIP
//   and MinIP select, never round: their partitioned image equals the one
//   pass image bit for bit. Front-to-back compositing rounds at each merge
//   as well as at each sample: docs/accuracy.md measures the difference.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "golden/registers.hpp"
#include "golden/renderers.hpp"
#include "golden/volume.hpp"

namespace cube4::golden {

struct Block {
  int index = 0;                                 // position in visibility order (0 in front)
  std::array<int, 3> cell{};                     // block coordinates along permuted x, y, z
  std::array<int, 3> core_lo{}, core_hi{};       // permuted voxels composited, [lo, hi)
  std::array<int, 3> store_lo{}, store_hi{};     // permuted voxels stored: core and border
  std::array<int, 3> object_lo{}, object_dim{};  // the stored voxels as an object-space box
  Registers regs;                                // the block machine's registers
  int u0 = 0, v0 = 0;                            // its base plane's pixel (0, 0) in the volume's
  int base_width() const { return regs.base_width(); }
  int base_height() const { return regs.base_height(); }
};

struct BlockPlan {
  std::array<int, 3> counts{1, 1, 1};  // blocks along object x, y, z
  Registers whole;                     // the one-pass registers the blocks derive from
  std::vector<Block> blocks;           // visibility order (parallel projection; perspective: rays moving +x, +y)
  // Front-to-back block indices for rays moving towards -x (bit 0) and -y
  // (bit 1); order[0] is 0, 1, 2, ...; all four are that in parallel projection.
  std::array<std::vector<int>, 4> order;
  // The order the ray of the volume's base-plane pixel (u, v) crosses the blocks in.
  const std::vector<int>& order_at(int u, int v) const;
};

// Smallest core along an axis: a thinner block would store more border than
// core (the border is up to three voxels).
constexpr int kMinBlockCore = 4;
// Largest number of blocks: a composition tree of depth 12.
constexpr int kMaxBlocks = 4096;

// The plan for `whole` (the volume's registers, program_host()) of a volume
// of object size `object_dim`, cut into counts[a] pieces along object axis
// a. Throws InputError naming `what` (the scene key or option) for counts
// that do not divide the volume sensibly or registers a block cannot hold.
BlockPlan plan_blocks(const Registers& whole, const std::array<int, 3>& object_dim,
                      const std::array<int, 3>& counts, const std::string& what);

// The voxels block `b` stores, as a volume of its own (same spacing and width).
Volume block_volume(const Volume& vol, const Block& b);

// Where block b's partial-image pixel (u, v) lies in the volume's base plane.
inline std::array<int, 2> whole_pixel(const Block& b, int u, int v) { return {u + b.u0, v + b.v0}; }

// The composition network's result: the volume's base plane from the
// blocks' partial images (partials[i] is block i's, with its accumulators,
// BasePlane::acc), per pixel compose_tree() in visibility order, then
// pixel_of(). `accumulators` keeps the composed rays in the result's acc.
BasePlane compose_blocks(const BlockPlan& plan, const std::vector<const BasePlane*>& partials,
                         bool accumulators = false);

// A block's partial image by the fixed-point renderer (its accumulators kept).
BasePlane render_block_fixed(const Volume& block_vol, const Block& b, FixedOptions options);
// The partitioned image by the fixed-point renderer: every block rendered,
// then composed. The bit-exact specification of a partitioned render.
BasePlane render_blocks_fixed(const Volume& vol, const BlockPlan& plan, const FixedOptions& options);

}  // namespace cube4::golden
