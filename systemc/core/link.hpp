// A registered point-to-point link between two clocked units: the producer
// writes at a clock edge, the consumer reads the value at the next edge (one
// cycle of latency, like the register at a unit's output). A primitive
// channel without events: every process that uses it runs on the clock, so
// nothing needs notifying, and a beat is copied once per cycle.
#pragma once
#include <systemc>

namespace cube4::sysc {

template <class T>
class Link : public sc_core::sc_prim_channel {
 public:
  explicit Link(const char* name) : sc_core::sc_prim_channel(name) {}
  const T& read() const { return current_; }
  // Between frames, with the simulation paused: both values back to idle.
  void reset() { current_ = next_ = T{}; }
  void write(const T& v) {
    next_ = v;
    request_update();
  }
  // The value for the next edge, for the producer to write in place (a
  // beat is then not built in a temporary and copied). Only the producer
  // writes it, so a field it never sets keeps its idle value.
  T& next() {
    request_update();
    return next_;
  }

 private:
  void update() override { current_ = next_; }
  T current_{}, next_{};
};

}  // namespace cube4::sysc
