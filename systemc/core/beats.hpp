// What travels between the units in a cycle-level run, one value per clock:
// a "beat" is one partial beam (one lane per pipeline) with the control that
// travels with it. The fields are those of the RTL streams
// (docs/rtl-interp.md, rtl-gradient.md, rtl-composite.md); both levels of a
// unit read and write the same beats, so any mix can be connected.
#pragma once
#include <array>
#include <cstdint>

namespace cube4::sysc {

// Largest p of a cycle-level run (the RTL variants are built for a list of
// p up to this, CUBE4_SYSTEM_PIPES); transaction-level runs take any p.
constexpr int kMaxLanes = 16;

struct BeamFlags {
  bool beam_start = false, beam_end = false;    // partial beam j = 0, j = B-1
  bool slice_start = false, slice_end = false;  // beam y = 0, last beam of the slice
  bool flush = false;  // voxel stream only: a beam of no voxels after a pass (docs/rtl-interp.md)
  bool prime = false;  // voxel stream only: a frame's priming pass, VolumePro's z gradient (docs/rtl-interp-zdiff.md)
};

// Stream former -> interpolation: one pass per sample slice (plus the zero
// pass when the gradient unit runs, and with VolumePro's z gradient a
// priming pass first), beams 0 .. ny-1, and a flush beam where
// FramePlan::beams() says.
struct VoxelBeat {
  bool valid = false;
  BeamFlags f;
  uint32_t wx = 0, wy = 0, wz = 0;  // the pass's weights
  uint64_t tag = 0;                 // stream tag (systemc/core/frame_plan.hpp)
  std::array<uint16_t, kMaxLanes> voxel{};
};

// Interpolation -> gradient: samples S(j*p + k, y) of a pass, beams 0 .. ny-1.
// vtag: each sample's voxel tag (bela §III), 0 without tags. zdiff: with
// VolumePro's z gradient each sample's interpolated voxel z difference
// (golden interpolated_z_difference()), 0 otherwise.
struct SampleBeat {
  bool valid = false;
  BeamFlags f;
  uint64_t tag = 0;
  std::array<uint16_t, kMaxLanes> sample{};
  std::array<uint8_t, kMaxLanes> vtag{};
  std::array<int32_t, kMaxLanes> zdiff{};
};

// Perspective (Cube-4 §3): the interpolation unit's samples by ray, not by
// voxel position. Pipeline k's lane carries the sample it formed this
// clock, if any (bit k of `valid`), with its ray (u, v), its pass's stream
// tag and its voxel tag (docs/rtl-interp-persp.md: a sample leaves on the
// pipeline of the column two after its ray's home cell). `step` is the
// stream's step (its valid voxel beats counted from 0) that formed the
// beat, lane k at stream position step * p + k, or -1 on a clock that
// carries no step: the position the units behind form their own work at
// (golden/perspective_dataflow.hpp), as the ring's control would travel
// with it. zdiff: with VolumePro's z gradient each sample's filtered voxel
// z difference (golden perspective_z_difference()), 0 otherwise.
struct RaySampleBeat {
  uint32_t valid = 0;
  int64_t step = -1;
  // The flags and pass tag of that stream step (its VoxelBeat's): the
  // ring's control, which the perspective gradient ring needs with the
  // samples (it stores them by pass and row and forms gradients by beam).
  BeamFlags f;
  uint64_t pass_tag = 0;
  std::array<uint16_t, kMaxLanes> sample{};
  std::array<int32_t, kMaxLanes> u{}, v{};
  std::array<uint32_t, kMaxLanes> tag{};
  std::array<uint8_t, kMaxLanes> vtag{};
  std::array<int32_t, kMaxLanes> zdiff{};
};

// Perspective gradient -> shading: each ray's sample with its gradient,
// by ray (RaySampleBeat's lanes, `step` the position that formed the
// gradient: gradient_cell()).
struct RayGradientBeat {
  uint32_t valid = 0;
  int64_t step = -1;
  BeamFlags f;            // that step's flags and pass tag (RaySampleBeat's)
  uint64_t pass_tag = 0;
  std::array<uint16_t, kMaxLanes> sample{};
  std::array<int16_t, kMaxLanes> gx{}, gy{}, gz{};
  std::array<int32_t, kMaxLanes> u{}, v{};
  std::array<uint32_t, kMaxLanes> tag{};
  std::array<uint8_t, kMaxLanes> vtag{};
};

// Perspective shading -> compositing: each ray's shaded sample before
// cropping and the cut plane, by ray (the gradient beat's lanes).
struct RayShadedBeat {
  uint32_t valid = 0;
  int64_t step = -1;  // the stream step whose gradient beat it is (RayGradientBeat::step)
  BeamFlags f;        // that step's flags and pass tag
  uint64_t pass_tag = 0;
  std::array<uint16_t, kMaxLanes> red{}, green{}, blue{}, alpha{}, value{};
  std::array<int32_t, kMaxLanes> u{}, v{};
  std::array<uint32_t, kMaxLanes> tag{};
};

// Gradient -> shading: the centre sample, its gradient and its position.
struct GradientBeat {
  bool valid = false;
  BeamFlags f;
  int x = 0, y = 0;    // x of lane 0 (= j*p), beam y
  uint32_t slice = 0;  // sample slice k
  std::array<uint16_t, kMaxLanes> sample{};
  std::array<int16_t, kMaxLanes> gx{}, gy{}, gz{};
  std::array<uint8_t, kMaxLanes> vtag{};  // the centre sample's voxel tag
};

// Shading -> compositing: shaded samples before cropping and the cut plane.
struct ShadedBeat {
  bool valid = false;
  BeamFlags f;
  int x = 0, y = 0;
  uint32_t slice = 0;
  std::array<uint16_t, kMaxLanes> red{}, green{}, blue{}, alpha{}, value{};
};

}  // namespace cube4::sysc
