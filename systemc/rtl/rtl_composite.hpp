// Compositing unit at RTL: cube4_composite_ring (p pipelines, ray storage,
// ray alignment, pixel ports). The per-slice control it needs beside the
// samples (dx, dy, next dx/dy, DDA offsets, weights, first/last slice) is
// the weight generator's slice_control() of the slice number that travels
// with the samples.
#pragma once
#include <stdexcept>
#include <vector>

#include "systemc/core/frame_plan.hpp"
#include "systemc/core/pixel_memory.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/rtl/polygon_streams.hpp"
#include "systemc/rtl/rtl_model.hpp"
#include "systemc/rtl/unit_registers.hpp"
#include "systemc/rtl/unit_streams.hpp"

namespace cube4::sysc {

template <class M>
class RtlComposite final : public CompositeIf {
 public:
  static constexpr int kPosBits = golden::kPositionBits, kLatency = 7;

  // polygons: the frame's polygon images (Cube-5), for a ring verilated
  // with HasPolygons; null for a frame without polygons. frames: how many
  // frames of the view stream back to back (each reads the same slab lines).
  RtlComposite(const FramePlan& plan, PixelMemory& pixels, VerilatedContext& ctx, const TraceWindow& trace,
               const golden::PolygonFrame* polygons = nullptr, int frames = 1)
      : plan_(plan), pixels_(pixels),
        // The polygon hardware's outputs depend on its inputs within the cycle.
        m_(ctx, "composite", trace, "composite", polygons ? Outputs::Combinational : Outputs::Registered),
        poly_(polygons), frames_(frames) {
    rtl::drive_composite_registers(*m_, plan.r, poly_ != nullptr);
    if (poly_) start_polygons();
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
    if (poly_) drive_polygons(in);
    m_.settle();
    if (poly_)
      for (size_t q = 0; q < slabs_.size(); ++q) {
        consumed_[q] = static_cast<int>(get_bits(m.slab_consume_o, static_cast<int>(q) * 3, 3));
        next_line_[q] = get_bits(m.slab_line_o, static_cast<int>(q), 1) != 0;
      }
    out.pixel_valid = static_cast<uint32_t>(get_bits(m.pixel_valid_o, 0, p));
    for (int k = 0; out.pixel_valid >> k; ++k) {
      if (!(out.pixel_valid >> k & 1)) continue;
      const int u = static_cast<int>(get_bits(m.pixel_u_o, k * kPosBits, kPosBits));
      const int w = static_cast<int>(get_bits(m.pixel_v_o, k * kPosBits, kPosBits));
      pixels_.write(k, u, w, static_cast<uint16_t>(get_bits(m.pixel_red_o, k * a, a)),
                    static_cast<uint16_t>(get_bits(m.pixel_green_o, k * a, a)),
                    static_cast<uint16_t>(get_bits(m.pixel_blue_o, k * a, a)),
                    static_cast<uint16_t>(get_bits(m.pixel_alpha_o, k * a, a)));
      if (pixels_.keeps_accumulators()) pixels_.write_acc(u, w, rtl::composite_pixel_acc(m, k, plan_.r.p));
    }
    m_.rise();
    for (size_t q = 0; q < slabs_.size(); ++q) slabs_[q].clocked(consumed_[q], next_line_[q]);
    out.frame_done = drain_ > 0 && --drain_ == 0;
  }
  Level level() const override { return Level::Rtl; }

 private:
  // The host's start of a polygon frame (golden start_polygons()): every
  // pixel front over back, which the rays that meet samples overwrite.
  void start_polygons() {
    golden::BasePlane& bp = pixels_.plane();
    for (size_t i = 0; i < poly_->front.size(); ++i) {
      const golden::Pixel px =
          golden::leave_with_polygons(golden::pixel_to_acc(poly_->front[i], plan_.r.p), poly_->back[i], plan_.r.p);
      bp.rgba[i * 4] = px.r;
      bp.rgba[i * 4 + 1] = px.g;
      bp.rgba[i * 4 + 2] = px.b;
      bp.rgba[i * 4 + 3] = px.a;
    }
    for (int q = 0; q < plan_.p; ++q) slabs_.emplace_back(*poly_, q, plan_.p, frames_);
    consumed_.assign(slabs_.size(), 0);
    next_line_.assign(slabs_.size(), false);
  }
  // Each sample's ray data (Z, front and back pixels, by the ray's
  // base-plane pixel) and each pipeline's slab-line window.
  void drive_polygons(const ShadedBeat& in) {
    rtl::PolygonBeat b;
    if (in.valid) {
      const golden::SliceControl& c = plan_.slices[in.slice];
      b.slice = in.slice;
      for (int q = 0; q < plan_.p; ++q) {
        const int x = in.x + q;
        if (x < plan_.nx)
          rtl::put_ray(b, q, *poly_, x - c.ix + plan_.r.base_origin_x(), in.y - c.iy + plan_.r.base_origin_y());
      }
    }
    rtl::drive_composite_polygons(*m_, b, plan_.p, plan_.r.p.alpha_bits);
    for (const rtl::SlabLineSource& src : slabs_) src.present(*m_);
  }

  const FramePlan& plan_;
  PixelMemory& pixels_;
  RtlModel<M> m_;
  rtl::CompositeControl control_;
  int drain_ = 0;
  const golden::PolygonFrame* poly_;
  int frames_;
  std::vector<rtl::SlabLineSource> slabs_;
  std::vector<int> consumed_;
  std::vector<bool> next_line_;
};

}  // namespace cube4::sysc
