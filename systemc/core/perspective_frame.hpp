// A perspective frame clocked (Cube-4 §3; docs/system.md, "Perspective
// frames"): the stream former's voxel beats (address generation, skewed
// memory, de-skew; the perspective stream's flush beams at the end)
// through the perspective interpolation unit (clocked TLM or RTL), the
// gradient unit (clocked TLM: the gradient ring's schedule; a bypass
// without gradients), the shading unit and the compositor (clocked TLM), a
// beat a clock with registered links in between: under the SystemC kernel
// (a process for the former and one per unit, on the machine's clock) or
// on a plain loop, with the same cycles, samples, gradients and pixels.
// Every sample and gradient that leaves a unit is kept by its slice and
// ray and checked: each ray of each slice leaves once per frame, and with
// `check` its value equals golden's (the first difference is the frame's
// mismatch). Without a shading unit, shading and compositing run loosely
// timed after the stream, golden render_perspective() given the units'
// samples and gradients (FixedOptions::given_samples, given_gradients).
// With a polygon source the stream waits for each pass's slab image at
// its first beat, as a parallel frame's does (pass_gate.hpp).
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "golden/polygon_frame.hpp"
#include "golden/renderers.hpp"
#include "golden/volume.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/polygon_source.hpp"
#include "systemc/core/stream_former.hpp"
#include "systemc/core/system.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/tlm/tlm_composite_persp.hpp"

namespace cube4::sysc {

struct PerspectiveFrameResult {
  golden::BasePlane plane;
  uint64_t beats = 0;              // voxel beats the former gave, all frames
  uint64_t last_beat_cycle = 0;    // the cycle of the former's last beat
  uint64_t last_sample_cycle = 0;  // the cycle the unit's last sample left
  uint64_t last_gradient_cycle = 0;  // the cycle the gradient unit's last gradient left (0: none ran)
  uint64_t cycles = 0;             // clock cycles simulated
  uint64_t samples = 0;            // samples that left the unit, all frames
  uint64_t gradients = 0;          // gradients that left the gradient unit, all frames
  uint64_t polygon_stall_cycles = 0;  // the first frame's waits for slab images
  // With shading and compositing clocked: the cycle each frame's end left
  // the compositor (its last pixel written), frame by frame.
  std::vector<uint64_t> frame_done_cycles;
  std::optional<Mismatch> mismatch;
};

struct PerspectiveFrameInput {
  const FramePlan& plan;
  const golden::Volume& vol;
  int frames = 1;
  bool check = false;
  bool accumulators = false;
  const golden::PolygonFrame* polygons = nullptr;
  golden::Progress progress;
  PolygonSource* source = nullptr;  // the slab images' connection in time, or none (ideal)
  Kernel kernel = Kernel::SystemC;
};

// The units behind the stream former, in pipeline order. `gradient`: the
// gradient unit, or none (gradients loosely timed, golden's from the
// interpolation unit's samples; or, with shading clocked and no gradients
// in the scene, a bypass). `shade` and `composite`: shading and
// compositing clocked, or none (loosely timed after the stream).
struct PerspectiveUnits {
  PerspInterpIf& interp;
  PerspGradientIf* gradient = nullptr;
  PerspShadeIf* shade = nullptr;
  PerspCompositor* composite = nullptr;
};
PerspectiveFrameResult run_perspective_frame(const PerspectiveFrameInput& in, StreamFormer& former,
                                             const PerspectiveUnits& units);
inline PerspectiveFrameResult run_perspective_frame(const PerspectiveFrameInput& in, StreamFormer& former,
                                                    PerspInterpIf& interp, PerspGradientIf* gradient = nullptr) {
  return run_perspective_frame(in, former, PerspectiveUnits{interp, gradient});
}

}  // namespace cube4::sysc
