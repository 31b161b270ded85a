// Shading at transaction level: golden shade_classified() per lane (as
// shade_with() of the gradient's cached shading), on a
// delay line as long as cube4_shade_unit's latency, so that the shading
// stage takes the same cycles at both levels.
//
// With `skip_transparent` (nothing but TLM compositing reads the stream: no
// --check, no RTL compositor) a sample that cannot change its ray
// (golden::sample_cannot_change_ray) is not shaded: it streams its value,
// α = 0 and black, which the compositor steps over as it would the shaded
// sample (golden::blend_changes_ray); with `stops` (the TLM compositor) so
// does a sample on a ray the compositor has stopped.
#pragma once
#include <memory>
#include <vector>

#include "golden/pipeline.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/tlm/tlm_composite.hpp"

namespace cube4::sysc {

// cube4_shade_unit's latency: magnitude (NrIterations + 1), then the
// shader: reflection 4 + cube coordinates (1 + ceil((log2 res + W) / 2)) +
// reflectance 3 + phong 3 (rtl/cube4_shade.sv, DivBitsPerStage = 2).
int shade_latency(const golden::Precision& p);

class TlmShade final : public ShadeIf {
 public:
  explicit TlmShade(const FramePlan& plan, bool skip_transparent = false, const TlmComposite* stops = nullptr);
  void clock(const GradientBeat& in, ShadedBeat& out) override;
  Level level() const override { return Level::Tlm; }

 private:
  const FramePlan& plan_;
  bool skip_transparent_;
  const TlmComposite* stops_;
  uint64_t frame_ = 0;  // the frame of the beat coming in, from 1
  std::unique_ptr<golden::FacePositionTable> faces_;
  golden::GradientShadingCache shading_;  // the golden renderer's: equal gradients shade alike
  std::vector<ShadedBeat> line_;  // circular delay line
  size_t head_ = 0;
};

}  // namespace cube4::sysc
