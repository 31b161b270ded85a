// A clocked perspective frame's gradients (the gradient unit's,
// systemc/tlm/tlm_gradient_persp.hpp) by slice and ray, as the renderer
// asks for them, with each ray's arrivals counted: one per frame streamed,
// the same each frame. After the stream, with `check`, each is compared
// with golden perspective_gradient() of the samples the interpolation unit
// gave (which the frame checks against golden's), so that a mismatch here
// is the gradient unit's own. Which rays sample a slice is golden's
// (FrameRays), whatever weight generator the units ran with.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "golden/perspective.hpp"
#include "golden/renderers.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/frame_rays.hpp"
#include "systemc/core/system.hpp"

namespace cube4::sysc {

class RayGradients final : public golden::PerspectiveGradients {
 public:
  RayGradients(const FramePlan& plan, const FrameRays& rays, int frames);

  golden::Gradient gradient(int k, int64_t u, int64_t v) const override;

  // One gradient that left the unit on some lane.
  void take(uint32_t k, int64_t u, int64_t v, const golden::Gradient& g);
  // After the stream: the first ray without its `frames` gradients, then
  // (with check) the first whose gradient is not golden's from `samples`
  // (and with VolumePro's z gradient each ray's `z_difference`, which came
  // with its sample).
  using ZDifferences = std::function<int32_t(int k, int64_t u, int64_t v)>;
  void finish(const golden::PerspectiveSamples& samples, bool check, const ZDifferences& z_difference);

  uint64_t taken() const { return taken_; }
  const std::optional<Mismatch>& first() const { return first_; }

 private:
  struct Slice {
    std::vector<int16_t> gx, gy, gz;
    std::vector<int> count;
  };
  void fail(int k, int64_t u, int64_t v, const std::string& expected, const std::string& got);

  const FramePlan& plan_;
  const FrameRays& rays_;
  int frames_;
  std::vector<Slice> slices_;
  uint64_t taken_ = 0;
  std::optional<Mismatch> first_;
};

}  // namespace cube4::sysc
