// The machine's clock as the clocked tops use it: a rising edge each
// period and nothing else. Every process of the machine and the
// composition network runs on the rising edge and talks through registered
// links (link.hpp), so no signal needs to toggle: sc_clock's boolean signal,
// its falling edge and the signal updates of both edges were about a third
// of the kernel's work per simulated cycle (docs/performance.md,
// "Simulation speed of the system model").
#pragma once
#include <functional>
#include <stdexcept>
#include <string>
#include <systemc>
#include <utility>

namespace cube4::sysc {

class EdgeClock : public sc_core::sc_module {
 public:
  EdgeClock(sc_core::sc_module_name name, const sc_core::sc_time& period)
      : sc_core::sc_module(name), period_(period) {
    SC_METHOD(rise);
  }
  SC_HAS_PROCESS(EdgeClock);
  // Notified at each rising edge, first at time 0. Processes made
  // sensitive to it run in the edge's evaluation phase and see every link
  // as the previous edge left it.
  const sc_core::sc_event& posedge_event() const { return posedge_; }
  // Rising edges so far: the current one's number while its processes run.
  uint64_t edges() const { return edges_; }
  // Work done at every rising edge inside the clock's own process, before
  // the processes sensitive to posedge_event() run: the same evaluation
  // phase, the same links, for one process activation a cycle instead of
  // two and no event triggered for it (the clocked top's units,
  // schedules.cpp). One hook: a second would silently take the first's
  // place, so it is refused.
  void at_each_edge(std::function<void()> work) {
    if (work_) throw std::logic_error(std::string(name()) + ": the clock's edge work is already set");
    work_ = std::move(work);
  }

 private:
  void rise() {
    ++edges_;
    if (work_) work_();
    posedge_.notify();
    next_trigger(period_);
  }
  sc_core::sc_time period_;
  sc_core::sc_event posedge_;
  std::function<void()> work_;
  uint64_t edges_ = 0;
};

}  // namespace cube4::sysc
