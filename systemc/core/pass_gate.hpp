// The stream's one wait for Cube-5's slab images (polygon_source.hpp): the
// stream former holds at the first beat of each pass, an invalid beat a
// cycle, until the polygon source releases the pass. Every clocked run's
// stream obeys it, parallel (schedules.cpp) and perspective
// (perspective_frame.cpp).
#pragma once
#include <cstdint>

#include "systemc/core/polygon_source.hpp"
#include "systemc/core/stream_former.hpp"

namespace cube4::sysc {

class PassGate {
 public:
  explicit PassGate(PolygonSource& source) : source_(source) {}

  // Whether the former waits in `cycle` (called once a cycle, in order).
  bool holds(const StreamFormer& former, uint64_t cycle) {
    if (former.done()) return false;
    const StreamFormer::Upcoming n = former.upcoming();
    // Passes are numbered from first_pass() (-1: a priming pass) in a frame.
    const int id = n.frame * (former.passes() + 1) + n.pass + 1;
    if (n.first_of_pass && id != released_) {
      if (n.pass == former.first_pass() && n.frame == 1) first_frame_stalls_ = source_.stall_cycles();
      release_at_ = source_.release(n.pass, cycle);
      released_ = id;
    }
    return cycle < release_at_;
  }
  // The cycles the first frame waited (all of them while it is the only one).
  uint64_t first_frame_stalls(int frames) const { return frames > 1 ? first_frame_stalls_ : source_.stall_cycles(); }

 private:
  PolygonSource& source_;
  int released_ = -1;  // frame * (passes + 1) + pass + 1: the pass the source let start
  uint64_t release_at_ = 0;
  uint64_t first_frame_stalls_ = 0;
};

}  // namespace cube4::sysc
