// The perspective gradient unit at transaction level, clocked: the
// schedule planned for the perspective gradient ring (docs/perspective.md,
// "Gradient"), which its RTL is to follow beat by beat, computed with
// golden's perspective_gradient(). The unit keeps each pass's samples by
// ray as they leave the interpolation unit; at each stream position it
// forms the gradient of the cell gradient_cell() names (its home cell +
// (5, 5) in the next pass), if a ray of that pass has its home there,
// from that pass's samples and those of the passes before and after it,
// and the gradient leaves on the position's lane kLatency clocks later.
// An operand the schedule needs that has not arrived by then is an error
// (std::logic_error naming the ray, slice and position), so the unit
// checks the plan while it runs.
//
// With VolumePro's voxel-difference z gradient (plan.zdiff) a gradient's
// z is its ray's filtered voxel z difference, which came with the sample
// (golden perspective_gradient_voxel_z()); the schedule stays the
// 12-neighbourhood's, so the ring's storage and cycles do not depend on
// the z gradient chosen.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"

namespace cube4::sysc {

class TlmGradientPersp final : public PerspGradientIf {
 public:
  // cube4_gradient's three stages (docs/rtl-gradient.md, "Latency"; the
  // lateral scale sits beside stage 1).
  static constexpr int kLatency = 3;

  explicit TlmGradientPersp(const FramePlan& plan);
  void clock(const RaySampleBeat& in, RayGradientBeat& out) override;
  Level level() const override { return Level::Tlm; }

  uint64_t gradients() const { return gradients_; }

 private:
  // One pass's samples by ray: its slice's rays (golden samples()), each
  // with its value, voxel tag and whether it has arrived.
  struct PassSamples {
    int64_t pass = -1;  // in the stream
    int k = -1;         // its sample slice
    int64_t width = 0;
    std::vector<uint16_t> value;
    std::vector<int32_t> zdiff;  // plan.zdiff only
    std::vector<uint8_t> vtag, arrived;
  };
  PassSamples& pass_for(int64_t pass, int k);
  void take(const RaySampleBeat& in, int lane);
  // Slice k's sample of ray (u, v) from pass `pass` (0 for rays that miss
  // the slice, or a slice the frame does not have); `gradient_at` names the
  // position that asks, for the error when it has not arrived.
  uint32_t sample(int64_t pass, int k, int64_t u, int64_t v, int64_t gradient_at) const;
  void form(int64_t position, int lane, RayGradientBeat& out);

  const FramePlan& plan_;
  int64_t row_;
  std::array<PassSamples, 4> passes_;  // by pass % 4: the stored k - 1 and k, the streaming k + 1, the next arriving
  std::array<RayGradientBeat, kLatency> delay_;
  uint64_t clocks_ = 0, gradients_ = 0;
};

}  // namespace cube4::sysc
