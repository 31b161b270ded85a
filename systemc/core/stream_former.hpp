// Address generation, voxel memory reads, de-skew and the weight generator:
// the source of the pipelines' voxel stream, one partial beam per clock.
// Pass order (docs/rtl-interp.md): for each pass, beams 0 .. ny-1, partial
// beams 0 .. B-1, passes and frames back to back (with VolumePro's z
// gradient each frame starting with its priming pass, -1); after the last frame the
// zero pass (gradient unit on; it reads nothing) and a flush beam (a time
// slot, no read). The memory addresses come from
// the address generator (AddrIf: TlmAddr, systemc/tlm/tlm_addr.hpp, at TLM;
// RtlAddr, the verilated cube4_addr, at RTL), which the former runs one read
// ahead.
#pragma once
#include <cstdint>
#include <vector>

#include "systemc/core/beats.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/core/voxel_memory.hpp"

namespace cube4::sysc {

class StreamFormer {
 public:
  // `frames` frames of the same view back to back, with no gap. `addr` is
  // primed here with the first read (before the frame's first cycle).
  StreamFormer(const FramePlan& plan, VoxelMemory& mem, AddrIf& addr, int frames = 1);
  // The beat of this cycle (valid = false once the last frame's stream is out).
  VoxelBeat next();
  bool done() const { return at_.frame >= frames_; }
  // The beat next() gives next: its frame and pass, and whether it is the
  // pass's first (where a wait for the polygon source holds the stream).
  struct Upcoming {
    int frame = 0, pass = 0;
    bool first_of_pass = false;
  };
  Upcoming upcoming() const { return {at_.frame, at_.pass, at_.y == 0 && at_.j == 0}; }
  int passes() const { return plan_.passes; }
  int first_pass() const { return plan_.first_pass(); }
  uint64_t beats() const { return beats_; }

 private:
  struct Pos {
    int frame = 0, pass = 0, y = 0, j = 0;
  };
  Pos following(Pos p) const;
  // FramePlan::pass_voxel_slice(pass), kept: a beat asks for it several times.
  int slice(int pass) const { return slices_[static_cast<size_t>(pass - plan_.first_pass())]; }
  // FramePlan::step(...).reads.
  bool reads(const Pos& p) const { return p.frame < frames_ && p.y < plan_.ny && slice(p.pass) < plan_.nz; }
  // The walk's controls that go with issuing the read at p.
  AddrRequest request_for(const Pos& p) const;
  // The next position that reads, from p on (p itself included).
  Pos next_read(Pos p) const;

  const FramePlan& plan_;
  VoxelMemory& mem_;
  AddrIf& addr_;
  int frames_;
  Pos at_;
  uint64_t beats_ = 0;
  std::vector<int> slices_;      // of passes first_pass() .. passes - 1
  std::vector<uint64_t> tags_;  // FramePlan::pass_tag() of the same passes
};

}  // namespace cube4::sysc
