// Address generation, voxel memory reads, de-skew and the weight generator:
// the source of the pipelines' voxel stream, one partial beam per clock.
// Pass order (docs/rtl-interp.md): for each pass, beams 0 .. ny (ny is the
// zero beam: a time slot, no read), partial beams 0 .. B-1. The zero pass
// (gradient unit on) reads nothing either.
#pragma once
#include <cstdint>

#include "golden/units/skew.hpp"
#include "systemc/core/beats.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/voxel_memory.hpp"

namespace cube4::sysc {

class StreamFormer {
 public:
  // `frames` frames of the same view back to back, with no gap.
  StreamFormer(const FramePlan& plan, VoxelMemory& mem, int frames = 1);
  // The beat of this cycle (valid = false once the last frame's stream is out).
  VoxelBeat next();
  bool done() const { return frame_ >= frames_; }
  uint64_t beats() const { return beats_; }

 private:
  const FramePlan& plan_;
  VoxelMemory& mem_;
  golden::SkewTraversal traversal_;
  int frames_ = 1, frame_ = 0;
  int pass_ = 0, y_ = 0, j_ = 0;
  uint64_t beats_ = 0;
};

}  // namespace cube4::sysc
