// Built into every executable of the sanitizer build (CMakeLists.txt,
// CUBE4_SANITIZE): ASan's defaults for cube4, which ASAN_OPTIONS still
// overrides.
//
// intercept_tls_get_addr=0: clang 14's runtime records the range of each
// dynamic TLS block (the thread_local variables of a dlopen'ed library,
// which glibc mallocs at a thread's first access) by a guess: a block that
// starts 16 bytes past a page boundary is taken for glibc 2.19's layout and
// its range read from the 16 bytes before it. Under ASan those bytes are
// the allocator's chunk header, so the range is garbage, and LeakSanitizer's
// scan at exit dies in it ("Tracer caught signal 11", ScanRangeForPointers;
// google/sanitizers#1322). A block of up to 16 bytes (a 32-byte chunk)
// lands there one time in 128, depending on how many small allocations came
// first: log4cplus's, which libcube4_image_oiio.so brings, came and went
// with host registers, scene lights and the output path
// (docs/reliability.md). Nothing is lost without the interception: on
// glibc 2.36 every other block it records outside static TLS is "can't
// guess glibc version", recorded empty, so what the blocks hold never was
// found through these ranges. tb/tests/test_sanitizer_runtime.cpp places a
// block there.
#include <sanitizer/asan_interface.h>

// Called while ASan initialises, before any instrumented code may run.
extern "C" __attribute__((no_sanitize("address", "undefined", "coverage"))) const char* __asan_default_options() {
  return "intercept_tls_get_addr=0";
}
