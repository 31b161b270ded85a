#include "systemc/host/host_program.hpp"

#include "systemc/host/polygon_buffer.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "golden/slice_steps.hpp"
#include "systemc/host/register_map.hpp"

namespace cube4::sysc {
namespace rm = regmap;

namespace {

std::string hex(uint64_t v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%llx", static_cast<unsigned long long>(v));
  return buf;
}

std::string response_name(tlm::tlm_response_status s) {
  tlm::tlm_generic_payload p;
  p.set_response_status(s);
  return p.get_response_string();
}

// One transaction, no error handling: the caller decides.
tlm::tlm_response_status transact(TlmTarget& target, tlm::tlm_command cmd, uint64_t addr, uint32_t* words,
                                  size_t n, sc_core::sc_time& delay) {
  tlm::tlm_generic_payload t;
  const auto len = static_cast<unsigned>(4 * n);
  t.set_command(cmd);
  t.set_address(addr);
  t.set_data_ptr(reinterpret_cast<unsigned char*>(words));
  t.set_data_length(len);
  t.set_streaming_width(len);
  t.set_byte_enable_ptr(nullptr);
  t.set_dmi_allowed(false);
  t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  target.b_transport(t, delay);
  return t.get_response_status();
}

// Names the word at fault from the interface's own error registers.
[[noreturn]] void refused(TlmTarget& target, tlm::tlm_command cmd, uint64_t addr, const uint32_t* words,
                          size_t n, tlm::tlm_response_status status, sc_core::sc_time& delay) {
  uint32_t code = 0, at_words[2] = {0, 0};
  std::string reason;
  uint64_t at = addr;
  if (transact(target, tlm::TLM_READ_COMMAND, rm::kLastError, &code, 1, delay) == tlm::TLM_OK_RESPONSE &&
      transact(target, tlm::TLM_READ_COMMAND, rm::kErrorAddrLo, at_words, 2, delay) == tlm::TLM_OK_RESPONSE) {
    reason = " (LAST_ERROR " + std::to_string(code) + ": " + rm::error_name(static_cast<rm::ErrorCode>(code)) + ")";
    at = at_words[0] | uint64_t{at_words[1]} << 32;
  }
  std::string what = (cmd == tlm::TLM_WRITE_COMMAND ? "write of " : "read of ") + rm::describe_address(at);
  if (cmd == tlm::TLM_WRITE_COMMAND && at >= addr && at < addr + 4 * n)
    what += " = " + hex(words[(at - addr) / 4]);
  throw HostError("host interface: " + what + " refused: " + response_name(status) + reason);
}

void burst(TlmTarget& target, tlm::tlm_command cmd, uint64_t addr, uint32_t* words, size_t n,
           sc_core::sc_time& delay) {
  for (size_t i = 0; i < n; i += kBurstWords) {
    const size_t m = std::min(kBurstWords, n - i);
    const uint64_t a = addr + 4 * i;
    const tlm::tlm_response_status s = transact(target, cmd, a, words + i, m, delay);
    if (s != tlm::TLM_OK_RESPONSE) refused(target, cmd, a, words + i, m, s, delay);
  }
}


void check(bool ok, const std::string& what) {
  if (!ok) throw HostError("host program: " + what);
}

void check_table(size_t size, size_t expected, bool used, const char* field) {
  check(size == expected || (!used && size == 0),
        std::string("regs.") + field + " has " + std::to_string(size) + " entries, the hardware's table " +
            std::to_string(expected) + (used ? "" : " (or 0: the mode bits leave it unused)"));
}

// The frame's writable registers' words (not the voxel memory's: VOL_DIM,
// VOL_INDEX, VOL_SELECT, the slab; not the polygon images': POLY_*), one
// block per run of consecutive addresses.
std::vector<RegisterBlock> writable_blocks(const rm::RegisterValues& v) {
  const HardwareParams no_hardware;  // writable registers' getters read only the values
  std::vector<RegisterBlock> blocks;
  for (const rm::Register& reg : rm::kRegisters) {
    if (!rm::carries_frame_field(reg)) continue;
    if (blocks.empty() || blocks.back().addr + 4 * blocks.back().words.size() != reg.addr)
      blocks.push_back({reg.addr, {}});
    const uint64_t value = reg.get(v, no_hardware);
    blocks.back().words.push_back(static_cast<uint32_t>(value));
    if (reg.words == 2) blocks.back().words.push_back(static_cast<uint32_t>(value >> 32));
  }
  return blocks;
}


}  // namespace

void write_words(TlmTarget& target, uint64_t addr, const uint32_t* words, size_t n, sc_core::sc_time& delay) {
  // The payload's data pointer is not const; a write does not change it.
  burst(target, tlm::TLM_WRITE_COMMAND, addr, const_cast<uint32_t*>(words), n, delay);
}

void read_words(TlmTarget& target, uint64_t addr, uint32_t* words, size_t n, sc_core::sc_time& delay) {
  burst(target, tlm::TLM_READ_COMMAND, addr, words, n, delay);
}

void write_word(TlmTarget& target, uint64_t addr, uint32_t value, sc_core::sc_time& delay) {
  write_words(target, addr, &value, 1, delay);
}

uint32_t read_word(TlmTarget& target, uint64_t addr, sc_core::sc_time& delay) {
  uint32_t v = 0;
  read_words(target, addr, &v, 1, delay);
  return v;
}

HardwareId read_hardware_id(TlmTarget& target, sc_core::sc_time& delay) {
  uint32_t id[9];
  read_words(target, rm::kIdMagic, id, 9, delay);
  check(id[0] == rm::kMagic, "ID_MAGIC = " + hex(id[0]) + ", expected " + hex(rm::kMagic));
  check(id[1] >> 16 == rm::kVersion >> 16,
        "ID_VERSION = " + hex(id[1]) + ", this driver knows major version " + std::to_string(rm::kVersion >> 16));
  uint32_t p[rm::kPrecisionFields];
  read_words(target, rm::kPrecision, p, rm::kPrecisionFields, delay);
  HardwareId h;
  for (int i = 0; i < rm::kPrecisionFields; ++i)
    h.precision.*golden::kPrecisionFields[i].member = static_cast<int>(p[i]);
  h.pipelines = static_cast<int>(id[2]);
  h.max_dim = static_cast<int>(id[3]);
  h.base_max = static_cast<int>(id[8]);
  return h;
}

namespace {

// Two voxels per word, x fastest: the windows' order.
std::vector<uint32_t> pack_voxels(const std::vector<uint16_t>& v) {
  std::vector<uint32_t> words((v.size() + 1) / 2, 0);
  for (size_t i = 0; i < v.size(); ++i) words[i / 2] |= uint32_t{v[i]} << (16 * (i % 2));
  return words;
}

}  // namespace

void set_subvolume_dims_over_tlm(TlmTarget& target, int k, const std::array<int, 3>& dim, sc_core::sc_time& delay) {
  write_word(target, rm::kVolIndex, static_cast<uint32_t>(k), delay);
  const uint32_t dims[3] = {static_cast<uint32_t>(dim[0]), static_cast<uint32_t>(dim[1]), static_cast<uint32_t>(dim[2])};
  write_words(target, rm::kVolDim, dims, 3, delay);
}

namespace {
// One write_words() of n words: an address cycle per burst, a cycle per word.
sc_core::sc_time words_bus_time(uint64_t words, const sc_core::sc_time& bus_period) {
  const uint64_t transactions = (words + kBurstWords - 1) / kBurstWords;
  return bus_period * static_cast<double>(words + transactions);
}
}  // namespace

sc_core::sc_time volume_load_bus_time(uint64_t voxels, const sc_core::sc_time& bus_period) {
  return words_bus_time((voxels + 1) / 2, bus_period);
}

sc_core::sc_time polygon_load_bus_time(const golden::PolygonFrame& f, const sc_core::sc_time& bus_period) {
  const uint64_t pixels = static_cast<uint64_t>(f.width) * static_cast<uint64_t>(f.height);
  sc_core::sc_time t = words_bus_time(2 * pixels, bus_period) * 2.0 + words_bus_time(pixels, bus_period);
  for (const golden::SlabImage& s : f.slabs)
    if (!s.empty()) t += words_bus_time(slab_stream_words(s), bus_period);
  return t;
}

void load_subvolume_over_tlm(TlmTarget& target, int k, const golden::Volume& vol, sc_core::sc_time& delay) {
  check(vol.data.size() == vol.size(), "the volume holds " + std::to_string(vol.data.size()) +
                                           " voxels, its dimensions say " + std::to_string(vol.size()));
  check(k >= 0 && k < rm::kSubvolumes, "subvolume " + std::to_string(k) + " is not one of 0.." +
                                           std::to_string(rm::kSubvolumes - 1));
  check(vol.tags.empty() || vol.tags.size() == vol.size(),
        "the volume holds " + std::to_string(vol.tags.size()) + " tags, its dimensions say " + std::to_string(vol.size()));
  set_subvolume_dims_over_tlm(target, k, vol.dim, delay);
  // The voxel memory words: {tag, value}, the tag above the value's bits,
  // two voxels a word. Packed a chunk at a time (whole bursts, so the
  // transactions are those of one write_words call): a large volume is not
  // copied twice on its way to the machine.
  constexpr size_t kChunkWords = 256 * kBurstWords;
  const size_t voxels = vol.data.size(), n = (voxels + 1) / 2;
  auto word_of = [&](size_t v) { return v < voxels ? rm::voxel_word(vol, v) : uint32_t{0}; };
  std::vector<uint32_t> chunk(std::min(kChunkWords, n));
  for (size_t first = 0; first < n; first += kChunkWords) {
    const size_t m = std::min(kChunkWords, n - first);
    for (size_t i = 0; i < m; ++i) {
      const size_t v = 2 * (first + i);
      chunk[i] = word_of(v) | word_of(v + 1) << 16;
    }
    write_words(target, rm::kVolumeBase + 4 * first, chunk.data(), m, delay);
  }
}

void write_polygons_over_tlm(TlmTarget& target, const golden::PolygonFrame* f, sc_core::sc_time& delay,
                             const PolygonMap& map) {
  if (!f) return write_word(target, rm::kPolyEnable, 0, delay);
  const uint32_t size[3] = {static_cast<uint32_t>(f->width), static_cast<uint32_t>(f->height),
                            static_cast<uint32_t>(f->slabs.size())};
  write_words(target, rm::kPolySize, size, 3, delay);
  const size_t pixels = static_cast<size_t>(f->width) * f->height;
  check(f->front.size() == pixels && f->back.size() == pixels && f->z.size() == pixels,
        "polygon images of " + std::to_string(f->front.size()) + ", " + std::to_string(f->back.size()) + " and " +
            std::to_string(f->z.size()) + " pixels for a " + std::to_string(f->width) + " x " +
            std::to_string(f->height) + " base plane");
  if (map) {
    map(*f, delay);
    return write_word(target, rm::kPolyEnable, 1, delay);
  }
  for (const auto& [image, base] : {std::pair{&f->front, rm::kPolyFrontBase}, std::pair{&f->back, rm::kPolyBackBase}}) {
    std::vector<uint32_t> words(2 * pixels);
    for (size_t i = 0; i < pixels; ++i) {
      const golden::Pixel& px = (*image)[i];
      words[2 * i] = uint32_t{px.r} | uint32_t{px.g} << 16;
      words[2 * i + 1] = uint32_t{px.b} | uint32_t{px.a} << 16;
    }
    write_words(target, base, words.data(), words.size(), delay);
  }
  write_words(target, rm::kPolyZBase, f->z.data(), pixels, delay);
  for (size_t k = 0; k < f->slabs.size(); ++k) {
    const std::vector<uint32_t> stream = encode_slab_stream(f->slabs[k]);
    if (!stream.empty()) write_words(target, rm::kPolySlabBase + k * rm::kPolySlabStride, stream.data(), stream.size(), delay);
  }
  write_word(target, rm::kPolyEnable, 1, delay);
}

void select_subvolume_over_tlm(TlmTarget& target, int k, sc_core::sc_time& delay) {
  write_word(target, rm::kVolSelect, static_cast<uint32_t>(k), delay);
}

void load_volume_over_tlm(TlmTarget& target, const golden::Volume& vol, sc_core::sc_time& delay) {
  load_subvolume_over_tlm(target, 0, vol, delay);
  select_subvolume_over_tlm(target, 0, delay);
}

namespace {

// VOL_INDEX and the slab registers for a box of subvolume k.
void set_slab(TlmTarget& target, int k, const std::array<int, 3>& origin, const std::array<int, 3>& size,
              sc_core::sc_time& delay) {
  write_word(target, rm::kVolIndex, static_cast<uint32_t>(k), delay);
  const uint32_t box[6] = {static_cast<uint32_t>(origin[0]), static_cast<uint32_t>(origin[1]),
                           static_cast<uint32_t>(origin[2]), static_cast<uint32_t>(size[0]),
                           static_cast<uint32_t>(size[1]), static_cast<uint32_t>(size[2])};
  write_words(target, rm::kSlab, box, 6, delay);
}

}  // namespace

void write_slab_over_tlm(TlmTarget& target, int k, const std::array<int, 3>& origin, const std::array<int, 3>& size,
                         const std::vector<uint16_t>& voxels, sc_core::sc_time& delay) {
  const uint64_t n = uint64_t(size[0]) * size[1] * size[2];
  check(voxels.size() == n, std::to_string(voxels.size()) + " voxels for a slab of " + std::to_string(n));
  set_slab(target, k, origin, size, delay);
  const std::vector<uint32_t> words = pack_voxels(voxels);
  write_words(target, rm::kSlabBase, words.data(), words.size(), delay);
}

std::vector<uint16_t> read_slab_over_tlm(TlmTarget& target, int k, const std::array<int, 3>& origin,
                                         const std::array<int, 3>& size, sc_core::sc_time& delay) {
  const uint64_t n = uint64_t(size[0]) * size[1] * size[2];
  set_slab(target, k, origin, size, delay);
  std::vector<uint32_t> words((n + 1) / 2);
  read_words(target, rm::kSlabBase, words.data(), words.size(), delay);
  std::vector<uint16_t> voxels(n);
  for (size_t i = 0; i < n; ++i) voxels[i] = static_cast<uint16_t>(words[i / 2] >> (16 * (i % 2)));
  return voxels;
}

void write_tables_over_tlm(TlmTarget& target, const golden::Registers& regs, sc_core::sc_time& delay) {
  std::vector<uint32_t> w(2 * regs.classification.size());
  for (size_t i = 0; i < regs.classification.size(); ++i) {
    const golden::ClassEntry& e = regs.classification[i];
    w[2 * i] = uint32_t{e.r} | uint32_t{e.g} << 8 | uint32_t{e.b} << 16;
    w[2 * i + 1] = e.a;
  }
  write_words(target, rm::kClassBase, w.data(), w.size(), delay);
  const std::vector<uint32_t> gm(regs.gm_lut.begin(), regs.gm_lut.end());
  write_words(target, rm::kGmLutBase, gm.data(), gm.size(), delay);
  write_words(target, rm::kDiffuseBase, regs.diffuse_map.data(), regs.diffuse_map.size(), delay);
  write_words(target, rm::kSpecularBase, regs.specular_map.data(), regs.specular_map.size(), delay);
  std::vector<uint32_t> m(rm::kMaterialWords * regs.tag_coefs.size(), 0);
  for (size_t t = 0; t < regs.tag_coefs.size(); ++t) {
    const golden::ShadeCoefs& k = regs.tag_coefs[t];
    const uint32_t entry[6] = {k.ke, k.kd, k.ks, k.specular[0], k.specular[1], k.specular[2]};
    std::copy(entry, entry + 6, &m[rm::kMaterialWords * t]);
  }
  write_words(target, rm::kMaterialBase, m.data(), m.size(), delay);
}

std::vector<RegisterBlock> register_blocks(const golden::Registers& r) {
  rm::RegisterValues values;
  values.regs = r;
  return writable_blocks(values);
}

void write_view_over_tlm(TlmTarget& target, const golden::Registers& regs, sc_core::sc_time& delay) {
  for (const RegisterBlock& b : register_blocks(regs)) write_words(target, b.addr, b.words.data(), b.words.size(), delay);
}

void program_over_tlm(TlmTarget& target, const golden::Registers& regs, const golden::Volume& vol,
                      sc_core::sc_time& delay, const VolumeMap& map) {
  const HardwareId hw = read_hardware_id(target, delay);
  const golden::Precision& a = regs.p;
  if (const golden::PrecisionField* f = golden::first_difference(a, hw.precision))
    check(false, std::string("regs.p.") + f->key + " = " + std::to_string(a.*f->member) + ", the hardware's is " +
                     std::to_string(hw.precision.*f->member));
  for (int i = 0; i < 3; ++i) {
    check(vol.dim[i] >= 1 && vol.dim[i] <= hw.max_dim,
          "volume dim[" + std::to_string(i) + "] = " + std::to_string(vol.dim[i]) + " is out of range 1.." +
              std::to_string(hw.max_dim));
    const int axis = regs.perm[i];
    check(axis >= 0 && axis < 3, "regs.perm[" + std::to_string(i) + "] = " + std::to_string(axis) +
                                     " is not an axis");
    check(regs.dim[i] == vol.dim[axis], "regs.dim[" + std::to_string(i) + "] = " + std::to_string(regs.dim[i]) +
                                            ", the volume's dim[perm[" + std::to_string(i) + "] = " +
                                            std::to_string(axis) + "] = " + std::to_string(vol.dim[axis]));
  }
  check_table(regs.classification.size(), rm::class_entries(a), true, "classification");
  check_table(regs.gm_lut.size(), rm::gm_entries(a), regs.magnitude, "gm_lut");
  check_table(regs.diffuse_map.size(), rm::map_entries(a), regs.shading, "diffuse_map");
  check_table(regs.specular_map.size(), rm::map_entries(a), regs.specular, "specular_map");
  check_table(regs.tag_coefs.size(), rm::material_entries(a), regs.shading, "tag_coefs");

  if (map) {
    set_subvolume_dims_over_tlm(target, 0, vol.dim, delay);
    map(vol, delay);
    select_subvolume_over_tlm(target, 0, delay);
  } else {
    load_volume_over_tlm(target, vol, delay);
  }
  write_tables_over_tlm(target, regs, delay);
  write_view_over_tlm(target, regs, delay);
}

void start_frame_over_tlm(TlmTarget& target, sc_core::sc_time& delay) {
  write_word(target, rm::kCtrl, rm::kCtrlStart, delay);
}

uint32_t read_status_over_tlm(TlmTarget& target, sc_core::sc_time& delay) {
  return read_word(target, rm::kStatus, delay);
}

golden::BasePlane read_base_plane_over_tlm(TlmTarget& target, const golden::Registers& regs,
                                           sc_core::sc_time& delay) {
  uint32_t size[2];
  read_words(target, rm::kBaseWidth, size, 2, delay);
  golden::BasePlane bp;
  bp.width = static_cast<int>(size[0]);
  bp.height = static_cast<int>(size[1]);
  check(bp.width == regs.base_width() && bp.height == regs.base_height(),
        "BASE_WIDTH x BASE_HEIGHT = " + std::to_string(bp.width) + " x " + std::to_string(bp.height) +
            ", the registers' base plane is " + std::to_string(regs.base_width()) + " x " +
            std::to_string(regs.base_height()));
  const size_t pixels = static_cast<size_t>(bp.width) * bp.height;
  std::vector<uint32_t> words(2 * pixels);
  read_words(target, rm::kBaseBase, words.data(), words.size(), delay);
  bp.rgba.resize(4 * pixels);
  for (size_t i = 0; i < words.size(); ++i) {
    bp.rgba[2 * i] = static_cast<uint16_t>(words[i]);
    bp.rgba[2 * i + 1] = static_cast<uint16_t>(words[i] >> 16);
  }
  // As golden::render_fixed: where ray (0, 0) enters, for the warp
  // (perspective frames and polygon margins included).
  bp.bits = regs.p.alpha_bits;
  golden::set_base_plane_shift(bp, regs);
  return bp;
}

}  // namespace cube4::sysc
