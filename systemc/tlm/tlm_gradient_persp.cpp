#include "systemc/tlm/tlm_gradient_persp.hpp"

#include <stdexcept>
#include <string>

#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"

namespace cube4::sysc {

TlmGradientPersp::TlmGradientPersp(const FramePlan& plan) : plan_(plan), row_(static_cast<int64_t>(plan.B) * plan.p) {
  if (!plan.perspective || !plan.r.gradient)
    throw std::invalid_argument("TlmGradientPersp: a perspective frame with the gradient unit on");
}

TlmGradientPersp::PassSamples& TlmGradientPersp::pass_for(int64_t pass, int k) {
  PassSamples& s = passes_[static_cast<size_t>(pass & 3)];
  if (s.pass == pass) return s;
  const golden::PerspectiveSlice& slice = plan_.persp[static_cast<size_t>(k)];
  s.pass = pass;
  s.k = k;
  s.width = slice.rays_x.hi - slice.rays_x.lo;
  const auto n = static_cast<size_t>(s.width * (slice.rays_y.hi - slice.rays_y.lo));
  s.value.assign(n, 0);
  s.vtag.assign(n, 0);
  if (plan_.zdiff) s.zdiff.assign(n, 0);
  s.arrived.assign(n, 0);
  return s;
}

void TlmGradientPersp::take(const RaySampleBeat& in, int lane) {
  const auto i = static_cast<size_t>(lane);
  const golden::FormedCell c = golden::formed_cell(in.step * plan_.p + lane, row_, plan_.nx, plan_.ny);
  const auto k = static_cast<int>(in.tag[i]);
  if (!c.valid || k < 0 || k >= plan_.K || !golden::samples(plan_.persp[static_cast<size_t>(k)], in.u[i], in.v[i]))
    throw std::logic_error("TlmGradientPersp: a sample of no ray of its slice (slice " + std::to_string(k) + ", ray (" +
                           std::to_string(in.u[i]) + ", " + std::to_string(in.v[i]) + "))");
  PassSamples& s = pass_for(c.pass, k);
  const golden::PerspectiveSlice& slice = plan_.persp[static_cast<size_t>(k)];
  const auto at = static_cast<size_t>((in.v[i] - slice.rays_y.lo) * s.width + (in.u[i] - slice.rays_x.lo));
  s.value[at] = in.sample[i];
  s.vtag[at] = in.vtag[i];
  if (plan_.zdiff) s.zdiff[at] = in.zdiff[i];
  s.arrived[at] = 1;
}

uint32_t TlmGradientPersp::sample(int64_t pass, int k, int64_t u, int64_t v, int64_t gradient_at) const {
  if (k < 0 || k >= plan_.K) return 0;
  const golden::PerspectiveSlice& slice = plan_.persp[static_cast<size_t>(k)];
  if (!golden::samples(slice, u, v)) return 0;
  const PassSamples& s = passes_[static_cast<size_t>(pass & 3)];
  const auto at = static_cast<size_t>((v - slice.rays_y.lo) * s.width + (u - slice.rays_x.lo));
  if (s.pass != pass || s.k != k || !s.arrived[at])
    throw std::logic_error("TlmGradientPersp: the gradient formed at stream position " + std::to_string(gradient_at) +
                           " needs slice " + std::to_string(k) + "'s sample of ray (" + std::to_string(u) + ", " +
                           std::to_string(v) + "), which has not arrived");
  return s.value[at];
}

void TlmGradientPersp::form(int64_t position, int lane, RayGradientBeat& out) {
  const golden::FormedCell c = golden::gradient_cell(position, row_, plan_.nx, plan_.ny);
  if (!c.valid) return;
  const PassSamples& own = passes_[static_cast<size_t>(c.pass & 3)];
  if (own.pass != c.pass) return;  // no ray sampled that pass's slice (or the zero pass)
  const int k = own.k;
  const golden::PerspectiveSlice& s = plan_.persp[static_cast<size_t>(k)];
  const int F = plan_.r.p.dda_frac_bits, W = plan_.r.p.weight_bits;
  const golden::HomeLane hu = golden::home_lane(s.ray0_x, s.spacing, s.rays_x, c.x, F, W);
  const golden::HomeLane hv = golden::home_lane(s.ray0_y, s.spacing, s.rays_y, c.y, F, W);
  if (!hu.valid || !hv.valid) return;
  // Within a frame slice k's neighbours stream in the passes beside it;
  // the first and last slices have none on one side (the pass there is
  // another frame's, or the zero pass).
  auto from = [&](int64_t pass, int slice) {
    return [this, pass, slice, position](int64_t u, int64_t v) { return sample(pass, slice, u, v, position); };
  };
  const auto at = static_cast<size_t>((hv.ray - s.rays_y.lo) * own.width + (hu.ray - s.rays_x.lo));
  const golden::Gradient g =
      plan_.zdiff ? golden::perspective_gradient_voxel_z(plan_.r, s, hu.ray, hv.ray, from(c.pass, k), own.zdiff[at])
                  : golden::perspective_gradient(plan_.r, s, hu.ray, hv.ray, from(c.pass, k), from(c.pass - 1, k - 1),
                                                 from(c.pass + 1, k + 1));
  const auto i = static_cast<size_t>(lane);
  out.valid |= 1u << lane;
  out.sample[i] = static_cast<uint16_t>(sample(c.pass, k, hu.ray, hv.ray, position));
  out.gx[i] = static_cast<int16_t>(g.x);
  out.gy[i] = static_cast<int16_t>(g.y);
  out.gz[i] = static_cast<int16_t>(g.z);
  out.u[i] = static_cast<int32_t>(hu.ray);
  out.v[i] = static_cast<int32_t>(hv.ray);
  out.tag[i] = static_cast<uint32_t>(k);
  out.vtag[i] = own.vtag[at];
  ++gradients_;
}

void TlmGradientPersp::clock(const RaySampleBeat& in, RayGradientBeat& out) {
  RayGradientBeat& slot = delay_[clocks_++ % kLatency];
  out = slot;
  slot = RayGradientBeat{};
  if (in.step < 0) return;
  // The beat's samples first: a gradient may take its operands from the
  // beat that arrives at its own position.
  for (int k = 0; k < plan_.p; ++k)
    if (in.valid >> k & 1) take(in, k);
  for (int k = 0; k < plan_.p; ++k) form(in.step * plan_.p + k, k, slot);
  slot.step = in.step;
  slot.f = in.f;
  slot.pass_tag = in.pass_tag;
}

}  // namespace cube4::sysc
