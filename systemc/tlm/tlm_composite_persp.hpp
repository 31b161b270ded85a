// Compositing of perspective samples at transaction level, clocked: each
// lane's shaded sample is cropped and cut at its place on its slice
// (golden sample_place(), crop_and_cut()) and blended into its ray's
// accumulator, kept by ray index (docs/perspective.md, "Rays and their
// accumulators"), as golden render_perspective() composites it. Every
// sample is blended: golden's skipping of transparent samples and stopped
// rays is exact, so the pixels are the same, and so are the accumulators
// (the full-α rule golden keeps them by). A frame ends with its last
// sample, counted (golden perspective_samples()): then every ray's pixel
// is written (golden write_rays()) and `frame_done` rises kLatency clocks
// later, the parallel compositor's to the pixel port. Without polygons:
// their slabs stay with the loosely timed path (systemc/core/
// perspective_frame.hpp).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "golden/renderers.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"

namespace cube4::sysc {

class TlmCompositePersp final : public PerspCompositeIf {
 public:
  static constexpr int kLatency = 7;

  // `accumulators`: keep each frame's accumulators in its plane (BasePlane::acc).
  TlmCompositePersp(const FramePlan& plan, bool accumulators);
  void clock(const RayShadedBeat& in, CompositeOut& out) override;
  Level level() const override { return Level::Tlm; }

  // The last frame that ended, and how many have.
  const golden::BasePlane& plane() const { return plane_; }
  uint64_t frames_done() const { return frames_done_; }
  uint64_t samples_per_frame() const { return per_frame_; }

 private:
  void composite(const RayShadedBeat& in, size_t lane);
  void end_frame();

  const FramePlan& plan_;
  bool accumulators_;
  int origin_x_, origin_y_;
  uint64_t per_frame_, composited_ = 0, frames_done_ = 0;
  std::vector<golden::RayAcc> rays_;
  golden::BasePlane plane_;
  std::array<bool, kLatency> done_{};  // circular delay line of frame ends
  size_t head_ = 0;
};

}  // namespace cube4::sysc
