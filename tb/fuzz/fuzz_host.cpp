// The host interface as a host program drives it: a small scene programmed
// over TLM (volume, tables, registers), then the input's register writes on
// top, then START, the frame rendered by the machine at the loosely timed
// TLM level (the golden renderer) or, by the first byte's second bit, by
// one clocked beat by beat at TLM (every unit's clocked model, the
// perspective units' too, each unit's output checked against golden's: a
// difference aborts). Whatever the registers hold, a write or
// START may be refused with an error response, a frame may render, but
// nothing may crash, read or write outside its memory, leak or hang (a
// parallel view's negative shear once passed START and corrupted the heap).
//
// Input: a byte choosing the scene (bit 0) and the machine (bit 1), then
// records of 5 bytes, {register, w0, w1, w2, w3}: the register is an
// index into the register map's writable registers, the word written to
// its low word (or, with the register's top bit set, to its high word).
#include <systemc>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "golden/host_driver.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "systemc/core/machine.hpp"
#include "systemc/host/host_if.hpp"
#include "systemc/host/host_program.hpp"
#include "systemc/host/register_map.hpp"
#include "tb/fuzz/fuzz_support.hpp"

namespace {

using namespace cube4;
namespace rm = sysc::regmap;

// A shaded sphere at a view that is not axis-aligned, and a perspective
// one: both projections' registers are there to be mutated.
const char* const kScenes[] = {
    R"({"volume": {"synthetic": "sphere", "size": [9, 7, 6]}, "shading": true, "view": {"rotate": [20, 35, 10]},
        "output": {"width": 16, "height": 16}})",
    R"({"volume": {"synthetic": "sphere", "size": [9, 7, 6]}, "shading": true,
        "view": {"projection": "perspective", "fov": 50, "eye": [4, 3, -14], "up": [0, 1, 0]},
        "output": {"width": 16, "height": 16}})",
};

struct Programmed {
  golden::Scene scene;
  golden::Volume volume;
  golden::HostProgram host;
};

sysc::SystemConfig tlm_config(bool clocked) {
  sysc::SystemConfig c;
  c.levels.fill(sysc::Level::Tlm);
  c.cycle_level = clocked;
  c.check = clocked;  // every clocked unit's output against golden's
  return c;
}

// The process's host interface and machine (machine.hpp: bound to a bus,
// so that a clocked frame's SystemC elaboration finds every port bound),
// its configuration set per input.
struct Rig {
  sysc::SystemConfig cfg = tlm_config(false), clocked_cfg = tlm_config(true);
  sysc::HostSession session = sysc::host_session(cfg, golden::Precision{});
  std::vector<Programmed> scenes;
  std::vector<const rm::Register*> writable;
  Rig() {
    for (const char* json : kScenes) {
      Programmed p;
      p.scene = golden::parse_scene(json, "fuzz.json");
      p.volume = golden::load_volume(p.scene.volume, p.scene.precision.voxel_bits, "");
      p.host = golden::program_host(p.scene, p.volume);
      scenes.push_back(std::move(p));
    }
    for (const rm::Register& r : rm::kRegisters)
      if (r.access != rm::Access::R && std::strcmp(r.name, "CTRL") != 0) writable.push_back(&r);
  }
};

Rig& rig() {
  static Rig r;
  return r;
}

void write(sysc::TlmTarget& target, uint64_t addr, uint32_t word) {
  tlm::tlm_generic_payload t;
  t.set_command(tlm::TLM_WRITE_COMMAND);
  t.set_address(addr);
  t.set_data_ptr(reinterpret_cast<unsigned char*>(&word));
  t.set_data_length(4);
  t.set_streaming_width(4);
  t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
  target.b_transport(t, delay);
}

}  // namespace

void cube4::fuzz::write_seeds(const std::string& dir) {
  // No writes (each scene as programmed), and a few single writes.
  write_seed(dir, "none0", Bytes{0});
  write_seed(dir, "none1", Bytes{1});
  write_seed(dir, "clocked0", Bytes{2});
  write_seed(dir, "clocked1", Bytes{3});
  for (unsigned char reg = 0; reg < 40; reg += 3)
    write_seed(dir, "one" + std::to_string(reg), Bytes{static_cast<unsigned char>(reg & 1), reg, 0xff, 0xff, 0x7f, 0x80});
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  Rig& r = rig();
  const Programmed& p = r.scenes[data[0] % r.scenes.size()];
  const bool clocked = data[0] & 2;
  r.session.machine.set_config(clocked ? r.clocked_cfg : r.cfg);
  sysc::TlmTarget& host = r.session.target;
  sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
  write(host, rm::kCtrl, rm::kCtrlReset);
  sysc::program_over_tlm(host, p.host.regs, p.volume, delay);
  for (size_t i = 1; i + 5 <= size; i += 5) {
    const rm::Register& reg = *r.writable[(data[i] & 0x7f) % r.writable.size()];
    const bool high = (data[i] & 0x80) && reg.words == 2;
    uint32_t word = 0;
    std::memcpy(&word, data + i + 1, 4);
    write(host, reg.addr + (high ? 4 : 0), word);
  }
  write(host, rm::kCtrl, rm::kCtrlStart);
  // A clocked unit whose output differs from golden's is a finding: every
  // model here is golden's own functions on the clocked schedule.
  if (const auto& last = r.session.machine.last(); clocked && last && last->mismatch) {
    std::fprintf(stderr, "fuzz_host: clocked frame: %s\n", last->mismatch->describe().c_str());
    std::abort();
  }
  return 0;
}
