#include "systemc/core/frame_plan.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace cube4::sysc {

FramePlan::FramePlan(const golden::Registers& regs, int pipes, int user_tag_bits_, uint64_t tag_base_,
                     std::vector<golden::SliceControl> slice_controls,
                     std::vector<golden::PerspectiveSlice> perspective_slices)
    : r(regs), p(pipes), nx(regs.dim[0]), ny(regs.dim[1]), nz(regs.dim[2]),
      B(pipes > 0 ? (regs.dim[0] + pipes - 1) / pipes : 0),  // p < 1 is refused below
      K(regs.sample_slices()), perspective(regs.perspective), passes(K + (regs.gradient ? 1 : 0)),
      zdiff(zdiff_stream(regs)),
      user_tag_bits(user_tag_bits_),
      tag_base(tag_base_) {
  if (p < 1) throw std::invalid_argument("pipelines: " + std::to_string(p) + " (must be at least 1)");
  if (user_tag_bits < 1 || user_tag_bits > 32)
    throw std::invalid_argument("user tag bits: " + std::to_string(user_tag_bits) + " (1 to 32)");
  // The system reads the slice number back from the tag: it must not wrap.
  if (tag_base == 0 && K >= (int64_t{1} << user_tag_bits))
    throw std::invalid_argument("sample slices: " + std::to_string(K) + " (the stream tag holds fewer than " +
                                std::to_string(int64_t{1} << user_tag_bits) + ")");
  if (regs.supersampling >= (1 << kSupersamplingBits))
    throw std::invalid_argument("supersampling: " + std::to_string(regs.supersampling) + " (at most " +
                                std::to_string((1 << kSupersamplingBits) - 1) + ")");
  if (perspective) {
    if (!perspective_slices.empty() && perspective_slices.size() != static_cast<size_t>(K))
      throw std::logic_error("frame plan: " + std::to_string(perspective_slices.size()) +
                             " perspective slices for a frame of " + std::to_string(K));
    persp = std::move(perspective_slices);
    for (int k = static_cast<int>(persp.size()); k < K; ++k) persp.push_back(golden::perspective_slice(r, k));
  }
  if (!slice_controls.empty()) {
    if (slice_controls.size() != static_cast<size_t>(K) + 1)
      throw std::logic_error("frame plan: " + std::to_string(slice_controls.size()) +
                             " slice controls for a frame of " + std::to_string(K) + " slices (K + 1 needed)");
    slices = std::move(slice_controls);
    return;
  }
  slices.reserve(static_cast<size_t>(K) + 1);
  for (int k = 0; k <= K; ++k) slices.push_back(golden::slice_control(r, k));
}

int FramePlan::pass_voxel_slice(int pass) const {
  if (zero_pass(pass)) return nz;
  if (prime_pass(pass)) return 0;
  if (perspective) {
    const golden::PerspectiveSlice& s = persp[static_cast<size_t>(pass)];
    return std::min(nz, s.z_voxel + (s.wz != 0 ? 1 : 0) + (zdiff ? 1 : 0));
  }
  const golden::SliceControl& c = slices[static_cast<size_t>(pass)];
  return std::min(nz, c.z_voxel + (c.wz != 0 ? 1 : 0) + (zdiff ? 1 : 0));
}

PassStep FramePlan::step(int pass, int y, int j) const {
  PassStep s;
  s.f.beam_start = j == 0;
  s.f.beam_end = j == B - 1;
  s.f.flush = y >= ny;
  s.f.slice_start = y == 0 && !s.f.flush;
  s.f.slice_end = y == ny - 1;
  s.f.prime = prime_pass(pass) && !s.f.flush;
  if (perspective && !s.f.flush && !zero_pass(pass) && !prime_pass(pass)) {
    s.wz = persp[static_cast<size_t>(pass)].wz;
  } else if (!zero_pass(pass) && !prime_pass(pass) && !s.f.flush) {
    const golden::SliceControl& c = slices[static_cast<size_t>(pass)];
    s.wx = c.wx;
    s.wy = c.wy;
    s.wz = c.wz;
  }
  s.voxel_slice = pass_voxel_slice(pass);
  s.reads = y < ny && s.voxel_slice < nz;
  return s;
}

uint64_t FramePlan::pass_tag(int pass) const {
  // The priming pass gives no samples: its tag never leaves the ring. In
  // perspective the rings see it as the zero pass's (slice K: no rays).
  if (prime_pass(pass)) return perspective ? user_tag(K) : 0;
  if (perspective) return user_tag(pass);
  const golden::SliceControl* control = zero_pass(pass) ? nullptr : &slices[static_cast<size_t>(pass)];
  return rtl::gradient_tag(control, 0, static_cast<uint64_t>(r.supersampling), pass == 0, user_tag(pass), r.p.weight_bits,
                           user_tag_bits);
}

#ifdef CUBE4_SYSTEM_TAG_BITS
static_assert(rtl::gradient_tag_bits(CUBE4_SYSTEM_WEIGHT_BITS, kUserTagBits) == CUBE4_SYSTEM_TAG_BITS,
              "the system's verilated rings carry another tag width (cube4_gradient_tag_bits)");
#endif

}  // namespace cube4::sysc
