// What stands in the gradient unit's place when the scene needs no
// gradients (docs/system.md, effect sets): the samples pass with zero
// gradients (golden Gradient{}), and their position is counted from the
// stream's flags, as the gradient unit would report it. No logic of the
// gradient unit is simulated at either level.
#pragma once
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"

namespace cube4::sysc {

class GradientBypass final : public GradientIf {
 public:
  explicit GradientBypass(const FramePlan& plan) : plan_(plan) {}
  void clock(const SampleBeat& in, GradientBeat& out) override {
    out = GradientBeat{};
    if (!in.valid) return;
    if (in.f.slice_start && in.f.beam_start) y_ = 0;
    out.valid = true;
    out.f = in.f;
    out.x = j_ * plan_.p;
    out.y = y_;
    out.slice = plan_.tag_slice(in.tag);
    out.sample = in.sample;
    out.vtag = in.vtag;
    ++j_;
    if (in.f.beam_end) {
      j_ = 0;
      ++y_;
    }
  }
  Level level() const override { return Level::Tlm; }

 private:
  const FramePlan& plan_;
  int y_ = 0, j_ = 0;
};

// The same for perspective frames: each ray's sample passes on its lane
// with a zero gradient, in the cycle it arrives.
class PerspGradientBypass final : public PerspGradientIf {
 public:
  void clock(const RaySampleBeat& in, RayGradientBeat& out) override {
    out = RayGradientBeat{};
    out.valid = in.valid;
    out.step = in.step;
    out.f = in.f;
    out.pass_tag = in.pass_tag;
    out.sample = in.sample;
    out.u = in.u;
    out.v = in.v;
    out.tag = in.tag;
    out.vtag = in.vtag;
  }
  Level level() const override { return Level::Tlm; }
};

}  // namespace cube4::sysc
