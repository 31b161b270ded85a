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
  const golden::SliceControl* control = zero_pass(pass) ? nullptr : &slices[static_cast<size_t>(pass)];
  return rtl::gradient_tag(control, 0, static_cast<uint64_t>(r.supersampling), static_cast<uint64_t>(pass),
                           r.p.weight_bits, kUserTagBits);
}

#ifdef CUBE4_SYSTEM_TAG_BITS
static_assert(rtl::gradient_tag_bits(golden::Precision{}.weight_bits, kUserTagBits) == CUBE4_SYSTEM_TAG_BITS,
              "the system's verilated rings carry another tag width (cube4_gradient_tag_bits)");
#endif

}  // namespace cube4::sysc
