// The compositing ring's polygon inputs (Cube-5; docs/rtl-composite.md,
// "Polygons"), bound to its ports once, as unit_streams.hpp does for the
// sample stream: what each pipeline's sample brings of its ray (Z, front
// and back pixels, read by the ray's base-plane pixel from the frame's
// polygon images) and each pipeline's slab line source, the word source of
// its run-length decoder (cube4_rle_decode). Header-only, without SystemC;
// on any verilated cube4_composite_ring.
//
// The data are golden's PolygonFrame (golden/polygon_frame.hpp), made by
// the host rasteriser; nothing here computes a pixel.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "golden/polygon_frame.hpp"
#include "golden/rle_buffer.hpp"
#include "systemc/core/beats.hpp"
#include "systemc/rtl/vl_bits.hpp"

namespace cube4::rtl {

// One cycle's polygon inputs: the slice, and per pipeline the sample's ray.
struct PolygonBeat {
  uint32_t slice = 0;
  std::array<uint32_t, sysc::kMaxLanes> z{};
  std::array<golden::Pixel, sysc::kMaxLanes> front{}, back{};
};

// The ray data of sample (x, y) of a slice whose DDA offsets are (ix, iy):
// base-plane pixel (x - ix + origin_x, y - iy + origin_y), as the
// compositor's ray storage aligns it (golden SliceCompositor).
inline void put_ray(PolygonBeat& b, int lane, const golden::PolygonFrame& f, int u, int v) {
  const size_t i = static_cast<size_t>(v) * static_cast<size_t>(f.width) + static_cast<size_t>(u);
  const auto l = static_cast<size_t>(lane);
  b.z[l] = f.z[i];
  b.front[l] = f.front[i];
  b.back[l] = f.back[i];
}

template <class M>
void drive_composite_polygons(M& m, const PolygonBeat& b, int pipes, int alpha_bits) {
  const int a = alpha_bits, zb = golden::kZBits;
  m.slice_k_i = b.slice;
  for (int k = 0; k < pipes; ++k) {
    const auto i = static_cast<size_t>(k);
    put_bits(m.ray_z_i, k * zb, zb, b.z[i]);
    put_bits(m.ray_front_red_i, k * a, a, b.front[i].r);
    put_bits(m.ray_front_green_i, k * a, a, b.front[i].g);
    put_bits(m.ray_front_blue_i, k * a, a, b.front[i].b);
    put_bits(m.ray_front_alpha_i, k * a, a, b.front[i].a);
    put_bits(m.ray_back_red_i, k * a, a, b.back[i].r);
    put_bits(m.ray_back_green_i, k * a, a, b.back[i].g);
    put_bits(m.ray_back_blue_i, k * a, a, b.back[i].b);
    put_bits(m.ray_back_alpha_i, k * a, a, b.back[i].a);
  }
}

// Pipeline `lane`'s slab lines in the order its decoder reads them: slice
// by slice, beam by beam (an empty slab image as cleared lines, which
// decode to its blank pixels), and again for each of `frames` frames of
// the view streamed back to back. The window shows the five words at the read
// position; at each clock edge the position advances by the words the
// decoder consumed, and moves to the next line's start at an edge that
// ends a cycle with slab_line_o high.
class SlabLineSource {
 public:
  SlabLineSource(const golden::PolygonFrame& f, int lane, int pipes, int frames = 1)
      : f_(f), lane_(lane), frames_(frames) {
    for (const golden::SlabImage& s : f.slabs)
      if (s.lanes() != pipes)
        throw std::logic_error("slab images of " + std::to_string(s.lanes()) + " lanes for a ring of " +
                               std::to_string(pipes) + " pipelines");
  }

  // The window of this cycle on pipeline `lane_`'s ports.
  template <class M>
  void present(M& m) const {
    constexpr int kW = 16;
    const int base = lane_ * 5 * kW;
    const size_t left = line_.size() - at_;
    for (int i = 0; i < 5; ++i)
      put_bits(m.slab_window_i, base + i * kW, kW, static_cast<size_t>(i) < left ? line_[at_ + i] : 0);
    put_bits(m.slab_avail_i, lane_ * 3, 3, left < 5 ? left : 5);
  }
  // After the clock edge: the decoder's consume_o and the ring's
  // slab_line_o of the cycle that edge ended.
  void clocked(int consumed, bool next_line) {
    at_ += static_cast<size_t>(consumed);
    if (next_line) advance();
  }
  // Lines started so far.
  size_t lines() const { return started_; }

 private:
  void advance() {
    const int ny = f_.slabs.empty() ? 0 : f_.slabs.front().beams();
    if (ny > 0 && k_ == static_cast<int>(f_.slabs.size()) && frame_ + 1 < frames_) {
      k_ = 0;  // the next frame of the view: the same slab images
      ++frame_;
    }
    if (ny == 0 || k_ >= static_cast<int>(f_.slabs.size()))
      throw std::logic_error("slab line source: the decoder started more lines than the frames have");
    const golden::SlabImage& s = f_.slabs[static_cast<size_t>(k_)];
    if (s.empty()) {
      cleared_ = golden::rle_clear(s.lane_width(lane_));
      line_ = cleared_;
    } else {
      line_ = s.line(y_, lane_);
    }
    at_ = 0;
    ++started_;
    if (++y_ == ny) {
      y_ = 0;
      ++k_;
    }
  }

  const golden::PolygonFrame& f_;
  int lane_, frames_;
  int k_ = 0, y_ = 0, frame_ = 0;  // the next line's slice, beam and frame
  golden::RleWords line_;  // none before the first line
  golden::RleLine cleared_;
  size_t at_ = 0, started_ = 0;
};

}  // namespace cube4::rtl
