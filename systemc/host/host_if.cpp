#include "systemc/host/host_if.hpp"

#include "systemc/host/host_program.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cube4::sysc {
namespace rm = regmap;
using rm::ErrorCode;
using rm::Region;

namespace {

tlm::tlm_response_status status_of(ErrorCode e) {
  switch (e) {
    case ErrorCode::None: return tlm::TLM_OK_RESPONSE;
    case ErrorCode::Unmapped: return tlm::TLM_ADDRESS_ERROR_RESPONSE;
    case ErrorCode::Alignment:
    case ErrorCode::Streaming:
    case ErrorCode::CtrlInBurst: return tlm::TLM_BURST_ERROR_RESPONSE;
    case ErrorCode::ByteEnable: return tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE;
    case ErrorCode::ReadOnly:
    case ErrorCode::WriteOnly: return tlm::TLM_COMMAND_ERROR_RESPONSE;
    default: return tlm::TLM_GENERIC_ERROR_RESPONSE;
  }
}

uint64_t region_base(Region r) {
  switch (r) {
    case Region::Class: return rm::kClassBase;
    case Region::GmLut: return rm::kGmLutBase;
    case Region::Diffuse: return rm::kDiffuseBase;
    case Region::Specular: return rm::kSpecularBase;
    case Region::Material: return rm::kMaterialBase;
    case Region::Base: return rm::kBaseBase;
    case Region::Volume: return rm::kVolumeBase;
    case Region::Slab: return rm::kSlabBase;
    case Region::PolyFront: return rm::kPolyFrontBase;
    case Region::PolyBack: return rm::kPolyBackBase;
    case Region::PolyZ: return rm::kPolyZBase;
    case Region::PolySlab: return rm::kPolySlabBase;
    default: return 0;
  }
}

// The last sample slice's whole-voxel ray offset, in 128 bits because the
// DDA registers may hold anything and golden::dda_position would overflow.
__int128 last_offset(int64_t start, int64_t step, int slices, int frac_bits) {
  const __int128 pos = static_cast<__int128>(start) + static_cast<__int128>(step) * (slices - 1);
  return pos >> frac_bits;  // floor, as dda_split's arithmetic shift
}

}  // namespace

HostInterface::HostInterface(sc_core::sc_module_name name, const HostConfig& config, HostBackend& backend)
    : sc_core::sc_module(name), socket("socket"), config_(config), backend_(backend), regs_(config.hw) {
  socket.register_b_transport(this, &HostInterface::b_transport);
  socket.register_transport_dbg(this, &HostInterface::transport_dbg);
}

void HostInterface::b_transport(tlm::tlm_generic_payload& t, sc_core::sc_time& delay) {
  Outcome o;
  try {
    o = execute(t, false);
  } catch (const std::exception&) {
    // A backend that throws mid-transaction must not take the simulation down.
    o = {tlm::TLM_GENERIC_ERROR_RESPONSE, ErrorCode::BackendFailure, t.get_address()};
  }
  t.set_response_status(o.status);
  t.set_dmi_allowed(false);
  record(o);
  const bool moved = o.status == tlm::TLM_OK_RESPONSE && t.get_command() != tlm::TLM_IGNORE_COMMAND;
  const unsigned words = moved ? t.get_data_length() / 4 : 0;
  delay += config_.bus_period * static_cast<double>(1 + words);
}

unsigned int HostInterface::transport_dbg(tlm::tlm_generic_payload& t) {
  try {
    const Outcome o = execute(t, true);
    return o.status == tlm::TLM_OK_RESPONSE && t.get_command() != tlm::TLM_IGNORE_COMMAND ? t.get_data_length() : 0;
  } catch (const std::exception&) {
    return 0;
  }
}

void HostInterface::record(const Outcome& o) {
  if (o.status == tlm::TLM_OK_RESPONSE) return;
  error_ = true;
  last_error_ = o.code;
  error_addr_ = o.addr;
}

HostInterface::Outcome HostInterface::check_shape(const tlm::tlm_generic_payload& t, bool debug) const {
  const uint64_t addr = t.get_address();
  const unsigned len = t.get_data_length();
  auto fail = [&](ErrorCode e) { return Outcome{status_of(e), e, addr}; };
  // Debug transport has no byte enables or streaming (TLM-2.0 LRM 11.3).
  if (!debug && t.get_byte_enable_ptr() != nullptr) return fail(ErrorCode::ByteEnable);
  if (len == 0 || len % 4 != 0 || addr % 4 != 0 || t.get_data_ptr() == nullptr)
    return fail(ErrorCode::Alignment);
  if (!debug && t.get_streaming_width() < len) return fail(ErrorCode::Streaming);
  return {};
}

