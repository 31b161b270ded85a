// The output queue of a TLM unit that emits a slice of beats at once and
// hands them out one a clock (interpolation, gradient). A std::deque
// allocates and frees a block every few beats; this keeps its storage, so
// a frame's beats reuse one buffer.
#pragma once
#include <cstddef>
#include <iterator>
#include <vector>

namespace cube4::sysc {

template <class Beat>
class BeatQueue {
 public:
  bool empty() const { return head_ == beats_.size(); }
  void push_back(const Beat& b) { beats_.push_back(b); }
  // A new beat at the back, default-constructed, to be filled in place
  // (a slice of beats is emitted at once: no temporary copied per beat).
  Beat& emplace_back() { return beats_.emplace_back(); }
  // The oldest beat, removed, into out.
  void pop_front(Beat& out) {
    out = beats_[head_++];
    if (head_ == beats_.size()) {
      beats_.clear();
      head_ = 0;
    } else if (head_ >= kCompactAfter && 2 * head_ >= beats_.size()) {
      // Never drained (the next slice arrived before the last beat left):
      // drop what was handed out, so the buffer does not grow frame by frame.
      beats_.erase(beats_.begin(), beats_.begin() + static_cast<std::ptrdiff_t>(head_));
      head_ = 0;
    }
  }

 private:
  static constexpr size_t kCompactAfter = 4096;
  std::vector<Beat> beats_;
  size_t head_ = 0;
};

}  // namespace cube4::sysc
