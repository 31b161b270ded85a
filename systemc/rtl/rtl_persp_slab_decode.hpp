// The slab pixels behind a perspective frame's samples at RTL:
// cube4_persp_slab_decode (docs/rtl-rle-decode.md, "In perspective") over
// the frame's run-length slab images (PerspSlabLines), feeding the RTL
// compositing ring (RtlCompositePersp) where the TLM unit reads the images
// decoded (PerspPolygonPixels).
//
// Timing: the unit has a cycle of latency and the ring takes a sample's
// slab pixel with the sample, so its requests are issued a cycle ahead: a
// beat's requests go in on the clock before the ring's (in hardware, from
// the shading unit's last stage, where each sample's ray and slice are
// known). Each clock() is one cycle of the unit, its edge included; the
// ring's schedule and the frame's cycles do not change.
#pragma once
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "golden/polygon_frame.hpp"
#include "golden/units/composite.hpp"
#include "systemc/core/beats.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/rtl/persp_slab_lines.hpp"
#include "systemc/rtl/rtl_model.hpp"
#include "systemc/rtl/vl_bits.hpp"

namespace cube4::sysc {

// What the RTL perspective compositing ring is given behind each sample.
class PerspSlabPixelsIf {
 public:
  virtual ~PerspSlabPixelsIf() = default;
  // One cycle: the pixels behind `in`'s samples (blank on lanes without one).
  virtual void decode(const RayShadedBeat& in, std::array<golden::Pixel, kMaxLanes>& out) = 0;
};

template <class D>
class RtlPerspSlabDecode final : public PerspSlabPixelsIf {
 public:
  RtlPerspSlabDecode(const FramePlan& plan, const golden::PolygonFrame& polygons, VerilatedContext& ctx,
                     const TraceWindow& trace)
      : plan_(plan), p_(plan.p), lines_(rows(plan, polygons), plan.p),
        m_(ctx, "persp_slab_decode", trace, "slab_decode") {}

  void decode(const RayShadedBeat& in, std::array<golden::Pixel, kMaxLanes>& out) override {
    using rtl::get_bits;
    D& m = *m_;
    // A sample's row of rays starts at rank 0 and ends at its slice's last ray.
    const uint32_t valid = in.step >= 0 ? in.valid : 0u;
    uint32_t first = 0, last = 0;
    for (int k = 0; k < p_; ++k) {
      if (!(valid >> k & 1)) continue;
      const auto i = static_cast<size_t>(k);
      const golden::PerspectiveSlice& s = plan_.persp[in.tag[i]];
      first |= static_cast<uint32_t>(in.u[i] == s.rays_x.lo) << k;
      last |= static_cast<uint32_t>(in.u[i] + 1 == s.rays_x.hi) << k;
    }
    m.req_valid_i = valid;
    m.req_first_i = first;
    m.req_last_i = last;
    lines_.present(m, [] { return uint16_t{0}; });
    m_.settle();
    lines_.take(m);
    m_.rise();
    lines_.clocked();
    ++clocks_;
    if (m.error_o)
      throw std::logic_error("cube4_persp_slab_decode: a slab line ended inside a flit (clock " +
                             std::to_string(clocks_) + ")");
    for (int k = 0; k < p_; ++k) {
      const auto i = static_cast<size_t>(k);
      out[i] = valid >> k & 1 ? golden::Pixel{static_cast<uint16_t>(get_bits(m.pixel_red_o, k * 16, 16)),
                                              static_cast<uint16_t>(get_bits(m.pixel_green_o, k * 16, 16)),
                                              static_cast<uint16_t>(get_bits(m.pixel_blue_o, k * 16, 16)),
                                              static_cast<uint16_t>(get_bits(m.pixel_alpha_o, k * 16, 16))}
                              : golden::Pixel{};
    }
  }

 private:
  // The frame's rows of rays in stream order: slice k's rows are beams
  // 0 .. its rays in y of k's slab image.
  static std::vector<rtl::PerspSlabLines::Row> rows(const FramePlan& plan, const golden::PolygonFrame& f) {
    std::vector<rtl::PerspSlabLines::Row> rows;
    for (int k = 0; k < plan.K; ++k) {
      const golden::PerspectiveSlice& s = plan.persp[static_cast<size_t>(k)];
      if (s.rays_x.hi <= s.rays_x.lo) continue;  // no ray samples the slice: no row is asked for
      for (int64_t y = 0; y < s.rays_y.hi - s.rays_y.lo; ++y)
        rows.push_back({&f.slabs[static_cast<size_t>(k)], static_cast<int>(y)});
    }
    return rows;
  }

  const FramePlan& plan_;
  int p_;
  rtl::PerspSlabLines lines_;
  RtlModel<D> m_;
  uint64_t clocks_ = 0;
};

}  // namespace cube4::sysc