uint64_t HostInterface::mapped_bytes(Region r) const {
  const uint64_t n = static_cast<uint64_t>(config_.hw.max_dim);
  switch (r) {
    case Region::Registers: return rm::kRegisterSpace;
    case Region::Base: return 8 * (2 * n) * (2 * n);
    case Region::Volume:
    case Region::Slab: return (2 * n * n * n + 3) / 4 * 4;
    case Region::PolyFront:
    case Region::PolyBack: return 8 * (2 * n) * (2 * n);
    case Region::PolyZ: return 4 * (2 * n) * (2 * n);
    case Region::PolySlab: return rm::kPolySlabStride * rm::kMaxSupersampling * n;
    case Region::None: return 0;
    default: return regs_.table_bytes(r);
  }
}

HostInterface::Outcome HostInterface::execute(tlm::tlm_generic_payload& t, bool debug) {
  Outcome o = check_shape(t, debug);
  if (o.status != tlm::TLM_OK_RESPONSE) return o;
  const uint64_t addr = t.get_address();
  const unsigned len = t.get_data_length();
  const Region r = rm::region_of(addr);
  const uint64_t end = region_base(r) + mapped_bytes(r);
  if (r == Region::None || addr >= end) return {tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCode::Unmapped, addr};
  if (end - addr < len) return {tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCode::Unmapped, end};
  if (t.get_command() == tlm::TLM_IGNORE_COMMAND) {
    // No access, but the address is checked word by word like any other.
    for (uint64_t a = addr; r == Region::Registers && a < addr + len; a += 4) {
      uint32_t v = 0;
      if (a < rm::kIdMagic ? !read_control(a, v) : regs_.read(a, v) != ErrorCode::None)
        return {tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCode::Unmapped, a};
    }
    return {};
  }

  const bool write = t.is_write();
  const unsigned n = len / 4;
  std::vector<uint32_t> words(n);
  // The data array holds words in host order (TLM-2.0 host endianness).
  if (write) std::memcpy(words.data(), t.get_data_ptr(), len);
  switch (r) {
    case Region::Registers: o = access_registers(write, addr, words.data(), n, debug); break;
    case Region::Volume:
      if (!write) return {tlm::TLM_COMMAND_ERROR_RESPONSE, ErrorCode::WriteOnly, addr};
      // A debugger must not disturb the voxel memory behind a frame's back.
      if (debug) return {tlm::TLM_COMMAND_ERROR_RESPONSE, ErrorCode::ReadOnly, addr};
      o = write_volume(addr, words.data(), n);
      break;
    case Region::Slab:
      // A debugger may look, but must not change voxel memory.
      if (debug && write) return {tlm::TLM_COMMAND_ERROR_RESPONSE, ErrorCode::ReadOnly, addr};
      o = access_slab(write, addr, words.data(), n);
      break;
    case Region::PolyFront:
    case Region::PolyBack:
    case Region::PolyZ:
    case Region::PolySlab:
      if (!write) return {tlm::TLM_COMMAND_ERROR_RESPONSE, ErrorCode::WriteOnly, addr};
      if (debug) return {tlm::TLM_COMMAND_ERROR_RESPONSE, ErrorCode::ReadOnly, addr};
      // The composite buffer is the running frame's.
      if (backend_.busy()) return {status_of(ErrorCode::Busy), ErrorCode::Busy, addr};
      if (const auto f = polygons_.write(addr, words.data(), n, regs_.poly_size(), config_.hw.precision))
        return {status_of(f->code), f->code, f->addr};
      break;
    case Region::Base:
      if (write) return {tlm::TLM_COMMAND_ERROR_RESPONSE, ErrorCode::ReadOnly, addr};
      o = read_base_plane(addr, words.data(), n);
      break;
    default: o = access_tables(write, addr, words.data(), n); break;
  }
  if (o.status == tlm::TLM_OK_RESPONSE && !write) std::memcpy(t.get_data_ptr(), words.data(), len);
  return o;
}

