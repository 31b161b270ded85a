// The system model: the stream former (address generation, skewed voxel
// memory, de-skew, weight generator), p pipelines of interpolation ->
// gradient -> shading -> compositing units (each at TLM or RTL), and pixel
// memory. run_frame() renders one frame of the given registers and volume
// and counts its cycles. docs/system.md describes the structure and the
// cycle accounting.
#pragma once
#include <stdexcept>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "golden/polygon_connections.hpp"
#include "golden/polygon_frame.hpp"
#include "golden/registers.hpp"
#include "golden/renderers.hpp"
#include "golden/scene.hpp"
#include "golden/volume.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/core/trace_window.hpp"

namespace cube4::sysc {

// Who clocks a cycle-level run: the SystemC kernel (one process on the
// clock's edge clocking every unit, registered links), or a plain C++ loop
// over the same units (the speed ceiling for benchmarks; same cycles, same
// image).
enum class Kernel { SystemC, PlainLoop };

struct SystemConfig {
  int p = 4;
  Kernel kernel = Kernel::SystemC;
  // Every unit at TLM but clocked beat by beat (the per-unit TLM models of
  // systemc/tlm/) instead of one loosely timed transaction.
  bool cycle_level = false;
  std::array<Level, kUnits> levels{Level::Rtl, Level::Rtl, Level::Rtl, Level::Rtl, Level::Rtl};
  TraceWindow trace;         // RTL units only
  bool check = false;        // compare every unit's output stream with golden
  // Simulate what the scene does not need as well (to measure what skipping
  // saves): the gradient unit, and at RTL the full shading and compositing hardware.
  bool simulate_unneeded = false;
  int frames = 1;            // cycle-level runs: frames of the same view streamed back to back
  // Verilator's random reset: every register and memory the RTL does not
  // reset starts from values drawn from this seed (the RTL is verilated with
  // --x-initial unique), so runs with two seeds are two X-states.
  uint32_t seed = 1;
  // Keep every ray's accumulator in pixel memory beside its pixel (the
  // result plane's acc): a block of a partitioned volume, whose partial
  // image the composition network reads (golden/blocks.hpp).
  bool accumulators = false;
  // How the frame's slab images reach the pipelines, and the rates of the
  // engine that draws them (systemc/core/polygon_source.hpp; the scene's
  // "polygon_engine"), in cycles of this clock: a hybrid frame's waits.
  golden::PolygonEngine polygon_engine;
  double clock_hz = 125e6;
  // The geometry engine's work for the frame's polygons, when the images
  // came over the host bus (which carries their pixels, not the work that
  // drew them); unset: golden::polygon_work() of the frame run_frame() gets.
  std::optional<golden::PolygonWork> polygon_work;
  // Threads of a cycle-level run: 1, or 2 with the shading and compositing
  // units on a thread of their own (systemc/core/schedules.hpp; the same
  // cycles and image); 0: 2 when the shading or compositing unit runs at
  // RTL on a machine of two cores or more. A traced run takes one (its
  // waveforms end where the frame does).
  int threads = 0;
  // Evaluate the RTL units' assertions (rtl/assert/); a failure ends the
  // frame with RtlAssertionError. cube4 render --no-assert turns them off.
  bool assertions = true;
  bool all_tlm() const {
    for (Level l : levels)
      if (l != Level::Tlm) return false;
    return true;
  }
};

// The first value a unit emitted that differs from golden's.
struct Mismatch {
  Unit unit = Unit::Interp;
  int slice = 0, x = 0, y = 0;
  std::string expected, got;
  std::string describe() const;
};

struct SystemResult {
  golden::BasePlane plane;
  uint64_t frame_cycles = 0;    // first voxel beat to last pixel written (first-frame latency)
  uint64_t measured_interval = 0;  // cycles between the last pixels of back-to-back frames (frames > 1)
  uint64_t stream_cycles = 0;   // voxel beats (and polygon waits) per frame: the steady-state interval of back-to-back frames
  uint64_t samples = 0;         // rays-slices composited: nx * ny * K, perspective_samples() in perspective
  uint64_t voxel_reads = 0;     // voxel memory reads (one per module per read cycle)
  uint64_t simulated_cycles = 0;  // clock cycles simulated (cycle-level runs)
  // A hybrid frame: its connection ("rle", "dual", "ideal"; empty without
  // polygons) and the cycles the first frame waited for slab images (in
  // frame_cycles and, once a frame, in stream_cycles).
  std::string polygon_connection;
  uint64_t polygon_stall_cycles = 0;
  std::array<uint64_t, 4> last_beat{};  // cycle of the last beat on each link (former, interp, gradient, shade)
  double wall_seconds = 0;
  std::array<Level, kUnits> levels{};
  Level weight_generator = Level::Tlm;   // Rtl: cube4_dda's slice controls (with the interpolation unit at RTL)
  std::array<bool, kUnits> simulated{};  // false: not needed by the scene, not simulated
  std::vector<std::string> skipped;      // logic the scene does not need, not simulated
  std::vector<std::string> unused;       // logic the scene does not need, simulated inside an RTL unit
  std::optional<Mismatch> mismatch;      // --check: the first unit output that differs
  // A clocked perspective frame: shading and compositing ran loosely timed
  // after the stream (systemc/core/perspective_frame.hpp), so frame_cycles
  // is the cycle model's; last_beat[0..1] were measured, and last_beat[2]
  // when the gradient unit ran clocked.
  bool back_loosely_timed = false;
  bool gradient_clocked = false;  // ... and its gradient unit ran on the clock, before them
  int threads = 1;                // simulation threads the frame ran on
  // A perspective frame: the cycle model's first-frame latency and
  // steady-state interval of the same volume in parallel projection.
  uint64_t parallel_frame_cycles = 0, parallel_stream_cycles = 0;
};

// `polygons`: the frame's polygon images (Cube-5; golden/polygon_frame.hpp,
// made by golden::rasterise_polygons() for these registers), a frame input
// like the volume, which the compositing unit composites with the samples
// (at TLM through the golden slice compositor, at RTL through the ring
// verilated with polygon hardware: check_polygon_levels()).
SystemResult run_frame(const golden::Registers& r, const golden::Volume& vol, const SystemConfig& cfg,
                       const golden::Progress& progress = {}, const golden::PolygonFrame* polygons = nullptr);

// Whether `cfg` can draw a frame's polygons: the compositing unit at
// transaction level, or at RTL for a p whose ring is verilated with polygon
// hardware (CMake CUBE4_SYSTEM_POLYGON_PIPES). Throws std::invalid_argument
// naming the p values that have it.
void check_polygon_levels(const SystemConfig& cfg, bool perspective = false);

// Whether the built system can run `cfg` on registers `r`, from the
// registers alone (so before any voxel is loaded; run_frame() checks the
// same): the pipeline counts verilated, the RTL's widths, the lanes of a
// cycle-level run, the ring storage of each ring unit at RTL (a unit
// without ring storage, shading or address generation, is not held to it),
// the stream tag's slices. Throws std::invalid_argument naming the limit,
// the value and what to do; VolumeTooLarge for a limit that smaller
// sub-cubes (--blocks) would meet.
struct VolumeTooLarge : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};
void check_system_limits(const golden::Registers& r, const SystemConfig& cfg);

// The analytic cycle count of a frame at the hardware's rate, for any p
// (systemc/core/cycle_model.cpp; equal to run_frame()'s frame_cycles at RTL,
// which the system tests assert).
struct CycleCount {
  uint64_t stream = 0;   // voxel beats of a frame in a stream of frames: the steady-state interval
  uint64_t flush = 0;    // the flush beam's beats that end a stream after its last frame (0: in `stream`)
  uint64_t latency = 0;  // first-frame latency: stream + flush + the pipeline's drain
  // The latency of a frame that another follows back to back (the first of
  // a stream of frames): `latency`, except that with VolumePro's z gradient
  // the next frame's priming pass streams before the samples that finish
  // this frame's last slice of gradients, one pass (ny·B cycles) later.
  uint64_t latency_followed = 0;
};
CycleCount frame_cycles(const golden::Registers& r, int p);
// A perspective frame's stream position that forms its last ray (its
// sample, or with gradients its gradient): the largest over the slices of
// their last home row, then column. -1 for a frame no ray samples.
int64_t last_ray_position(const golden::Registers& r, int p);

// The threads a cycle-level run of `cfg` uses (SystemConfig::threads).
int simulation_threads(const SystemConfig& cfg);

}  // namespace cube4::sysc
