#include "systemc/core/frame_plan.hpp"

#include <stdexcept>
#include <string>

namespace cube4::sysc {

FramePlan::FramePlan(const golden::Registers& regs, int pipes)
    : r(regs), p(pipes), nx(regs.dim[0]), ny(regs.dim[1]), nz(regs.dim[2]),
      B(pipes > 0 ? (regs.dim[0] + pipes - 1) / pipes : 0),  // p < 1 is refused below
      K(regs.sample_slices()), passes(K + (regs.gradient ? 1 : 0)) {
  if (p < 1) throw std::invalid_argument("pipelines: " + std::to_string(p) + " (must be at least 1)");
  if (K >= (1 << kUserTagBits))
    throw std::invalid_argument("sample slices: " + std::to_string(K) + " (the stream tag holds fewer than " +
                                std::to_string(1 << kUserTagBits) + ")");
  if (regs.supersampling >= (1 << kSupersamplingBits))
    throw std::invalid_argument("supersampling: " + std::to_string(regs.supersampling) + " (at most " +
                                std::to_string((1 << kSupersamplingBits) - 1) + ")");
  slices.reserve(static_cast<size_t>(K) + 1);
  for (int k = 0; k <= K; ++k) slices.push_back(golden::slice_control(r, k));
}

int FramePlan::pass_voxel_slice(int pass) const {
  if (zero_pass(pass)) return nz;
  const golden::SliceControl& c = slices[static_cast<size_t>(pass)];
  return c.z_voxel + (c.wz != 0 ? 1 : 0);
}

uint64_t FramePlan::pass_tag(int pass) const {
  const int w = r.p.weight_bits;
  uint64_t t = 0;
  int pos = 0;
  auto put = [&](uint64_t v, int bits) {
    t |= (v & ((uint64_t{1} << bits) - 1)) << pos;
    pos += bits;
  };
  if (!zero_pass(pass)) {
    const golden::SliceControl& c = slices[static_cast<size_t>(pass)];
    for (const golden::Realign& a : {c.behind_x, c.behind_y, c.ahead_x, c.ahead_y}) {
      put(a.weight, w);
      put(a.base < 0 ? 1 : 0, 1);
    }
  } else {
    put(0, 4 * (w + 1));
  }
  put(static_cast<uint64_t>(r.supersampling), kSupersamplingBits);
  put(zero_pass(pass) ? 1 : 0, 1);
  put(static_cast<uint64_t>(pass), kUserTagBits);
  return t;
}

}  // namespace cube4::sysc
