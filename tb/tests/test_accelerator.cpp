// cube4 as an IP block (systemc/ip/accelerator.hpp) in a platform of the
// test's own: reset, BUSY for exactly the frame's cycles, the interrupt at
// the frame's end and its clearing by the next START and by reset, a START
// refused while busy, and the base plane read back equal to golden.
#include <gtest/gtest.h>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include <systemc>

#include "golden/host_driver.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "systemc/host/host_program.hpp"
#include "systemc/host/register_map.hpp"
#include "systemc/ip/accelerator.hpp"

namespace {

using namespace cube4;
namespace rm = sysc::regmap;
using sc_core::SC_NS;
using sc_core::sc_time;

constexpr double kPeriodNs = 10;

struct Host : sc_core::sc_module {
  tlm_utils::simple_initiator_socket<Host> socket{"socket"};
  sc_core::sc_in<bool> irq_i{"irq_i"};
  sc_core::sc_out<bool> rst_no{"rst_no"};
  golden::Registers regs;
  golden::Volume volume;
  // What the thread saw, checked after the simulation.
  bool irq_in_reset = true, busy_after_start = false, irq_after_start = true, refused_while_busy = false;
  bool done_at_irq = false, irq_dropped_by_start = false, irq_dropped_by_reset = false, idle_after_reset = false;
  double irq_after_ns = 0;
  golden::BasePlane plane;

  SC_HAS_PROCESS(Host);
  explicit Host(sc_core::sc_module_name n) : sc_core::sc_module(n) { SC_THREAD(run); }

  uint32_t status() {
    sc_time d = sc_core::SC_ZERO_TIME;
    return sysc::read_status_over_tlm(*socket.operator->(), d);
  }
  void run() {
    sysc::TlmTarget& bus = *socket.operator->();
    rst_no.write(false);
    wait(3 * kPeriodNs, SC_NS);
    irq_in_reset = irq_i.read();
    rst_no.write(true);
    sc_time d = sc_core::SC_ZERO_TIME;
    sysc::program_over_tlm(bus, regs, volume, d);
    wait(d);
    d = sc_core::SC_ZERO_TIME;
    const sc_time start = sc_core::sc_time_stamp();
    sysc::start_frame_over_tlm(bus, d);
    busy_after_start = status() & rm::kStatusBusy;
    try {
      sysc::start_frame_over_tlm(bus, d);
    } catch (const sysc::HostError&) {
      refused_while_busy = true;
    }
    wait(kPeriodNs, SC_NS);
    irq_after_start = irq_i.read();
    wait(irq_i.posedge_event());
    irq_after_ns = (sc_core::sc_time_stamp() - start).to_seconds() * 1e9;
    const uint32_t s = status();
    done_at_irq = (s & rm::kStatusDone) && !(s & rm::kStatusBusy);
    d = sc_core::SC_ZERO_TIME;
    plane = sysc::read_base_plane_over_tlm(bus, regs, d);
    // The next START clears the interrupt at the next clock edge...
    sysc::start_frame_over_tlm(bus, d);
    wait(2 * kPeriodNs, SC_NS);
    irq_dropped_by_start = !irq_i.read();
    // ... and a reset in the middle of that frame abandons it.
    rst_no.write(false);
    wait(2 * kPeriodNs, SC_NS);
    irq_dropped_by_reset = !irq_i.read();
    rst_no.write(true);
    wait(2 * kPeriodNs, SC_NS);
    idle_after_reset = (status() & (rm::kStatusBusy | rm::kStatusDone)) == 0;
    sc_core::sc_stop();
  }
};

TEST(Accelerator, FrameInterruptBusyAndResetThroughTheIpBlock) {
  const golden::Scene scene = golden::parse_scene(
      R"({"volume": {"synthetic": "sphere", "size": [20, 18, 16]}, "view": {"rotate": [20, 30, 0]}})", "t.json");
  sysc::AcceleratorConfig cfg;
  Host host("host");
  host.volume = golden::load_volume(scene.volume, scene.precision.voxel_bits, ".");
  host.regs = golden::program_host(scene, host.volume).regs;
  cfg.hw.precision = host.regs.p;
  cfg.hw.pipelines = 4;
  cfg.hw.max_dim = 64;
  sc_core::sc_clock clk("clk", kPeriodNs, SC_NS);
  sc_core::sc_signal<bool> rst_n("rst_n", true), irq("irq");
  sysc::Accelerator acc("cube4", cfg);
  host.socket.bind(acc.socket);
  acc.clk_i(clk);
  acc.rst_ni(rst_n);
  acc.irq_o(irq);
  host.irq_i(irq);
  host.rst_no(rst_n);
  sc_core::sc_start(sc_time(10, sc_core::SC_MS));

  EXPECT_FALSE(host.irq_in_reset);
  EXPECT_TRUE(host.busy_after_start);
  EXPECT_TRUE(host.refused_while_busy) << "a START while BUSY is an error response";
  EXPECT_FALSE(host.irq_after_start);
  EXPECT_TRUE(host.done_at_irq);
  // The frame takes exactly the cycle model's cycles: the interrupt rises
  // on the frame_cycles-th rising edge from START on (an edge at START's
  // very instant counts as the first).
  const uint64_t cycles = sysc::frame_cycles(host.regs, 4).latency;
  EXPECT_GE(host.irq_after_ns, (cycles - 1) * kPeriodNs);
  EXPECT_LE(host.irq_after_ns, cycles * kPeriodNs);
  EXPECT_EQ(host.plane.rgba, golden::render_fixed(host.volume, host.regs).rgba);
  EXPECT_TRUE(host.irq_dropped_by_start);
  EXPECT_TRUE(host.irq_dropped_by_reset);
  EXPECT_TRUE(host.idle_after_reset);
}

}  // namespace
