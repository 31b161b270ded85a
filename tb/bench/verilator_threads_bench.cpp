// Clocks P instances of the shading unit (cube4_shade_unit, verilated as
// Vshade by scripts/perf_verilator_threads.sh with the options under test)
// in one VerilatedContext, as the system model clocks one per pipeline,
// with random samples and gradients, and prints the time per unit-cycle as
// JSON. Usage: verilator_threads_bench P CYCLES
#include <verilated.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "Vshade.h"

int main(int argc, char** argv) {
  const int p = argc > 1 ? std::atoi(argv[1]) : 4;
  const long cycles = argc > 2 ? std::atol(argv[2]) : 50000;
  auto ctx = std::make_unique<VerilatedContext>();
  std::vector<std::unique_ptr<Vshade>> units;
  for (int i = 0; i < p; ++i) units.push_back(std::make_unique<Vshade>(ctx.get(), ("shade" + std::to_string(i)).c_str()));
  for (auto& u : units) {
    u->rst_ni = 0;
    u->clk_i = 0;
    u->eval();
    u->clk_i = 1;
    u->eval();
    u->rst_ni = 1;
    // Every stage busy: magnitude, shading and specular on.
    u->magnitude_i = 1;
    u->shading_i = 1;
    u->specular_i = 1;
    u->kd_i = 200;
    u->ks_i = 100;
    u->ke_i = 20;
  }
  std::mt19937 rng(1);
  const auto t0 = std::chrono::steady_clock::now();
  for (long c = 0; c < cycles; ++c)
    for (auto& u : units) {
      u->valid_i = 1;
      u->sample_i = rng() & 4095;
      u->grad_x_i = rng() & 255;
      u->grad_y_i = rng() & 255;
      u->grad_z_i = rng() & 255;
      u->clk_i = 0;
      u->eval();
      u->clk_i = 1;
      u->eval();
    }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("{\"units\": %d, \"cycles\": %ld, \"seconds\": %.6f, \"us_per_unit_cycle\": %.4f}\n", p, cycles, s,
              s / static_cast<double>(cycles) / p * 1e6);
  for (auto& u : units) u->final();
  return 0;
}
