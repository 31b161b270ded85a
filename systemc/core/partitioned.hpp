// A partitioned volume on several machines (golden/blocks.hpp): each block
// rendered by a machine of its own (any level, through the host interface,
// its accumulators kept in pixel memory), then the partial images merged by
// the composition network (compose_network.hpp). The machines work in
// parallel, so a frame takes the slowest block's cycles plus the network's;
// with double-buffered pixel memories (bela §IV) back-to-back frames stream
// at the larger of the slowest block's interval and the network's.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "golden/blocks.hpp"
#include "systemc/core/compose_network.hpp"
#include "systemc/core/system.hpp"

namespace cube4::sysc {

struct PartitionedResult {
  std::vector<SystemResult> blocks;  // per block, plan order (each with its partial image)
  NetworkResult network;
  uint64_t frame_cycles = 0;   // slowest block's latency + the network's
  uint64_t stream_cycles = 0;  // max(slowest block's interval, the network's)
  uint64_t samples = 0;
  double bus_seconds = 0;      // host-bus time of every block's programming and read-back
  // --check: the first difference from golden (a block's partial image, a
  // unit's stream, or the network's image).
  std::optional<std::string> mismatch;
};

// The first difference between a block's partial image and golden's (a
// pixel or the accumulator behind it), or "" if none.
std::string partial_difference(const golden::BasePlane& want, const golden::BasePlane& got);

// progress: the blocks' frames, then the network.
PartitionedResult render_partitioned(const golden::BlockPlan& plan, const golden::Volume& vol,
                                     const SystemConfig& cfg, const NetworkConfig& net,
                                     const golden::Progress& progress = {});

}  // namespace cube4::sysc
