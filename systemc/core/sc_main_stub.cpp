// libsystemc.so's main() calls sc_main(). cube4's own programs (the command,
// the tests, the benchmarks) have a main() of their own, which the linker
// prefers, and start the kernel from run_frame(); they link this stub
// (cube4_sc_main_stub) because libsystemc.so still needs the symbol. The
// system library itself defines no sc_main, so a user's platform that
// embeds the accelerator (examples/platform/) brings its own.
#include <cstdio>

// SystemC declares it extern "C" (sysc/kernel/sc_externs.h).
extern "C" int sc_main(int, char**) {
  std::fprintf(stderr, "cube4: sc_main is not an entry point of this program\n");
  return 1;
}