HostInterface::Outcome HostInterface::access_registers(bool write, uint64_t addr, uint32_t* words,
                                                       unsigned n, bool debug) {
  // Every word is checked before any is written, so a refused burst changes nothing.
  for (unsigned i = 0; i < n; ++i) {
    const uint64_t a = addr + 4 * uint64_t{i};
    ErrorCode e = ErrorCode::None;
    if (a < rm::kIdMagic) {
      uint32_t v = 0;
      if (!read_control(a, v)) e = ErrorCode::Unmapped;
      else if (!write) words[i] = v;
      else if (a != rm::kCtrl || debug) e = ErrorCode::ReadOnly;
      else if (n > 1) e = ErrorCode::CtrlInBurst;
    } else {
      e = write ? regs_.check_write(a, words[i]) : regs_.read(a, words[i]);
    }
    if (e != ErrorCode::None) return {status_of(e), e, a};
  }
  if (!write) return {};
  if (addr == rm::kCtrl) return write_ctrl(words[0]);  // alone: checked above
  for (unsigned i = 0; i < n; ++i) regs_.write(addr + 4 * uint64_t{i}, words[i]);
  // Writing the polygon images' size starts them blank.
  if (addr < rm::kPolySize + 12 && addr + 4 * uint64_t{n} > rm::kPolySize) polygons_.clear();
  return {};
}

HostInterface::Outcome HostInterface::access_tables(bool write, uint64_t addr, uint32_t* words, unsigned n) {
  for (unsigned i = 0; i < n; ++i) {
    const uint64_t a = addr + 4 * uint64_t{i};
    const ErrorCode e = write ? regs_.check_write(a, words[i]) : regs_.read(a, words[i]);
    if (e != ErrorCode::None) return {status_of(e), e, a};
  }
  if (write)
    for (unsigned i = 0; i < n; ++i) regs_.write(addr + 4 * uint64_t{i}, words[i]);
  return {};
}

bool HostInterface::read_control(uint64_t a, uint32_t& v) const {
  auto lo = [](uint64_t x) { return static_cast<uint32_t>(x); };
  auto hi = [](uint64_t x) { return static_cast<uint32_t>(x >> 32); };
  switch (a) {
    case rm::kCtrl: v = 0; return true;
    case rm::kStatus: {
      const bool busy = backend_.busy();
      const bool done = started_ && !busy && backend_.frames_done() >= done_target_;
      v = (busy ? rm::kStatusBusy : 0) | (done ? rm::kStatusDone : 0) | (error_ ? rm::kStatusError : 0);
      return true;
    }
    case rm::kLastError: v = static_cast<uint32_t>(last_error_); return true;
    case rm::kErrorAddrLo: v = lo(error_addr_); return true;
    case rm::kErrorAddrHi: v = hi(error_addr_); return true;
    case rm::kFrameCountLo: v = lo(backend_.frames_done()); return true;
    case rm::kFrameCountHi: v = hi(backend_.frames_done()); return true;
    case rm::kCyclesLo: v = lo(backend_.last_frame_cycles()); return true;
    case rm::kCyclesHi: v = hi(backend_.last_frame_cycles()); return true;
    case rm::kBaseWidth: v = static_cast<uint32_t>(backend_.base_width()); return true;
    case rm::kBaseHeight: v = static_cast<uint32_t>(backend_.base_height()); return true;
    default: return false;
  }
}

HostInterface::Outcome HostInterface::write_ctrl(uint32_t v) {
  if (v & ~rm::kCtrlMask) return {tlm::TLM_GENERIC_ERROR_RESPONSE, ErrorCode::FieldRange, rm::kCtrl};
  if (v & (rm::kCtrlReset | rm::kCtrlClearError)) {
    error_ = false;
    last_error_ = ErrorCode::None;
    error_addr_ = 0;
  }
  if (v & rm::kCtrlReset) {
    regs_.reset();
    polygons_.clear();
    told_dims_ = {};  // the system model hears the volumes' dims again
    started_ = false;        // DONE waits for the next frame
  }
  if (v & rm::kCtrlStart) return start_frame();
  return {};
}

ErrorCode HostInterface::commit_volume_dims(int k) {
  const std::array<int, 3> d = regs_.volume_dims(k);
  if (d[0] == 0 || d[1] == 0 || d[2] == 0) return ErrorCode::VolumeDimsUnset;
  std::array<int, 3>& told = told_dims_[static_cast<size_t>(k)];
  if (d != told) {
    backend_.set_volume_dims(k, d[0], d[1], d[2]);
    told = d;
  }
  return ErrorCode::None;
}

