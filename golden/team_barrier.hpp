// A barrier for a fixed team of threads that meet again and again, a few
// hundred times a frame (C++17 has no std::barrier): the last to arrive
// runs `on_complete` alone, then every thread goes on. Waiting spins, then
// yields: a phase lasts tens of microseconds, less than a sleeping thread
// takes to wake. Whatever a thread wrote before arriving is visible to all
// after the barrier (release on arrival, acquire on leaving).
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>

namespace cube4::golden {

class TeamBarrier {
 public:
  explicit TeamBarrier(int threads, std::function<void()> on_complete = {})
      : threads_(threads), on_complete_(std::move(on_complete)) {}

  void arrive_and_wait() {
    const uint64_t phase = phase_.load(std::memory_order_acquire);
    if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == threads_) {
      if (on_complete_) on_complete_();
      arrived_.store(0, std::memory_order_relaxed);
      phase_.store(phase + 1, std::memory_order_release);
      return;
    }
    for (int spins = 0; phase_.load(std::memory_order_acquire) == phase; ++spins)
      if (spins > 2000) std::this_thread::yield();
  }

 private:
  const int threads_;
  std::function<void()> on_complete_;
  std::atomic<int> arrived_{0};
  std::atomic<uint64_t> phase_{0};
};

}  // namespace cube4::golden
