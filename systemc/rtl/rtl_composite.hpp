// Compositing unit at RTL: cube4_composite_ring (p pipelines, ray storage,
// ray alignment, pixel ports). The per-slice control it needs beside the
// samples (dx, dy, next dx/dy, DDA offsets, weights, first/last slice) is
// the weight generator's slice_control() of the slice number that travels
// with the samples.
#pragma once
#include <stdexcept>

#include "systemc/core/frame_plan.hpp"
#include "systemc/core/pixel_memory.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/rtl/rtl_model.hpp"
#include "systemc/rtl/unit_registers.hpp"

namespace cube4::sysc {

template <class M>
class RtlComposite final : public CompositeIf {
 public:
  static constexpr int kPosBits = golden::kPositionBits, kLatency = 7;

  RtlComposite(const FramePlan& plan, PixelMemory& pixels, VerilatedContext& ctx, const TraceWindow& trace)
      : plan_(plan), pixels_(pixels), m_(ctx, "composite", trace, "composite") {
    M& m = *m_;
    rtl::drive_composite_registers(m, plan.r);
    m.nx_i = static_cast<uint32_t>(plan.nx);
    m.last_ix_i = static_cast<uint32_t>(plan.slices[static_cast<size_t>(plan.K - 1)].ix);
    m.last_iy_i = static_cast<uint32_t>(plan.slices[static_cast<size_t>(plan.K - 1)].iy);
  }

  void clock(const ShadedBeat& in, CompositeOut& out) override {
    using rtl::get_bits;
    using rtl::put_bits;
    const golden::Precision& pr = plan_.r.p;
    const int a = pr.alpha_bits, v = pr.voxel_bits, p = plan_.p;
    M& m = *m_;
    m.valid_i = in.valid;
    if (in.valid) {
      if (in.slice >= static_cast<uint32_t>(plan_.K))
        throw std::logic_error("compositing unit (RTL): sample of slice " + std::to_string(in.slice) +
                               " in a frame of " + std::to_string(plan_.K) + " slices");
      const golden::SliceControl& c = plan_.slices[in.slice];
      const golden::SliceControl& next = plan_.slices[in.slice + 1];
      m.beam_start_i = in.f.beam_start;
      m.beam_end_i = in.f.beam_end;
      m.slice_start_i = in.f.slice_start;
      m.slice_end_i = in.f.slice_end;
      m.first_slice_i = in.slice == 0;
      m.last_slice_i = in.slice + 1 == static_cast<uint32_t>(plan_.K);
      m.dx_i = c.dx != 0;
      m.dy_i = c.dy != 0;
      m.next_dx_i = next.dx != 0;
      m.next_dy_i = next.dy != 0;
      m.ix_i = static_cast<uint32_t>(c.ix);
      m.iy_i = static_cast<uint32_t>(c.iy);
      m.x_i = static_cast<uint32_t>(in.x);
      m.y_i = static_cast<uint32_t>(in.y);
      m.z_i = static_cast<uint32_t>(c.z_voxel);
      m.wx_i = c.wx;
      m.wy_i = c.wy;
      m.wz_i = c.wz;
      for (int k = 0; k < p; ++k) {
        const auto i = static_cast<size_t>(k);
        put_bits(m.red_i, k * a, a, in.red[i]);
        put_bits(m.green_i, k * a, a, in.green[i]);
        put_bits(m.blue_i, k * a, a, in.blue[i]);
        put_bits(m.alpha_i, k * a, a, in.alpha[i]);
        put_bits(m.value_i, k * v, v, in.value[i]);
      }
      if (m.last_slice_i && in.f.slice_end && in.f.beam_end) drain_ = kLatency + 1;
    }
    m_.settle();
    out.pixels.valid = static_cast<uint32_t>(get_bits(m.pixel_valid_o, 0, p));
    for (int k = 0; out.pixels.valid >> k; ++k) {
      if (!(out.pixels.valid >> k & 1)) continue;
      const int u = static_cast<int>(get_bits(m.pixel_u_o, k * kPosBits, kPosBits));
      const int w = static_cast<int>(get_bits(m.pixel_v_o, k * kPosBits, kPosBits));
      pixels_.write(k, u, w, static_cast<uint16_t>(get_bits(m.pixel_red_o, k * a, a)),
                    static_cast<uint16_t>(get_bits(m.pixel_green_o, k * a, a)),
                    static_cast<uint16_t>(get_bits(m.pixel_blue_o, k * a, a)),
                    static_cast<uint16_t>(get_bits(m.pixel_alpha_o, k * a, a)));
    }
    m_.rise();
    out.frame_done = drain_ > 0 && --drain_ == 0;
  }
  Level level() const override { return Level::Rtl; }

 private:
  const FramePlan& plan_;
  PixelMemory& pixels_;
  RtlModel<M> m_;
  int drain_ = 0;
};

}  // namespace cube4::sysc
