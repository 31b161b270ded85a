// One value per simulated cycle from one thread to another, in batches: the
// hand-over between the two halves of a frame's units when they run on two
// threads (systemc/core/schedules.cpp). The machine's links carry no
// back-pressure, so the later half can run any number of cycles behind the
// earlier one; a batch of cycles per lock keeps the hand-over's cost far
// below the units' work per cycle, and a bound on the batches in flight
// keeps the earlier half from running away with the memory.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <vector>

namespace cube4::sysc {

template <class T>
class CyclePipe {
 public:
  explicit CyclePipe(size_t batch = 1024, size_t max_pending = 8) : batch_(batch), max_pending_(max_pending) {
    filling_.reserve(batch_);
  }
  CyclePipe(const CyclePipe&) = delete;
  CyclePipe& operator=(const CyclePipe&) = delete;

  // Producer: the next cycle's value, default-constructed, to fill in place.
  // Waits while max_pending batches are unread; once the consumer has
  // stopped it only recycles its own batch (nothing will read it).
  T& next() {
    if (filling_.size() == batch_) hand_over();
    filling_.emplace_back();
    return filling_.back();
  }
  // Producer: takes back the value next() gave last (a cycle it did not
  // finish).
  void discard() {
    if (!filling_.empty()) filling_.pop_back();
  }
  // Producer: no more values; what was filled is handed over.
  void close() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!stopped_ && !filling_.empty()) pending_.push_back(std::move(filling_));
    filling_.clear();
    closed_ = true;
    changed_.notify_all();
  }

  // Consumer: the next cycle's value, or nullptr once the producer has
  // closed and every value has been read.
  const T* pop() {
    if (at_ < reading_.size()) return &reading_[at_++];
    std::unique_lock<std::mutex> lock(mutex_);
    if (reading_.capacity() > 0) {
      reading_.clear();
      free_.push_back(std::move(reading_));
      reading_ = {};
    }
    changed_.wait(lock, [&] { return !pending_.empty() || closed_; });
    if (pending_.empty()) return nullptr;
    reading_ = std::move(pending_.front());
    pending_.pop_front();
    changed_.notify_all();
    at_ = 1;
    return &reading_[0];
  }
  // Consumer: reads no more; the producer stops waiting for it.
  void stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    pending_.clear();
    reading_.clear();
    at_ = 0;
    changed_.notify_all();
  }
  // Whether the consumer has stopped (either side may ask).
  bool stopped() const { return stopped_.load(std::memory_order_acquire); }

 private:
  void hand_over() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return pending_.size() < max_pending_ || stopped_; });
    if (stopped_) {
      filling_.clear();
      return;
    }
    pending_.push_back(std::move(filling_));
    if (free_.empty()) {
      filling_ = {};
      filling_.reserve(batch_);
    } else {
      filling_ = std::move(free_.back());
      free_.pop_back();
    }
    changed_.notify_all();
  }

  // Each side's fields on cache lines of their own, and the stop flag,
  // which the producer reads every cycle, on one that nobody writes while
  // values flow: a line one side writes and the other reads every cycle
  // would travel between the cores every cycle.
  const size_t batch_, max_pending_;
  alignas(64) std::vector<T> filling_;  // the producer's
  alignas(64) std::vector<T> reading_;  // the consumer's
  size_t at_ = 0;
  alignas(64) std::atomic<bool> stopped_{false};
  alignas(64) std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::vector<T>> pending_;
  std::vector<std::vector<T>> free_;
  bool closed_ = false;
};

}  // namespace cube4::sysc
