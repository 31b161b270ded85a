// cube4 as an IP block for a user's SystemC platform: the accelerator with
// its TLM-2.0 host target (registers, tables, volume and base-plane windows
// of docs/registers.md), clock and reset inputs and a frame-done interrupt.
//
//   cube4::sysc::Accelerator acc{"cube4", cube4::sysc::AcceleratorConfig{}};
//   initiator.socket.bind(acc.socket);
//   acc.clk_i(clk);  acc.rst_ni(rst_n);  acc.irq_o(irq);
//
// Timing: a START computes the frame at once (every unit at the configured
// level: TLM, RTL or mixed, bit-exact) and takes the frame's exact cycle
// count (the cycle model's, equal to the RTL's) in clk_i cycles: BUSY for
// that many rising edges, then DONE and irq_o high. irq_o is a level: it
// stays high until the next START or a reset. rst_ni low (asynchronous,
// active low) resets the register file (as CTRL.RESET), drops irq_o and
// abandons a running frame. The host bus is loosely timed, as HostInterface:
// each transaction annotates its bus time on `delay`.
//
// The clocked frame runs on the system model's plain-loop schedule, which
// needs no SystemC processes of its own, so any number of accelerators can
// sit in a simulation that is already running (examples/platform/).
#pragma once
#include <tlm>

#include <array>
#include <cstdint>
#include <memory>
#include <systemc>

#include "systemc/core/system.hpp"
#include "systemc/host/host_backend.hpp"
#include "systemc/host/host_if.hpp"

namespace cube4::sysc {

struct AcceleratorConfig {
  HardwareParams hw;                  // precision, pipelines, largest volume dimension
  std::array<Level, kUnits> levels{Level::Tlm, Level::Tlm, Level::Tlm, Level::Tlm, Level::Tlm};
  bool check = false;                 // compare every unit's stream with golden; see last_frame()->mismatch
  uint32_t seed = 1;                  // RTL random reset
  sc_core::sc_time bus_period{30, sc_core::SC_NS};
};

class Accelerator : public sc_core::sc_module {
 public:
  tlm::tlm_target_socket<32> socket;  // the host bus (32-bit data, 64-bit addresses)
  sc_core::sc_in<bool> clk_i;
  sc_core::sc_in<bool> rst_ni;
  sc_core::sc_out<bool> irq_o;        // frame done

  // Throws std::invalid_argument for parameters the register map cannot hold.
  Accelerator(sc_core::sc_module_name name, const AcceleratorConfig& config);
  ~Accelerator() override;

  // The last completed frame (its cycles, levels, check result).
  const SystemResult* last_frame() const;

  SC_HAS_PROCESS(Accelerator);

 private:
  class Backend;
  void on_clock_or_reset();

  std::unique_ptr<Backend> backend_;
  std::unique_ptr<HostInterface> host_;
};

}  // namespace cube4::sysc
