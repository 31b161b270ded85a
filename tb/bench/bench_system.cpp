// Times the system model on one core, frame by frame (base plane only: the
// warp is host code, timed in bench_golden). Prints one JSON object with
// simulated cycles per wall second and samples per wall second.
//   bench_system [SCENE] [--model golden|tlm|tlm-cycle|rtl|mixed:UNIT,...] [--kernel systemc|plain]
//                [--pipes P] [--frames N] [--warmup K] [--threads 0|1|2] [--simulate-all]
// golden: render_fixed() alone, the reference for the TLM level.
// tlm-cycle: every unit's TLM model clocked beat by beat; --kernel plain:
// the same units on a plain C++ loop instead of the SystemC kernel.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "golden/errors.hpp"
#include "golden/host_driver.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "systemc/core/system.hpp"
#include "tb/heap_tuning.hpp"

using namespace cube4;

int main(int argc, char** argv) {
  keep_frame_buffers_in_heap();  // as cube4 does: the frames time what a user's run costs
  std::string scene_path, model = "rtl", kernel = "systemc";
  int frames = 3, warmup = 1, pipes = 0, threads = 0;
  bool cfg_all = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) { std::fprintf(stderr, "bench_system: %s needs a value\n", a.c_str()); std::exit(2); }
      return argv[++i];
    };
    if (a == "--model") model = value();
    else if (a == "--kernel") kernel = value();
    else if (a == "--pipes") pipes = std::atoi(value().c_str());
    else if (a == "--frames") frames = std::atoi(value().c_str());
    else if (a == "--warmup") warmup = std::atoi(value().c_str());
    else if (a == "--threads") threads = std::atoi(value().c_str());
    else if (a == "--simulate-all") cfg_all = true;
    else if (!a.empty() && a[0] != '-') scene_path = a;
    else { std::fprintf(stderr, "bench_system: unknown option %s\n", a.c_str()); return 2; }
  }
  sysc::SystemConfig cfg;
  if (model == "golden") {
  } else if (model == "tlm" || model == "tlm-cycle") {
    cfg.levels.fill(sysc::Level::Tlm);
    cfg.cycle_level = model == "tlm-cycle";
  } else if (model == "rtl") {
    cfg.levels.fill(sysc::Level::Rtl);
  } else if (model.rfind("mixed:", 0) == 0) {
    cfg.levels.fill(sysc::Level::Tlm);
    std::stringstream list(model.substr(6));
    std::string name;
    while (std::getline(list, name, ','))
      for (int u = 0; u < sysc::kUnits; ++u)
        if (name == sysc::unit_name(static_cast<sysc::Unit>(u))) cfg.levels[static_cast<size_t>(u)] = sysc::Level::Rtl;
  } else {
    std::fprintf(stderr, "bench_system: --model %s: use tlm, tlm-cycle, rtl or mixed:UNIT,...\n", model.c_str());
    return 2;
  }
  if (kernel != "systemc" && kernel != "plain") {
    std::fprintf(stderr, "bench_system: --kernel %s: use systemc or plain\n", kernel.c_str());
    return 2;
  }
  cfg.kernel = kernel == "plain" ? sysc::Kernel::PlainLoop : sysc::Kernel::SystemC;
  cfg.simulate_unneeded = cfg_all;
  cfg.threads = threads;
  try {
    golden::Scene s = scene_path.empty() ? golden::default_scene() : golden::load_scene(scene_path);
    const std::string dir = scene_path.empty() ? "." : std::filesystem::path(scene_path).parent_path().string();
    const golden::Volume vol = golden::load_volume(s.volume, s.precision.voxel_bits, dir.empty() ? "." : dir);
    const golden::HostProgram h = golden::program_host(s, vol);
    cfg.p = pipes > 0 ? pipes : s.pipelines;
    std::vector<double> sec;
    sysc::SystemResult last;
    for (int f = 0; f < warmup + frames; ++f) {
      const auto t0 = std::chrono::steady_clock::now();
      if (model == "golden") {
        last.plane = golden::render_fixed(vol, h.regs);
        last.samples = static_cast<uint64_t>(h.regs.dim[0]) * h.regs.dim[1] * h.regs.sample_slices();
        last.frame_cycles = sysc::frame_cycles(h.regs, cfg.p).latency;
      } else {
        last = sysc::run_frame(h.regs, vol, cfg);
      }
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (f >= warmup) sec.push_back(t);
    }
    std::sort(sec.begin(), sec.end());
    const double median = sec[sec.size() / 2];
    const uint64_t cycles = last.simulated_cycles ? last.simulated_cycles : last.frame_cycles;
    nlohmann::json j = {
        {"model", model},
        {"kernel", kernel},
        {"pipelines", cfg.p},
        {"threads", model == "golden" ? 1 : sysc::simulation_threads(cfg)},
        {"scene", scene_path.empty() ? "(default)" : scene_path},
        {"frames", frames},
        {"cycles_per_frame", last.frame_cycles},
        {"clock_simulated", last.simulated_cycles != 0},
        {"samples_per_frame", last.samples},
        {"ms", {{"min", sec.front() * 1e3}, {"median", median * 1e3}, {"max", sec.back() * 1e3}}},
        {"cycles_per_second", static_cast<double>(cycles) / median},
        {"samples_per_second", static_cast<double>(last.samples) / median},
    };
    std::printf("%s\n", j.dump().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_system: %s\n", e.what());
    return 1;
  }
  return 0;
}
