// The perspective gradient unit at RTL: cube4_gradient_persp_ring
// (docs/rtl-gradient-persp.md), its p pipelines and links, on the schedule
// TlmGradientPersp models (the same beats, cycle for cycle). Each beat is
// one stream step: its flags and the samples the interpolation unit formed
// in it; at a pass's first step the ring takes that pass's constants, looked
// up by the pass tag the beat carries (the frame plan's perspective slices:
// golden perspective_slice(), or the RTL weight generator's). The zero pass
// (tag K) has no rays. With voxel tags M is a ring with kRtlVoxelTagBits of
// tag hardware: each sample's tag is stored with it and leaves with its
// ray's gradient. With VolumePro's z gradient (plan.zdiff) M is a ring with
// HasVoxelZ: each sample's filtered voxel z difference is stored with it
// and gives its gradient's z.
#pragma once
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/rtl/rtl_interp_persp.hpp"
#include "systemc/rtl/rtl_model.hpp"
#include "systemc/rtl/unit_streams.hpp"
#include "systemc/rtl/vl_bits.hpp"
#include "systemc/tlm/tlm_gradient_persp.hpp"

namespace cube4::sysc {

template <class M>
class RtlGradientPersp final : public PerspGradientIf {
 public:
  // cube4_gradient's stages behind the step that forms a gradient: the
  // schedule the clocked TLM unit and the cycle model count.
  static constexpr int kLatency = 3;
  static_assert(kLatency == TlmGradientPersp::kLatency);

  RtlGradientPersp(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace)
      : plan_(plan), p_(plan.p), v_(plan.r.p.voxel_bits), g_(plan.r.p.gradient_bits), tag_bits_(plan.tag_bits()),
        vtag_bits_(plan.r.p.tag_bits > 0 ? kRtlVoxelTagBits : 0), zdiff_(plan.zdiff),
        m_(ctx, "gradient_persp", trace, "gradient", Outputs::Registered) {
    m_->supersampling_i = static_cast<uint8_t>(plan.r.supersampling);
    // The ring takes one realignment step per neighbour for both axes (as
    // cube4_dda gives it): m_k / m_(k -/+ 1), the same in x and y.
    for (const golden::PerspectiveSlice& s : plan.persp)
      if (s.behind_x.step != s.behind_y.step || s.ahead_x.step != s.ahead_y.step)
        throw std::logic_error("RtlGradientPersp: slice " + std::to_string(s.k) +
                               "'s realignment steps differ between x and y");
  }

  void clock(const RaySampleBeat& in, RayGradientBeat& out) override {
    using rtl::get_bits;
    using rtl::put_bits;
    M& m = *m_;
    const bool step = in.step >= 0;
    rtl::drive_stream_flags(m, step, in.f);
    if (step && in.f.slice_start && in.f.beam_start && !in.f.flush) drive_pass(in.pass_tag);
    m.sample_valid_i = step ? in.valid : 0u;
    const int vtag_port = vtag_bits_ > 0 ? vtag_bits_ : 1;
    for (int k = 0; k < p_; ++k) {
      const auto i = static_cast<size_t>(k);
      put_bits(m.sample_i, k * v_, v_, in.sample[i]);
      put_bits(m.vtag_i, k * vtag_port, vtag_port, in.vtag[i]);
      if (zdiff_)
        put_bits(m.zdiff_i, k * (v_ + 1), v_ + 1, static_cast<uint64_t>(in.zdiff[i]) & ((uint64_t{1} << (v_ + 1)) - 1));
    }
    m_.settle();
    out = RayGradientBeat{};
    // The step's control travels beside the ring.
    Control& c = control_[clocks_++ % kLatency];
    out.step = c.step;
    out.f = c.f;
    out.pass_tag = c.pass_tag;
    c = {in.step, in.f, in.pass_tag};
    for (int k = 0; k < p_; ++k) {
      if (!get_bits(m.valid_o, k, 1)) continue;
      const auto i = static_cast<size_t>(k);
      out.valid |= 1u << k;
      out.sample[i] = static_cast<uint16_t>(get_bits(m.sample_o, k * v_, v_));
      out.gx[i] = static_cast<int16_t>(rtl::sign_extend(get_bits(m.gx_o, k * g_, g_), g_));
      out.gy[i] = static_cast<int16_t>(rtl::sign_extend(get_bits(m.gy_o, k * g_, g_), g_));
      out.gz[i] = static_cast<int16_t>(rtl::sign_extend(get_bits(m.gz_o, k * g_, g_), g_));
      out.u[i] = static_cast<int32_t>(rtl::sign_extend(get_bits(m.ray_u_o, k * kPerspRayBits, kPerspRayBits), kPerspRayBits));
      out.v[i] = static_cast<int32_t>(rtl::sign_extend(get_bits(m.ray_v_o, k * kPerspRayBits, kPerspRayBits), kPerspRayBits));
      out.tag[i] = static_cast<uint32_t>(get_bits(m.tag_o, k * tag_bits_, tag_bits_));
      out.vtag[i] = vtag_bits_ > 0 ? static_cast<uint8_t>(get_bits(m.vtag_o, k * vtag_bits_, vtag_bits_)) : 0;
    }
    m_.rise();
  }
  Level level() const override { return Level::Rtl; }

 private:
  static uint64_t word(int64_t v, int bits) { return static_cast<uint64_t>(v) & ((uint64_t{1} << bits) - 1); }
  // The constants of the pass `tag` names: its sample slice, with whether
  // it is the frame's first or last (K: the zero pass, no rays).
  void drive_pass(uint64_t tag) {
    M& m = *m_;
    const bool zero = tag >= static_cast<uint64_t>(plan_.K);
    const golden::PerspectiveSlice& s = plan_.persp[zero ? plan_.persp.size() - 1 : static_cast<size_t>(tag)];
    drive_persp_rays(m, s, zero);
    m.behind_start_x_i = word(s.behind_x.start, kPerspPosBits);
    m.behind_start_y_i = word(s.behind_y.start, kPerspPosBits);
    m.behind_step_i = word(s.behind_x.step, kPerspPosBits);
    m.ahead_start_x_i = word(s.ahead_x.start, kPerspPosBits);
    m.ahead_start_y_i = word(s.ahead_y.start, kPerspPosBits);
    m.ahead_step_i = word(s.ahead_x.step, kPerspPosBits);
    m.lateral_recip_i = static_cast<uint32_t>(s.lateral_reciprocal);
    m.first_i = !zero && tag == 0;
    m.last_i = !zero && tag + 1 == static_cast<uint64_t>(plan_.K);
    rtl::put_bits(m.tag_i, 0, tag_bits_, tag);
  }

  const FramePlan& plan_;
  int p_, v_, g_, tag_bits_, vtag_bits_;  // vtag_bits_: the model's VoxelTagBits
  bool zdiff_;
  RtlModel<M> m_;
  struct Control {
    int64_t step = -1;
    BeamFlags f;
    uint64_t pass_tag = 0;
  };
  std::array<Control, kLatency> control_;  // the ring's 3 cycles, by clock % 3
  uint64_t clocks_ = 0;
};

}  // namespace cube4::sysc
