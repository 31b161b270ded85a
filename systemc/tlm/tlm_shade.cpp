#include "systemc/tlm/tlm_shade.hpp"

namespace cube4::sysc {

int shade_latency(const golden::Precision& p) {
  int cell_bits = 0;
  while ((1 << cell_bits) < p.map_face_res) ++cell_bits;
  const int div_bits_per_stage = 2;
  const int cube = 1 + (cell_bits + p.weight_bits + div_bits_per_stage - 1) / div_bits_per_stage;
  return (p.nr_iterations + 1) + 4 + cube + 3 + 3;
}

TlmShade::TlmShade(const FramePlan& plan, bool skip_transparent, const TlmComposite* stops)
    : plan_(plan),
      skip_transparent_(skip_transparent),
      stops_(skip_transparent ? stops : nullptr),
      faces_(golden::make_face_table(plan.r)),
      shading_(plan.r, faces_.get()),
      line_(static_cast<size_t>(shade_latency(plan.r.p))) {}

void TlmShade::clock(const GradientBeat& in, ShadedBeat& out) {
  out = line_[head_];
  ShadedBeat& s = line_[head_];
  if (++head_ == line_.size()) head_ = 0;
  if (!in.valid) {
    s = ShadedBeat{};
    return;
  }
  // Lanes from p on stay zero (never written); lanes below it are all
  // written, so a valid beat needs no clearing.
  if (in.slice == 0 && in.f.slice_start && in.f.beam_start) ++frame_;
  s.valid = true;
  s.f = in.f;
  s.x = in.x;
  s.y = in.y;
  s.slice = in.slice;
  for (int k = 0; k < plan_.p; ++k) {
    const auto i = static_cast<size_t>(k);
    if (skip_transparent_ && (golden::sample_cannot_change_ray(plan_.r, in.sample[i], in.vtag[i]) ||
                              (stops_ && in.x + k < plan_.nx && stops_->ray_stopped(frame_, in.slice, in.x + k, in.y)))) {
      s.red[i] = s.green[i] = s.blue[i] = s.alpha[i] = 0;
      s.value[i] = in.sample[i];
      continue;
    }
    const golden::Gradient g{in.gx[i], in.gy[i], in.gz[i]};
    const golden::ShadedSample r = golden::shade_with(plan_.r, in.sample[i], in.vtag[i], shading_(g));
    s.red[i] = static_cast<uint16_t>(r.rgb[0]);
    s.green[i] = static_cast<uint16_t>(r.rgb[1]);
    s.blue[i] = static_cast<uint16_t>(r.rgb[2]);
    s.alpha[i] = static_cast<uint16_t>(r.alpha);
    s.value[i] = static_cast<uint16_t>(r.value);
  }
}

}  // namespace cube4::sysc
