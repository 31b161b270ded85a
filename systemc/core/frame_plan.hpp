// Everything a frame's stream is made of, derived once from the registers
// and p: the traversal sizes, the per-slice control of the weight generator
// (golden slice_control()) and the stream tag that carries it through the
// interpolation unit to the gradient unit. The cycle model of a frame
// (frame_cycles(), systemc/core/cycle_model.cpp) is computed from the same sizes.
#pragma once
#include <cstdint>
#include <vector>

#include "golden/pipeline.hpp"
#include "golden/registers.hpp"
#include "systemc/rtl/gradient_tag.hpp"

namespace cube4::sysc {

// The gradient ring's user tag as the system builds it (systemc/CMakeLists.txt):
// the slice number, below 2^16.
using rtl::kSupersamplingBits;
constexpr int kUserTagBits = 16;

struct FramePlan {
  FramePlan(const golden::Registers& regs, int pipes);

  const golden::Registers& r;
  int p;              // pipelines
  int nx, ny, nz;     // permuted volume
  int B;              // partial beams per beam, ceil(nx / p)
  int K;              // sample slices, nz * S
  int passes;         // interpolation passes: K, plus the zero pass when the gradient unit runs
  std::vector<golden::SliceControl> slices;  // slice_control(k), k = 0 .. K (K: the next of the last)

  // The pass's voxel slice: z_voxel(k) when wz = 0, else z_voxel(k) + 1
  // (docs/rtl-interp.md); nz for the zero pass (no memory read).
  int pass_voxel_slice(int pass) const;
  bool zero_pass(int pass) const { return pass >= K; }
  // The interpolation ring's tag of a pass: the gradient ring's control
  // fields (realign x4, S, ZeroSlice), then the slice number.
  uint64_t pass_tag(int pass) const;
  int tag_bits() const { return rtl::gradient_tag_bits(r.p.weight_bits, kUserTagBits); }
  uint32_t tag_slice(uint64_t tag) const {
    return static_cast<uint32_t>(tag >> (tag_bits() - kUserTagBits)) & ((1u << kUserTagBits) - 1);
  }
  bool tag_zero_slice(uint64_t tag) const { return tag >> (tag_bits() - kUserTagBits - 1) & 1; }
};

}  // namespace cube4::sysc
