#include "systemc/tlm/tlm_shade_persp.hpp"

#include "systemc/tlm/tlm_shade.hpp"

namespace cube4::sysc {

TlmShadePersp::TlmShadePersp(const FramePlan& plan)
    : plan_(plan),
      faces_(golden::make_face_table(plan.r)),
      shading_(plan.r, faces_.get()),
      line_(static_cast<size_t>(shade_latency(plan.r.p))) {}

void TlmShadePersp::clock(const RayGradientBeat& in, RayShadedBeat& out) {
  RayShadedBeat& s = line_[head_];
  out = s;
  if (++head_ == line_.size()) head_ = 0;
  s.valid = in.valid;
  s.step = in.step;
  s.f = in.f;
  s.pass_tag = in.pass_tag;
  for (int k = 0; in.valid && k < plan_.p; ++k) {
    if (!(in.valid >> k & 1)) continue;
    const auto i = static_cast<size_t>(k);
    const golden::ShadedSample r =
        golden::shade_with(plan_.r, in.sample[i], in.vtag[i], shading_(golden::Gradient{in.gx[i], in.gy[i], in.gz[i]}));
    s.red[i] = static_cast<uint16_t>(r.rgb[0]);
    s.green[i] = static_cast<uint16_t>(r.rgb[1]);
    s.blue[i] = static_cast<uint16_t>(r.rgb[2]);
    s.alpha[i] = static_cast<uint16_t>(r.alpha);
    s.value[i] = static_cast<uint16_t>(r.value);
    s.u[i] = in.u[i];
    s.v[i] = in.v[i];
    s.tag[i] = in.tag[i];
  }
}

}  // namespace cube4::sysc
