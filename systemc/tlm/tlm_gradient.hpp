// Gradient unit at transaction level: collects sample slices, and when
// slice s+1 (or the next frame's first slice, or the stream's zero slice:
// then with zeros ahead) has arrived, computes the gradients of slice s with
// golden gather_neighbourhood() + sample_gradient() and streams them out.
// Latency: a slice, where the RTL takes a beam.
//
// With `skip_transparent` (set by run_frame() when nothing but TLM shading
// and compositing reads the stream: no --check, no RTL unit behind it) the
// gradient of a sample that cannot change its ray
// (golden::sample_cannot_change_ray) is not computed and streams as zero;
// with `stops` (the TLM compositor, on the same thread) neither is that of
// a sample on a ray the compositor has stopped.
#pragma once

#include "golden/slice_steps.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/tlm/beat_queue.hpp"
#include "systemc/tlm/tlm_composite.hpp"

namespace cube4::sysc {

class TlmGradient final : public GradientIf {
 public:
  explicit TlmGradient(const FramePlan& plan, bool skip_transparent = false, const TlmComposite* stops = nullptr);
  void clock(const SampleBeat& in, GradientBeat& out) override;
  Level level() const override { return Level::Tlm; }

 private:
  void emit_current(const golden::Plane& ahead);
  const FramePlan& plan_;
  bool skip_transparent_;
  const TlmComposite* stops_;
  uint64_t frame_ = 0;  // the frame of current_slice_, from 1
  golden::Plane behind_, current_, ahead_;
  golden::Plane zeros_;  // ahead of a frame's last slice
  // The voxel tags of the current and ahead slices' samples (the centre's
  // tag travels with it; no tag of a neighbour is used).
  golden::Plane tags_current_, tags_ahead_;
  // With VolumePro's z gradient (plan.zdiff): the interpolated z
  // differences of those slices' samples (the centre's, like its tag).
  golden::Plane zdiff_current_, zdiff_ahead_;
  int current_slice_ = -1;  // none yet in this frame
  int y_ = 0, j_ = 0;
  BeatQueue<GradientBeat> out_;
};

}  // namespace cube4::sysc
