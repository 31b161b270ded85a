// The gradient ring's stream tag (cube4_gradient_ring), which the
// interpolation ring carries from a slice's voxels to its samples: the
// slice's four realign fields (weight, then base < 0), the supersampling
// factor, the zero-slice bit, the frame-start bit and, on top, the user's
// tag. The system's
// stream former (FramePlan::pass_tag) and the ring testbenches form it
// here; CMake's cube4_gradient_tag_bits (rtl/CMakeLists.txt) sizes the
// verilated rings with the same layout at the system's WeightBits.
#pragma once
#include <cstdint>

#include "golden/pipeline.hpp"

namespace cube4::rtl {

constexpr int kSupersamplingBits = 4;  // cube4_pkg::SupersamplingBits: S up to 15 (checked in rtl_factory.cpp)

constexpr int gradient_tag_bits(int weight_bits, int user_tag_bits) {
  return 4 * (weight_bits + 1) + kSupersamplingBits + 2 + user_tag_bits;
}

// control: the slice's control, or nullptr for the zero slice (the one past
// the last, whose control the ring never uses: its realign fields are
// `zero_slice_realign`, any value). frame_start: the slice is a frame's
// first (the one after it is the previous frame's zero slice ahead).
inline uint64_t gradient_tag(const golden::SliceControl* control, uint64_t zero_slice_realign, uint64_t supersampling,
                             bool frame_start, uint64_t user_tag, int weight_bits, int user_tag_bits) {
  uint64_t t = 0;
  int pos = 0;
  auto put = [&](uint64_t v, int bits) {
    t |= (v & ((uint64_t{1} << bits) - 1)) << pos;
    pos += bits;
  };
  if (control) {
    for (const golden::Realign& a : {control->behind_x, control->behind_y, control->ahead_x, control->ahead_y}) {
      put(a.weight, weight_bits);
      put(a.base < 0 ? 1 : 0, 1);
    }
  } else {
    put(zero_slice_realign, 4 * (weight_bits + 1));
  }
  put(supersampling, kSupersamplingBits);
  put(control ? 0 : 1, 1);
  put(frame_start ? 1 : 0, 1);
  put(user_tag, user_tag_bits);
  return t;
}

}  // namespace cube4::rtl