void HostInterface::map_volume(const golden::Volume& vol, sc_core::sc_time& delay) {
  const int k = regs_.vol_index();
  if (backend_.busy()) throw std::invalid_argument("host interface: map_volume while a frame runs");
  if (regs_.volume_dims(k) != vol.dim)
    throw std::invalid_argument("host interface: map_volume of a " + std::to_string(vol.dim[0]) + "x" +
                                std::to_string(vol.dim[1]) + "x" + std::to_string(vol.dim[2]) +
                                " volume into subvolume " + std::to_string(k) + ", whose VOL_DIM differs");
  // The checks the VOLUME window makes word by word.
  const uint32_t max = rm::voxel_word_max(config_.hw.precision);
  if (vol.bits != config_.hw.precision.voxel_bits)
    throw std::invalid_argument("host interface: map_volume of " + std::to_string(vol.bits) +
                                "-bit voxels into a " + std::to_string(config_.hw.precision.voxel_bits) +
                                "-bit voxel memory");
  for (size_t i = 0; i < vol.data.size(); ++i) {
    const uint32_t w = rm::voxel_word(vol, i);
    if (w > max)
      throw std::invalid_argument("host interface: map_volume: voxel " + std::to_string(i) + " holds " +
                                  std::to_string(w) + ", wider than the voxel memory word (at most " +
                                  std::to_string(max) + ")");
  }
  commit_volume_dims(k);
  backend_.map_volume(k, vol);
  mapped_ = k;
  delay += volume_load_bus_time(vol.data.size(), config_.bus_period);
}

void HostInterface::map_polygons(const golden::PolygonFrame& f, sc_core::sc_time& delay) {
  auto refuse = [](const std::string& what) { throw std::invalid_argument("host interface: map_polygons: " + what); };
  if (backend_.busy()) refuse("while a frame runs");
  const std::array<int, 3> size = regs_.poly_size();
  const size_t pixels = static_cast<size_t>(f.width) * static_cast<size_t>(f.height);
  if (size != std::array<int, 3>{f.width, f.height, static_cast<int>(f.slabs.size())} || f.front.size() != pixels ||
      f.back.size() != pixels || f.z.size() != pixels)
    refuse("images of " + std::to_string(f.width) + " x " + std::to_string(f.height) + " pixels and " +
           std::to_string(f.slabs.size()) + " slabs, but POLY_WIDTH, POLY_HEIGHT, POLY_SLICES = " +
           std::to_string(size[0]) + ", " + std::to_string(size[1]) + ", " + std::to_string(size[2]));
  // The checks the windows make word by word. START's of the slab lines
  // hold already: a SlabImage's lines are well formed by construction.
  const uint32_t channel_max = (uint32_t{1} << config_.hw.precision.alpha_bits) - 1;
  // The largest channel and depth first (a loop without exits, which the
  // compiler vectorises); the pixel to name only when one is out of range.
  const auto largest = [](const golden::Pixel& px) { return std::max({px.r, px.g, px.b, px.a}); };
  uint32_t channel = 0, depth = 0;
  for (size_t i = 0; i < pixels; ++i) {
    channel = std::max<uint32_t>({channel, largest(f.front[i]), largest(f.back[i])});
    depth = std::max(depth, f.z[i]);
  }
  for (size_t i = 0; i < pixels && (channel > channel_max || depth > golden::kZNone); ++i) {
    if (std::max(largest(f.front[i]), largest(f.back[i])) > channel_max)
      refuse("pixel " + std::to_string(i) + " has a channel above " + std::to_string(channel_max));
    if (f.z[i] > golden::kZNone) refuse("pixel " + std::to_string(i) + " has a depth above kZNone");
  }
  polygons_.map(f, size);
  delay += polygon_load_bus_time(f, config_.bus_period);
}

void HostInterface::unmap_volume() {
  if (mapped_ >= 0) backend_.unmap_volume(mapped_);
  mapped_ = -1;
}

