#include "tb/system_report.hpp"

#include <cstdio>

namespace cube4::tb {

nlohmann::json describe_system(const sysc::SystemResult& r, const sysc::SystemConfig& cfg, double clock_mhz,
                               double wall_seconds, const std::string& check_failure) {
  nlohmann::json units = nlohmann::json::object();
  for (int u = 0; u < sysc::kUnits; ++u) {
    const auto i = static_cast<size_t>(u);
    const bool loose =
        r.back_loosely_timed && ((u == static_cast<int>(sysc::Unit::Gradient) && !r.gradient_clocked) ||
                                 u == static_cast<int>(sysc::Unit::Shade) || u == static_cast<int>(sysc::Unit::Composite));
    units[sysc::unit_name(static_cast<sysc::Unit>(u))] =
        !r.simulated[i] ? "not simulated (not needed by the scene)" : loose ? "tlm (loosely timed)" : sysc::level_name(r.levels[i]);
  }
  // Not one of the five units: the slice controls of the interpolation
  // unit's level (golden slice_control() at TLM, cube4_dda at RTL).
  units["weight_generator"] = sysc::level_name(r.weight_generator);
  const double hz = clock_mhz * 1e6;
  nlohmann::json j = {
      {"pipelines", cfg.p},
      {"units", units},
      {"skipped", r.skipped},
      {"unused_rtl_logic", r.unused},
      {"cycles_per_frame", r.frame_cycles},
      {"cycles_steady_state_interval", r.stream_cycles},
      {"cycles_steady_state_interval_measured",
       r.measured_interval ? nlohmann::json(r.measured_interval) : nlohmann::json("not measured (use --frames 2 or more)")},
      {"frames_back_to_back", cfg.frames},
      {"fps_first_frame", hz / static_cast<double>(r.frame_cycles)},
      {"fps_steady_state", hz / static_cast<double>(r.stream_cycles)},
      {"samples_per_cycle", static_cast<double>(r.samples) / static_cast<double>(r.stream_cycles)},
      {"voxel_reads", r.voxel_reads},
      {"simulated_cycles", r.simulated_cycles},
      {"simulated_cycles_per_wall_second",
       wall_seconds > 0 ? static_cast<double>(r.simulated_cycles ? r.simulated_cycles : r.frame_cycles) / wall_seconds
                        : 0.0},
      {"simulation_threads", r.threads},
      {"seed", cfg.seed},
      {"rtl_assertions", cfg.assertions ? "on" : "off (--no-assert)"},
      {"timing", r.back_loosely_timed && r.gradient_clocked
                     ? "simulated clock cycles through the interpolation unit (its last sample in cycle " +
                           std::to_string(r.last_beat[1]) + ") and the gradient unit (its last gradient in cycle " +
                           std::to_string(r.last_beat[2]) +
                           "), then shading and compositing loosely timed (perspective: no clocked models of them "
                           "yet); cycles_per_frame is the cycle model's"
                 : r.back_loosely_timed
                     ? "simulated clock cycles through the interpolation unit (its last sample in cycle " +
                           std::to_string(r.last_beat[1]) +
                           "), then gradient, shading and compositing loosely timed (perspective: no clocked "
                           "models of them yet); cycles_per_frame is the cycle model's"
                 : cfg.all_tlm() && !cfg.cycle_level ? "cycle model (loosely timed, no clock simulated)"
                                                     : "simulated clock cycles"},
      {"check", !cfg.check                ? std::string("off")
                : !check_failure.empty()     ? check_failure
                : r.back_loosely_timed && r.gradient_clocked
                    ? std::string("passed: base plane, the interpolation unit's samples and the gradient unit's "
                                  "gradients bit-exact (shading and compositing loosely timed)")
                : r.back_loosely_timed ? std::string("passed: base plane and the interpolation unit's samples bit-exact "
                                                     "(the units after it loosely timed)")
                                             : std::string("passed: base plane and unit streams bit-exact")},
  };
  if (r.parallel_frame_cycles > 0) {
    // Cube-4 implies perspective costs no cycles (a voxel per pipeline per
    // cycle either way): the stream is the same, the first frame's end is
    // not (docs/perspective.md, "The dataflow").
    j["perspective_cost"] = {
        {"parallel_projection_cycles_per_frame", r.parallel_frame_cycles},
        {"extra_cycles_per_frame", static_cast<int64_t>(r.frame_cycles) - static_cast<int64_t>(r.parallel_frame_cycles)},
        {"parallel_projection_steady_state_interval", r.parallel_stream_cycles},
        {"extra_cycles_steady_state",
         static_cast<int64_t>(r.stream_cycles) - static_cast<int64_t>(r.parallel_stream_cycles)}};
  }
  if (!r.polygon_connection.empty()) {
    j["polygon_connection"] = r.polygon_connection;
    j["polygon_wait_cycles"] = r.polygon_stall_cycles;
  }
  if (!cfg.trace.file.empty()) j["trace"] = cfg.trace.file;
  return j;
}

void print_system_summary(const sysc::SystemResult& r, const sysc::SystemConfig& cfg, double clock_mhz) {
  std::string levels;
  for (int u = 0; u < sysc::kUnits; ++u) {
    const auto i = static_cast<size_t>(u);
    levels += std::string(levels.empty() ? "" : " ") + sysc::unit_name(static_cast<sysc::Unit>(u)) + "=" +
              (r.simulated[i] ? sysc::level_name(r.levels[i]) : "skipped");
  }
  std::fprintf(stderr,
               "cube4: p=%d [%s]: %llu cycles/frame (%llu steady), %.1f fps at %.0f MHz, %.2f samples/cycle%s\n",
               cfg.p, levels.c_str(), static_cast<unsigned long long>(r.frame_cycles),
               static_cast<unsigned long long>(r.stream_cycles), clock_mhz * 1e6 / static_cast<double>(r.stream_cycles),
               clock_mhz, static_cast<double>(r.samples) / static_cast<double>(r.stream_cycles),
               cfg.check ? "; check passed (bit-exact)" : "");
  if (!cfg.all_tlm())
    std::fprintf(stderr, "cube4: RTL random reset seed %u (--seed or CUBE4_SEED to change)\n", cfg.seed);
}

nlohmann::json describe_blocks(const golden::BlockPlan& plan) {
  nlohmann::json blocks = nlohmann::json::array();
  for (const golden::Block& b : plan.blocks)
    blocks.push_back({{"index", b.index},
                      {"cell_permuted", b.cell},
                      {"core_permuted", {b.core_lo, b.core_hi}},
                      {"stored_permuted", {b.store_lo, b.store_hi}},
                      {"stored_object", {{"origin", b.object_lo}, {"size", b.object_dim}}},
                      {"base_plane", {b.base_width(), b.base_height()}},
                      {"base_plane_origin", {b.u0, b.v0}}});
  return {{"counts", plan.counts},
          {"machines", plan.blocks.size()},
          {"order", plan.whole.perspective
                        ? "front to back per ray: permuted block z, then y and x each ascending or descending as "
                          "the ray moves (four orders, by the ray's quadrant about the eye)"
                        : "front to back: permuted block z, then y, then x"},
          {"per_block", blocks}};
}

nlohmann::json describe_partitioned(const sysc::PartitionedResult& r, const sysc::SystemConfig& cfg,
                                    double clock_mhz, double wall_seconds, const std::string& check_failure) {
  const double hz = clock_mhz * 1e6;
  nlohmann::json machines = nlohmann::json::array();
  for (const sysc::SystemResult& b : r.blocks)
    machines.push_back(describe_system(b, cfg, clock_mhz, b.wall_seconds, ""));
  const sysc::NetworkResult& n = r.network;
  return {
      {"machines", r.blocks.size()},
      {"pipelines_per_machine", cfg.p},
      {"cycles_per_frame", r.frame_cycles},
      {"cycles_steady_state_interval", r.stream_cycles},
      {"fps_first_frame", hz / static_cast<double>(r.frame_cycles)},
      {"fps_steady_state", hz / static_cast<double>(r.stream_cycles)},
      {"samples_per_cycle", static_cast<double>(r.samples) / static_cast<double>(r.stream_cycles)},
      {"network",
       {{"level", sysc::level_name(n.level)},
        {"nodes", n.nodes},
        {"depth", n.depth},
        {"cycles", n.cycles},
        {"cycles_steady_state_interval", n.stream_cycles},
        {"timing", n.clocked ? "simulated clock cycles" : "cycle model (loosely timed, no clock simulated)"},
        {"wall_seconds", n.wall_seconds}}},
      {"wall_seconds", wall_seconds},
      {"simulation_threads", cfg.all_tlm() && !cfg.cycle_level ? 1 : sysc::simulation_threads(cfg)},
      {"seed", cfg.seed},
      {"check", cfg.check ? (check_failure.empty()
                                 ? "passed: every block's partial image and unit streams, and the network's image, bit-exact"
                                 : check_failure)
                          : "off"},
      {"per_machine", machines},
  };
}

void print_partitioned_summary(const sysc::PartitionedResult& r, const sysc::SystemConfig& cfg, double clock_mhz) {
  std::fprintf(stderr,
               "cube4: %zu machines of p=%d, network of %d nodes (depth %d, %s): %llu cycles/frame (%llu steady), "
               "%.1f fps at %.0f MHz%s\n",
               r.blocks.size(), cfg.p, r.network.nodes, r.network.depth, sysc::level_name(r.network.level),
               static_cast<unsigned long long>(r.frame_cycles), static_cast<unsigned long long>(r.stream_cycles),
               clock_mhz * 1e6 / static_cast<double>(r.stream_cycles), clock_mhz,
               cfg.check ? "; check passed (bit-exact)" : "");
}

}  // namespace cube4::tb
