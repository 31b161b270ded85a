// Compositing of perspective samples at transaction level, clocked, on the
// compositing ring's plan (docs/perspective.md, "The plan for the
// compositing ring"), which its RTL is to follow beat by beat: each lane's
// shaded sample is blended `reach` stream positions after it arrives (its
// lane + reach), cropped and cut at its place on its slice (golden
// sample_place(), crop_and_cut()), into its ray's accumulator of the slice
// before, read from the store of that slice's parity at the ray's home
// there (at most `reach` cells away), or the empty accumulator where the
// ray enters. The new accumulator is stored at the ray's home, ready
// kLatency + reach steps after the blend (the blend's stages, then reach
// lanes back); a ray that does not sample the next slice writes its pixel
// instead (golden write_ray()). An accumulator that is not stored yet, or
// no longer, when its ray blends again, or a move beyond the reach, is an
// error (std::logic_error naming the ray and slice), so the unit checks the
// plan while it runs. Every sample is blended: golden's skipping of
// transparent samples and stopped rays is exact, so the pixels are the
// same, and so are the accumulators (the full-α rule golden keeps them by).
// A frame ends with its last sample, counted (golden
// perspective_samples()): then the pixels of rays that sampled nothing are
// written and `frame_done` rises kLatency clocks later, the parallel
// compositor's to the pixel port.
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
#include "systemc/core/persp_polygon_pixels.hpp"
#include "systemc/core/unit_if.hpp"

namespace cube4::sysc {

class TlmCompositePersp final : public PerspCompositor {
 public:
  static constexpr int kLatency = 7;

  // `accumulators`: keep each frame's accumulators in its plane (BasePlane::acc).
  TlmCompositePersp(const FramePlan& plan, bool accumulators, const golden::PolygonFrame* polygons = nullptr,
                    int reach = kPerspectiveReach);
  void clock(const RayShadedBeat& in, CompositeOut& out) override;
  Level level() const override { return Level::Tlm; }

  // The last frame that ended, and how many have.
  const golden::BasePlane& plane() const override { return plane_; }
  uint64_t frames_done() const { return frames_done_; }
  uint64_t samples_per_frame() const override { return per_frame_; }

 private:
  struct Sample {  // one lane of a shaded beat
    uint16_t red, green, blue, alpha, value;
    int32_t u, v;
    uint32_t k;
  };
  struct Stored {  // a ray's accumulator in a store
    golden::RayAcc acc;
    int64_t pass = -1;  // frame * K + slice: which slice of which frame
    int64_t u = 0, v = 0;
    int64_t ready = 0;  // the step from which it can be read
  };
  void blend(const Sample& in, int64_t position, int64_t step);
  void start_frame();
  void end_frame();

  const FramePlan& plan_;
  bool accumulators_;
  const golden::PolygonFrame* polygons_;
  PerspPolygonPixels polygon_pixels_;
  int reach_;
  int origin_x_, origin_y_;
  uint64_t per_frame_, composited_ = 0, frames_done_ = 0;
  // Samples waiting for their blend, by the stream position that blends it
  // (modulo the 2p + reach positions a sample can wait over).
  struct Pending {
    int64_t position = -1;
    Sample sample;
  };
  std::vector<Pending> pending_;
  std::array<std::vector<Stored>, 2> stores_;  // by pass parity, home row * nx + column
  golden::BasePlane frame_, plane_;       // the frame being written, the last one done
  std::vector<uint8_t> written_;          // the frame's pixels written (their rays left)
  std::array<bool, kLatency> done_{};     // circular delay line of frame ends
  size_t head_ = 0;
};

}  // namespace cube4::sysc
