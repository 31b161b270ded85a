// Gradient unit at RTL: cube4_gradient_ring (p pipelines and their links).
// With voxel tags (bela §III) M is a ring with kRtlVoxelTagBits of tag
// hardware: each sample's tag goes in, the centre's comes out. With
// VolumePro's z gradient (plan.zdiff) M is a ring with HasVoxelZ, fed each
// sample's interpolated z difference.
#pragma once
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/rtl/rtl_model.hpp"

namespace cube4::sysc {

template <class M>
class RtlGradient final : public GradientIf {
 public:
  RtlGradient(const FramePlan& plan, int max_dim, VerilatedContext& ctx, const TraceWindow& trace)
      : p_(plan.p), v_(plan.r.p.voxel_bits), g_(plan.r.p.gradient_bits), tag_bits_(plan.tag_bits()),
        vtag_bits_(plan.r.p.tag_bits > 0 ? kRtlVoxelTagBits : 0), dim_bits_(clog2(max_dim + plan.p)), zdiff_(plan.zdiff),
        m_(ctx, "gradient", trace, "gradient", Outputs::Registered) {}

  void clock(const SampleBeat& in, GradientBeat& out) override {
    using rtl::get_bits;
    using rtl::put_bits;
    using rtl::sign_extend;
    M& m = *m_;
    const uint64_t all = p_ >= 64 ? ~uint64_t{0} : (uint64_t{1} << p_) - 1;
    m.valid_i = in.valid ? all : 0;
    m.beam_start_i = in.f.beam_start ? all : 0;
    m.beam_end_i = in.f.beam_end ? all : 0;
    m.slice_start_i = in.f.slice_start ? all : 0;
    m.slice_end_i = in.f.slice_end ? all : 0;
    for (int k = 0; k < p_; ++k) {
      put_bits(m.sample_i, k * v_, v_, in.sample[static_cast<size_t>(k)]);
      put_bits(m.tag_i, k * tag_bits_, tag_bits_, in.tag);
      if (vtag_bits_ > 0) put_bits(m.vtag_i, k * vtag_bits_, vtag_bits_, in.vtag[static_cast<size_t>(k)]);
      if (zdiff_)
        put_bits(m.zdiff_i, k * (v_ + 1), v_ + 1,
                 static_cast<uint64_t>(in.zdiff[static_cast<size_t>(k)]) & ((uint64_t{1} << (v_ + 1)) - 1));
    }
    m_.settle();
    out.valid = m.valid_o & 1;
    out.f.beam_start = m.beam_start_o & 1;
    out.f.beam_end = m.beam_end_o & 1;
    out.f.slice_start = m.slice_start_o & 1;
    out.f.slice_end = m.slice_end_o & 1;
    out.x = static_cast<int>(get_bits(m.x_o, 0, dim_bits_));
    out.y = static_cast<int>(get_bits(m.y_o, 0, dim_bits_));
    out.slice = static_cast<uint32_t>(get_bits(m.tag_o, 0, kUserTagBits));
    for (int k = 0; k < p_; ++k) {
      const auto i = static_cast<size_t>(k);
      out.sample[i] = static_cast<uint16_t>(get_bits(m.sample_o, k * v_, v_));
      if (vtag_bits_ > 0) out.vtag[i] = static_cast<uint8_t>(get_bits(m.vtag_o, k * vtag_bits_, vtag_bits_));
      out.gx[i] = static_cast<int16_t>(sign_extend(get_bits(m.gx_o, k * g_, g_), g_));
      out.gy[i] = static_cast<int16_t>(sign_extend(get_bits(m.gy_o, k * g_, g_), g_));
      out.gz[i] = static_cast<int16_t>(sign_extend(get_bits(m.gz_o, k * g_, g_), g_));
    }
    m_.rise();
  }
  Level level() const override { return Level::Rtl; }

 private:
  static int clog2(int v) {
    int b = 0;
    while ((1 << b) < v) ++b;
    return b;
  }
  int p_, v_, g_, tag_bits_, vtag_bits_, dim_bits_;  // vtag_bits_: the model's VoxelTagBits
  bool zdiff_;
  RtlModel<M> m_;
};

}  // namespace cube4::sysc
