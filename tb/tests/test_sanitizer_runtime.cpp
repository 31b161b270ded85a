// The sanitizer build's runtime settings (tb/sanitizer_options.cpp). What
// this checks happens at exit, in LeakSanitizer's scan: a failure is the
// process's exit status ("Tracer caught signal 11"), after gtest has
// reported the test passed.
#include <dlfcn.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <future>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace {

constexpr uintptr_t kPage = 4096;
// Where clang 14's runtime takes a dynamic TLS block for glibc 2.19's and
// reads its range from the 16 bytes before it.
constexpr uintptr_t kGuessedOffset = 16;
constexpr size_t kMaxGrooming = 1024;

using ProbeBlock = void* (*)();

ProbeBlock open_probe() {
  void* handle = ::dlopen(CUBE4_DTLS_PROBE, RTLD_NOW | RTLD_LOCAL);
  return handle ? reinterpret_cast<ProbeBlock>(::dlsym(handle, "cube4_dtls_probe_block")) : nullptr;
}

// In a new thread, whose allocator cache hands out consecutive chunks:
// allocations of the probe block's size until the next one starts
// kGuessedOffset past a page, then the first access, which allocates the
// block. Whether it landed there; if so the thread stays alive, so that
// the scan at exit meets the block.
bool place_block_in_a_parked_thread(ProbeBlock probe_block) {
  std::promise<bool> placed;
  std::thread([&placed, probe_block] {
    std::vector<void*> grooming;
    grooming.reserve(kMaxGrooming);  // its own growth would take chunks of the same size
    const auto at = [&grooming](size_t i) { return reinterpret_cast<uintptr_t>(grooming[i]); };
    grooming.push_back(std::malloc(sizeof(void*)));
    grooming.push_back(std::malloc(sizeof(void*)));
    const uintptr_t stride = at(1) - at(0);
    while (grooming.size() < kMaxGrooming && (at(grooming.size() - 1) + stride) % kPage != kGuessedOffset)
      grooming.push_back(std::malloc(sizeof(void*)));
    const uintptr_t block = reinterpret_cast<uintptr_t>(probe_block());
    for (void* p : grooming) std::free(p);
    const bool there = block % kPage == kGuessedOffset;
    placed.set_value(there);
    if (there)
      for (;;) ::pause();
  }).detach();
  return placed.get_future().get();
}

// Without tb/sanitizer_options.cpp the scan at exit dies in the block's
// guessed range.
TEST(SanitizerRuntime, DynamicTlsBlockWhereTheRuntimeGuessesAGlibcHeaderIsScannedSafely) {
  const ProbeBlock probe_block = open_probe();
  ASSERT_NE(probe_block, nullptr) << ::dlerror();
  bool placed = false;
  for (int attempt = 0; attempt < 8 && !placed; ++attempt) placed = place_block_in_a_parked_thread(probe_block);
  ASSERT_TRUE(placed) << "no dynamic TLS block landed " << kGuessedOffset
                      << " bytes past a page: the allocator changed, and this test with it";
}

}  // namespace
