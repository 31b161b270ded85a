// The SystemC modules a cycle-level run clocks: the machine's top
// (schedules.cpp), the perspective stream's (perspective_frame.cpp) and the
// composition network's (compose_network.cpp).
// SystemC adds no module once a simulation has run, so the first of them a
// process needs builds both, on one clock.
#pragma once
#include <systemc>

#include "systemc/core/edge_clock.hpp"

namespace cube4::sysc {

// The network's and the perspective stream's tops, built (with the
// machine's) on first use.
sc_core::sc_module& network_top();
sc_core::sc_module& perspective_top();
// Build them on the machine's clock (called once each, by the function
// that builds the machine's).
sc_core::sc_module* build_network_top(const EdgeClock& clk);
sc_core::sc_module* build_perspective_top(const EdgeClock& clk);

}  // namespace cube4::sysc
