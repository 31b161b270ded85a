// What the SystemC kernel alone costs a clocked frame: the machine's clock
// (systemc/core/edge_clock.hpp) with edge work that does nothing else, as
// the clocked top gives it (systemc/core/schedules.cpp), for the frame's
// cycles. A clocked frame under SystemC costs at least the plain
// loop's time plus this (docs/performance.md, scripts/perf_system.sh).
//   bench_edge_clock [--cycles N] [--frames F] [--warmup K]
// Prints one line of JSON: the cycles and the median and smallest time.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <systemc>
#include <vector>

#include "systemc/core/edge_clock.hpp"

namespace {

SC_MODULE(IdleTop) {
  cube4::sysc::EdgeClock clk{"clk", sc_core::sc_time(1, sc_core::SC_NS)};
  uint64_t left = 0;

  SC_CTOR(IdleTop) { clk.at_each_edge([this] { edge(); }); }
  void edge() {
    if (left > 0 && --left == 0) sc_core::sc_pause();
  }
};

}  // namespace

int main(int argc, char** argv) {
  uint64_t cycles = 346855;  // the default scene's RTL frame at p = 4
  int frames = 5, warmup = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "bench_edge_clock: unknown option or missing value: %s\n", a.c_str());
      return 2;
    }
    const long long v = std::atoll(argv[++i]);
    if (v <= 0) {
      std::fprintf(stderr, "bench_edge_clock: %s must be positive, got %s\n", a.c_str(), argv[i]);
      return 2;
    }
    if (a == "--cycles") cycles = static_cast<uint64_t>(v);
    else if (a == "--frames") frames = static_cast<int>(v);
    else if (a == "--warmup") warmup = static_cast<int>(v);
    else {
      std::fprintf(stderr, "bench_edge_clock: unknown option %s\n", a.c_str());
      return 2;
    }
  }
  IdleTop top("idle");
  std::vector<double> ms;
  for (int f = 0; f < warmup + frames; ++f) {
    top.left = cycles;
    const auto t0 = std::chrono::steady_clock::now();
    sc_core::sc_start();
    const auto t1 = std::chrono::steady_clock::now();
    if (f >= warmup) ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  std::printf("{\"cycles\":%llu,\"frames\":%d,\"ms\":{\"median\":%.4f,\"min\":%.4f}}\n",
              static_cast<unsigned long long>(cycles), frames, ms[ms.size() / 2], ms.front());
  return 0;
}
