// Interpolation unit at RTL: cube4_interp_ring (p pipelines and their links).
// With voxel tags (bela §III) M is a ring with kRtlVoxelTagBits of tag
// hardware: the voxel words {tag, value} go in whole, each sample's tag
// comes out on its lane. With VolumePro's z gradient (plan.zdiff) M is a
// ring with HasZDiff: each sample's interpolated z difference comes out
// beside it.
#pragma once
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/rtl/rtl_model.hpp"
#include "systemc/rtl/unit_streams.hpp"

namespace cube4::sysc {

template <class M>
class RtlInterp final : public InterpIf {
 public:
  RtlInterp(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace)
      : p_(plan.p), v_(plan.r.p.voxel_bits), tag_bits_(plan.tag_bits()),
        vtag_bits_(plan.r.p.tag_bits > 0 ? kRtlVoxelTagBits : 0), zdiff_(plan.zdiff),
        m_(ctx, "interp", trace, "interp", Outputs::Registered) {}

  void clock(const VoxelBeat& in, SampleBeat& out) override {
    using rtl::get_bits;
    M& m = *m_;
    rtl::drive_interp_stream(m, in, p_, v_ + vtag_bits_, tag_bits_);
    m_.settle();
    // All pipelines run in lock step: pipeline 0's control stands for all.
    out.valid = m.valid_o & 1;
    out.f.beam_start = m.beam_start_o & 1;
    out.f.beam_end = m.beam_end_o & 1;
    out.f.slice_start = m.slice_start_o & 1;
    out.f.slice_end = m.slice_end_o & 1;
    out.tag = get_bits(m.tag_o, 0, tag_bits_);
    for (int k = 0; k < p_; ++k) {
      const auto i = static_cast<size_t>(k);
      out.sample[i] = static_cast<uint16_t>(get_bits(m.sample_o, k * v_, v_));
      if (vtag_bits_ > 0) out.vtag[i] = static_cast<uint8_t>(get_bits(m.vtag_o, k * vtag_bits_, vtag_bits_));
      if (zdiff_)
        out.zdiff[i] = static_cast<int32_t>(rtl::sign_extend(get_bits(m.zdiff_o, k * (v_ + 1), v_ + 1), v_ + 1));
    }
    m_.rise();
  }
  Level level() const override { return Level::Rtl; }

 private:
  int p_, v_, tag_bits_, vtag_bits_;  // vtag_bits_: the model's VoxelTagBits
  bool zdiff_;
  RtlModel<M> m_;
};

}  // namespace cube4::sysc
