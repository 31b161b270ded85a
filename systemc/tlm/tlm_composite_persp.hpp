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
// later, the parallel compositor's to the pixel port.
// With a polygon frame (Cube-5 in perspective, docs/perspective.md) each
// ray starts from its front image pixel, a sample is blended only in front
// of the ray's Z, each sample is followed by the ray's pixel of its
// slice's slab image (the slab's pixel (x, y) is the slice's ray of rank
// (x, y)), and a ray leaves over its back image pixel: golden
// render_perspective()'s order per ray.
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
  TlmCompositePersp(const FramePlan& plan, bool accumulators, const golden::PolygonFrame* polygons = nullptr);
  void clock(const RayShadedBeat& in, CompositeOut& out) override;
  Level level() const override { return Level::Tlm; }

  // The last frame that ended, and how many have.
  const golden::BasePlane& plane() const { return plane_; }
  uint64_t frames_done() const { return frames_done_; }
  uint64_t samples_per_frame() const { return per_frame_; }

 private:
  void composite(const RayShadedBeat& in, size_t lane);
  void start_frame();
  void end_frame();
  // Slice k's slab image, decoded (the last two slices asked for are kept).
  const std::vector<golden::Pixel>& slab(uint32_t k);

  const FramePlan& plan_;
  bool accumulators_;
  const golden::PolygonFrame* polygons_;
  std::array<std::pair<int64_t, std::vector<golden::Pixel>>, 2> slabs_{{{-1, {}}, {-1, {}}}};
  int origin_x_, origin_y_;
  uint64_t per_frame_, composited_ = 0, frames_done_ = 0;
  std::vector<golden::RayAcc> rays_;
  golden::BasePlane plane_;
  std::array<bool, kLatency> done_{};  // circular delay line of frame ends
  size_t head_ = 0;
};

}  // namespace cube4::sysc
