// The machine's clock (systemc/core/edge_clock.hpp): a rising edge each
// period from time 0, its edge work (what the clocked top's units run on)
// done at every edge before the processes made sensitive to the edge, all
// in the edge's evaluation phase. Its own executable: SystemC elaborates
// once per process, and this test builds its own modules.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <systemc>
#include <vector>

#include "systemc/core/edge_clock.hpp"
#include "systemc/core/link.hpp"

namespace {

using cube4::sysc::EdgeClock;
using cube4::sysc::Link;

SC_MODULE(Recorder) {
  EdgeClock clk{"clk", sc_core::sc_time(1, sc_core::SC_NS)};
  Link<int> link{"link", clk};
  std::vector<std::string> log;

  SC_CTOR(Recorder) {
    clk.at_each_edge([this] { work(); });
    SC_METHOD(on_edge);
    sensitive << clk.posedge_event();
    dont_initialize();
  }
  // "edge@ns": the clock's edge count and the simulated time.
  std::string at() const {
    const auto ns = static_cast<int>(sc_core::sc_time_stamp().to_seconds() * 1e9 + 0.5);
    return std::to_string(clk.edges()) + "@" + std::to_string(ns);
  }
  // The work writes the edge's number into the link; the process reads what
  // the work wrote one edge earlier.
  void work() {
    log.push_back("work " + at() + " read " + std::to_string(link.read()));
    link.write(static_cast<int>(clk.edges()));
  }
  void on_edge() { log.push_back("process " + at() + " read " + std::to_string(link.read())); }
};

TEST(EdgeClock, EdgeWorkRunsAtEveryEdgeBeforeTheEdgesProcesses) {
  Recorder r("recorder");
  sc_core::sc_start(sc_core::sc_time(3.5, sc_core::SC_NS));
  const std::vector<std::string> want = {
      "work 1@0 read 0", "process 1@0 read 0",  // the first edge at time 0
      "work 2@1 read 1", "process 2@1 read 1",  //
      "work 3@2 read 2", "process 3@2 read 2",  //
      "work 4@3 read 3", "process 4@3 read 3",
  };
  EXPECT_EQ(r.log, want);
  // A second hook would take the top's place without a word: refused.
  EXPECT_THROW(r.clk.at_each_edge([] {}), std::logic_error);
}

}  // namespace
