// The image composition network above N cube4 machines (bela §III.D): the
// machines render the blocks of a partitioned volume (golden/blocks.hpp)
// into their pixel memories, and a tree of N − 1 compositing nodes, depth
// ceil(log2 N), merges their partial images in visibility order, one pixel
// per clock, into the volume's base plane; an output stage rounds each
// composed pixel to the frame buffer's width. Golden compose_blocks() is
// the specification; the nodes run at TLM (golden compose()) or RTL
// (verilated cube4_compose_node, and cube4_compose_out for the output
// stage), clocked by the SystemC kernel or the plain loop like the
// machines, or loosely timed (one transaction, the cycle model's count).
//
// Dataflow and timing, one clock per pixel:
//   cycle c: every machine's pixel memory reads pixel c − 1 of the volume's
//            base plane in raster order (its own partial pixel there, or
//            the empty ray where its partial image has none); the read
//            data reaches the leaf link one cycle later;
//   a node:  front and back from its children's links (near-neighbour:
//            each node talks only to its two children and its parent),
//            Latency = 2 cycles, result on its own link one cycle later;
//            a child nearer the leaves than its sibling is delayed by the
//            difference (skew registers), so both inputs carry one pixel;
//   output:  the root's link through cube4_compose_out (1 cycle) into the
//            frame buffer.
// So the last pixel is written at W·H + 2 + depth·(Latency + 1)
// (network_cycles()), and back-to-back images stream at one per W·H cycles.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "golden/blocks.hpp"
#include "systemc/core/system.hpp"
#include "systemc/core/trace_window.hpp"

class VerilatedContext;

namespace cube4::sysc {

constexpr int kComposeNodeLatency = 2;  // cube4_compose_node's default Latency
constexpr int kComposeOutLatency = 1;   // cube4_compose_out

// One pixel on a network link.
struct NodeBeat {
  bool valid = false;
  golden::RayAcc px;
};
struct OutBeat {
  bool valid = false;
  golden::Pixel px;
};

// A compositing node: front and back in one cycle, the composed pixel of
// the inputs kComposeNodeLatency cycles earlier out (both inputs are valid
// together: the tree aligns them).
struct ComposeNodeIf {
  virtual ~ComposeNodeIf() = default;
  virtual NodeBeat clock(const NodeBeat& front, const NodeBeat& back) = 0;
  virtual Level level() const = 0;
};
// The output stage: a composed pixel in, its frame-buffer pixel of the
// input kComposeOutLatency cycles earlier out.
struct ComposeOutIf {
  virtual ~ComposeOutIf() = default;
  virtual OutBeat clock(const NodeBeat& in) = 0;
};

struct NetworkConfig {
  Level level = Level::Tlm;
  bool cycle_level = false;  // at TLM: clock the golden nodes instead of one loosely timed transaction
  Kernel kernel = Kernel::SystemC;
  bool check = false;        // compare the image with golden compose_blocks()
  uint32_t seed = 1;         // RTL random reset
  bool assertions = true;    // RTL: the nodes' assertions (rtl/assert/), RtlAssertionError when one fails
  TraceWindow trace;         // RTL: F.compose.fst (the root node) if set
};

struct NetworkResult {
  golden::BasePlane plane;      // the volume's base plane
  uint64_t cycles = 0;          // first pixel read to last pixel written
  uint64_t stream_cycles = 0;   // W·H: the interval of back-to-back images
  int nodes = 0, depth = 0;
  Level level = Level::Tlm;
  bool clocked = false;
  double wall_seconds = 0;
  std::optional<std::string> mismatch;  // --check: the first pixel that differs from golden
};

struct NetworkCycles {
  uint64_t stream = 0, latency = 0;
  int nodes = 0, depth = 0;
};
NetworkCycles network_cycles(int width, int height, int blocks);

// Merges `partials` (block i's partial image, with its accumulators) as
// `plan` says. Throws std::invalid_argument for partial images that do not
// fit the plan.
NetworkResult run_network(const golden::BlockPlan& plan, const std::vector<const golden::BasePlane*>& partials,
                          const NetworkConfig& cfg, const golden::Progress& progress = {});

// The TLM node and output stage (golden compose() and pixel_of(), with the
// RTL's latencies).
std::unique_ptr<ComposeNodeIf> make_tlm_compose_node(golden::BlendMode mode, const golden::Precision& p);
std::unique_ptr<ComposeOutIf> make_tlm_compose_out(const golden::Precision& p);

}  // namespace cube4::sysc
