// The host interface: a TLM-2.0 target on the host bus (32-bit data,
// 64-bit addresses) holding the register file of docs/registers.md.
// Blocking transport only, loosely timed: b_transport never calls wait(),
// it adds the bus time of the transaction to `delay` (one address cycle
// plus one cycle per 32-bit word), so it may be called from an SC_THREAD,
// or from sc_main without a running simulation. transport_dbg reads and
// writes storage without side effects or delay.
//
// Errors are response statuses, never exceptions or SystemC reports:
//   byte enables                      -> TLM_BYTE_ENABLE_ERROR_RESPONSE
//   address/length not a multiple of 4, streaming, CTRL in a burst
//                                     -> TLM_BURST_ERROR_RESPONSE
//   any word unmapped, or the transaction spans two regions
//                                     -> TLM_ADDRESS_ERROR_RESPONSE
//   write to read-only, read of write-only -> TLM_COMMAND_ERROR_RESPONSE
//   value out of range, busy, START checks -> TLM_GENERIC_ERROR_RESPONSE
// Each sets STATUS.ERROR and records LAST_ERROR and ERROR_ADDR. A refused
// transaction changes nothing: every word is checked before any is taken.
#pragma once
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include <cstdint>
#include <systemc>

#include "golden/registers.hpp"
#include "systemc/host/host_backend.hpp"
#include "systemc/host/polygon_buffer.hpp"
#include "systemc/host/register_file.hpp"

namespace cube4::sysc {

struct HostConfig {
  HardwareParams hw;
  // About 33 MHz: VolumePro sat on 32-bit PCI.
  sc_core::sc_time bus_period{30, sc_core::SC_NS};
};

class HostInterface : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<HostInterface> socket;

  // Throws std::invalid_argument when the map cannot hold config.hw.
  HostInterface(sc_core::sc_module_name name, const HostConfig& config, HostBackend& backend);

  // The register file as register values (Precision: the hardware's).
  golden::Registers decoded() const { return regs_.decoded(); }
  const HostConfig& config() const { return config_; }
  void set_bus_period(const sc_core::sc_time& t) { config_.bus_period = t; }

  // The model's DMI-style volume load (a VolumeMap for program_over_tlm):
  // subvolume VOL_INDEX, whose VOL_DIM must be vol.dim, holds vol's voxels
  // without their moving over the bus; `delay` gains the bus time of the
  // bursts that would have moved them. The backend may use vol in place
  // until unmap_volume(), so vol must outlive that; a voxel or slab write
  // to the subvolume before then makes it the backend's own copy. Throws
  // std::invalid_argument (and maps nothing) for other dims, a busy
  // machine or a voxel wider than its word.
  void map_volume(const golden::Volume& vol, sc_core::sc_time& delay);
  // Ends it: the subvolume reads as cleared, as after a new VOL_DIM.
  void unmap_volume();
  // The DMI-style load of the polygon images (a PolygonMap for
  // write_polygons_over_tlm): the POLY_* windows hold f's images, whose
  // sizes POLY_WIDTH, POLY_HEIGHT and POLY_SLICES must give, without their
  // moving over the bus; `delay` gains the window writes' bus time. The
  // frame START runs uses f in place, so f must outlive it; a window write
  // before then makes the images the buffer's own words. Throws
  // std::invalid_argument (and maps nothing) for other sizes, a busy
  // machine, or a pixel channel or depth wider than its window's word (what
  // the windows refuse word by word); slab images whose beams are not the
  // frame's are START's PolygonImage fault, as through the windows.
  void map_polygons(const golden::PolygonFrame& f, sc_core::sc_time& delay);

  // The socket's forward interface, to call without binding an initiator
  // (tests, sc_main before elaboration).
  tlm::tlm_fw_transport_if<>& target() { return socket.get_base_interface(); }

 private:
  struct Outcome {
    tlm::tlm_response_status status = tlm::TLM_OK_RESPONSE;
    regmap::ErrorCode code = regmap::ErrorCode::None;
    uint64_t addr = 0;  // the word at fault
  };

  void b_transport(tlm::tlm_generic_payload& t, sc_core::sc_time& delay);
  unsigned int transport_dbg(tlm::tlm_generic_payload& t);

  Outcome execute(tlm::tlm_generic_payload& t, bool debug);
  Outcome check_shape(const tlm::tlm_generic_payload& t, bool debug) const;
  uint64_t mapped_bytes(regmap::Region r) const;
  Outcome access_registers(bool write, uint64_t addr, uint32_t* words, unsigned n, bool debug);
  Outcome access_tables(bool write, uint64_t addr, uint32_t* words, unsigned n);
  Outcome write_volume(uint64_t addr, const uint32_t* words, unsigned n);
  Outcome access_slab(bool write, uint64_t addr, uint32_t* words, unsigned n);
  Outcome read_base_plane(uint64_t addr, uint32_t* words, unsigned n) const;
  bool read_control(uint64_t addr, uint32_t& v) const;
  Outcome write_ctrl(uint32_t v);
  Outcome start_frame();
  // Tells the backend subvolume k's dimensions if they changed since.
  regmap::ErrorCode commit_volume_dims(int k);
  void record(const Outcome& o);

  HostConfig config_;
  HostBackend& backend_;
  RegisterFile regs_;
  PolygonBuffer polygons_;  // the POLY_* windows, until START consumes them
  int mapped_ = -1;         // the subvolume map_volume() mapped, until unmap_volume()
  // What the backend was last given, per subvolume.
  std::array<std::array<int, 3>, regmap::kSubvolumes> told_dims_{};
  bool error_ = false;
  regmap::ErrorCode last_error_ = regmap::ErrorCode::None;
  uint64_t error_addr_ = 0;
  bool started_ = false;
  uint64_t done_target_ = 0;  // frames_done() once the frame started last completes
};

}  // namespace cube4::sysc
