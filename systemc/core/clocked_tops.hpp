// The SystemC modules a cycle-level run clocks: the machine's top
// (system.cpp) and the composition network's (compose_network.cpp).
// SystemC adds no module once a simulation has run, so the first of them a
// process needs builds both, on one clock.
#pragma once
#include <systemc>

#include "systemc/core/edge_clock.hpp"

namespace cube4::sysc {

// The network's top, built (with the machine's) on first use.
sc_core::sc_module& network_top();
// Builds the network's top on the machine's clock (called once, by the
// function that builds the machine's).
sc_core::sc_module* build_network_top(const EdgeClock& clk);

}  // namespace cube4::sysc
