// Pixel memory: the base plane the compositing units write, one port per
// pipeline, and the host reads. Writes outside the base plane are errors of
// the compositing unit, reported with the pipeline and the pixel.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>

#include "golden/renderers.hpp"
#include "golden/slice_steps.hpp"

namespace cube4::sysc {

class PixelMemory {
 public:
  // accumulators: keep each ray's accumulator too (a block's partial image).
  explicit PixelMemory(const golden::Registers& r, bool accumulators = false) : plane_(golden::empty_base_plane(r)) {
    if (accumulators) plane_.acc.assign(static_cast<size_t>(plane_.width) * plane_.height, golden::RayAcc{});
  }

  void write(int pipe, int u, int v, uint16_t red, uint16_t green, uint16_t blue, uint16_t alpha) {
    if (u < 0 || v < 0 || u >= plane_.width || v >= plane_.height)
      throw std::logic_error("pixel memory: pipeline " + std::to_string(pipe) + " wrote pixel (" + std::to_string(u) +
                             ", " + std::to_string(v) + ") outside the " + std::to_string(plane_.width) + "x" +
                             std::to_string(plane_.height) + " base plane");
    uint16_t* px = &plane_.rgba[(static_cast<size_t>(v) * plane_.width + u) * 4];
    px[0] = red; px[1] = green; px[2] = blue; px[3] = alpha;
    ++writes_;
  }
  bool keeps_accumulators() const { return !plane_.acc.empty(); }
  // The accumulator of the ray whose pixel (u, v) was written.
  void write_acc(int u, int v, const golden::RayAcc& acc) {
    if (keeps_accumulators()) plane_.acc[static_cast<size_t>(v) * plane_.width + u] = acc;
  }
  // The transaction-level compositor writes the plane through the golden
  // slice compositor.
  golden::BasePlane& plane() { return plane_; }
  const golden::BasePlane& plane() const { return plane_; }
  uint64_t writes() const { return writes_; }

 private:
  golden::BasePlane plane_;
  uint64_t writes_ = 0;
};

}  // namespace cube4::sysc
