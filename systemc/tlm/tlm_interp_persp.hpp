// The perspective interpolation unit at transaction level, clocked: the
// stream and timing of the perspective ring (cube4_interp_persp_ring,
// docs/rtl-interp-persp.md) computed with golden's functions. Each stream
// position forms the cell golden formed_cell() names, if a ray of that
// pass has its home there (home_lane() along x and along y), with
// perspective_sample() over the pass's two voxel slices; the sample leaves
// on that position's lane 4 clocks after the beat that formed it, as the
// ring's does. So its samples, lanes and cycles are the ring's, and the
// system tests compare the two beat by beat.
//
// The voxel slices are the ring's: each pass's streamed slice, and the
// stored slice of the last pass with wz = 0 (cube4_slice_store), which a
// pass with wz > 0 reads as its lower slice.
//
// With VolumePro's z gradient (plan.zdiff) each sample also carries its
// filtered voxel z difference (golden perspective_z_difference()), which
// needs voxel slices z - 1 .. z + 2: the stream reads one slice ahead
// after a priming pass, as the parallel unit's (docs/rtl-interp-zdiff.md):
// the priming pass and each wz = 0 pass stream z + 1 and move the stored
// slices down by one (z - 1, z, z + 1), the others stream z + 2. The
// priming pass forms no samples.
#pragma once
#include <array>
#include <cstdint>
#include <memory>

#include "golden/slice_steps.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"

namespace cube4::sysc {

class TlmInterpPersp final : public PerspInterpIf {
 public:
  explicit TlmInterpPersp(const FramePlan& plan);
  void clock(const VoxelBeat& in, RaySampleBeat& out) override;
  Level level() const override { return Level::Tlm; }

 private:
  // A voxel slice with its tags (the memory words' upper bits).
  struct Slice {
    golden::Plane voxels, tags;
  };
  // What a pass forms its samples from, kept until its last cell is formed
  // (during the next pass's first beams, or the flush beams).
  struct Pass {
    int64_t index = -1;  // in the stream
    uint64_t tag = 0;    // its stream tag: the sample slice k (K: the zero pass)
    bool prime = false;  // the priming pass (zdiff): no samples
    std::shared_ptr<const Slice> lo, hi;
    std::shared_ptr<const Slice> below, above;  // zdiff: voxel slices z - 1 and z + 2 (wz > 0 only)
  };
  std::shared_ptr<Slice> new_slice() const;
  void start_pass(const VoxelBeat& in);
  void form(int64_t position, int lane, RaySampleBeat& out) const;

  const FramePlan& plan_;
  int voxel_bits_;
  bool tagged_;
  std::array<Pass, 2> passes_;          // by index % 2: the streaming pass and the one before
  std::shared_ptr<Slice> streaming_;    // the streaming pass's slice, being written
  std::shared_ptr<const Slice> store_;  // the last slice a pass with wz = 0 streamed; zdiff: z
  std::shared_ptr<const Slice> below_, above_;  // zdiff: z - 1 and z + 1
  int64_t pass_ = -1, steps_ = 0;       // the streaming pass; valid beats so far
  int y_ = 0, j_ = 0;
  std::array<RaySampleBeat, 4> delay_;  // the ring's 4 cycles, by clock % 4
  uint64_t clocks_ = 0;
};

}  // namespace cube4::sysc
