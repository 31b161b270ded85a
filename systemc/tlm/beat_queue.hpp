// The output queue of a TLM unit that emits a slice of beats at once and
// hands them out one a clock (interpolation, gradient). A std::deque
// allocates and frees a block every few beats; this keeps its storage, so
// a frame's beats reuse one buffer, and it does not clear a slot before
// handing it out again: clearing a beat of about 130 bytes a clock in each
// of the two queues took 9 % of a clocked TLM frame (docs/performance.md).
#pragma once
#include <algorithm>
#include <cstddef>
#include <iterator>
#include <vector>

namespace cube4::sysc {

template <class Beat>
class BeatQueue {
 public:
  bool empty() const { return head_ == size_; }
  void push_back(const Beat& b) { slot() = b; }
  // A slot at the back to be filled in place. It holds a beat this queue
  // held before (or an idle one), so the unit writes every field it
  // drives, zeros included; a field it never drives (lanes beyond p, the
  // tag or z-difference lanes of a frame without them) keeps the idle
  // value every beat of this queue left there.
  Beat& recycled_back() { return slot(); }
  // The oldest beat, removed, into out.
  void pop_front(Beat& out) {
    out = beats_[head_++];
    if (head_ == size_) {
      head_ = size_ = 0;
    } else if (head_ >= kCompactAfter && 2 * head_ >= size_) {
      // Never drained (the next slice arrived before the last beat left):
      // drop what was handed out, so the buffer does not grow frame by frame.
      std::move(beats_.begin() + static_cast<std::ptrdiff_t>(head_),
                beats_.begin() + static_cast<std::ptrdiff_t>(size_), beats_.begin());
      size_ -= head_;
      head_ = 0;
    }
  }

 private:
  Beat& slot() {
    if (size_ == beats_.size()) beats_.emplace_back();
    return beats_[size_++];
  }
  static constexpr size_t kCompactAfter = 4096;
  std::vector<Beat> beats_;  // [head_, size_) queued; the rest recycled slots
  size_t head_ = 0, size_ = 0;
};

}  // namespace cube4::sysc
