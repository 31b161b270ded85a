// An example platform with cube4 as one IP block among the user's own: a
// host CPU (a TLM-2.0 initiator thread) loads a volume, programs a frame,
// starts it, sleeps until the frame-done interrupt and reads the base plane
// back, all over the accelerator's bus socket; a clock and a reset drive
// the accelerator. The host then compares the base plane with the golden
// model's, bit for bit.
//
//   cube4_platform [SCENE.json] [tlm|rtl]     exit 0: equal, 1: different, 2: bad input
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include <cstdio>
#include <string>
#include <systemc>

#include "golden/errors.hpp"
#include "golden/host_driver.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "systemc/host/host_program.hpp"
#include "systemc/ip/accelerator.hpp"

namespace {

using namespace cube4;

SC_MODULE(HostCpu) {
  tlm_utils::simple_initiator_socket<HostCpu> socket{"socket"};
  sc_core::sc_in<bool> irq_i{"irq_i"};
  sc_core::sc_out<bool> rst_no{"rst_no"};

  const golden::Registers* regs = nullptr;
  const golden::Volume* volume = nullptr;
  golden::BasePlane plane;
  sc_core::sc_time frame_time;
  bool finished = false;

  SC_CTOR(HostCpu) { SC_THREAD(run); }

  void run() {
    rst_no.write(false);  // hold the accelerator in reset for two cycles
    wait(20, sc_core::SC_NS);
    rst_no.write(true);
    sysc::TlmTarget& bus = *socket.operator->();
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    sysc::program_over_tlm(bus, *regs, *volume, delay);  // volume, tables, registers
    wait(delay);
    delay = sc_core::SC_ZERO_TIME;
    const sc_core::sc_time start = sc_core::sc_time_stamp();
    sysc::start_frame_over_tlm(bus, delay);
    wait(delay);
    if (!irq_i.read()) wait(irq_i.posedge_event());  // sleep until the frame is done
    frame_time = sc_core::sc_time_stamp() - start;
    delay = sc_core::SC_ZERO_TIME;
    plane = sysc::read_base_plane_over_tlm(bus, *regs, delay);
    wait(delay);
    finished = true;
    sc_core::sc_stop();
  }
};

}  // namespace

int sc_main(int argc, char** argv) {
  const std::string scene_path = argc > 1 ? argv[1] : "";
  const std::string level = argc > 2 ? argv[2] : "tlm";
  try {
    const golden::Scene scene = scene_path.empty()
                                    ? golden::parse_scene(R"({"volume": {"synthetic": "sphere", "size": [24, 20, 16]},
                                          "view": {"rotate": [20, 30, 0]}})", "built-in scene")
                                    : golden::load_scene(scene_path);
    const golden::Volume volume = golden::load_volume(scene.volume, scene.precision.voxel_bits, ".");
    const golden::Registers regs = golden::program_host(scene, volume).regs;

    sysc::AcceleratorConfig config;
    config.hw.precision = regs.p;
    config.hw.pipelines = 4;
    config.hw.max_dim = 256;
    if (level == "rtl") config.levels.fill(sysc::Level::Rtl);
    else if (level != "tlm") throw golden::InputError("level '" + level + "' (tlm or rtl)");

    sc_core::sc_clock clk("clk", 8, sc_core::SC_NS);  // 125 MHz, VolumePro's clock
    sc_core::sc_signal<bool> rst_n("rst_n", true), irq("irq");
    sysc::Accelerator accelerator("cube4", config);
    HostCpu cpu("cpu");
    cpu.regs = &regs;
    cpu.volume = &volume;
    cpu.socket.bind(accelerator.socket);
    accelerator.clk_i(clk);
    accelerator.rst_ni(rst_n);
    accelerator.irq_o(irq);
    cpu.irq_i(irq);
    cpu.rst_no(rst_n);
    sc_core::sc_start();

    if (!cpu.finished) {
      std::fprintf(stderr, "platform: the host did not finish\n");
      return 1;
    }
    const golden::BasePlane want = golden::render_fixed(volume, regs);
    const sysc::SystemResult* frame = accelerator.last_frame();
    std::printf("platform: %s frame of %llu cycles, interrupt after %s; base plane %dx%d %s golden\n", level.c_str(),
                static_cast<unsigned long long>(frame ? frame->frame_cycles : 0), cpu.frame_time.to_string().c_str(),
                cpu.plane.width, cpu.plane.height, cpu.plane.rgba == want.rgba ? "equals" : "DIFFERS from");
    return cpu.plane.rgba == want.rgba ? 0 : 1;
  } catch (const golden::InputError& e) {
    std::fprintf(stderr, "platform: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "platform: %s\n", e.what());
    return 1;
  }
}
