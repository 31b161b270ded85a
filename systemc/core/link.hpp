// A registered point-to-point link between two clocked units: the producer
// writes at a clock edge, the consumer reads the value at the next edge (one
// cycle of latency, like the register at a unit's output). Every process
// that uses it runs on the rising edge of one EdgeClock, so the link needs
// neither events nor the kernel's update phase: it keeps two values, and
// at edge n the consumer reads the one written at edge n - 1 while the
// producer writes the other. The producer must write every edge (each
// unit's process does, from a frame's first edge to its last).
#pragma once
#include <array>
#include <systemc>

#include "systemc/core/edge_clock.hpp"

namespace cube4::sysc {

template <class T>
class Link : public sc_core::sc_prim_channel {
 public:
  Link(const char* name, const EdgeClock& clk) : sc_core::sc_prim_channel(name), clk_(clk) {}
  const T& read() const { return values_[clk_.edges() & 1]; }
  // Between frames, with the simulation paused: both values back to idle.
  void reset() { values_ = {}; }
  void write(const T& v) { next() = v; }
  // The value for the next edge, for the producer to write in place (a
  // beat is then not built in a temporary and copied). Only the producer
  // writes it, so a field it never sets keeps its idle value.
  T& next() { return values_[(clk_.edges() + 1) & 1]; }

 private:
  const EdgeClock& clk_;
  std::array<T, 2> values_{};
};

}  // namespace cube4::sysc
