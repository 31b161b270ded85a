// A barrier for a fixed team of threads that meet again and again (C++17
// has no std::barrier): the last to arrive runs `on_complete` alone, then
// every thread goes on. Whatever a thread wrote before arriving is visible
// to all after the barrier (the mutex orders it).
#pragma once
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>

namespace cube4::golden {

class TeamBarrier {
 public:
  explicit TeamBarrier(int threads, std::function<void()> on_complete = {})
      : threads_(threads), on_complete_(std::move(on_complete)) {}

  void arrive_and_wait() {
    std::unique_lock<std::mutex> lock(mutex_);
    const uint64_t phase = phase_;
    if (++arrived_ == threads_) {
      if (on_complete_) on_complete_();
      arrived_ = 0;
      ++phase_;
      lock.unlock();
      wake_.notify_all();
      return;
    }
    wake_.wait(lock, [&] { return phase_ != phase; });
  }

 private:
  const int threads_;
  std::function<void()> on_complete_;
  std::mutex mutex_;
  std::condition_variable wake_;
  int arrived_ = 0;
  uint64_t phase_ = 0;
};

}  // namespace cube4::golden
