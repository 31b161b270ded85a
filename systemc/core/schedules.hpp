// How a cycle-level frame's units are clocked (run_frame() builds them,
// system.cpp): on the SystemC kernel (one process a clock edge that clocks
// every unit, registered links) or on a plain C++ loop over the same
// units, each either on one thread or split between two. All four give the
// same cycles, streams and image (the system tests compare them).
//
// Two threads: the machine's links carry no back-pressure, so the shading
// and compositing units (the back) can run any number of cycles behind the
// address generation, interpolation and gradient units (the front), fed
// each cycle's gradient beat through a CyclePipe. At RTL the shading units
// of the upper quarter of the pipelines stay on the front (their lanes of the
// shaded beat travel with the gradient beat), which evens the two halves'
// work: the shading units are most of an RTL frame
// (docs/performance.md, "Simulation speed of the system model").
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "golden/renderers.hpp"
#include "systemc/core/stream_checker.hpp"
#include "systemc/core/stream_former.hpp"
#include "systemc/core/pass_gate.hpp"
#include "systemc/core/system.hpp"
#include "systemc/core/unit_if.hpp"

class VerilatedContext;

namespace cube4::sysc {

// The units of one frame (plain objects: a frame creates them afresh) and
// the frame's progress through them.
struct FrameUnits {
  std::unique_ptr<AddrIf> addr;
  std::unique_ptr<StreamFormer> former;
  std::unique_ptr<InterpIf> interp;
  std::unique_ptr<GradientIf> gradient;
  std::unique_ptr<ShadeIf> shade;
  std::unique_ptr<CompositeIf> composite;
  StreamChecker* checker = nullptr;
  std::optional<PassGate> gate;  // a hybrid frame's slab images in time
  golden::Progress progress;
  uint64_t total_beats = 1;
  int frames = 1;

  // Written by the front (stream former .. gradient unit).
  uint64_t cycle = 0;
  uint64_t last_valid[3] = {0, 0, 0};  // last cycle the voxel, sample and gradient links carried a beat

  // Written by the back (shading and compositing units), a cache line of
  // their own: on two threads a line both wrote every cycle would travel
  // between the cores every cycle.
  alignas(64) uint64_t last_shaded = 0;  // last cycle the shaded link carried a beat
  uint64_t done_cycle = 0;
  std::vector<uint64_t> frame_done_cycles;  // the cycle each frame's last pixel was written
  bool done = false;

  // Two threads (read-only while the frame runs): `shade` then holds the back's shading units (pipelines
  // [0, front_first_lane)) and `front_shade`, if any, the front's (the
  // rest, at RTL). Each thread's verilated models have a context of their
  // own (Verilator reports an assertion to the thread's context), made the
  // thread's while it runs them.
  alignas(64) bool threaded = false;
  std::unique_ptr<ShadeIf> front_shade;
  int p = 1, front_first_lane = 0;
  VerilatedContext* front_ctx = nullptr;
  VerilatedContext* back_ctx = nullptr;
};

// Runs the units from the frame's first cycle to its last pixel (u.done).
void run_units(FrameUnits& u, Kernel kernel);

}  // namespace cube4::sysc
