// The input streams of the RTL rings, bound to their ports once: the
// system's RTL wrappers (rtl_interp.hpp, rtl_composite.hpp) and the ring
// testbenches (tb/rtl/test_*_ring.cpp) drive the verilated rings through
// these, so a port the RTL adds or widens is bound in one place, and what
// the compositing ring is told about a slice is derived from the frame plan
// in one place. Header-only and without SystemC (the beats and the plan are
// plain structs), on any verilated cube4_interp_ring / cube4_composite_ring,
// and the pass constants every perspective ring takes.
#pragma once
#include <cstdint>

#include "golden/perspective.hpp"
#include "golden/precision.hpp"
#include "systemc/core/beats.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/rtl/vl_bits.hpp"

namespace cube4::rtl {

// A stream step's valid bit and beam flags, as every interpolation ring
// takes them from the voxel stream (parallel and perspective), and the
// perspective gradient and compositing rings from the beats behind it.
template <class M>
void drive_stream_flags(M& m, bool valid, const sysc::BeamFlags& f) {
  m.valid_i = valid;
  m.beam_start_i = f.beam_start;
  m.beam_end_i = f.beam_end;
  m.slice_start_i = f.slice_start;
  m.slice_end_i = f.slice_end;
  m.flush_i = f.flush;
}
template <class M>
void drive_stream_flags(M& m, const sysc::VoxelBeat& b) {
  drive_stream_flags(m, b.valid, b.f);
}

// The interpolation ring's inputs in one cycle (docs/rtl-interp.md). While
// b.valid is low the other inputs may hold anything: the ring ignores them.
// word_bits: the voxel word's, voxel_bits plus the ring's VoxelTagBits (the
// memory word {tag, value}, bela §III).
template <class M>
void drive_interp_stream(M& m, const sysc::VoxelBeat& b, int pipes, int word_bits, int tag_bits) {
  drive_stream_flags(m, b);
  m.prime_i = b.f.prime;
  for (int k = 0; k < pipes; ++k) put_bits(m.voxel_i, k * word_bits, word_bits, b.voxel[static_cast<size_t>(k)]);
  m.wx_i = b.wx;
  m.wy_i = b.wy;
  m.wz_i = b.wz;
  put_bits(m.tag_i, 0, tag_bits, b.tag);
}

// What the compositing ring needs beside a partial beam's shaded samples
// (docs/rtl-composite.md): the beam flags, the slice's position in the
// frame, its DDA offsets and steps (and the next slice's), the beam's
// position and the weights, and the frame's width and last offsets.
struct CompositeControl {
  bool valid = false;
  sysc::BeamFlags f;
  bool first_slice = false, last_slice = false, dx = false, dy = false, next_dx = false, next_dy = false;
  uint32_t ix = 0, iy = 0, x = 0, y = 0, z = 0, wx = 0, wy = 0, wz = 0;
  uint32_t nx = 0, last_ix = 0, last_iy = 0;
};

// The control of sample slice k's partial beam at (x = j*p, y): the weight
// generator's slice_control() of k and of k + 1 (plan.slices), which the
// system looks up by the slice number the stream carries.
inline CompositeControl composite_control(const sysc::FramePlan& plan, int k, const sysc::BeamFlags& f, int x,
                                          int y) {
  const golden::SliceControl& c = plan.slices[static_cast<size_t>(k)];
  const golden::SliceControl& next = plan.slices[static_cast<size_t>(k) + 1];
  CompositeControl cc;
  cc.valid = true;
  cc.f = f;
  cc.first_slice = k == 0;
  cc.last_slice = k + 1 == plan.K;
  cc.dx = c.dx != 0;
  cc.dy = c.dy != 0;
  cc.next_dx = next.dx != 0;
  cc.next_dy = next.dy != 0;
  cc.ix = static_cast<uint32_t>(c.ix);
  cc.iy = static_cast<uint32_t>(c.iy);
  cc.x = static_cast<uint32_t>(x);
  cc.y = static_cast<uint32_t>(y);
  cc.z = static_cast<uint32_t>(c.z_voxel);
  cc.wx = c.wx;
  cc.wy = c.wy;
  cc.wz = c.wz;
  cc.nx = static_cast<uint32_t>(plan.nx);
  // The base-plane pixel of x = 0 at the last slice's offset: the last
  // slice's ix, iy plus the margins a polygon scene adds (zero without).
  cc.last_ix = static_cast<uint32_t>(plan.r.base_origin_x());
  cc.last_iy = static_cast<uint32_t>(plan.r.base_origin_y());
  return cc;
}

// The compositing ring's stream inputs in one cycle: the control and each
// pipeline's shaded sample (colour and α at alpha_bits, value at voxel_bits).
template <class M>
void drive_composite_stream(M& m, const CompositeControl& c, const sysc::ShadedBeat& s, int pipes,
                            const golden::Precision& pr) {
  const int a = pr.alpha_bits, v = pr.voxel_bits;
  m.valid_i = c.valid;
  m.beam_start_i = c.f.beam_start;
  m.beam_end_i = c.f.beam_end;
  m.slice_start_i = c.f.slice_start;
  m.slice_end_i = c.f.slice_end;
  m.first_slice_i = c.first_slice;
  m.last_slice_i = c.last_slice;
  m.dx_i = c.dx;
  m.dy_i = c.dy;
  m.next_dx_i = c.next_dx;
  m.next_dy_i = c.next_dy;
  m.ix_i = c.ix;
  m.iy_i = c.iy;
  m.x_i = c.x;
  m.y_i = c.y;
  m.z_i = c.z;
  m.wx_i = c.wx;
  m.wy_i = c.wy;
  m.wz_i = c.wz;
  m.nx_i = c.nx;
  m.last_ix_i = c.last_ix;
  m.last_iy_i = c.last_iy;
  for (int k = 0; k < pipes; ++k) {
    const auto i = static_cast<size_t>(k);
    put_bits(m.red_i, k * a, a, s.red[i]);
    put_bits(m.green_i, k * a, a, s.green[i]);
    put_bits(m.blue_i, k * a, a, s.blue[i]);
    put_bits(m.alpha_i, k * a, a, s.alpha[i]);
    put_bits(m.value_i, k * v, v, s.value[i]);
  }
}

// Pipeline k's finished ray on the compositing ring's pixel port as its
// accumulator (golden RayAcc): the partial image of a block.
template <class M>
golden::RayAcc composite_pixel_acc(const M& m, int k, const golden::Precision& pr) {
  const int ab = golden::acc_bits(pr), v = pr.voxel_bits;
  golden::RayAcc acc;
  acc.r = static_cast<uint32_t>(get_bits(m.pixel_acc_red_o, k * ab, ab));
  acc.g = static_cast<uint32_t>(get_bits(m.pixel_acc_green_o, k * ab, ab));
  acc.b = static_cast<uint32_t>(get_bits(m.pixel_acc_blue_o, k * ab, ab));
  acc.a = static_cast<uint32_t>(get_bits(m.pixel_acc_alpha_o, k * ab, ab));
  acc.value = static_cast<uint16_t>(get_bits(m.pixel_value_o, k * v, v));
  acc.valid = get_bits(m.pixel_selected_o, k, 1) != 0;
  return acc;
}

}  // namespace cube4::rtl

namespace cube4::sysc {

// The system's perspective rings' widths (systemc/CMakeLists.txt).
constexpr int kPerspPosBits = 48, kPerspRayBits = 16;

// The constants both perspective rings take of a pass: the rays' spacing,
// ray 0's position and the rays that sample the slice, per axis (none in
// the zero pass).
template <class M>
void drive_persp_rays(M& m, const golden::PerspectiveSlice& s, bool zero) {
  auto pos = [](int64_t v) { return static_cast<uint64_t>(v) & ((uint64_t{1} << kPerspPosBits) - 1); };
  auto ray = [&](int64_t v) { return static_cast<uint16_t>(static_cast<uint64_t>(zero ? 0 : v) & 0xffffu); };
  static_assert(kPerspRayBits == 16, "the rays' ports are 16 bits");
  m.spacing_i = pos(s.spacing);
  m.ray0_x_i = pos(s.ray0_x);
  m.ray0_y_i = pos(s.ray0_y);
  m.rays_x_lo_i = ray(s.rays_x.lo);
  m.rays_x_hi_i = ray(s.rays_x.hi);
  m.rays_y_lo_i = ray(s.rays_y.lo);
  m.rays_y_hi_i = ray(s.rays_y.hi);
}

}  // namespace cube4::sysc
