#include "systemc/core/machine.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

#include <tlm_utils/simple_initiator_socket.h>

#include "systemc/host/host_if.hpp"
#include "systemc/host/host_program.hpp"

namespace cube4::sysc {

void Machine::set_volume_dims(int k, int nx, int ny, int nz) {
  golden::Volume& v = volumes_[static_cast<size_t>(k)];
  v.dim = {nx, ny, nz};
  std::vector<uint16_t>().swap(v.data);
  std::vector<uint8_t>().swap(v.tags);
  v.source = "host interface, subvolume " + std::to_string(k);
  mapped_[static_cast<size_t>(k)] = nullptr;
  cleared_[static_cast<size_t>(k)] = true;
}

golden::Volume& Machine::own(int k) {
  const size_t i = static_cast<size_t>(k);
  golden::Volume& v = volumes_[i];
  if (mapped_[i]) {
    const int bits = v.bits;
    v = *mapped_[i];
    v.bits = bits;
    if (tag_bits_ > 0 && v.tags.empty()) v.tags.assign(v.size(), 0);
    v.source = "host interface, subvolume " + std::to_string(k);
    mapped_[i] = nullptr;
  } else if (cleared_[i]) {
    v.data.assign(v.size(), 0);
    if (tag_bits_ > 0) v.tags.assign(v.size(), 0);
  }
  cleared_[i] = false;
  return v;
}

const golden::Volume& Machine::volume(int k) const {
  const size_t i = static_cast<size_t>(k);
  if (mapped_[i]) return *mapped_[i];
  // A cleared subvolume is allocated on first use, as the machine's own.
  if (cleared_[i]) return const_cast<Machine*>(this)->own(k);
  return volumes_[i];
}

void Machine::map_volume(int k, const golden::Volume& vol) {
  const size_t i = static_cast<size_t>(k);
  if (vol.dim != volumes_[i].dim || vol.bits != volumes_[i].bits)
    throw std::invalid_argument("machine: mapped volume of other dims or voxel width than subvolume " +
                                std::to_string(k));
  std::vector<uint16_t>().swap(volumes_[i].data);
  std::vector<uint8_t>().swap(volumes_[i].tags);
  mapped_[i] = &vol;
  cleared_[i] = false;
}

void Machine::unmap_volume(int k) {
  const size_t i = static_cast<size_t>(k);
  if (!mapped_[i]) return;
  mapped_[i] = nullptr;
  cleared_[i] = true;
}

void Machine::write_voxel(int k, int x, int y, int z, uint16_t v) {
  golden::Volume& vol = own(k);
  const size_t i = vol.index(x, y, z);
  vol.data[i] = static_cast<uint16_t>(v & vol.max_value());
  if (tag_bits_ > 0) vol.tags[i] = static_cast<uint8_t>(v >> vol.bits);
}

void Machine::write_voxels(int k, uint64_t first, uint64_t count, const uint32_t* words, int /*nx*/, int /*ny*/) {
  golden::Volume& vol = own(k);
  const uint16_t max = static_cast<uint16_t>(vol.max_value());
  auto word = [words](uint64_t i) { return static_cast<uint16_t>(words[i / 2] >> (16 * (i % 2))); };
  uint16_t* data = vol.data.data() + first;
  for (uint64_t i = 0; i < count; ++i) data[i] = word(i) & max;
  if (tag_bits_ > 0) {
    uint8_t* tags = vol.tags.data() + first;
    for (uint64_t i = 0; i < count; ++i) tags[i] = static_cast<uint8_t>(word(i) >> vol.bits);
  }
}

uint16_t Machine::read_voxel(int k, int x, int y, int z) const {
  const golden::Volume& vol = volume(k);
  return static_cast<uint16_t>(vol.at(x, y, z) | vol.tag_at(x, y, z) << vol.bits);
}

void Machine::start_frame(const golden::Registers& regs, int k, const golden::PolygonFrame* polygons) {
  error_ = nullptr;
  try {
    last_ = run_frame(regs, volume(k), cfg_, progress_, polygons);
  } catch (...) {
    // The host interface reports a refused frame as a status code; the
    // reason is kept for the program that drives the host.
    error_ = std::current_exception();
    throw;
  }
  ++frames_;
}

std::array<uint16_t, 4> Machine::read_pixel(int u, int v) const {
  const golden::BasePlane& bp = last_->plane;
  const uint16_t* px = &bp.rgba[(static_cast<size_t>(v) * bp.width + u) * 4];
  return {px[0], px[1], px[2], px[3]};
}

namespace {

// The host's bus master. The host program calls the target's forward
// interface directly (before the first sc_start, where a port cannot be
// used yet); the socket is bound so that elaboration finds it connected.
SC_MODULE(HostBus) {
  tlm_utils::simple_initiator_socket<HostBus> socket{"socket"};
  SC_CTOR(HostBus) {}
};

struct Hosted {
  HardwareParams hw;
  std::unique_ptr<Machine> machine;
  std::unique_ptr<HostInterface> host;
  std::unique_ptr<HostBus> bus;
};

Hosted& hosted_once() {
  static Hosted h;
  return h;
}

Hosted& hosted(const SystemConfig& cfg, const golden::Precision& p, int max_dim) {
  Hosted& h = hosted_once();
  HardwareParams hw;
  hw.precision = p;
  hw.pipelines = cfg.p;
  // The largest volume the interface takes, rounded up to a power of two:
  // a process renders volumes of several sizes through it (the blocks of a
  // partitioned volume differ by their borders), and it is built once.
  hw.max_dim = 256;
  while (hw.max_dim < max_dim && hw.max_dim < regmap::kMaxDimLimit) hw.max_dim *= 2;
  if (!h.host) {
    if (sc_core::sc_get_status() != sc_core::SC_ELABORATION)
      throw std::invalid_argument(
          "host interface: this process has simulated frames without it already, and SystemC adds no module once "
          "it runs; render through the host interface first, or in a process of its own");
    h.hw = hw;
    h.machine = std::make_unique<Machine>(cfg, p.voxel_bits, p.tag_bits);
    h.host = std::make_unique<HostInterface>("host", HostConfig{hw, sc_core::sc_time(30, sc_core::SC_NS)}, *h.machine);
    h.bus = std::make_unique<HostBus>("host_bus");
    h.bus->socket.bind(h.host->socket);
  } else if (hw.pipelines != h.hw.pipelines) {
    throw std::invalid_argument("host interface: built for p = " + std::to_string(h.hw.pipelines) +
                                " in this process; SystemC elaborates once, so run p = " +
                                std::to_string(hw.pipelines) + " in a process of its own");
  } else if (hw.max_dim > h.hw.max_dim) {
    throw std::invalid_argument("host interface: built for volumes of up to " + std::to_string(h.hw.max_dim) +
                                " voxels per axis in this process; SystemC elaborates once, so render the " +
                                std::to_string(max_dim) + "-voxel volume in a process of its own");
  }
  h.machine->set_config(cfg);
  return h;
}

}  // namespace

bool host_interface_available(int p) {
  const Hosted& h = hosted_once();
  return h.host ? h.hw.pipelines == p : sc_core::sc_get_status() == sc_core::SC_ELABORATION;
}

HostSession host_session(const SystemConfig& cfg, const golden::Precision& p, int max_dim) {
  Hosted& h = hosted(cfg, p, max_dim);
  return {h.host->target(), *h.machine};
}

SystemResult render_through_host(const golden::Registers& r, const golden::Volume& vol, const SystemConfig& cfg,
                                 const golden::Progress& progress, double* bus_seconds,
                                 const golden::PolygonFrame* polygons, VolumeLoad load) {
  Hosted& h = hosted(cfg, r.p, std::max({vol.dim[0], vol.dim[1], vol.dim[2]}));
  h.machine->set_progress(progress);
  TlmTarget& target = h.host->target();
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
  // A mapped volume is the frame's only: the caller's may not outlive it.
  struct Unmap {
    HostInterface* host;
    ~Unmap() {
      if (host) host->unmap_volume();
    }
  } unmap{load == VolumeLoad::Mapped ? h.host.get() : nullptr};
  VolumeMap map;
  if (load == VolumeLoad::Mapped) map = [&h](const golden::Volume& v, sc_core::sc_time& d) { h.host->map_volume(v, d); };
  program_over_tlm(target, r, vol, delay, map);
  // Mapped, the polygon images too: the frame below uses them in place.
  PolygonMap map_polygons;
  if (load == VolumeLoad::Mapped)
    map_polygons = [&h](const golden::PolygonFrame& f, sc_core::sc_time& d) { h.host->map_polygons(f, d); };
  write_polygons_over_tlm(target, polygons, delay, map_polygons);
  try {
    start_frame_over_tlm(target, delay);
  } catch (const HostError&) {
    if (h.machine->error()) std::rethrow_exception(h.machine->error());
    throw;
  }
  if (!h.machine->last()) throw std::logic_error("host interface: START ran no frame");
  SystemResult res = *h.machine->last();
  golden::BasePlane read = read_base_plane_over_tlm(target, r, delay);
  // The accumulators stay the pixel memory's: the composition network reads
  // them there, not over the host bus.
  read.acc = std::move(res.plane.acc);
  res.plane = std::move(read);
  if (bus_seconds) *bus_seconds = delay.to_seconds();
  return res;
}

}  // namespace cube4::sysc
