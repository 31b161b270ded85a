// Compositing unit at transaction level: collects a slice of shaded samples,
// then crops, cuts, aligns and blends it with the golden SliceCompositor
// (the renderer's own), which writes the leaving rays into pixel memory.
// Latency: a slice.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "golden/slice_steps.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/pixel_memory.hpp"
#include "systemc/core/unit_if.hpp"

namespace cube4::sysc {

class TlmComposite final : public CompositeIf {
 public:
  TlmComposite(const FramePlan& plan, PixelMemory& pixels);
  void clock(const ShadedBeat& in, CompositeOut& out) override;
  Level level() const override { return Level::Tlm; }

 private:
  const FramePlan& plan_;
  PixelMemory& pixels_;
  std::optional<golden::SliceCompositor> compositor_;  // a new one per frame
  std::vector<golden::ShadedSample> slice_;
};

}  // namespace cube4::sysc
