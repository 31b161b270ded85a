// The polygon side of a hybrid frame in time (Cube-5 §§4-5): when each
// slab image is in the composite buffer, and so when the pipelines may
// start the slice that composites it. The data themselves are the frame's
// polygon images (golden::PolygonFrame), which the compositing unit reads
// as before; what this models is the connection that brings them:
//
//  - Rle (§5, Fig. 15): the geometry engine draws slab k into one half of
//    the double-buffered run-length buffer, taking golden
//    rle_draw_seconds() (its fill and triangle rates, and Fig. 13's insert
//    copying a flit per buffer clock). Slabs 0 and 1 start at the frame's
//    start, one after the other; slab k + 1 (k >= 1) goes into slab k - 1's
//    half, free once slice k starts compositing. A slice whose slab is
//    not drawn waits for it.
//  - Dual (§4, Fig. 9): one shared buffer, the engines take turns: the
//    opaque polygons before the frame's first pass, then before each
//    slice the geometry engine draws its slab (golden dual_draw_seconds())
//    while the pipelines wait.
//  - Ideal: every image there at the start (no wait): the frame costs the
//    volume's cycles.
//
// Slice k composites while pass k + lag streams: lag is 1 when the
// gradient unit runs (its output is a slice behind its input), else 0, so
// with gradients slab 0 is drawn while the first pass streams. A wait
// holds the stream former at the first beat of that pass (a gap in the
// stream, which every unit takes), so the cycle-level runs, RTL included,
// simulate it, and the loosely timed run adds the same waits to its
// analytic frame (stalls_of_frame()). golden connection_times() is the
// same connections' frame time in seconds, for slices alone (docs/
// performance.md, "Cube-5: the two connections").
#pragma once
#include <cstdint>
#include <vector>

#include "golden/polygon_connections.hpp"
#include "golden/scene.hpp"
#include "systemc/core/frame_plan.hpp"

namespace cube4::sysc {

// "rle", "dual", "ideal": the scene's polygon_engine.connection.
const char* polygon_connection_name(golden::PolygonConnection c);

class PolygonSource {
 public:
  // `work`: what the geometry engine draws (golden polygon_work() of the
  // rasteriser's frame).
  PolygonSource(const FramePlan& plan, const golden::PolygonWork& work, const golden::PolygonEngine& e,
                double clock_hz);

  // The cycle at which `pass` may start, for a pass due at cycle `due` (its
  // first beat's cycle without a wait). Called once per pass, in order; a
  // frame's pass 0 starts the frame's drawing.
  uint64_t release(int pass, uint64_t due);
  // Cycles waited so far.
  uint64_t stall_cycles() const { return stalls_; }
  // A frame's waits with its passes streamed back to back, each
  // pass_cycles long (what the clocked runs do): for the loosely timed run.
  uint64_t stalls_of_frame(uint64_t pass_cycles);

 private:
  golden::PolygonConnection kind_;
  int slices_, lag_;
  int first_pass_;  // FramePlan::first_pass(): -1 with a priming pass
  std::vector<uint64_t> draw_;  // per slab, cycles (Rle: run-length buffer; Dual: shared buffer)
  uint64_t opaque_ = 0;         // Dual: the opaque polygons' cycles
  std::vector<uint64_t> drawn_;  // Rle: the cycle each slab is complete
  uint64_t stalls_ = 0;
};

}  // namespace cube4::sysc
