// Everything a frame's stream is made of, derived once from the registers
// and p: the traversal sizes, the pass order with its flags and weights
// (step()), the per-slice control of the weight generator (golden
// slice_control()) and the stream tag that carries it through the
// interpolation unit to the gradient unit. The system's stream former and
// the RTL ring testbenches (tb/rtl/ring_bench.hpp) both form their streams
// here; the cycle model of a frame (frame_cycles(),
// systemc/core/cycle_model.cpp) is computed from the same sizes. No
// SystemC: library cube4_stream.
#pragma once
#include <cstdint>
#include <vector>

#include "golden/perspective.hpp"
#include "golden/pipeline.hpp"
#include "golden/registers.hpp"
#include "systemc/core/beats.hpp"
#include "systemc/rtl/gradient_tag.hpp"

namespace cube4::sysc {

// The gradient ring's user tag as the system builds it (systemc/CMakeLists.txt):
// the slice number, below 2^16.
using rtl::kSupersamplingBits;
constexpr int kUserTagBits = 16;
// The perspective compositing ring's reach R: how far a ray's home may
// move from one slice to the next, in cells along either axis
// (docs/perspective.md, "The plan for the compositing ring"). Three covers
// every view the reach table measured; a frame that needs more is refused
// at the clocked levels (check_perspective_levels(), system.cpp).
constexpr int kPerspectiveReach = 3;

// What travels with one partial beam of the pass order: its flags, the
// pass's weights and the voxel slice it reads.
struct PassStep {
  BeamFlags f;
  uint32_t wx = 0, wy = 0, wz = 0;  // zero in the zero pass
  int voxel_slice = 0;              // pass_voxel_slice(pass)
  bool reads = false;               // a memory read: y < ny and voxel_slice < nz
};

// The flush beams that end a stream, after its last pass (passes back to
// back, docs/rtl-interp.md): one for the interpolation ring; in
// perspective three for its ring (docs/rtl-interp-persp.md), six with the
// gradient ring, whose last slice's gradients are formed up to six beams
// past the pass after it (golden gradient_cell()).
constexpr int stream_flush_beams(bool perspective, bool gradient) { return !perspective ? 1 : gradient ? 6 : 3; }

// VolumePro's z gradient (gradient on, z_gradient voxel_differences): the
// stream reads one voxel slice ahead after a priming pass, in either
// projection (docs/rtl-interp-zdiff.md; FramePlan::zdiff).
inline bool zdiff_stream(const golden::Registers& r) {
  return r.gradient && r.z_gradient == golden::ZGradient::VoxelDifferences;
}

struct FramePlan {
  // user_tag_bits and tag_base shape the tag's user field (the system's:
  // the pass number in kUserTagBits); a testbench that streams frames back
  // to back gives each frame its own base so that the tags tell them apart.
  // slice_controls: the weight generator's control of slices 0 .. K when it
  // runs at RTL (rtl_slice_controls(), systemc/rtl/rtl_factory.hpp); empty:
  // golden slice_control(), its specification and TLM model.
  // perspective_slices: likewise for a perspective frame, slices 0 .. K - 1
  // of the perspective weight generator when it runs at RTL; empty: golden
  // perspective_slice().
  FramePlan(const golden::Registers& regs, int pipes, int user_tag_bits = kUserTagBits, uint64_t tag_base = 0,
            std::vector<golden::SliceControl> slice_controls = {},
            std::vector<golden::PerspectiveSlice> perspective_slices = {});

  const golden::Registers& r;
  int p;              // pipelines
  int nx, ny, nz;     // permuted volume
  int B;              // partial beams per beam, ceil(nx / p)
  int K;              // sample slices, nz * S
  bool perspective;   // Cube-4's perspective (regs.perspective): rays by index (docs/perspective.md)
  int passes;         // interpolation passes: K, plus the zero pass when the gradient unit runs
                      // (a stream's last frame; frames before it stream K: passes_in_stream()),
                      // numbered 0 ..; with zdiff the priming pass -1 comes first (first_pass())
  bool zdiff;         // VolumePro's z gradient (gradient on, z_gradient voxel_differences): the
                      // stream reads one voxel slice ahead after a priming pass (docs/rtl-interp-zdiff.md)
  int user_tag_bits;
  uint64_t tag_base;
  std::vector<golden::SliceControl> slices;  // slice_control(k), k = 0 .. K (K: the next of the last)
  std::vector<golden::PerspectiveSlice> persp;  // perspective: perspective_slice(k), k = 0 .. K - 1

  // The pass's voxel slice: z_voxel(k) when wz = 0, else z_voxel(k) + 1
  // (docs/rtl-interp.md); with zdiff one slice more, and 0 for the priming
  // pass; nz for the zero pass (no memory read; nor of any slice past nz).
  int pass_voxel_slice(int pass) const;
  bool zero_pass(int pass) const { return pass >= K; }
  // A frame's first pass: -1, the priming pass, with zdiff; 0 otherwise.
  int first_pass() const { return zdiff ? -1 : 0; }
  bool prime_pass(int pass) const { return pass < 0; }
  // A frame's passes in a stream of frames: the zero pass only ends the
  // stream (the next frame's first slice is the zero slice ahead of this
  // frame's last, docs/rtl-gradient.md).
  int passes_in_stream(bool stream_last_frame) const { return stream_last_frame ? passes : K; }
  // The beams the stream gives a pass: ny, and the flush beams (beams ny ..)
  // after the stream's last (stream_flush_beams()).
  int flush_beams() const { return stream_flush_beams(perspective, r.gradient); }
  int beams(bool stream_last_pass) const { return ny + (stream_last_pass ? flush_beams() : 0); }
  // A pass's beats in a stream of passes (the last pass's flush aside).
  uint64_t pass_beats() const { return static_cast<uint64_t>(ny) * static_cast<uint64_t>(B); }
  // Partial beam j of beam y (0 .. ny - 1, then the flush beams) of a pass.
  PassStep step(int pass, int y, int j) const;
  // The interpolation ring's tag of a pass: the gradient ring's control
  // fields (realign x4, S, ZeroSlice, FrameStart), then tag_base + pass;
  // in perspective only the latter (the perspective ring's TagBits), the
  // priming pass's being the zero pass's (no rays).
  uint64_t pass_tag(int pass) const;
  uint64_t user_tag(int pass) const {
    return (tag_base + static_cast<uint64_t>(pass)) & ((uint64_t{1} << user_tag_bits) - 1);
  }
  int tag_bits() const { return perspective ? user_tag_bits : rtl::gradient_tag_bits(r.p.weight_bits, user_tag_bits); }
  uint32_t tag_slice(uint64_t tag) const {
    return static_cast<uint32_t>(tag >> (tag_bits() - user_tag_bits) & ((uint64_t{1} << user_tag_bits) - 1));
  }
  bool tag_zero_slice(uint64_t tag) const { return tag >> (tag_bits() - user_tag_bits - 2) & 1; }
  bool tag_frame_start(uint64_t tag) const { return tag >> (tag_bits() - user_tag_bits - 1) & 1; }
};

}  // namespace cube4::sysc
