// --check: every unit's output stream against golden, sample by sample. The
// golden values come from render_fixed() (samples and gradients through its
// SampleProbe); shaded samples are golden shade_classified() of those. The
// first difference is kept with its unit, slice and position, so a wrong
// base plane is traced to the unit that first went wrong.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "golden/volume.hpp"
#include "systemc/core/beats.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/system.hpp"

namespace cube4::sysc {

class StreamChecker {
 public:
  StreamChecker(const FramePlan& plan, const golden::Volume& vol);
  void samples(const SampleBeat& b);
  void gradients(const GradientBeat& b);
  void shaded(const ShadedBeat& b);
  std::optional<Mismatch> first_mismatch() const;
  const golden::BasePlane& golden_plane() const { return plane_; }

 private:
  size_t index(int k, int x, int y) const {
    return (static_cast<size_t>(k) * plan_.ny + static_cast<size_t>(y)) * plan_.nx + static_cast<size_t>(x);
  }
  void mismatch(Unit u, int k, int x, int y, const std::string& expected, const std::string& got);

  const FramePlan& plan_;
  std::vector<uint16_t> sample_;
  std::vector<golden::Gradient> gradient_;
  std::vector<uint8_t> vtag_;  // each sample's voxel tag (all 0 without tags)
  golden::BasePlane plane_;
  std::array<std::optional<Mismatch>, kUnits> first_{};
  int sample_y_ = 0, sample_j_ = 0;
};

}  // namespace cube4::sysc
