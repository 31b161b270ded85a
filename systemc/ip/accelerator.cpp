#include "systemc/ip/accelerator.hpp"

#include <utility>

#include "systemc/core/machine.hpp"
#include "systemc/host/host_program.hpp"
#include "systemc/host/register_map.hpp"

namespace cube4::sysc {
namespace rm = regmap;

// The machine behind the host interface, with the frame's cycles played out
// on clk_i: BUSY while cycles remain.
class Accelerator::Backend final : public HostBackend {
 public:
  Backend(const SystemConfig& cfg, const golden::Precision& p) : machine_(cfg, p.voxel_bits, p.tag_bits) {}

  void set_volume_dims(int k, int nx, int ny, int nz) override { machine_.set_volume_dims(k, nx, ny, nz); }
  void write_voxel(int k, int x, int y, int z, uint16_t v) override { machine_.write_voxel(k, x, y, z, v); }
  uint16_t read_voxel(int k, int x, int y, int z) const override { return machine_.read_voxel(k, x, y, z); }
  void start_frame(const golden::Registers& regs, int k, const golden::PolygonFrame* polygons) override {
    machine_.start_frame(regs, k, polygons);  // throws to refuse the frame: nothing changes then
    remaining_ = machine_.last()->frame_cycles;
    started_ = true;
  }
  bool busy() const override { return remaining_ > 0; }
  uint64_t frames_done() const override { return machine_.frames_done() - (busy() ? 1 : 0); }
  uint64_t last_frame_cycles() const override { return busy() ? 0 : machine_.last_frame_cycles(); }
  int base_width() const override { return machine_.base_width(); }
  int base_height() const override { return machine_.base_height(); }
  std::array<uint16_t, 4> read_pixel(int u, int v) const override { return machine_.read_pixel(u, v); }

  // One rising edge: true when the frame's last cycle has just passed.
  bool tick() { return remaining_ > 0 && --remaining_ == 0; }
  bool take_started() { return std::exchange(started_, false); }
  void abandon() { remaining_ = 0, started_ = false; }
  const SystemResult* last() const { return busy() || !machine_.last() ? nullptr : &*machine_.last(); }

 private:
  Machine machine_;
  uint64_t remaining_ = 0;
  bool started_ = false;
};

namespace {
SystemConfig system_config(const AcceleratorConfig& c) {
  SystemConfig s;
  s.p = c.hw.pipelines;
  s.levels = c.levels;
  s.check = c.check;
  s.seed = c.seed;
  s.kernel = Kernel::PlainLoop;  // no processes of its own inside a running simulation
  return s;
}
}  // namespace

Accelerator::Accelerator(sc_core::sc_module_name name, const AcceleratorConfig& config)
    : sc_core::sc_module(name),
      socket("socket"),
      clk_i("clk_i"),
      rst_ni("rst_ni"),
      irq_o("irq_o"),
      backend_(std::make_unique<Backend>(system_config(config), config.hw.precision)) {
  host_ = std::make_unique<HostInterface>("host", HostConfig{config.hw, config.bus_period}, *backend_);
  socket.bind(host_->socket);
  // One process drives irq_o: the clock edge, or the reset (asynchronous).
  SC_METHOD(on_clock_or_reset);
  sensitive << clk_i.pos() << rst_ni.neg();
  dont_initialize();
}

Accelerator::~Accelerator() = default;

const SystemResult* Accelerator::last_frame() const { return backend_->last(); }

void Accelerator::on_clock_or_reset() {
  if (!rst_ni.read()) {
    if (rst_ni.negedge()) {  // entering reset: the register file as after CTRL.RESET
      backend_->abandon();
      sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
      write_word(host_->target(), rm::kCtrl, rm::kCtrlReset, delay);
    }
    irq_o.write(false);
    return;
  }
  if (backend_->take_started()) irq_o.write(false);
  if (backend_->tick()) irq_o.write(true);
}

}  // namespace cube4::sysc
