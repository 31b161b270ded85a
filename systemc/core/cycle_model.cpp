// The cycles of a frame at one voxel per pipeline per clock
// (docs/system.md, "Cycle accounting"):
//   stream  = passes * beams * ceil(nx / p), the steady-state interval
//             passes = nz * S sample slices, + 1 zero pass with gradients;
//             beams  = ny, + 1 flush beam per pass with gradients (the
//             gradient unit's own zero beam takes that slot)
//   flush   = the stream's last flush beam, ceil(nx / p), when passes
//             follow back to back (the next frame's first beam drains the
//             last pass in a stream of frames, in the same cycles)
//   latency = stream + flush + the drain after the last voxel beat (below),
//             measured by the RTL run and asserted equal by the system tests.
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/system.hpp"
#include "systemc/tlm/tlm_shade.hpp"

namespace cube4::sysc {

CycleCount frame_cycles(const golden::Registers& r, int p) {
  const int nx = r.dim[0], ny = r.dim[1];
  const uint64_t B = static_cast<uint64_t>((nx + p - 1) / p);
  const uint64_t passes = static_cast<uint64_t>(r.sample_slices()) + (r.gradient ? 1 : 0);
  const bool flush_each_pass = r.gradient;  // FramePlan::flush_each_pass
  CycleCount c;
  c.stream = passes * static_cast<uint64_t>(ny + (flush_each_pass ? 1 : 0)) * B;
  c.flush = flush_each_pass ? 0 : B;
  // After the stream's last beat (the flush beam's last, which ends a
  // beam), each registered link adds a cycle, then:
  //   interpolation: 3 (a beat that ends a beam leaves the alignment
  //     register at once, then the trilinear's 3 stages: docs/rtl-interp.md);
  //   gradient: its own zero beam of B steps, the alignment register, 3
  //     stages (docs/rtl-gradient.md); without gradients nothing;
  //   shading: cube4_shade_unit's latency; compositing: 7 to the pixel port.
  constexpr uint64_t kLink = 1, kInterpLastBeat = 3, kGradientStages = 3, kComposite = 7;
  const uint64_t shade = static_cast<uint64_t>(shade_latency(r.p));
  const uint64_t gradient = r.gradient ? kLink + B + 1 + kGradientStages : kLink;
  const uint64_t drain = kLink + kInterpLastBeat + gradient + kLink + shade + kLink + kComposite;
  c.latency = c.stream + c.flush + drain;
  return c;
}

}  // namespace cube4::sysc
