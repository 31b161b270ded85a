// The rays of a perspective frame's slices as golden defines them
// (perspective_slice()), whatever weight generator the units ran with, and
// the index of each ray in its slice (row by row from the slice's first
// ray): how the clocked frame's stores and checks of samples and gradients
// (perspective_frame.cpp, ray_gradients.hpp) lay out their per-slice arrays.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "golden/perspective.hpp"

namespace cube4::sysc {

class FrameRays {
 public:
  explicit FrameRays(const golden::Registers& r) {
    for (int k = 0; k < r.sample_slices(); ++k) {
      const golden::PerspectiveSlice& s = slices_.emplace_back(golden::perspective_slice(r, k));
      widths_.push_back(s.rays_x.empty() || s.rays_y.empty() ? 0 : s.rays_x.hi - s.rays_x.lo);
    }
  }
  int slices() const { return static_cast<int>(slices_.size()); }
  const golden::PerspectiveSlice& slice(int k) const { return slices_[static_cast<size_t>(k)]; }
  // Whether slice k exists and ray (u, v) samples it.
  bool samples(int k, int64_t u, int64_t v) const { return k >= 0 && k < slices() && golden::samples(slice(k), u, v); }
  // Rays sampling slice k, and ray (u, v)'s index among them and back.
  size_t count(int k) const {
    const golden::PerspectiveSlice& s = slice(k);
    return widths_[static_cast<size_t>(k)] == 0 ? 0 : static_cast<size_t>(width(k) * (s.rays_y.hi - s.rays_y.lo));
  }
  size_t index(int k, int64_t u, int64_t v) const {
    const golden::PerspectiveSlice& s = slice(k);
    return static_cast<size_t>((v - s.rays_y.lo) * width(k) + (u - s.rays_x.lo));
  }
  int64_t u_of(int k, size_t i) const { return slice(k).rays_x.lo + static_cast<int64_t>(i) % width(k); }
  int64_t v_of(int k, size_t i) const { return slice(k).rays_y.lo + static_cast<int64_t>(i) / width(k); }

 private:
  int64_t width(int k) const { return widths_[static_cast<size_t>(k)]; }
  std::vector<golden::PerspectiveSlice> slices_;
  std::vector<int64_t> widths_;
};

}  // namespace cube4::sysc
