// Shading of perspective samples at transaction level, clocked: golden
// shade_with() per lane of the gradient unit's ray beats (the parallel
// shading unit's functions: a perspective sample shades as a parallel one
// does, docs/perspective.md, "Gradient"), on a delay line as long as
// cube4_shade_unit's latency (shade_latency()), the stage the perspective
// ring is to keep. Each lane keeps its ray and slice.
#pragma once
#include <memory>
#include <vector>

#include "golden/pipeline.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"

namespace cube4::sysc {

class TlmShadePersp final : public PerspShadeIf {
 public:
  explicit TlmShadePersp(const FramePlan& plan);
  void clock(const RayGradientBeat& in, RayShadedBeat& out) override;
  Level level() const override { return Level::Tlm; }

 private:
  const FramePlan& plan_;
  std::unique_ptr<golden::FacePositionTable> faces_;
  golden::GradientShadingCache shading_;  // the golden renderer's: equal gradients shade alike
  std::vector<RayShadedBeat> line_;       // circular delay line
  size_t head_ = 0;
};

}  // namespace cube4::sysc