HostInterface::Outcome HostInterface::start_frame() {
  auto fail = [](ErrorCode e) { return Outcome{status_of(e), e, rm::kCtrl}; };
  if (backend_.busy()) return fail(ErrorCode::Busy);
  const int k = regs_.vol_select();
  const std::array<int, 3> vol = regs_.volume_dims(k);
  if (vol[0] == 0 || vol[1] == 0 || vol[2] == 0) return fail(ErrorCode::VolumeDimsUnset);
  const golden::Registers r = regs_.decoded();
  for (int i = 0; i < 3; ++i)
    if (r.dim[i] != vol[r.perm[i]]) return fail(ErrorCode::ViewMismatch);
  // The pixel memory holds BASE_MAX x BASE_MAX pixels.
  const int f = r.p.dda_frac_bits;
  // Perspective: rays at least one voxel apart on the first slice (one for
  // a whole volume, more for a block starting deeper: golden/blocks.hpp) and
  // at most the box filter's 3 on the last (golden/units/dda_perspective.hpp),
  // or nothing below can divide by the spacing.
  if (r.perspective) {
    const int64_t one = int64_t{1} << f;
    if (r.scale_start < one || r.scale_start > 3 * one)
      return {status_of(ErrorCode::FieldRange), ErrorCode::FieldRange, rm::address_of("SCALE_START")};
    if (r.scale_step < 0 || r.scale_start + __int128{r.scale_step} * (r.sample_slices() - 1) > 3 * one)
      return {status_of(ErrorCode::FieldRange), ErrorCode::FieldRange, rm::address_of("SCALE_STEP")};
  }
  // Parallel: shears forwards by at most a voxel a slice, from a start at
  // or past 0; perspective: ray 0 where no sum overflows
  // (golden::dda_out_of_range()).
  if (const char* field = golden::dda_out_of_range(r)) {
    std::string name = field;
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return {status_of(ErrorCode::FieldRange), ErrorCode::FieldRange, rm::address_of(name)};
  }
  // Parallel: the volume's columns and the rays' last offset; perspective:
  // every ray that samples a slice (Registers::rays_entering).
  auto extent = [&](int axis, int64_t start, int64_t step) -> __int128 {
    const __int128 margins = r.margin_lo[static_cast<size_t>(axis)] + r.margin_hi[static_cast<size_t>(axis)];
    if (!r.perspective) return r.dim[static_cast<size_t>(axis)] + last_offset(start, step, r.sample_slices(), f) + margins;
    const golden::RayRange rays = r.rays_entering(axis);
    return __int128{rays.hi} - rays.lo + margins;
  };
  const __int128 w = extent(0, r.x_start, r.x_step), h = extent(1, r.y_start, r.y_step);
  const int base_max = 2 * config_.hw.max_dim;
  if (w < 1 || w > base_max || h < 1 || h > base_max) return fail(ErrorCode::BasePlaneTooLarge);
  if (r.cut_enabled && r.cut.falloff < 0) return fail(ErrorCode::CutFalloffNegative);
  if (const rm::Register* wide = regs_.wide_value_out_of_range())
    return {status_of(ErrorCode::FieldRange), ErrorCode::FieldRange, wide->addr};

  golden::PolygonFrame decoded;
  const golden::PolygonFrame* polygons = nullptr;
  if (regs_.poly_enable()) {
    if (const auto f = polygons_.frame(regs_.poly_size(), static_cast<int>(w), static_cast<int>(h), r.sample_slices(),
                                       r.dim[0], r.dim[1], config_.hw.pipelines, decoded, polygons))
      return {status_of(f->code), f->code, f->addr};
  }

  const uint64_t before = backend_.frames_done();
  try {
    if (commit_volume_dims(k) != ErrorCode::None) return fail(ErrorCode::VolumeDimsUnset);
    backend_.start_frame(r, k, polygons);
  } catch (const std::exception&) {
    return fail(ErrorCode::BackendFailure);
  }
  if (polygons) polygons_.clear();  // the frame has consumed them
  started_ = true;
  done_target_ = before + 1;
  return {};
}

HostInterface::Outcome HostInterface::write_volume(uint64_t addr, const uint32_t* words, unsigned n) {
  auto fail = [](ErrorCode e, uint64_t a) { return Outcome{status_of(e), e, a}; };
  if (backend_.busy()) return fail(ErrorCode::Busy, addr);
  const int k = regs_.vol_index();
  const std::array<int, 3> d = regs_.volume_dims(k);
  if (d[0] == 0 || d[1] == 0 || d[2] == 0) return fail(ErrorCode::VolumeDimsUnset, addr);
  const uint64_t voxels = uint64_t(d[0]) * d[1] * d[2];
  const uint32_t max = rm::voxel_word_max(config_.hw.precision);  // {tag, value}
  const uint64_t first = (addr - rm::kVolumeBase) / 2;
  for (unsigned i = 0; i < n; ++i) {
    const uint64_t v = first + 2 * uint64_t{i};
    const uint64_t a = addr + 4 * uint64_t{i};
    if (v >= voxels) return fail(ErrorCode::VoxelOutOfVolume, a);
    // A high half past the last voxel is padding of an odd-sized volume: ignored.
    if ((words[i] & 0xFFFF) > max || (v + 1 < voxels && (words[i] >> 16) > max))
      return fail(ErrorCode::FieldRange, a);
  }
  commit_volume_dims(k);
  backend_.write_voxels(k, first, std::min(voxels, first + 2 * uint64_t{n}) - first, words, d[0], d[1]);
  return {};
}

