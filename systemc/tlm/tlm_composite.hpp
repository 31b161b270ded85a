// Compositing unit at transaction level: collects a slice of shaded samples,
// then crops, cuts, aligns and blends it with the golden SliceCompositor
// (the renderer's own), which writes the leaving rays into pixel memory.
// With a polygon frame the compositor draws the polygons too (the front
// image, the Z test, each slice's slab, the back image). Latency: a slice.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "golden/empty_space.hpp"
#include "golden/slice_steps.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/pixel_memory.hpp"
#include "systemc/core/unit_if.hpp"

namespace cube4::sysc {

class TlmComposite final : public CompositeIf {
 public:
  TlmComposite(const FramePlan& plan, PixelMemory& pixels, const golden::PolygonFrame* polygons = nullptr);
  void clock(const ShadedBeat& in, CompositeOut& out) override;
  Level level() const override { return Level::Tlm; }
  // Whether sample (x, y) of slice k of the `frame`-th frame (from 1) lies on
  // a ray this compositor has stopped, as the golden renderer stops rays
  // (golden::RayStop): the units ahead need not compute it. They run ahead,
  // a frame's first slices while the last of the frame before are
  // composited, so a frame not yet begun here has no stopped ray.
  bool ray_stopped(uint64_t frame, uint32_t k, int x, int y) const {
    return compositor_ && frame == frames_ && compositor_->ray_stopped(plan_.slices[k], x, y);
  }

 private:
  const FramePlan& plan_;
  PixelMemory& pixels_;
  const golden::PolygonFrame* polygons_;
  std::optional<golden::SliceCompositor> compositor_;  // a new one per frame, from its first slice
  uint64_t frames_ = 0;                                 // frames begun
  std::vector<golden::ShadedSample> slice_;
  // Per beam of the slice being collected: the samples that may change
  // their ray (golden::blend_changes_ray before cropping and cutting, which
  // only take opacity and visibility away), so that the compositor visits
  // no more of the beam than those.
  std::vector<golden::Span> changing_;
};

}  // namespace cube4::sysc
