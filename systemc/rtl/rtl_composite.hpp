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
#include "systemc/rtl/unit_streams.hpp"

namespace cube4::sysc {

template <class M>
class RtlComposite final : public CompositeIf {
 public:
  static constexpr int kPosBits = golden::kPositionBits, kLatency = 7;

  RtlComposite(const FramePlan& plan, PixelMemory& pixels, VerilatedContext& ctx, const TraceWindow& trace)
      : plan_(plan), pixels_(pixels), m_(ctx, "composite", trace, "composite") {
    rtl::drive_composite_registers(*m_, plan.r);
  }

  void clock(const ShadedBeat& in, CompositeOut& out) override {
    using rtl::get_bits;
    const int a = plan_.r.p.alpha_bits, p = plan_.p;
    M& m = *m_;
    if (in.valid) {
      if (in.slice >= static_cast<uint32_t>(plan_.K))
        throw std::logic_error("compositing unit (RTL): sample of slice " + std::to_string(in.slice) +
                               " in a frame of " + std::to_string(plan_.K) + " slices");
      control_ = rtl::composite_control(plan_, static_cast<int>(in.slice), in.f, in.x, in.y);
      if (control_.last_slice && in.f.slice_end && in.f.beam_end) drain_ = kLatency + 1;
    } else {
      control_.valid = false;  // the rest is held: the ring ignores it
    }
    rtl::drive_composite_stream(m, control_, in, p, plan_.r.p);
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
      if (pixels_.keeps_accumulators()) pixels_.write_acc(u, w, rtl::composite_pixel_acc(m, k, plan_.r.p));
    }
    m_.rise();
    out.frame_done = drain_ > 0 && --drain_ == 0;
  }
  Level level() const override { return Level::Rtl; }

 private:
  const FramePlan& plan_;
  PixelMemory& pixels_;
  RtlModel<M> m_;
  rtl::CompositeControl control_;
  int drain_ = 0;
};

}  // namespace cube4::sysc
