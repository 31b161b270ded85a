// The one SystemC interface of each rendering-pipeline unit, implemented at
// two levels: TLM (systemc/tlm/, golden functions) and RTL (systemc/rtl/, the
// verilated ring or unit). A cycle-level run calls clock() once per clock
// edge with the beat the unit sees in that cycle; the unit returns the beat
// on its output in that cycle.
#pragma once
#include <string>
#include <systemc>

#include "golden/renderers.hpp"
#include "golden/units/addr.hpp"
#include "systemc/core/beats.hpp"

namespace cube4::sysc {

enum class Level { Tlm, Rtl };
inline const char* level_name(Level l) { return l == Level::Tlm ? "tlm" : "rtl"; }

// The units, in pipeline order, then the address generator (the stream
// former's); the names are the command line's.
enum class Unit { Interp = 0, Gradient = 1, Shade = 2, Composite = 3, Addr = 4 };
constexpr int kUnits = 5;
inline const char* unit_name(Unit u) {
  static const char* const names[] = {"interp", "gradient", "shade", "composite", "addr"};
  return names[static_cast<int>(u)];
}

template <class In, class Out>
struct UnitIf : virtual sc_core::sc_interface {
  virtual void clock(const In& in, Out& out) = 0;
  virtual Level level() const = 0;
};

// What the compositing unit reports of an edge: which of its pixel ports
// wrote pixel memory (the unit writes it itself, PixelMemory), and whether
// the frame's last pixel has been written. Small, because a clocked run
// builds one every edge (the ports' 200 bytes of lanes it once carried,
// which nothing read, cost about 3 % of a clocked TLM frame to clear).
struct CompositeOut {
  uint32_t pixel_valid = 0;  // bit k: pipeline k's port
  bool frame_done = false;
};

using InterpIf = UnitIf<VoxelBeat, SampleBeat>;
using PerspInterpIf = UnitIf<VoxelBeat, RaySampleBeat>;  // perspective frames' interpolation unit
using PerspGradientIf = UnitIf<RaySampleBeat, RayGradientBeat>;  // and their gradient unit,
using PerspShadeIf = UnitIf<RayGradientBeat, RayShadedBeat>;      // shading unit
using PerspCompositeIf = UnitIf<RayShadedBeat, CompositeOut>;     // and compositing unit,
// which keeps each frame's base plane (its rays' pixels, written as they
// leave): the frame runner reads the last frame's when it ends.
struct PerspCompositor : PerspCompositeIf {
  virtual const golden::BasePlane& plane() const = 0;  // the last frame that ended
  virtual uint64_t samples_per_frame() const = 0;
};
using GradientIf = UnitIf<SampleBeat, GradientBeat>;
using ShadeIf = UnitIf<GradientBeat, ShadedBeat>;
using CompositeIf = UnitIf<ShadedBeat, CompositeOut>;

// Address generation: one clock edge. `issue` asks for the next read partial
// beam (j, y, z) of the traversal, with the walk's controls for it; the
// result is the access of the partial beam issued at the previous edge.
struct AddrRequest {
  bool issue = false;
  bool repeat_slice = false;  // with a slice's last partial beam: walk the slice again
  bool again = false;         // with the frame's last partial beam: the frame once more
};
// j, y, z and access mean something only when valid.
struct AddrResult {
  bool valid = false;
  int j = 0, y = 0, z = 0;
  golden::BeamAccess access;
};
struct AddrIf : virtual sc_core::sc_interface {
  // The answer stays valid until the next clock.
  virtual const AddrResult& clock(const AddrRequest& next, int j, int y, int z) = 0;
  virtual Level level() const = 0;
  // What the next edge will answer, where the model already holds it (the
  // TLM model's pending access; nullptr from the RTL, whose registers are
  // not read before their edge). For the simulator only: the stream former
  // prefetches those voxels, nothing of the machine's behaviour depends on it.
  virtual const AddrResult* upcoming() const { return nullptr; }
};

}  // namespace cube4::sysc
