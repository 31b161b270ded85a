// The cycles of a frame at one voxel per pipeline per clock
// (docs/system.md, "Cycle accounting"):
//   stream  = nz * S passes * ny beams * ceil(nx / p): the steady-state
//             interval of frames back to back; with VolumePro's z gradient
//             one pass more, the frame's priming pass (docs/rtl-interp-zdiff.md)
//   flush   = what ends a stream after its last frame: the zero pass when
//             the gradient unit runs (ny beams) and one flush beam, in
//             beams of ceil(nx / p) (in a stream of frames the next frame's
//             first pass and first beam do their work in the same cycles)
//   latency = stream + flush + the drain after the last voxel beat (below),
//             measured by the RTL run and asserted equal by the system tests;
//             a frame another follows (latency_followed) waits with VolumePro's
//             z gradient for the next frame's priming pass too
// A perspective frame (docs/perspective.md, "The dataflow") streams the
// same passes (the priming pass too, with VolumePro's z gradient) and ends
// with three flush beams, not one, or six with the gradient ring
// (stream_flush_beams()). Its units are clocked by ray,
// so its latency is that of the frame's last-formed ray: the stream
// position that forms its gradient (gradient_forming_position(): its home
// cell + (5, 5) in the next pass), or without gradients its sample
// (forming_position()), counted from the frame's first pass (the priming
// pass's positions come before), a beat a cycle from cycle 1; then the links, the
// interpolation ring's 4 cycles, the gradient ring's 3 (no zero beam), the
// shading unit, and the compositor's 7 from the step that blends it,
// kPerspectiveReach positions later (systemc/tlm/tlm_composite_persp.hpp).
#include <algorithm>

#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/system.hpp"
#include "systemc/tlm/tlm_composite_persp.hpp"
#include "systemc/tlm/tlm_gradient_persp.hpp"
#include "systemc/tlm/tlm_shade.hpp"

namespace cube4::sysc {

int64_t last_ray_position(const golden::Registers& r, int p) {
  const int nx = r.dim[0], ny = r.dim[1], F = r.p.dda_frac_bits;
  const int64_t row = static_cast<int64_t>((nx + p - 1) / p) * p;
  int64_t last = -1;
  // The priming pass streams before slice 0's.
  const int64_t primed = zdiff_stream(r) ? row * ny : 0;
  for (int k = 0; k < r.sample_slices(); ++k) {
    const golden::PerspectiveSlice s = golden::perspective_slice(r, k);
    if (s.rays_x.empty() || s.rays_y.empty()) continue;
    const int64_t hx = golden::home_cell(golden::ray_position(s.ray0_x, s.spacing, s.rays_x.hi - 1), F);
    const int64_t hy = golden::home_cell(golden::ray_position(s.ray0_y, s.spacing, s.rays_y.hi - 1), F);
    last = std::max(last, primed + (r.gradient ? golden::gradient_forming_position(k, hx, hy, row, ny)
                                               : golden::forming_position(k, hx, hy, row, ny)));
  }
  return last;
}

CycleCount frame_cycles(const golden::Registers& r, int p) {
  const int nx = r.dim[0], ny = r.dim[1];
  const uint64_t B = static_cast<uint64_t>((nx + p - 1) / p);
  const bool zdiff = zdiff_stream(r);
  const uint64_t passes = static_cast<uint64_t>(r.sample_slices()) + (zdiff ? 1 : 0);
  CycleCount c;
  c.stream = passes * static_cast<uint64_t>(ny) * B;
  const auto flush_beams = static_cast<uint64_t>(stream_flush_beams(r.perspective, r.gradient));
  c.flush = (r.gradient ? static_cast<uint64_t>(ny) * B : 0) + flush_beams * B;
  // After the stream's last beat (the flush beam's last, which ends a
  // beam), each registered link adds a cycle, then:
  //   interpolation: 3 (a beat that ends a beam leaves the alignment
  //     register at once, then the trilinear's 3 stages: docs/rtl-interp.md);
  //   gradient: its own zero beam of B steps, the alignment register, 3
  //     stages (docs/rtl-gradient.md); without gradients nothing;
  //   shading: cube4_shade_unit's latency; compositing: 7 to the pixel port.
  // In perspective the interpolation ring's sample leaves 4 cycles after
  // the step that forms it (docs/rtl-interp-persp.md).
  constexpr uint64_t kLink = 1, kGradientStages = 3, kComposite = 7;
  const uint64_t interp = r.perspective ? 4 : 3;
  const uint64_t shade = static_cast<uint64_t>(shade_latency(r.p));
  const uint64_t gradient = !r.gradient      ? kLink
                            : r.perspective ? kLink + TlmGradientPersp::kLatency
                                            : kLink + B + 1 + kGradientStages;
  const uint64_t drain = kLink + interp + gradient + kLink + shade + kLink + kComposite;
  c.latency = c.stream + c.flush + drain;
  // In perspective the drain follows the beat of the frame's last ray.
  static_assert(TlmCompositePersp::kLatency == kComposite);
  if (const int64_t last = r.perspective ? last_ray_position(r, p) : -1; last >= 0)
    c.latency = static_cast<uint64_t>((last + kPerspectiveReach) / p) + 1 + drain;
  // A parallel frame's last gradients wait for the next frame's first pass,
  // which comes after its priming pass; a perspective frame's last ray is
  // formed in the pass after its last, the next frame's priming pass or the
  // zero pass alike.
  c.latency_followed = c.latency + (zdiff && !r.perspective ? static_cast<uint64_t>(ny) * B : 0);
  return c;
}

}  // namespace cube4::sysc
