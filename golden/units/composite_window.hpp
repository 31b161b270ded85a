// Block window: the compositor's test of whether a sample belongs to the
// block a machine renders when a volume is split into sub-cubes (bela §II;
// golden/blocks.hpp). A block machine stores its core plus the border its
// interpolation and gradients read (voxels duplicated from the neighbouring
// blocks, VolumePro §4.2); it computes the border's samples, because the
// core's gradients need them, but must composite only the core's, or two
// machines would each add the same sample to a ray. The window is the core,
// in the block machine's permuted voxel coordinates: a sample at cell
// (x, y) of a slice in voxel slice z is composited iff every coordinate lies
// in its inclusive range. It acts with cropping (a sample must pass both),
// which cannot express it: the user's crop table combines three slabs, and a
// window ANDed with an arbitrary table needs three more.
#pragma once
#include <array>
#include <cstdint>

namespace cube4::golden {

struct WindowRegs {
  std::array<std::array<int32_t, 2>, 3> range{{{0, 0}, {0, 0}, {0, 0}}};  // inclusive [lo, hi] per permuted axis
};

constexpr bool window_inside(int32_t x, int32_t y, int32_t z, const WindowRegs& w) {
  return w.range[0][0] <= x && x <= w.range[0][1] && w.range[1][0] <= y && y <= w.range[1][1] &&
         w.range[2][0] <= z && z <= w.range[2][1];
}

}  // namespace cube4::golden
