#include "systemc/core/partitioned.hpp"

#include <algorithm>

#include "systemc/core/machine.hpp"

namespace cube4::sysc {

std::string partial_difference(const golden::BasePlane& want, const golden::BasePlane& got) {
  if (want.width != got.width || want.height != got.height)
    return "partial image " + std::to_string(got.width) + "x" + std::to_string(got.height) + ", golden's " +
           std::to_string(want.width) + "x" + std::to_string(want.height);
  for (size_t i = 0; i < want.acc.size(); ++i) {
    const golden::RayAcc &w = want.acc[i], &g = got.acc[i];
    if (w == g && std::equal(&want.rgba[4 * i], &want.rgba[4 * i] + 4, &got.rgba[4 * i])) continue;
    return "pixel (" + std::to_string(i % static_cast<size_t>(want.width)) + ", " +
           std::to_string(i / static_cast<size_t>(want.width)) + "): expected accumulator (" + std::to_string(w.r) +
           ", " + std::to_string(w.g) + ", " + std::to_string(w.b) + ", " + std::to_string(w.a) + "), got (" +
           std::to_string(g.r) + ", " + std::to_string(g.g) + ", " + std::to_string(g.b) + ", " + std::to_string(g.a) +
           ")";
  }
  return {};
}

PartitionedResult render_partitioned(const golden::BlockPlan& plan, const golden::Volume& vol,
                                     const SystemConfig& cfg, const NetworkConfig& net,
                                     const golden::Progress& progress) {
  PartitionedResult res;
  SystemConfig machine = cfg;
  machine.accumulators = true;
  const double n = static_cast<double>(plan.blocks.size()) + 1;  // and the network
  uint64_t slowest_latency = 0, slowest_stream = 0;
  for (const golden::Block& b : plan.blocks) {
    const golden::Volume bv = golden::block_volume(vol, b);
    golden::Progress p;
    if (progress) p = [&, i = res.blocks.size()](double f) { progress((static_cast<double>(i) + f) / n); };
    double bus = 0;
    res.blocks.push_back(render_through_host(b.regs, bv, machine, p, &bus));
    const SystemResult& r = res.blocks.back();
    res.bus_seconds += bus;
    res.samples += r.samples;
    slowest_latency = std::max(slowest_latency, r.frame_cycles);
    slowest_stream = std::max(slowest_stream, r.stream_cycles);
    if (cfg.check && !res.mismatch) {
      const std::string where = "block " + std::to_string(b.index) + ": ";
      const std::string diff = partial_difference(golden::render_block_fixed(bv, b, {}), r.plane);
      if (!diff.empty()) res.mismatch = where + diff;
      else if (r.mismatch) res.mismatch = where + "first unit output that differs: " + r.mismatch->describe();
    }
  }
  std::vector<const golden::BasePlane*> partials;
  for (const SystemResult& r : res.blocks) partials.push_back(&r.plane);
  golden::Progress p;
  if (progress) p = [&](double f) { progress((n - 1 + f) / n); };
  NetworkConfig nc = net;
  nc.check = cfg.check;
  res.network = run_network(plan, partials, nc, p);
  if (cfg.check && !res.mismatch && res.network.mismatch) res.mismatch = *res.network.mismatch;
  res.frame_cycles = slowest_latency + res.network.cycles;
  res.stream_cycles = std::max(slowest_stream, res.network.stream_cycles);
  return res;
}

}  // namespace cube4::sysc