// The slab window: the voxels of the box SLAB_X0.. SLAB_NZ of subvolume
// VOL_INDEX, x fastest, two per word (VolumePro §4.2: single voxels, slices
// and rectangular slabs read and written between frames).
HostInterface::Outcome HostInterface::access_slab(bool write, uint64_t addr, uint32_t* words, unsigned n) {
  auto fail = [](ErrorCode e, uint64_t a) { return Outcome{status_of(e), e, a}; };
  if (backend_.busy()) return fail(ErrorCode::Busy, addr);
  const int k = regs_.vol_index();
  const std::array<int, 3> d = regs_.volume_dims(k), o = regs_.slab_origin(), s = regs_.slab_size();
  if (d[0] == 0 || d[1] == 0 || d[2] == 0) return fail(ErrorCode::VolumeDimsUnset, addr);
  for (int i = 0; i < 3; ++i)
    if (s[i] < 1 || o[i] + s[i] > d[i]) return fail(ErrorCode::SlabOutOfVolume, addr);
  const uint64_t voxels = uint64_t(s[0]) * s[1] * s[2];
  const uint32_t max = rm::voxel_word_max(config_.hw.precision);  // {tag, value}
  const uint64_t first = (addr - rm::kSlabBase) / 2;
  for (unsigned i = 0; i < n; ++i) {
    const uint64_t v = first + 2 * uint64_t{i};
    const uint64_t a = addr + 4 * uint64_t{i};
    if (v >= voxels) return fail(ErrorCode::SlabOutOfVolume, a);
    if (write && ((words[i] & 0xFFFF) > max || (v + 1 < voxels && (words[i] >> 16) > max)))
      return fail(ErrorCode::FieldRange, a);
  }
  commit_volume_dims(k);
  for (unsigned i = 0; i < n; ++i) {
    if (!write) words[i] = 0;
    for (uint64_t h = 0; h < 2; ++h) {
      const uint64_t v = first + 2 * uint64_t{i} + h;
      if (v >= voxels) break;  // a word's high half past an odd slab's end: ignored, read as 0
      const int x = o[0] + static_cast<int>(v % s[0]);
      const int y = o[1] + static_cast<int>(v / s[0] % s[1]);
      const int z = o[2] + static_cast<int>(v / s[0] / s[1]);
      if (write) {
        backend_.write_voxel(k, x, y, z, static_cast<uint16_t>(words[i] >> (16 * h)));
      } else {
        words[i] |= uint32_t{backend_.read_voxel(k, x, y, z)} << (16 * h);
      }
    }
  }
  return {};
}

HostInterface::Outcome HostInterface::read_base_plane(uint64_t addr, uint32_t* words, unsigned n) const {
  auto fail = [](ErrorCode e, uint64_t a) { return Outcome{status_of(e), e, a}; };
  // The pipelines are writing the pixel memory.
  if (backend_.busy()) return fail(ErrorCode::Busy, addr);
  const int w = backend_.base_width(), h = backend_.base_height();
  const uint64_t pixels = w > 0 && h > 0 ? uint64_t(w) * h : 0;
  for (unsigned i = 0; i < n; ++i) {
    const uint64_t a = addr + 4 * uint64_t{i};
    const uint64_t p = (a - rm::kBaseBase) / 8;
    if (p >= pixels) return fail(ErrorCode::PixelOutOfImage, a);
    const std::array<uint16_t, 4> px = backend_.read_pixel(static_cast<int>(p % w), static_cast<int>(p / w));
    words[i] = (a & 4) ? (px[2] | uint32_t{px[3]} << 16) : (px[0] | uint32_t{px[1]} << 16);
  }
  return {};
}

}  // namespace cube4::sysc
