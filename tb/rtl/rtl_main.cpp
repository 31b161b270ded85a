// main() of every RTL unit-test executable: seeds Verilator's randomisation
// of X's and uninitialised state, so no test depends on default values.
// CUBE4_SEED=<n> reproduces a run; the seed is printed either way.
#include <gtest/gtest.h>
#include <verilated.h>

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  const char* env = std::getenv("CUBE4_SEED");
  const int seed = env ? std::atoi(env) : 20261124;
  std::printf("RTL tests: Verilator random reset seed %d (set CUBE4_SEED to change)\n", seed);
  Verilated::randReset(2);
  Verilated::randSeed(seed);
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
