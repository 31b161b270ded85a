// The perspective compositing unit at RTL: cube4_composite_persp_ring
// (docs/rtl-composite-persp.md), its p pipelines and links, on the schedule
// TlmCompositePersp models (the same frame ends, cycle for cycle). Each
// beat is one stream step: its flags and the shaded samples on their
// lanes; at a pass's first step the ring takes that pass's constants,
// looked up by the pass tag the beat carries (the zero pass, tag K, has no
// rays). Each ray's pixel (and with `accumulators` its accumulator) is
// written as it leaves the ring; a frame ends with the last of its rays,
// when the pixels of rays that sampled nothing are written too. With a
// polygon frame (a ring built with HasPolygons) every sample goes in with
// its ray's depth, front and back pixels and the slab pixel behind it,
// read from the host's polygon images (PerspPolygonPixels), the slab pixel
// run-length decoded by cube4_persp_slab_decode (RtlPerspSlabDecode), and
// the rays that sampled nothing are the front over the back pixel.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/slice_steps.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/persp_polygon_pixels.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/rtl/rtl_model.hpp"
#include "systemc/rtl/rtl_persp_slab_decode.hpp"
#include "systemc/rtl/unit_registers.hpp"
#include "systemc/rtl/unit_streams.hpp"
#include "systemc/rtl/vl_bits.hpp"

namespace cube4::sysc {

template <class M>
class RtlCompositePersp final : public PerspCompositor {
 public:
  // With `polygons`, `slab` decodes the slab pixels (its images).
  RtlCompositePersp(const FramePlan& plan, bool accumulators, VerilatedContext& ctx, const TraceWindow& trace,
                    const golden::PolygonFrame* polygons = nullptr, std::unique_ptr<PerspSlabPixelsIf> slab = nullptr)
      : plan_(plan), p_(plan.p), v_(plan.r.p.voxel_bits), a_(plan.r.p.alpha_bits),
        ab_(plan.r.p.alpha_bits + plan.r.p.acc_guard_bits), tag_bits_(plan.tag_bits()), accumulators_(accumulators),
        origin_x_(plan.r.base_origin_x()), origin_y_(plan.r.base_origin_y()),
        per_frame_(golden::perspective_samples(plan.r)), plane_(golden::empty_base_plane(plan.r)),
        polygon_pixels_(plan, polygons), slab_(std::move(slab)),
        // The polygon hardware's outputs depend on its inputs within the cycle.
        m_(ctx, "composite_persp", trace, "composite", polygons ? Outputs::Combinational : Outputs::Registered) {
    if (polygons && !slab_) throw std::logic_error("RtlCompositePersp: polygons without a slab decoder");
    rtl::drive_composite_registers(*m_, plan.r);
    m_->poly_enabled_i = polygons != nullptr;
    // The rays that leave a frame: those that sample some slice (each
    // samples one run of slices and leaves once).
    std::vector<uint8_t> sampled(static_cast<size_t>(plane_.width) * plane_.height, 0);
    for (const golden::PerspectiveSlice& s : plan.persp)
      for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
        for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) sampled[pixel(u, v)] = 1;
    for (const uint8_t s : sampled) leaving_per_frame_ += s;
    start_frame();
  }

  void clock(const RayShadedBeat& in, CompositeOut& out) override {
    using rtl::get_bits;
    using rtl::put_bits;
    M& m = *m_;
    out = CompositeOut{};
    const bool step = in.step >= 0;
    rtl::drive_stream_flags(m, step, in.f);
    if (step && in.f.slice_start && in.f.beam_start && !in.f.flush) drive_pass(in.pass_tag);
    m.sample_valid_i = step ? in.valid : 0u;
    if (slab_) slab_->decode(in, slab_pixels_);
    for (int k = 0; k < p_; ++k) {
      const auto i = static_cast<size_t>(k);
      put_bits(m.red_i, k * a_, a_, in.red[i]);
      put_bits(m.green_i, k * a_, a_, in.green[i]);
      put_bits(m.blue_i, k * a_, a_, in.blue[i]);
      put_bits(m.alpha_i, k * a_, a_, in.alpha[i]);
      put_bits(m.value_i, k * v_, v_, in.value[i]);
      if (polygon_pixels_.frame() && step && (in.valid >> k & 1)) drive_polygons(k, in.u[i], in.v[i]);
    }
    m_.settle();
    for (int k = 0; k < p_; ++k) {
      if (!get_bits(m.pixel_valid_o, k, 1)) continue;
      const int64_t u = rtl::sign_extend(get_bits(m.ray_u_o, k * kPerspRayBits, kPerspRayBits), kPerspRayBits);
      const int64_t v = rtl::sign_extend(get_bits(m.ray_v_o, k * kPerspRayBits, kPerspRayBits), kPerspRayBits);
      const size_t i = pixel(u, v);
      golden::write_pixel(frame_, static_cast<int>(u + origin_x_), static_cast<int>(v + origin_y_),
                          {static_cast<uint16_t>(get_bits(m.pixel_red_o, k * a_, a_)),
                           static_cast<uint16_t>(get_bits(m.pixel_green_o, k * a_, a_)),
                           static_cast<uint16_t>(get_bits(m.pixel_blue_o, k * a_, a_)),
                           static_cast<uint16_t>(get_bits(m.pixel_alpha_o, k * a_, a_))});
      if (!frame_.acc.empty()) {
        golden::RayAcc& acc = frame_.acc[i];
        acc.r = static_cast<uint32_t>(get_bits(m.acc_red_o, k * ab_, ab_));
        acc.g = static_cast<uint32_t>(get_bits(m.acc_green_o, k * ab_, ab_));
        acc.b = static_cast<uint32_t>(get_bits(m.acc_blue_o, k * ab_, ab_));
        acc.a = static_cast<uint32_t>(get_bits(m.acc_alpha_o, k * ab_, ab_));
        acc.value = static_cast<uint16_t>(get_bits(m.acc_value_o, k * v_, v_));
        acc.valid = get_bits(m.acc_selected_o, k, 1) != 0;
      }
      written_[i] = 1;
      if (++left_ == leaving_per_frame_) {
        end_frame();
        out.frame_done = true;
      }
    }
    m_.rise();
  }
  Level level() const override { return Level::Rtl; }
  const golden::BasePlane& plane() const override { return plane_; }
  uint64_t samples_per_frame() const override { return per_frame_; }

