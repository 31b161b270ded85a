// The perspective interpolation unit at RTL: cube4_interp_persp_ring
// (docs/rtl-interp-persp.md), its p pipelines and links. Each beat drives
// the ring's stream and, looked up by the pass the beat's tag names, that
// pass's constants (the frame plan's perspective slices: golden
// perspective_slice(), or the RTL weight generator's); the ring keeps the
// finished pass's own for its drain. The zero pass has no rays.
// With voxel tags (bela §III) M is a ring with kRtlVoxelTagBits of tag
// hardware: the voxel words {tag, value} go in whole, each sample's tag
// comes out beside it. With VolumePro's z gradient (plan.zdiff) M is a ring
// with HasZDiff: it is told the frame's priming pass and gives each
// sample's filtered voxel z difference beside it.
#pragma once
#include <array>
#include <cstdint>

#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/rtl/rtl_model.hpp"
#include "systemc/rtl/unit_streams.hpp"
#include "systemc/rtl/vl_bits.hpp"

namespace cube4::sysc {

template <class M>
class RtlInterpPersp final : public PerspInterpIf {
 public:
  RtlInterpPersp(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace)
      : plan_(plan), p_(plan.p), v_(plan.r.p.voxel_bits), tag_bits_(plan.tag_bits()),
        vtag_bits_(plan.r.p.tag_bits > 0 ? kRtlVoxelTagBits : 0), zdiff_(plan.zdiff),
        m_(ctx, "interp_persp", trace, "interp", Outputs::Registered) {}

  void clock(const VoxelBeat& in, RaySampleBeat& out) override {
    using rtl::get_bits;
    using rtl::put_bits;
    M& m = *m_;
    rtl::drive_stream_flags(m, in);
    m.prime_i = in.f.prime;
    const int word_bits = v_ + vtag_bits_;
    for (int k = 0; k < p_; ++k) put_bits(m.voxels_i, k * word_bits, word_bits, in.voxel[static_cast<size_t>(k)]);
    m.wz_i = in.wz;
    put_bits(m.tag_i, 0, tag_bits_, in.tag);
    if (in.valid) drive_pass(in.tag);
    m_.settle();
    // The ring's control travels with its samples; the model counts the
    // steps and carries their flags and tags beside it (TlmInterpPersp's delay).
    Control& c = control_[clocks_++ & 3];
    out.step = c.step;
    out.f = c.f;
    out.pass_tag = c.pass_tag;
    c = in.valid ? Control{next_step_++, in.f, in.tag} : Control{};
    out.valid = 0;
    for (int k = 0; k < p_; ++k) {
      if (!get_bits(m.valid_o, k, 1)) continue;
      const auto i = static_cast<size_t>(k);
      out.valid |= 1u << k;
      out.sample[i] = static_cast<uint16_t>(get_bits(m.sample_o, k * v_, v_));
      out.u[i] = static_cast<int32_t>(rtl::sign_extend(get_bits(m.ray_u_o, k * kPerspRayBits, kPerspRayBits), kPerspRayBits));
      out.v[i] = static_cast<int32_t>(rtl::sign_extend(get_bits(m.ray_v_o, k * kPerspRayBits, kPerspRayBits), kPerspRayBits));
      out.tag[i] = static_cast<uint32_t>(get_bits(m.tag_o, k * tag_bits_, tag_bits_));
      out.vtag[i] = vtag_bits_ > 0 ? static_cast<uint8_t>(get_bits(m.vtag_o, k * vtag_bits_, vtag_bits_)) : 0;
      if (zdiff_)
        out.zdiff[i] = static_cast<int32_t>(rtl::sign_extend(get_bits(m.zdiff_o, k * (v_ + 1), v_ + 1), v_ + 1));
    }
    m_.rise();
  }
  Level level() const override { return Level::Rtl; }

 private:
  // The constants of the pass `tag` names (its sample slice; K: the zero pass, no rays).
  void drive_pass(uint64_t tag) {
    M& m = *m_;
    const bool zero = tag >= static_cast<uint64_t>(plan_.K);
    const golden::PerspectiveSlice& s = plan_.persp[zero ? plan_.persp.size() - 1 : static_cast<size_t>(tag)];
    drive_persp_rays(m, s, zero);
    m.recip_i = static_cast<uint32_t>(s.box_reciprocal);
  }

  const FramePlan& plan_;
  int p_, v_, tag_bits_, vtag_bits_;  // vtag_bits_: the model's VoxelTagBits
  bool zdiff_;
  RtlModel<M> m_;
  struct Control {
    int64_t step = -1;
    BeamFlags f;
    uint64_t pass_tag = 0;
  };
  std::array<Control, 4> control_;  // the ring's 4 cycles, by clock % 4
  int64_t next_step_ = 0;
  uint64_t clocks_ = 0;
};

}  // namespace cube4::sysc
