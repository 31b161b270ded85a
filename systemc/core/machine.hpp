// The machine as the host sees it: the HostBackend behind the TLM-2.0 host
// interface (systemc/host/). Host voxel writes fill the volume the voxel
// memory is loaded from, START runs a frame through the system model, and
// the base plane is read back from its pixel memory.
#pragma once
#include <cstdint>
#include <exception>
#include <optional>

#include "golden/volume.hpp"
#include "systemc/core/system.hpp"
#include "systemc/host/host_backend.hpp"
#include "systemc/host/host_program.hpp"
#include "systemc/host/register_map.hpp"

namespace cube4::sysc {

class Machine final : public HostBackend {
 public:
  // A voxel memory word is {tag, value}: tag_bits above voxel_bits (bela's
  // "bits per voxel and tag"); the machine keeps them as golden::Volume's
  // data and tags.
  Machine(const SystemConfig& cfg, int voxel_bits, int tag_bits = 0) : cfg_(cfg), tag_bits_(tag_bits) {
    for (golden::Volume& v : volumes_) v.bits = voxel_bits;
  }

  void set_config(const SystemConfig& cfg) { cfg_ = cfg; }
  void set_progress(golden::Progress p) { progress_ = std::move(p); }
  const std::optional<SystemResult>& last() const { return last_; }
  // Why the last START failed (null if it did not).
  std::exception_ptr error() const { return error_; }

  void set_volume_dims(int k, int nx, int ny, int nz) override;
  void write_voxel(int k, int x, int y, int z, uint16_t v) override;
  // The voxel memory is golden::Volume's object order: a burst is a run.
  void write_voxels(int k, uint64_t first, uint64_t count, const uint32_t* words, int nx, int ny) override;
  // Subvolume k is vol itself (no copy) until unmap_volume() or a voxel
  // write, which first makes it the machine's own.
  void map_volume(int k, const golden::Volume& vol) override;
  void unmap_volume(int k) override;
  uint16_t read_voxel(int k, int x, int y, int z) const override;
  // Runs the frame to its end (the host interface's START is blocking),
  // with the polygon images the host loaded through the POLY_* windows.
  void start_frame(const golden::Registers& regs, int k, const golden::PolygonFrame* polygons) override;
  // Subvolume k as the voxel memory holds it.
  const golden::Volume& volume(int k) const;
  bool busy() const override { return false; }
  uint64_t frames_done() const override { return frames_; }
  uint64_t last_frame_cycles() const override { return last_ ? last_->frame_cycles : 0; }
  int base_width() const override { return last_ ? last_->plane.width : 0; }
  int base_height() const override { return last_ ? last_->plane.height : 0; }
  std::array<uint16_t, 4> read_pixel(int u, int v) const override;

 private:
  SystemConfig cfg_;
  int tag_bits_;
  // Subvolume k: volumes_[k], or the host's volume mapped in its place, or
  // (cleared_[k]) all zero, allocated only when first needed: a volume
  // whose every voxel the host writes or maps is never zeroed first.
  golden::Volume& own(int k);
  std::array<golden::Volume, regmap::kSubvolumes> volumes_;
  std::array<const golden::Volume*, regmap::kSubvolumes> mapped_{};
  std::array<bool, regmap::kSubvolumes> cleared_{};
  golden::Progress progress_;
  std::optional<SystemResult> last_;
  uint64_t frames_ = 0;
  std::exception_ptr error_;
};

// A frame as a host runs it: program the registers, tables and volume
// through the host interface (TLM-2.0 transactions), start it, read the
// base plane back. The result's plane is what the host read. `bus_time`
// returns the annotated host-bus time of the whole exchange. `polygons`:
// the frame's polygon images (Cube-5), written through the POLY_* windows
// (write_polygons_over_tlm), so their transfer is in the bus time. The host
// interface and machine are built once per process (SystemC elaborates
// once), for the first call's p and precision.
// `load`: the volume through the VOLUME window (Bus), or mapped in place for
// the frame (Mapped: HostInterface::map_volume, the same bus time, no copy:
// the loosely timed model's speed and memory on large volumes), and so are
// the polygon images (HostInterface::map_polygons: the same bus time, no
// encoding, decoding or copy); after a mapped frame the machine's
// subvolume 0 reads as cleared.
enum class VolumeLoad { Bus, Mapped };
SystemResult render_through_host(const golden::Registers& r, const golden::Volume& vol, const SystemConfig& cfg,
                                 const golden::Progress& progress, double* bus_seconds = nullptr,
                                 const golden::PolygonFrame* polygons = nullptr, VolumeLoad load = VolumeLoad::Bus);
// The process's host interface and machine, as render_through_host()
// builds them (for cfg.p, precision p, volumes up to max_dim per axis), for
// a host program of its own: several subvolumes, slab updates between
// frames, frames without reloading the volume (systemc/host/host_program.hpp).
struct HostSession {
  TlmTarget& target;
  Machine& machine;
};
HostSession host_session(const SystemConfig& cfg, const golden::Precision& p, int max_dim = 256);

// Whether render_through_host() can run a frame for p pipelines in this
// process: its modules are built already, for p, or can still be built
// (no frame has been simulated yet: SystemC adds no module once it runs).
bool host_interface_available(int p);

}  // namespace cube4::sysc
