// The host side of the host interface: programs a frame and reads the base
// plane back through blocking TLM transactions (docs/registers.md,
// "Programming one frame").
//
// Plain C++ functions. They call b_transport and never wait(), so they run
// from sc_main (with HostInterface::target(); no simulation need run) or
// from an SC_THREAD through a bound initiator socket (`*socket[0]`);
// in a thread, wait(delay) afterwards (or let a quantum keeper) to consume
// the bus time they annotate. (A target that waits would need an
// SC_THREAD caller; HostInterface never waits.)
//
// Every refused transaction, and every register set the hardware cannot
// take, is a HostError naming the register, the value and the reason.
#pragma once
#include <tlm>

#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <systemc>
#include <vector>

#include "golden/polygon_frame.hpp"
#include "golden/registers.hpp"
#include "golden/renderers.hpp"
#include "golden/volume.hpp"

namespace cube4::sysc {

struct HostError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using TlmTarget = tlm::tlm_fw_transport_if<>;

// Bursts are cut into transactions of at most this many words (one 4 KiB
// page, what a DMA engine moves at once).
constexpr size_t kBurstWords = 1024;

void write_words(TlmTarget& target, uint64_t addr, const uint32_t* words, size_t n, sc_core::sc_time& delay);
void read_words(TlmTarget& target, uint64_t addr, uint32_t* words, size_t n, sc_core::sc_time& delay);
void write_word(TlmTarget& target, uint64_t addr, uint32_t value, sc_core::sc_time& delay);
uint32_t read_word(TlmTarget& target, uint64_t addr, sc_core::sc_time& delay);

// What the identification and precision registers report.
struct HardwareId {
  golden::Precision precision;
  int pipelines = 0;
  int max_dim = 0;
  int base_max = 0;
};
HardwareId read_hardware_id(TlmTarget& target, sc_core::sc_time& delay);

// The words of regs' writable registers (all but the voxel memory's: VOL_DIM,
// VOL_INDEX, VOL_SELECT and the slab), one block per run
// of consecutive addresses in regmap::kRegisters: what write_view_over_tlm
// writes, one burst each.
struct RegisterBlock {
  uint64_t addr;
  std::vector<uint32_t> words;
};
std::vector<RegisterBlock> register_blocks(const golden::Registers& regs);

// The pieces of program_over_tlm, in its order. load_volume_over_tlm loads
// vol as subvolume 0 and selects it for START.
void load_volume_over_tlm(TlmTarget& target, const golden::Volume& vol, sc_core::sc_time& delay);
void write_tables_over_tlm(TlmTarget& target, const golden::Registers& regs, sc_core::sc_time& delay);
void write_view_over_tlm(TlmTarget& target, const golden::Registers& regs, sc_core::sc_time& delay);

// Puts vol into subvolume VOL_INDEX (its VOL_DIM already written) without
// moving it over the bus, annotating the bus time its bursts would take:
// HostInterface::map_volume, the model's DMI-style load.
using VolumeMap = std::function<void(const golden::Volume& vol, sc_core::sc_time& delay)>;

// Checks regs against the hardware (precision, table sizes) and the volume
// (regs.dim[i] == vol.dim[regs.perm[i]]), then writes the volume (through
// `map` if given), every table the mode bits use, and every register. Does
// not start the frame.
void program_over_tlm(TlmTarget& target, const golden::Registers& regs, const golden::Volume& vol,
                      sc_core::sc_time& delay, const VolumeMap& map = {});

// Subvolumes (VolumePro §4.2, docs/registers.md "Subvolumes and slabs"):
// several volumes resident in voxel memory, one rendered per START.
// VOL_INDEX = k and its VOL_DIM.
void set_subvolume_dims_over_tlm(TlmTarget& target, int k, const std::array<int, 3>& dim, sc_core::sc_time& delay);
// What loading that many voxels through the VOLUME window annotates: one
// address cycle per burst of kBurstWords and one cycle per word.
sc_core::sc_time volume_load_bus_time(uint64_t voxels, const sc_core::sc_time& bus_period);
// Loads vol as subvolume k (VOL_INDEX = k, VOL_DIM, the volume window);
// the other subvolumes keep theirs.
void load_subvolume_over_tlm(TlmTarget& target, int k, const golden::Volume& vol, sc_core::sc_time& delay);
// START renders subvolume k.
void select_subvolume_over_tlm(TlmTarget& target, int k, sc_core::sc_time& delay);
// A box of subvolume k, `size` voxels from `origin` (object order, x
// fastest): written from `voxels` or read back. A voxel is a 1×1×1 box, a
// slice nx×ny×1. Between frames, without reloading the rest.
void write_slab_over_tlm(TlmTarget& target, int k, const std::array<int, 3>& origin, const std::array<int, 3>& size,
                         const std::vector<uint16_t>& voxels, sc_core::sc_time& delay);
std::vector<uint16_t> read_slab_over_tlm(TlmTarget& target, int k, const std::array<int, 3>& origin,
                                         const std::array<int, 3>& size, sc_core::sc_time& delay);

// Puts the polygon images into the POLY_* windows (their sizes already
// written) without moving them over the bus, annotating the bus time the
// window writes would take: HostInterface::map_polygons, the DMI-style load.
using PolygonMap = std::function<void(const golden::PolygonFrame& f, sc_core::sc_time& delay)>;

// The frame's polygon images (Cube-5) through the POLY_* windows (or `map`
// if given), then POLY_ENABLE; with none, POLY_ENABLE = 0. Every image is
// written, blank or not (the host does not know what the composite buffer
// held); a slab image without fragments is not (the buffer starts each
// frame without).
void write_polygons_over_tlm(TlmTarget& target, const golden::PolygonFrame* polygons, sc_core::sc_time& delay,
                             const PolygonMap& map = {});
// What writing f's images through the windows annotates (the sizes and
// POLY_ENABLE apart): per window write, one address cycle per burst of
// kBurstWords and one cycle per word.
sc_core::sc_time polygon_load_bus_time(const golden::PolygonFrame& f, const sc_core::sc_time& bus_period);

void start_frame_over_tlm(TlmTarget& target, sc_core::sc_time& delay);
uint32_t read_status_over_tlm(TlmTarget& target, sc_core::sc_time& delay);

// The last frame's base plane, as golden::render_fixed returns it for regs
// (shifts and channel width from regs; its size must be regs' base plane).
golden::BasePlane read_base_plane_over_tlm(TlmTarget& target, const golden::Registers& regs,
                                           sc_core::sc_time& delay);

}  // namespace cube4::sysc