 private:
  size_t pixel(int64_t u, int64_t v) const {
    return static_cast<size_t>(v + origin_y_) * static_cast<size_t>(plane_.width) + static_cast<size_t>(u + origin_x_);
  }
  void start_frame() {
    frame_ = golden::empty_base_plane(plan_.r);
    if (accumulators_) frame_.acc.assign(static_cast<size_t>(frame_.width) * frame_.height, golden::RayAcc{});
    written_.assign(static_cast<size_t>(frame_.width) * frame_.height, 0);
    left_ = 0;
  }
  void end_frame() {
    // Rays that sampled nothing leave as they started.
    for (int y = 0; y < frame_.height; ++y)
      for (int x = 0; x < frame_.width; ++x)
        if (!written_[static_cast<size_t>(y) * frame_.width + x])
          golden::write_ray(frame_, x, y, polygon_pixels_.start(static_cast<size_t>(y) * frame_.width + x), plan_.r.p,
                            polygon_pixels_.frame());
    plane_ = std::move(frame_);
    start_frame();
  }
  // Lane k's sample of ray (u, v): its polygon data.
  void drive_polygons(int k, int64_t u, int64_t v) {
    using rtl::put_bits;
    M& m = *m_;
    const golden::PolygonFrame& poly = *polygon_pixels_.frame();
    const size_t i = pixel(u, v);
    put_bits(m.ray_z_i, k * golden::kZBits, golden::kZBits, poly.z[i]);
    auto drive = [&](const golden::Pixel& px, auto& red, auto& green, auto& blue, auto& alpha) {
      put_bits(red, k * a_, a_, px.r);
      put_bits(green, k * a_, a_, px.g);
      put_bits(blue, k * a_, a_, px.b);
      put_bits(alpha, k * a_, a_, px.a);
    };
    drive(poly.front[i], m.ray_front_red_i, m.ray_front_green_i, m.ray_front_blue_i, m.ray_front_alpha_i);
    drive(poly.back[i], m.ray_back_red_i, m.ray_back_green_i, m.ray_back_blue_i, m.ray_back_alpha_i);
    drive(slab_pixels_[static_cast<size_t>(k)], m.slab_red_i, m.slab_green_i, m.slab_blue_i, m.slab_alpha_i);
  }
  // The constants of the pass `tag` names (K: the zero pass, no rays).
  void drive_pass(uint64_t tag) {
    M& m = *m_;
    const bool zero = tag >= static_cast<uint64_t>(plan_.K);
    const golden::PerspectiveSlice& s = plan_.persp[zero ? plan_.persp.size() - 1 : static_cast<size_t>(tag)];
    drive_persp_rays(m, s, zero);
    rtl::put_bits(m.z_voxel_i, 0, golden::kPositionBits, static_cast<uint64_t>(s.z_voxel));
    rtl::put_bits(m.wz_i, 0, plan_.r.p.weight_bits, s.wz);
    m.first_i = !zero && tag == 0;
    m.last_i = !zero && tag + 1 == static_cast<uint64_t>(plan_.K);
    rtl::put_bits(m.tag_i, 0, tag_bits_, tag);
    rtl::put_bits(m.slice_k_i, 0, 16, zero ? 0 : tag);
  }

  const FramePlan& plan_;
  int p_, v_, a_, ab_, tag_bits_;
  bool accumulators_;
  int origin_x_, origin_y_;
  uint64_t per_frame_, leaving_per_frame_ = 0, left_ = 0;
  golden::BasePlane frame_, plane_;
  std::vector<uint8_t> written_;
  PerspPolygonPixels polygon_pixels_;
  std::unique_ptr<PerspSlabPixelsIf> slab_;
  std::array<golden::Pixel, kMaxLanes> slab_pixels_{};
  RtlModel<M> m_;
};

}  // namespace cube4::sysc
