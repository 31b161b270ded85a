// Interpolation unit at transaction level: collects a pass of voxel beats
// into a slice, interpolates it with golden SliceInterp (the renderer's
// own), and streams the sample slice out, one beat per clock, after the
// pass has arrived. Its latency is a pass, not the RTL's 4 cycles; the
// stream it emits keeps the ring's protocol (a free cycle for every beat of
// a flush beam: the gradient unit's zero beam runs in them).
//
// With VolumePro's z gradient (plan.zdiff) the stream reads one slice
// ahead after a priming pass (docs/rtl-interp-zdiff.md); the model keeps
// the voxel slices z-1, z and z+1 as the ring's slice store does, and
// emits each sample's interpolated z difference beside it.
#pragma once

#include "golden/slice_steps.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/tlm/beat_queue.hpp"

namespace cube4::sysc {

class TlmInterp final : public InterpIf {
 public:
  explicit TlmInterp(const FramePlan& plan);
  void clock(const VoxelBeat& in, SampleBeat& out) override;
  Level level() const override { return Level::Tlm; }

 private:
  void end_of_pass(const VoxelBeat& in);
  void emit_pass(uint64_t tag);
  const FramePlan& plan_;
  // store_: voxel slice z_voxel; with zdiff below_ and above_ are z_voxel - 1
  // and z_voxel + 1 and the differences D(z), D(z + 1) go to d_lo_, d_hi_.
  golden::Plane pass_, store_, samples_;
  golden::Plane below_, above_, d_lo_, d_hi_, zdiffs_;
  // With voxel tags: the tags of the same voxels and samples (the voxel
  // words' upper bits), and the spans of a whole slice.
  bool tagged_;
  golden::Plane pass_tags_, store_tags_, above_tags_, sample_tags_;
  std::vector<golden::Span> whole_;
  golden::SliceInterp interp_;
  int y_ = 0, j_ = 0;
  BeatQueue<SampleBeat> out_;
};

}  // namespace cube4::sysc
