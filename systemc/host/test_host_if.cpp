// The host interface: register round trips for real and random register
// sets, volume load, base-plane read-back, every error path, status and
// identification, delay annotation, debug transport, and one frame
// programmed from an SC_THREAD through a bound initiator socket.
#include <gtest/gtest.h>

#include <tlm_utils/simple_initiator_socket.h>

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "golden/host_driver.hpp"
#include "golden/mesh.hpp"
#include "golden/polygons.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "systemc/host/host_if.hpp"
#include "systemc/host/host_program.hpp"
#include "systemc/host/register_map.hpp"

// gtest_main provides main(); libsystemc.so's own main() still needs the
// symbol to link. Never called.
int sc_main(int, char*[]) { return 1; }

using namespace cube4;
using namespace cube4::sysc;
namespace rm = cube4::sysc::regmap;
using rm::ErrorCode;
using sc_core::sc_time;
using sc_core::SC_NS;
using sc_core::SC_ZERO_TIME;

namespace {

// The system model's stand-in: records what the interface tells it and, when
// asked, renders frames with the golden model.
class TestBackend : public HostBackend {
 public:
  std::array<golden::Volume, rm::kSubvolumes> volumes;
  std::vector<int> writes_per_voxel;  // subvolume 0's
  std::vector<int> rendered;          // the subvolume of every frame started
  int dims_calls = 0;
  std::vector<golden::Registers> frames;
  bool is_busy = false;
  sc_time busy_until = SC_ZERO_TIME;   // busy in simulated time after a start
  sc_time frame_time = SC_ZERO_TIME;
  uint64_t done = 0, cycles = 0;
  golden::BasePlane plane;
  std::vector<std::optional<golden::PolygonFrame>> polygons;  // each frame's, as START handed them
  bool render = false;  // start_frame renders with golden::render_fixed
  bool refuse = false;  // start_frame throws

  void set_volume_dims(int k, int nx, int ny, int nz) override {
    ++dims_calls;
    golden::Volume& v = volumes.at(static_cast<size_t>(k));
    v = golden::Volume{};
    v.dim = {nx, ny, nz};
    v.data.assign(v.size(), 0);
    if (k == 0) writes_per_voxel.assign(v.size(), 0);
  }
  void write_voxel(int k, int x, int y, int z, uint16_t v) override {
    golden::Volume& vol = volumes.at(static_cast<size_t>(k));
    const size_t i = vol.index(x, y, z);
    vol.data.at(i) = v;
    if (k == 0) ++writes_per_voxel.at(i);
  }
  uint16_t read_voxel(int k, int x, int y, int z) const override {
    const golden::Volume& vol = volumes.at(static_cast<size_t>(k));
    return vol.data.at(vol.index(x, y, z));
  }
  void start_frame(const golden::Registers& regs, int k, const golden::PolygonFrame* poly) override {
    if (refuse) throw std::runtime_error("refused");
    frames.push_back(regs);
    rendered.push_back(k);
    polygons.push_back(poly ? std::optional<golden::PolygonFrame>(*poly) : std::nullopt);
    if (render) {
      golden::Volume& vol = volumes.at(static_cast<size_t>(k));
      vol.bits = regs.p.voxel_bits;
      plane = golden::render_fixed(vol, regs);
    }
    busy_until = sc_core::sc_time_stamp() + frame_time;
    cycles = 1000 + frames.size();
    ++done;
  }
  bool busy() const override { return is_busy || sc_core::sc_time_stamp() < busy_until; }
  uint64_t frames_done() const override { return done; }
  uint64_t last_frame_cycles() const override { return cycles; }
  int base_width() const override { return plane.width; }
  int base_height() const override { return plane.height; }
  std::array<uint16_t, 4> read_pixel(int u, int v) const override {
    const uint16_t* p = &plane.rgba.at((static_cast<size_t>(v) * plane.width + u) * 4);
    return {p[0], p[1], p[2], p[3]};
  }
};

golden::Precision narrow_precision() {
  golden::Precision p;
  p.voxel_bits = 8;
  p.weight_bits = 6;
  p.dda_frac_bits = 16;
  p.magnitude_bits = 6;
  p.color_bits = 6;
  p.alpha_bits = 16;
  p.gmlut_bits = 10;
  p.map_face_res = 4;
  p.map_bits = 20;
  p.map_frac_bits = 10;
  p.coef_bits = 12;
  p.coef_frac_bits = 9;
  p.eye_bits = 10;
  return p;
}

// The SC_THREAD host: programs one frame, polls, reads the base plane.
struct HostThread : sc_core::sc_module {
  tlm_utils::simple_initiator_socket<HostThread> socket{"socket"};
  const golden::Registers* regs = nullptr;
  const golden::Volume* vol = nullptr;
  golden::BasePlane result;
  sc_time annotated = SC_ZERO_TIME;
  int polls = 0;
  uint32_t final_status = 0;
  bool finished = false;

  explicit HostThread(sc_core::sc_module_name n) : sc_core::sc_module(n) { SC_THREAD(run); }
  SC_HAS_PROCESS(HostThread);

  void consume(sc_time& delay) {
    annotated += delay;
    wait(delay);
    delay = SC_ZERO_TIME;
  }
  void run() {
    if (regs == nullptr) return;
    TlmTarget& t = *socket[0];
    sc_time delay = SC_ZERO_TIME;
    program_over_tlm(t, *regs, *vol, delay);
    consume(delay);
    start_frame_over_tlm(t, delay);
    consume(delay);
    while ((final_status = read_status_over_tlm(t, delay)) & rm::kStatusBusy) {
      ++polls;
      consume(delay);
      wait(1, sc_core::SC_US);
    }
    consume(delay);
    result = read_base_plane_over_tlm(t, *regs, delay);
    consume(delay);
    finished = true;
  }
};

// Sink for the second host's socket: every target socket must be bound
// before sc_start.
struct IdleInitiator : sc_core::sc_module {
  tlm_utils::simple_initiator_socket<IdleInitiator> socket{"socket"};
  explicit IdleInitiator(sc_core::sc_module_name n) : sc_core::sc_module(n) {}
};

golden::Precision tag_precision() {
  golden::Precision p;
  p.voxel_bits = 8;
  p.tag_bits = 2;
  return p;
}

// Modules can be built only before the first sc_start: one set for the
// whole process.
struct Env {
  TestBackend backend;
  HostInterface host{"host", HostConfig{HardwareParams{golden::Precision{}, 4, 64}}, backend};
  TestBackend backend8;
  // A small voxel memory: two 32³ subvolumes fill it.
  HostInterface host8{"host8", HostConfig{HardwareParams{narrow_precision(), 3, 32, 2 * 32 * 32 * 32}}, backend8};
  // Voxel tags (bela §III): 8-bit values, 2-bit tags.
  TestBackend backend_tags;
  HostInterface host_tags{"host_tags", HostConfig{HardwareParams{tag_precision(), 2, 16}}, backend_tags};
  HostThread thread{"thread"};
  IdleInitiator idle{"idle"};
  IdleInitiator idle_tags{"idle_tags"};
  Env() {
    thread.socket.bind(host.socket);
    idle.socket.bind(host8.socket);
    idle_tags.socket.bind(host_tags.socket);
  }
};

Env& env() {
  static Env e;
  return e;
}

struct Raw {
  tlm::tlm_response_status status;
  std::vector<uint32_t> data;
  sc_time delay;
};

Raw transact(HostInterface& h, tlm::tlm_command cmd, uint64_t addr, std::vector<uint32_t> data,
             unsigned len = 0, unsigned char* byte_enables = nullptr, unsigned streaming = 0) {
  if (len == 0) len = static_cast<unsigned>(4 * data.size());
  data.resize(std::max<size_t>(data.size(), (len + 3) / 4));
  tlm::tlm_generic_payload t;
  t.set_command(cmd);
  t.set_address(addr);
  t.set_data_ptr(reinterpret_cast<unsigned char*>(data.data()));
  t.set_data_length(len);
  t.set_streaming_width(streaming ? streaming : len);
  t.set_byte_enable_ptr(byte_enables);
  if (byte_enables) t.set_byte_enable_length(len);
  t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  sc_time delay = SC_ZERO_TIME;
  h.target().b_transport(t, delay);
  return {t.get_response_status(), data, delay};
}

tlm::tlm_response_status write(HostInterface& h, uint64_t addr, std::vector<uint32_t> words) {
  return transact(h, tlm::TLM_WRITE_COMMAND, addr, std::move(words)).status;
}

uint32_t read(HostInterface& h, uint64_t addr) {
  const Raw r = transact(h, tlm::TLM_READ_COMMAND, addr, {0});
  EXPECT_EQ(r.status, tlm::TLM_OK_RESPONSE) << rm::describe_address(addr);
  return r.data[0];
}

void reset(HostInterface& h) {
  ASSERT_EQ(write(h, rm::kCtrl, {rm::kCtrlReset}), tlm::TLM_OK_RESPONSE);
}

// A new backend behind a reset interface (RESET makes the interface give the
// backend the volume dims again).
void fresh(HostInterface& h, TestBackend& b) {
  b = TestBackend{};
  reset(h);
}

// ---- Register-set equality, field by field ---------------------------------

#define EXPECT_FIELD(f) EXPECT_EQ(a.f, b.f) << where << ": field " #f

void expect_precision_equal(const golden::Precision& a, const golden::Precision& b, const std::string& where) {
  for (const golden::PrecisionField& f : golden::kPrecisionFields)
    EXPECT_EQ(a.*f.member, b.*f.member) << where << ": precision." << f.key;
}

template <class T, class Eq>
void expect_table_equal(const std::vector<T>& a, const std::vector<T>& b, Eq eq, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what << ": size";
  for (size_t i = 0; i < a.size(); ++i)
    if (!eq(a[i], b[i])) {
      ADD_FAILURE() << what << ": first difference at entry " << i;
      return;
    }
}

void expect_registers_equal(const golden::Registers& a, const golden::Registers& b, const std::string& where) {
  expect_precision_equal(a.p, b.p, where + " precision");
  EXPECT_FIELD(dim); EXPECT_FIELD(perm); EXPECT_FIELD(flip); EXPECT_FIELD(supersampling);
  EXPECT_FIELD(x_start); EXPECT_FIELD(x_step); EXPECT_FIELD(y_start); EXPECT_FIELD(y_step);
  expect_table_equal(a.classification, b.classification,
                     [](const golden::ClassEntry& x, const golden::ClassEntry& y) {
                       return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a;
                     }, where + ": classification");
  const auto same = [](auto x, auto y) { return x == y; };
  expect_table_equal(a.gm_lut, b.gm_lut, same, where + ": gm_lut");
  expect_table_equal(a.diffuse_map, b.diffuse_map, same, where + ": diffuse_map");
  expect_table_equal(a.specular_map, b.specular_map, same, where + ": specular_map");
  EXPECT_FIELD(coefs.ke); EXPECT_FIELD(coefs.kd); EXPECT_FIELD(coefs.ks); EXPECT_FIELD(coefs.specular);
  EXPECT_FIELD(eye);
  EXPECT_FIELD(gradient); EXPECT_FIELD(magnitude); EXPECT_FIELD(shading); EXPECT_FIELD(specular);
  EXPECT_FIELD(gm_opacity); EXPECT_FIELD(gm_diffuse); EXPECT_FIELD(gm_specular);
  EXPECT_EQ(static_cast<int>(a.blend), static_cast<int>(b.blend)) << where << ": field blend";
  EXPECT_FIELD(crop_enabled); EXPECT_FIELD(crop.slab); EXPECT_FIELD(crop.mask);
  EXPECT_FIELD(window_enabled); EXPECT_FIELD(window.range);
  EXPECT_FIELD(cut_enabled); EXPECT_FIELD(cut.a); EXPECT_FIELD(cut.b); EXPECT_FIELD(cut.c);
  EXPECT_FIELD(cut.dmin); EXPECT_FIELD(cut.dmax); EXPECT_FIELD(cut.falloff); EXPECT_FIELD(cut.inv_falloff);
  EXPECT_FIELD(cut.keep_inside);
}

#undef EXPECT_FIELD

// ---- Scenes -----------------------------------------------------------------------

struct SceneSetup {
  std::string name;
  golden::Volume volume;
  golden::Registers regs;
};

SceneSetup setup(const std::string& name, const std::string& json) {
  const golden::Scene s = golden::parse_scene(json, name + ".json");
  SceneSetup r{name, golden::load_volume(s.volume, s.precision.voxel_bits, "."), {}};
  r.regs = golden::program_host(s, r.volume).regs;
  return r;
}

const std::string kSphere = R"("volume": {"synthetic": "sphere", "size": [20, 24, 28]})";

std::vector<SceneSetup> default_precision_scenes() {
  return {
      setup("shaded_specular", "{" + kSphere + R"(, "view": {"rotate": [20, 30, 0]},
             "material": {"ks": 0.5}})"),
      setup("mip_flipped", "{" + kSphere + R"(, "view": {"direction": [0.2, -0.3, -1]},
             "shading": false, "blend": "mip"})"),
      setup("crop_cut", "{" + kSphere + R"(, "view": {"rotate": [-15, 130, 0]},
             "cropping": {"x": [2, 12], "y": [5, 20], "combine": "intersection", "invert": true},
             "cut_plane": {"normal": [1, 0, 1], "dmin": 10, "dmax": 18, "falloff": 3, "keep": "outside"}})"),
      setup("gm_supersampled", "{" + kSphere + R"(, "view": {"direction": [1, 0.3, 0.2], "ray_offset": [0.25, 0.5]},
             "gradient_modulation": {"opacity": true, "diffuse": true, "specular": true},
             "supersampling": 2})"),
      setup("minip_y", "{" + kSphere + R"(, "view": {"direction": [0.1, -1, 0.4], "up": [0, 0, 1]},
             "shading": false, "blend": "minip", "cropping": {"z": [3, 9], "combine": "cross"}})"),
  };
}

SceneSetup narrow_scene() {
  return setup("narrow_precision", R"({"volume": {"synthetic": "sphere", "size": [12, 10, 14]},
      "view": {"rotate": [70, -40, 10]}, "gradient_modulation": {"opacity": true, "specular": true},
      "precision": {"voxel_bits": 8, "weight_bits": 6, "dda_frac_bits": 16, "magnitude_bits": 6,
                    "color_bits": 6, "alpha_bits": 16, "gmlut_bits": 10, "map_face_res": 4,
                    "map_bits": 20, "map_frac_bits": 10, "coef_bits": 12, "coef_frac_bits": 9,
                    "eye_bits": 10}})");
}

// ---- Random register sets: every bit of every field -------------------------

golden::Registers random_registers(const golden::Precision& p, std::mt19937_64& rng, golden::Volume& vol) {
  auto bits = [&](int n) { return static_cast<uint32_t>(n >= 32 ? rng() : rng() & ((uint64_t{1} << n) - 1)); };
  auto coin = [&] { return (rng() & 1) != 0; };
  golden::Registers r;
  r.p = p;
  std::shuffle(r.perm.begin(), r.perm.end(), rng);
  for (int i = 0; i < 3; ++i) {
    r.dim[i] = 1 + static_cast<int>(rng() % 9);
    r.flip[i] = coin();
  }
  r.supersampling = 1 + static_cast<int>(rng() % 8);
  r.x_start = static_cast<int64_t>(rng());
  r.x_step = static_cast<int64_t>(rng());
  r.y_start = static_cast<int64_t>(rng());
  r.y_step = static_cast<int64_t>(rng());
  r.classification.resize(size_t{1} << p.voxel_bits);
  for (auto& e : r.classification)
    e = {static_cast<uint16_t>(bits(p.color_bits)), static_cast<uint16_t>(bits(p.color_bits)),
         static_cast<uint16_t>(bits(p.color_bits)), static_cast<uint16_t>(bits(p.alpha_bits))};
  r.gradient = coin();
  r.magnitude = coin();
  r.shading = coin();
  r.specular = coin();
  r.gm_opacity = coin();
  r.gm_diffuse = coin();
  r.gm_specular = coin();
  r.blend = static_cast<golden::BlendMode>(rng() % 3);
  const size_t map = size_t{6} * p.map_face_res * p.map_face_res;
  if (r.magnitude)
    for (size_t i = 0; i < (size_t{1} << p.magnitude_bits); ++i)
      r.gm_lut.push_back(static_cast<uint16_t>(bits(p.gmlut_bits)));
  if (r.shading)
    for (size_t i = 0; i < map; ++i) r.diffuse_map.push_back(bits(p.map_bits));
  if (r.specular)
    for (size_t i = 0; i < map; ++i) r.specular_map.push_back(bits(p.map_bits));
  r.coefs = {bits(p.coef_bits), bits(p.coef_bits), bits(p.coef_bits),
             {bits(p.alpha_bits), bits(p.alpha_bits), bits(p.alpha_bits)}};
  const int64_t e = golden::max_signed(p.eye_bits);
  for (auto& c : r.eye) c = static_cast<int32_t>(static_cast<int64_t>(rng() % (2 * e + 1)) - e);
  r.crop_enabled = coin();
  // Fields narrower than their registers: any value the hardware field holds.
  auto in_field = [&, hw = HardwareParams{p}](const char* name) {
    const rm::Limits l = *rm::limits(*rm::find_register(name), hw);
    return l.lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(l.hi - l.lo + 1));
  };
  for (auto& s : r.crop.slab) s = {static_cast<int32_t>(in_field("CROP_X_LO")), static_cast<int32_t>(in_field("CROP_X_HI"))};
  r.crop.mask = static_cast<uint8_t>(rng());
  r.window_enabled = coin();
  for (auto& s : r.window.range)
    s = {static_cast<int32_t>(in_field("WINDOW_X_LO")), static_cast<int32_t>(in_field("WINDOW_X_HI"))};
  r.cut_enabled = coin();
  r.cut = {static_cast<int32_t>(in_field("CUT_A")), static_cast<int32_t>(in_field("CUT_B")),
           static_cast<int32_t>(in_field("CUT_C")), in_field("CUT_DMIN"), in_field("CUT_DMAX"),
           in_field("CUT_FALLOFF"), static_cast<uint64_t>(in_field("CUT_INV_FALLOFF")), coin()};
  vol = golden::Volume{};
  vol.bits = p.voxel_bits;
  for (int i = 0; i < 3; ++i) vol.dim[r.perm[i]] = r.dim[i];
  for (size_t i = 0; i < vol.size(); ++i) vol.data.push_back(static_cast<uint16_t>(bits(p.voxel_bits)));
  return r;
}

}  // namespace

// ---- Identification and status ---------------------------------------------------

// Voxel tags: the voxel words carry {tag, value}, the CLASS window is
// addressed by {tag, value}, the MATERIAL window holds one entry per tag.
TEST(HostInterface, TaggedVoxelWordsClassAndMaterialWindows) {
  Env& e = env();
  fresh(e.host_tags, e.backend_tags);
  HostInterface& h = e.host_tags;
  EXPECT_EQ(read(h, rm::kIdClassEntries), 1024u);  // 2^(8 + 2)
  ASSERT_EQ(write(h, rm::kVolDim, {2, 1, 1}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(write(h, rm::kVolumeBase, {0x03FF | 0x0400u << 16}), tlm::TLM_GENERIC_ERROR_RESPONSE);  // a word past 10 bits
  EXPECT_EQ(read(h, rm::kLastError), static_cast<uint32_t>(ErrorCode::FieldRange));
  ASSERT_EQ(write(h, rm::kVolumeBase, {0x02FF | 0x0105u << 16}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(e.backend_tags.volumes[0].data, (std::vector<uint16_t>{0x02FF, 0x0105}));  // words as written
  EXPECT_EQ(write(h, rm::kClassBase + 8 * 1023 + 4, {7}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(write(h, rm::kClassBase + 8 * 1024, {0}), tlm::TLM_ADDRESS_ERROR_RESPONSE);
  // MATERIAL: tag 3's ke (coef_bits 10), its specular blue (alpha_bits 16), its reserved words.
  const uint64_t tag3 = rm::kMaterialBase + 4 * rm::kMaterialWords * 3;
  EXPECT_EQ(write(h, tag3, {0x3FF}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(write(h, tag3, {0x400}), tlm::TLM_GENERIC_ERROR_RESPONSE);
  EXPECT_EQ(write(h, tag3 + 4 * 5, {0xFFFF}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(write(h, tag3 + 4 * 6, {1}), tlm::TLM_GENERIC_ERROR_RESPONSE);
  EXPECT_EQ(write(h, tag3 + 4 * rm::kMaterialWords, {0}), tlm::TLM_ADDRESS_ERROR_RESPONSE);  // four tags
  EXPECT_EQ(read(h, tag3), 0x3FFu);
  EXPECT_EQ(rm::describe_address(tag3 + 4 * 5), "MATERIAL[3].spec_b (0x240074)");
  EXPECT_TRUE(h.decoded().tag_coefs.empty()) << "without MODE.shading the materials are not the frame's";
  ASSERT_EQ(write(h, rm::kMode, {rm::kModeShading | rm::kModeGradient}), tlm::TLM_OK_RESPONSE);
  const golden::Registers r = h.decoded();
  ASSERT_EQ(r.tag_coefs.size(), 4u);
  EXPECT_EQ(r.tag_coefs[3].ke, 0x3FFu);
  EXPECT_EQ(r.tag_coefs[3].specular[2], 0xFFFFu);
  EXPECT_EQ(r.classification[1023].a, 7u);
  ASSERT_EQ(write(h, rm::kCtrl, {rm::kCtrlReset}), tlm::TLM_OK_RESPONSE);
}

TEST(HostInterface, IdentificationAndPrecisionReportTheHardware) {
  Env& e = env();
  for (HostInterface* h : {&e.host, &e.host8}) {
    const HardwareParams& hw = h->config().hw;
    EXPECT_EQ(read(*h, rm::kIdMagic), rm::kMagic);
    EXPECT_EQ(read(*h, rm::kIdVersion), rm::kVersion);
    EXPECT_EQ(read(*h, rm::kIdPipelines), uint32_t(hw.pipelines));
    EXPECT_EQ(read(*h, rm::kIdMaxDim), uint32_t(hw.max_dim));
    EXPECT_EQ(read(*h, rm::kIdVoxelBits), uint32_t(hw.precision.voxel_bits));
    EXPECT_EQ(read(*h, rm::kIdClassEntries), 1u << hw.precision.voxel_bits);
    EXPECT_EQ(read(*h, rm::kIdGmLutEntries), 1u << hw.precision.magnitude_bits);
    EXPECT_EQ(read(*h, rm::kIdMapEntries), uint32_t(6 * hw.precision.map_face_res * hw.precision.map_face_res));
    EXPECT_EQ(read(*h, rm::kIdBaseMax), uint32_t(2 * hw.max_dim));
    for (const golden::PrecisionField& f : golden::kPrecisionFields)
      EXPECT_EQ(read(*h, rm::address_of(f.register_name)), uint32_t(hw.precision.*f.member)) << f.register_name;
    sc_time delay = SC_ZERO_TIME;
    const HardwareId id = read_hardware_id(h->target(), delay);
    expect_precision_equal(id.precision, hw.precision, h->name());
    EXPECT_EQ(id.pipelines, hw.pipelines);
    EXPECT_EQ(id.max_dim, hw.max_dim);
    EXPECT_EQ(id.base_max, 2 * hw.max_dim);
  }
}

TEST(HostInterface, StatusRegistersMirrorTheBackend) {
  Env& e = env();
  fresh(e.host, e.backend);
  EXPECT_EQ(read(e.host, rm::kStatus), 0u);
  e.backend.is_busy = true;
  EXPECT_EQ(read(e.host, rm::kStatus), rm::kStatusBusy);
  e.backend.is_busy = false;
  e.backend.done = (uint64_t{1} << 32) + 5;
  e.backend.cycles = (uint64_t{7} << 32) + 0x89ABCDEF;
  e.backend.plane.width = 37;
  e.backend.plane.height = 29;
  const Raw counters = transact(e.host, tlm::TLM_READ_COMMAND, rm::kFrameCountLo, {0, 0, 0, 0, 0, 0});
  ASSERT_EQ(counters.status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(counters.data, (std::vector<uint32_t>{5, 1, 0x89ABCDEF, 7, 37, 29}));
  EXPECT_EQ(read(e.host, rm::kCtrl), 0u);  // write-only bits read as zero
  // DONE only once a frame started here has completed.
  EXPECT_EQ(read(e.host, rm::kStatus) & rm::kStatusDone, 0u);
  ASSERT_EQ(write(e.host, rm::kVolDim, {4, 5, 6}), tlm::TLM_OK_RESPONSE);
  ASSERT_EQ(write(e.host, rm::kDimX, {4, 5, 6}), tlm::TLM_OK_RESPONSE);
  ASSERT_EQ(write(e.host, rm::kCtrl, {rm::kCtrlStart}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(read(e.host, rm::kStatus), rm::kStatusDone);
  ASSERT_EQ(e.backend.frames.size(), 1u);
  EXPECT_EQ(e.backend.dims_calls, 1);
  EXPECT_EQ(e.backend.volumes[0].dim, (std::array<int, 3>{4, 5, 6}));
  e.backend.is_busy = true;
  EXPECT_EQ(read(e.host, rm::kStatus), rm::kStatusBusy);
  e.backend.is_busy = false;
}

TEST(HostInterface, ResetRestoresEveryResetValue) {
  Env& e = env();
  fresh(e.host, e.backend);
  const SceneSetup s = setup("crop_cut", "{" + kSphere + R"(, "cut_plane": {"normal": [1, 2, 3], "falloff": 2},
      "cropping": {}, "gradient_modulation": {"opacity": true}})");
  sc_time delay = SC_ZERO_TIME;
  program_over_tlm(e.host.target(), s.regs, s.volume, delay);
  reset(e.host);
  golden::Registers expected;
  expected.p = e.host.config().hw.precision;
  expected.classification.assign(size_t{1} << expected.p.voxel_bits, golden::ClassEntry{});
  expect_registers_equal(e.host.decoded(), expected, "after reset");
  EXPECT_EQ(read(e.host, rm::kPerm), 0x24u);  // the identity permutation
  EXPECT_EQ(read(e.host, rm::kSupersampling), 1u);
  EXPECT_EQ(read(e.host, rm::kCropMask), 0x80u);
  EXPECT_EQ(read(e.host, rm::kCutFlags), rm::kCutKeepInside);
  EXPECT_EQ(read(e.host, rm::kVolDim), 0u);
  EXPECT_EQ(read(e.host, rm::kClassBase + 8 * 100), 0u);
  EXPECT_EQ(read(e.host, rm::kGmLutBase + 4 * 3), 0u);
}

// ---- Round trips ------------------------------------------------------------------

TEST(HostInterface, SceneRegistersRoundTripFieldByField) {
  Env& e = env();
  fresh(e.host, e.backend);
  std::set<std::array<int, 3>> perms;
  std::array<bool, 3> flipped{false, false, false};
  std::set<int> blends;
  bool crop = false, cut = false, ss2 = false, gm = false, specular = false;
  // No reset between scenes: each must overwrite everything the last one left.
  for (const SceneSetup& s : default_precision_scenes()) {
    sc_time delay = SC_ZERO_TIME;
    program_over_tlm(e.host.target(), s.regs, s.volume, delay);
    expect_registers_equal(e.host.decoded(), s.regs, s.name);
    EXPECT_EQ(e.backend.volumes[0].dim, s.volume.dim) << s.name;
    EXPECT_EQ(e.backend.volumes[0].data, s.volume.data) << s.name;
    EXPECT_GT(delay, SC_ZERO_TIME);
    ASSERT_EQ(write(e.host, rm::kCtrl, {rm::kCtrlStart}), tlm::TLM_OK_RESPONSE) << s.name;
    expect_registers_equal(e.backend.frames.back(), s.regs, s.name + " (as started)");
    perms.insert(s.regs.perm);
    for (int i = 0; i < 3; ++i) flipped[i] = flipped[i] || s.regs.flip[i];
    blends.insert(static_cast<int>(s.regs.blend));
    crop |= s.regs.crop_enabled;
    cut |= s.regs.cut_enabled;
    ss2 |= s.regs.supersampling == 2;
    gm |= s.regs.gm_opacity && s.regs.gm_diffuse && s.regs.gm_specular;
    specular |= s.regs.specular;
  }
  // The scenes cover what this test claims to.
  EXPECT_GE(perms.size(), 3u);
  EXPECT_EQ(flipped, (std::array<bool, 3>{true, true, true}));
  EXPECT_EQ(blends.size(), 3u);
  EXPECT_TRUE(crop && cut && ss2 && gm && specular);
}

TEST(HostInterface, NarrowPrecisionSceneRoundTrips) {
  Env& e = env();
  fresh(e.host8, e.backend8);
  const SceneSetup s = narrow_scene();
  ASSERT_TRUE(s.regs.specular && s.regs.magnitude);
  sc_time delay = SC_ZERO_TIME;
  program_over_tlm(e.host8.target(), s.regs, s.volume, delay);
  expect_registers_equal(e.host8.decoded(), s.regs, s.name);
  EXPECT_EQ(e.backend8.volumes[0].data, s.volume.data);
  // The field ranges follow this hardware's widths.
  EXPECT_EQ(write(e.host8, rm::kClassBase, {0x40}), tlm::TLM_GENERIC_ERROR_RESPONSE);  // color_bits 6
  EXPECT_EQ(write(e.host8, rm::kClassBase + 4, {0xFFFF}), tlm::TLM_OK_RESPONSE);       // alpha_bits 16
  EXPECT_EQ(write(e.host8, rm::kEye, {511}), tlm::TLM_OK_RESPONSE);                    // eye_bits 10
  EXPECT_EQ(write(e.host8, rm::kEye, {512}), tlm::TLM_GENERIC_ERROR_RESPONSE);
  EXPECT_EQ(write(e.host8, rm::kDimX, {33}), tlm::TLM_GENERIC_ERROR_RESPONSE);        // max_dim 32
  EXPECT_EQ(write(e.host8, rm::kGmLutBase + 4 * 64, {0}), tlm::TLM_ADDRESS_ERROR_RESPONSE);  // 2^6 entries
  EXPECT_EQ(write(e.host8, rm::kDiffuseBase + 4 * 96, {0}), tlm::TLM_ADDRESS_ERROR_RESPONSE);  // 6*4*4
  EXPECT_EQ(write(e.host8, rm::kDiffuseBase + 4 * 95, {0xFFFFF}), tlm::TLM_OK_RESPONSE);  // map_bits 20
  ASSERT_EQ(write(e.host8, rm::kCtrl, {rm::kCtrlReset}), tlm::TLM_OK_RESPONSE);
}

TEST(HostInterface, RandomRegisterSetsRoundTripEveryBit) {
  Env& e = env();
  std::mt19937_64 rng(12345);
  for (HostInterface* h : {&e.host, &e.host8}) {
    TestBackend& b = h == &e.host ? e.backend : e.backend8;
    for (int k = 0; k < 40; ++k) {
      golden::Volume vol;
      const golden::Registers r = random_registers(h->config().hw.precision, rng, vol);
      sc_time delay = SC_ZERO_TIME;
      program_over_tlm(h->target(), r, vol, delay);
      const std::string where = std::string(h->name()) + " set " + std::to_string(k);
      expect_registers_equal(h->decoded(), r, where);
      EXPECT_EQ(b.volumes[0].data, vol.data) << where;
      // Every register word reads back as written.
      for (const RegisterBlock& block : register_blocks(r)) {
        std::vector<uint32_t> back(block.words.size());
        read_words(h->target(), block.addr, back.data(), back.size(), delay);
        EXPECT_EQ(back, block.words) << where << ": " << rm::describe_address(block.addr);
      }
      std::vector<uint32_t> entry(2);
      const size_t i = rng() % r.classification.size();
      read_words(h->target(), rm::kClassBase + 8 * i, entry.data(), 2, delay);
      const golden::ClassEntry& c = r.classification[i];
      EXPECT_EQ(entry, (std::vector<uint32_t>{c.r | uint32_t{c.g} << 8 | uint32_t{c.b} << 16, c.a})) << where;
    }
  }
}

TEST(HostInterface, RegisterWordsReadBackAsWritten) {
  Env& e = env();
  reset(e.host);
  const std::vector<uint32_t> view = {7, 8, 9, 0x12, 0x5, 3, 0xFFFFFFFE, 0x80000000, 1, 2, 3, 4, 5, 6};
  ASSERT_EQ(write(e.host, rm::kDimX, view), tlm::TLM_OK_RESPONSE);
  const Raw r = transact(e.host, tlm::TLM_READ_COMMAND, rm::kDimX, std::vector<uint32_t>(view.size()));
  EXPECT_EQ(r.data, view);
  const golden::Registers d = e.host.decoded();
  EXPECT_EQ(d.perm, (std::array<int, 3>{2, 0, 1}));
  EXPECT_EQ(d.flip, (std::array<bool, 3>{true, false, true}));
  EXPECT_EQ(d.x_start, static_cast<int64_t>(0x80000000FFFFFFFEull));
  ASSERT_EQ(write(e.host, rm::kEye, {static_cast<uint32_t>(-127), 127, 0}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(e.host.decoded().eye, (golden::Eye{-127, 127, 0}));
  ASSERT_EQ(write(e.host, rm::kClassBase + 8 * 5, {0x00030201, 0xABC}), tlm::TLM_OK_RESPONSE);
  const golden::ClassEntry c = e.host.decoded().classification[5];
  EXPECT_EQ((std::array<int, 4>{c.r, c.g, c.b, c.a}), (std::array<int, 4>{1, 2, 3, 0xABC}));
  const uint32_t mode = rm::kModeShading | rm::kModeCut | (2u << rm::kModeBlendShift);
  ASSERT_EQ(write(e.host, rm::kMode, {mode}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(read(e.host, rm::kMode), mode);
  EXPECT_EQ(e.host.decoded().blend, golden::BlendMode::MinIp);
}

// ---- Volume ---------------------------------------------------------------------------

TEST(HostInterface, VolumeLoadWritesEveryVoxelOnceAtItsObjectCoordinate) {
  Env& e = env();
  fresh(e.host, e.backend);
  golden::Volume vol;
  vol.dim = {5, 3, 7};  // 105 voxels: the last word carries padding
  for (int z = 0; z < 7; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 5; ++x) vol.data.push_back(static_cast<uint16_t>(1 + x + 10 * y + 100 * z));
  sc_time delay = SC_ZERO_TIME;
  load_volume_over_tlm(e.host.target(), vol, delay);
  EXPECT_EQ(e.backend.dims_calls, 1);
  ASSERT_EQ(e.backend.volumes[0].dim, vol.dim);
  for (int z = 0; z < 7; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 5; ++x) {
        EXPECT_EQ(e.backend.volumes[0].at(x, y, z), 1 + x + 10 * y + 100 * z) << x << "," << y << "," << z;
        EXPECT_EQ(e.backend.writes_per_voxel[vol.index(x, y, z)], 1);
      }
  // One word by hand: voxel (4,1,2) = index 39 is the high half of the word at byte 2*38.
  ASSERT_EQ(write(e.host, rm::kVolumeBase + 2 * 38, {0x0BBB'0AAA}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(e.backend.volumes[0].at(3, 1, 2), 0xAAA);
  EXPECT_EQ(e.backend.volumes[0].at(4, 1, 2), 0xBBB);
  // The padding half of the last word is ignored, whatever it holds.
  ASSERT_EQ(write(e.host, rm::kVolumeBase + 2 * 104, {0xFFFF'0123}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(e.backend.volumes[0].at(4, 2, 6), 0x123);
  // Same dimensions again: the backend's volume is kept.
  ASSERT_EQ(write(e.host, rm::kVolDim, {5, 3, 7}), tlm::TLM_OK_RESPONSE);
  ASSERT_EQ(write(e.host, rm::kVolumeBase, {0x0001'0002}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(e.backend.dims_calls, 1);
}

// map_volume, the DMI-style load: what the VOLUME window's bursts would
// write (here a backend without in-place mapping copies through
// write_voxels), with their bus time, and nothing for a volume the
// subvolume or the voxel word cannot take.
TEST(HostInterface, MappedVolumeWritesWhatTheBurstsWouldAndAnnotatesTheirTime) {
  Env& e = env();
  golden::Volume vol;
  vol.dim = {5, 3, 7};
  for (int i = 0; i < 105; ++i) vol.data.push_back(static_cast<uint16_t>(7 * i % 4096));
  fresh(e.host, e.backend);
  sc_time bus = SC_ZERO_TIME;
  load_volume_over_tlm(e.host.target(), vol, bus);
  const golden::Volume by_bus = e.backend.volumes[0];

  fresh(e.host, e.backend);
  sc_time delay = SC_ZERO_TIME;
  set_subvolume_dims_over_tlm(e.host.target(), 0, vol.dim, delay);
  const sc_time dims_time = delay;
  e.host.map_volume(vol, delay);
  select_subvolume_over_tlm(e.host.target(), 0, delay);
  EXPECT_EQ(delay, bus) << "the same bus time as the bursts";
  EXPECT_EQ(delay - dims_time - e.host.config().bus_period * 2.0,
            volume_load_bus_time(vol.size(), e.host.config().bus_period));
  EXPECT_EQ(e.backend.volumes[0].data, by_bus.data);
  EXPECT_EQ(std::count(e.backend.writes_per_voxel.begin(), e.backend.writes_per_voxel.end(), 1), 105);
  e.host.unmap_volume();

  // Refused, nothing written: other dims, a voxel wider than the word.
  fresh(e.host, e.backend);
  set_subvolume_dims_over_tlm(e.host.target(), 0, {5, 3, 6}, delay);
  EXPECT_THROW(e.host.map_volume(vol, delay), std::invalid_argument);
  set_subvolume_dims_over_tlm(e.host.target(), 0, vol.dim, delay);
  golden::Volume wide = vol;
  wide.data[17] = 4096;
  EXPECT_THROW(e.host.map_volume(wide, delay), std::invalid_argument);
  EXPECT_EQ(std::count(e.backend.writes_per_voxel.begin(), e.backend.writes_per_voxel.end(), 0),
            static_cast<std::ptrdiff_t>(e.backend.writes_per_voxel.size()));
  fresh(e.host, e.backend);
}

// ---- Base plane -----------------------------------------------------------------------

// Subvolumes and slabs (VolumePro §4.2): several volumes resident at once,
// START renders the one VOL_SELECT names, and voxels, slices and boxes are
// written and read back through the slab window without touching anything
// else; the voxel memory refuses a size that leaves no room.
TEST(HostInterface, SubvolumesAndSlabsReadAndWriteOnlyTheirVoxels) {
  Env& e = env();
  fresh(e.host, e.backend);
  sc_time delay = SC_ZERO_TIME;
  golden::Volume a, b;
  a.dim = {10, 8, 6};
  b.dim = {5, 7, 3};
  for (golden::Volume* v : {&a, &b}) {
    v->data.resize(v->size());
    for (size_t i = 0; i < v->size(); ++i) v->data[i] = static_cast<uint16_t>((i * 37 + v->dim[0]) % 4096);
  }
  load_subvolume_over_tlm(e.host.target(), 0, a, delay);
  load_subvolume_over_tlm(e.host.target(), 5, b, delay);
  EXPECT_EQ(e.backend.volumes[0].data, a.data);
  EXPECT_EQ(e.backend.volumes[5].data, b.data);
  // START renders the selected subvolume.
  ASSERT_EQ(write(e.host, rm::kDimX, {5, 7, 3}), tlm::TLM_OK_RESPONSE);
  select_subvolume_over_tlm(e.host.target(), 5, delay);
  start_frame_over_tlm(e.host.target(), delay);
  ASSERT_EQ(e.backend.rendered, std::vector<int>{5});
  // A box, a slice and a voxel of subvolume 0; subvolume 5 untouched.
  golden::Volume want = a;
  const std::array<int, 3> o{2, 3, 1}, n{5, 4, 3};
  std::vector<uint16_t> box(static_cast<size_t>(n[0]) * n[1] * n[2]);
  for (size_t i = 0; i < box.size(); ++i) box[i] = static_cast<uint16_t>(4000 - i);
  write_slab_over_tlm(e.host.target(), 0, o, n, box, delay);
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x)
        want.data[want.index(o[0] + x, o[1] + y, o[2] + z)] = box[(static_cast<size_t>(z) * n[1] + y) * n[0] + x];
  std::vector<uint16_t> slice(10 * 8, 77);
  write_slab_over_tlm(e.host.target(), 0, {0, 0, 5}, {10, 8, 1}, slice, delay);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 10; ++x) want.data[want.index(x, y, 5)] = 77;
  write_slab_over_tlm(e.host.target(), 0, {9, 7, 0}, {1, 1, 1}, {1234}, delay);
  want.data[want.index(9, 7, 0)] = 1234;
  EXPECT_EQ(e.backend.volumes[0].data, want.data);
  EXPECT_EQ(e.backend.volumes[5].data, b.data);
  EXPECT_EQ(read_slab_over_tlm(e.host.target(), 0, o, n, delay), box);
  EXPECT_EQ(read_slab_over_tlm(e.host.target(), 0, {9, 7, 0}, {1, 1, 1}, delay), std::vector<uint16_t>{1234});
  EXPECT_EQ(read_slab_over_tlm(e.host.target(), 5, {0, 0, 0}, {5, 7, 3}, delay), b.data);
  EXPECT_EQ(read(e.host, rm::kStatus) & rm::kStatusError, 0u);
  // The small voxel memory of host8 (2·32³ voxels): two full subvolumes
  // fit, a third does not, and the refused write leaves the size unset.
  fresh(e.host8, e.backend8);
  for (uint32_t k = 0; k < 2; ++k) {
    ASSERT_EQ(write(e.host8, rm::kVolIndex, {k}), tlm::TLM_OK_RESPONSE);
    ASSERT_EQ(write(e.host8, rm::kVolDim, {32, 32, 32}), tlm::TLM_OK_RESPONSE);
  }
  ASSERT_EQ(write(e.host8, rm::kVolIndex, {2}), tlm::TLM_OK_RESPONSE);
  ASSERT_EQ(write(e.host8, rm::kVolDim, {1, 1}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(write(e.host8, rm::kVolDim + 8, {1}), tlm::TLM_GENERIC_ERROR_RESPONSE);
  EXPECT_EQ(read(e.host8, rm::kLastError), static_cast<uint32_t>(ErrorCode::VoxelMemoryFull));
  EXPECT_EQ(read(e.host8, rm::kVolDim + 8), 0u);
  // Shrinking subvolume 1 makes room.
  ASSERT_EQ(write(e.host8, rm::kVolIndex, {1}), tlm::TLM_OK_RESPONSE);
  ASSERT_EQ(write(e.host8, rm::kVolDim + 8, {31}), tlm::TLM_OK_RESPONSE);
  ASSERT_EQ(write(e.host8, rm::kVolIndex, {2}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(write(e.host8, rm::kVolDim + 8, {1}), tlm::TLM_OK_RESPONSE);
}

TEST(HostInterface, BasePlaneReadReturnsWhatTheBackendHolds) {
  Env& e = env();
  fresh(e.host, e.backend);
  const SceneSetup s = default_precision_scenes()[0];
  std::mt19937 rng(7);
  e.backend.plane.width = s.regs.base_width();
  e.backend.plane.height = s.regs.base_height();
  e.backend.plane.rgba.resize(size_t{4} * e.backend.plane.width * e.backend.plane.height);
  for (auto& c : e.backend.plane.rgba) c = static_cast<uint16_t>(rng() & 0xFFF);
  sc_time delay = SC_ZERO_TIME;
  const golden::BasePlane bp = read_base_plane_over_tlm(e.host.target(), s.regs, delay);
  EXPECT_EQ(bp.width, e.backend.plane.width);
  EXPECT_EQ(bp.height, e.backend.plane.height);
  EXPECT_EQ(bp.rgba, e.backend.plane.rgba);
  // Pixel (3, 2) by hand: {r | g<<16, b | a<<16}.
  const size_t i = 2 * static_cast<size_t>(bp.width) + 3;
  const Raw px = transact(e.host, tlm::TLM_READ_COMMAND, rm::kBaseBase + 8 * i, {0, 0});
  const uint16_t* c = &bp.rgba[4 * i];
  EXPECT_EQ(px.data, (std::vector<uint32_t>{c[0] | uint32_t{c[1]} << 16, c[2] | uint32_t{c[3]} << 16}));
}

TEST(HostInterface, FramesRenderedFromDecodedRegistersEqualTheGoldenBasePlane) {
  Env& e = env();
  std::vector<SceneSetup> scenes = default_precision_scenes();
  for (const SceneSetup& s : {scenes[0], scenes[2], scenes[3]}) {
    fresh(e.host, e.backend);
    e.backend.render = true;
    sc_time delay = SC_ZERO_TIME;
    program_over_tlm(e.host.target(), s.regs, s.volume, delay);
    start_frame_over_tlm(e.host.target(), delay);
    EXPECT_EQ(read_status_over_tlm(e.host.target(), delay), rm::kStatusDone);
    const golden::BasePlane got = read_base_plane_over_tlm(e.host.target(), s.regs, delay);
    const golden::BasePlane want = golden::render_fixed(s.volume, s.regs);
    EXPECT_EQ(got.width, want.width) << s.name;
    EXPECT_EQ(got.height, want.height) << s.name;
    EXPECT_EQ(got.bits, want.bits) << s.name;
    EXPECT_EQ(got.shift_x, want.shift_x) << s.name;
    EXPECT_EQ(got.shift_y, want.shift_y) << s.name;
    EXPECT_EQ(got.rgba, want.rgba) << s.name;
    int64_t alpha = 0;
    for (size_t i = 3; i < got.rgba.size(); i += 4) alpha += got.rgba[i];
    EXPECT_GT(alpha, 0) << s.name << ": an empty image would prove little";
  }
  e.backend.render = false;
}

// ---- Polygon images (Cube-5) ---------------------------------------------------------

namespace {

// A translucent box and sphere and an opaque box around a 24³ sphere, rasterised for the
// interface's four pipelines: margins, blank and covered pixels, Z, and
// slab images with runs and pixels in every lane.
struct PolygonSetup {
  golden::Volume volume;
  golden::HostProgram host;
  golden::PolygonFrame frame;
};

PolygonSetup polygon_setup() {
  const golden::Scene s = golden::parse_scene(R"({
    "volume": {"synthetic": "sphere", "size": [24, 24, 24]},
    "pipelines": 4,
    "view": {"rotate": [20, 30, 0]},
    "polygons": [
      {"shape": "box", "size": [60, 10, 10], "transform": {"translate": [12, 12, 12]}, "color": [1, 0.5, 0.2], "opacity": 0.4},
      {"shape": "box", "size": [6, 6, 30], "transform": {"translate": [12, 4, 12]}, "color": [0.2, 0.8, 0.2]},
      {"shape": "sphere", "radius": 5, "transform": {"translate": [9, 15, 12]}, "color": [0.9, 0.9, 0.2], "opacity": 0.6}
    ]})", "polygons.json");
  PolygonSetup r;
  r.volume = golden::load_volume(s.volume, s.precision.voxel_bits, ".");
  const std::vector<golden::Mesh> meshes = golden::load_meshes(s, ".");
  r.host = golden::program_host(s, r.volume, meshes);
  r.frame = golden::rasterise_polygons(s, meshes, r.host);
  return r;
}

void expect_frames_equal(const golden::PolygonFrame& want, const golden::PolygonFrame& got) {
  ASSERT_EQ(got.width, want.width);
  ASSERT_EQ(got.height, want.height);
  const auto same_pixel = [](const golden::Pixel& a, const golden::Pixel& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
  };
  expect_table_equal(want.front, got.front, same_pixel, "front");
  expect_table_equal(want.back, got.back, same_pixel, "back");
  expect_table_equal(want.z, got.z, [](uint32_t a, uint32_t b) { return a == b; }, "z");
  ASSERT_EQ(got.slabs.size(), want.slabs.size());
  for (size_t k = 0; k < want.slabs.size(); ++k) {
    const golden::SlabImage &w = want.slabs[k], &g = got.slabs[k];
    ASSERT_EQ(g.empty(), w.empty()) << "slab " << k;
    // Empty or not, a slab has the beams' shape (the RTL decoders check it).
    ASSERT_EQ(g.width(), w.width()) << "slab " << k;
    ASSERT_EQ(g.beams(), w.beams()) << "slab " << k;
    ASSERT_EQ(g.lanes(), w.lanes()) << "slab " << k;
    if (w.empty()) continue;
    for (int y = 0; y < w.beams(); ++y)
      for (int l = 0; l < w.lanes(); ++l) ASSERT_EQ(g.line(y, l), w.line(y, l)) << "slab " << k << " beam " << y << " lane " << l;
  }
}

void start_polygon_frame(Env& e, const PolygonSetup& s, sc_time& delay) {
  program_over_tlm(e.host.target(), s.host.regs, s.volume, delay);
  write_polygons_over_tlm(e.host.target(), &s.frame, delay);
  start_frame_over_tlm(e.host.target(), delay);
}

}  // namespace

// The bus time of a mapped load counts each slab's stream words from the
// image's kept totals; they must be the words the windows would carry.
TEST(HostInterface, SlabStreamWordsAreTheEncodedStreamsLength) {
  const PolygonSetup s = polygon_setup();
  std::mt19937 gen(3);
  std::vector<golden::SlabImage> slabs = s.frame.slabs;
  for (int width : {1, 6, 13})
    for (int lanes : {1, 3, 4}) {
      golden::SlabImage slab(width, 4, lanes);
      const golden::Precision p;
      for (int i = 0; i < 30; ++i) {
        const auto c = static_cast<uint16_t>(std::uniform_int_distribution<int>(1, 65535)(gen));
        slab.insert(std::uniform_int_distribution<int>(0, width - 1)(gen), i % 4, golden::Pixel{c, c, c, c}, p);
      }
      slabs.push_back(slab);
    }
  for (size_t k = 0; k < slabs.size(); ++k)
    EXPECT_EQ(slab_stream_words(slabs[k]), encode_slab_stream(slabs[k]).size()) << "slab " << k;
}

// map_polygons, the DMI-style load: the frame START hands the backend is
// the one the windows would have decoded, with the windows' bus time; a
// window write after it makes the images the buffer's words (and lands);
// images the sizes or the word widths refuse are not mapped.
TEST(HostInterface, MappedPolygonsAreTheWindowsWithoutTheCopy) {
  Env& e = env();
  const PolygonSetup s = polygon_setup();
  const PolygonMap map = [&e](const golden::PolygonFrame& f, sc_time& d) { e.host.map_polygons(f, d); };
  auto images_time = [&](const PolygonMap& m) {
    fresh(e.host, e.backend);
    sc_time delay = SC_ZERO_TIME;
    program_over_tlm(e.host.target(), s.host.regs, s.volume, delay);
    const sc_time before = delay;
    write_polygons_over_tlm(e.host.target(), &s.frame, delay, m);
    return delay - before;
  };
  const sc_time by_bus = images_time({});
  const sc_time mapped = images_time(map);
  EXPECT_EQ(mapped, by_bus);
  // Besides the images: the sizes (one transaction of three words) and
  // POLY_ENABLE (one of one), 4 + 2 bus cycles.
  EXPECT_EQ(mapped - e.host.config().bus_period * 6.0,
            polygon_load_bus_time(s.frame, e.host.config().bus_period));
  sc_time delay = SC_ZERO_TIME;
  start_frame_over_tlm(e.host.target(), delay);
  ASSERT_EQ(e.backend.polygons.size(), 1u);
  ASSERT_TRUE(e.backend.polygons[0].has_value());
  expect_frames_equal(s.frame, *e.backend.polygons[0]);

  // A front pixel written after the mapping.
  images_time(map);
  const size_t i = s.frame.front.size() / 2;
  golden::PolygonFrame changed = s.frame;
  changed.front[i] = golden::Pixel{1, 2, 3, 4};
  ASSERT_EQ(write(e.host, rm::kPolyFrontBase + 8 * i, {0x0002'0001, 0x0004'0003}), tlm::TLM_OK_RESPONSE);
  start_frame_over_tlm(e.host.target(), delay);
  ASSERT_TRUE(e.backend.polygons.back().has_value());
  expect_frames_equal(changed, *e.backend.polygons.back());

  // Refused: other sizes, a depth beyond kZNone.
  fresh(e.host, e.backend);
  program_over_tlm(e.host.target(), s.host.regs, s.volume, delay);
  const uint32_t wrong[3] = {static_cast<uint32_t>(s.frame.width + 1), static_cast<uint32_t>(s.frame.height),
                             static_cast<uint32_t>(s.frame.slabs.size())};
  write_words(e.host.target(), rm::kPolySize, wrong, 3, delay);
  EXPECT_THROW(e.host.map_polygons(s.frame, delay), std::invalid_argument);
  golden::PolygonFrame deep = s.frame;
  deep.z[3] = golden::kZNone + 1;
  const uint32_t right[3] = {static_cast<uint32_t>(s.frame.width), static_cast<uint32_t>(s.frame.height),
                             static_cast<uint32_t>(s.frame.slabs.size())};
  write_words(e.host.target(), rm::kPolySize, right, 3, delay);
  try {
    e.host.map_polygons(deep, delay);
    ADD_FAILURE() << "a depth beyond kZNone was mapped";
  } catch (const std::invalid_argument& x) {
    EXPECT_NE(std::string(x.what()).find("pixel 3 has a depth above kZNone"), std::string::npos) << x.what();
  }
  fresh(e.host, e.backend);
}

TEST(HostInterface, PolygonImagesReachTheFrameAsWrittenAndAreConsumedByIt) {
  Env& e = env();
  fresh(e.host, e.backend);
  const PolygonSetup s = polygon_setup();
  size_t slabs_with_fragments = 0;
  for (const golden::SlabImage& slab : s.frame.slabs) slabs_with_fragments += !slab.empty();
  ASSERT_GT(slabs_with_fragments, 0u) << "a frame without slab images would prove little";
  // Lanes that differ, so that a decoder mixing them up shows.
  bool lanes_differ = false;
  for (const golden::SlabImage& slab : s.frame.slabs)
    for (int y = 0; !slab.empty() && y < slab.beams(); ++y) lanes_differ |= slab.line(y, 0) != slab.line(y, 1);
  ASSERT_TRUE(lanes_differ);
  ASSERT_GT(s.frame.counts.opaque, 0u);
  ASSERT_GT(s.host.regs.margin_lo[0] + s.host.regs.margin_hi[0] + s.host.regs.margin_lo[1] + s.host.regs.margin_hi[1], 0)
      << "the boxes should reach past the volume's rays";

  sc_time delay = SC_ZERO_TIME;
  start_polygon_frame(e, s, delay);
  ASSERT_EQ(e.backend.polygons.size(), 1u);
  ASSERT_TRUE(e.backend.polygons[0].has_value());
  expect_frames_equal(s.frame, *e.backend.polygons[0]);

  // START consumed them: the next frame (POLY_ENABLE still set) gets blank images.
  start_frame_over_tlm(e.host.target(), delay);
  ASSERT_EQ(e.backend.polygons.size(), 2u);
  ASSERT_TRUE(e.backend.polygons[1].has_value());
  golden::PolygonFrame blank;
  blank.width = s.frame.width;
  blank.height = s.frame.height;
  blank.front.resize(s.frame.front.size());
  blank.back.resize(s.frame.back.size());
  blank.z.assign(s.frame.z.size(), golden::kZNone);
  blank.slabs.assign(s.frame.slabs.size(), golden::SlabImage(s.frame.slabs[0].width(), s.frame.slabs[0].beams(),
                                                             s.frame.slabs[0].lanes()));
  expect_frames_equal(blank, *e.backend.polygons[1]);

  // Without polygons the host clears POLY_ENABLE and the frame gets none.
  write_polygons_over_tlm(e.host.target(), nullptr, delay);
  start_frame_over_tlm(e.host.target(), delay);
  ASSERT_EQ(e.backend.polygons.size(), 3u);
  EXPECT_FALSE(e.backend.polygons[2].has_value());
  fresh(e.host, e.backend);
}

TEST(HostInterface, PolygonWindowsRefuseWhatTheFrameCannotTake) {
  Env& e = env();
  const PolygonSetup s = polygon_setup();
  const int w = s.frame.width, h = s.frame.height, slices = static_cast<int>(s.frame.slabs.size());
  auto last_error = [&e] {
    return std::pair{static_cast<ErrorCode>(read(e.host, rm::kLastError)),
                     read(e.host, rm::kErrorAddrLo) | uint64_t{read(e.host, rm::kErrorAddrHi)} << 32};
  };
  auto sized = [&](int width, int height, int k) {
    fresh(e.host, e.backend);
    sc_time delay = SC_ZERO_TIME;
    program_over_tlm(e.host.target(), s.host.regs, s.volume, delay);
    const uint32_t size[3] = {static_cast<uint32_t>(width), static_cast<uint32_t>(height), static_cast<uint32_t>(k)};
    write_words(e.host.target(), rm::kPolySize, size, 3, delay);
    write_word(e.host.target(), rm::kPolyEnable, 1, delay);
  };
  const uint64_t pixels = uint64_t(w) * h;

  // Past the images' size, in each window.
  sized(w, h, slices);
  EXPECT_EQ(write(e.host, rm::kPolyZBase + 4 * pixels, {0}), tlm::TLM_GENERIC_ERROR_RESPONSE);
  EXPECT_EQ(last_error(), std::pair(ErrorCode::PolygonSize, rm::kPolyZBase + 4 * pixels));
  EXPECT_EQ(write(e.host, rm::kPolyFrontBase + 8 * pixels - 4, {0, 0}), tlm::TLM_GENERIC_ERROR_RESPONSE);
  EXPECT_EQ(last_error(), std::pair(ErrorCode::PolygonSize, rm::kPolyFrontBase + 8 * pixels));
  const uint64_t past_slices = rm::kPolySlabBase + uint64_t(slices) * rm::kPolySlabStride;
  EXPECT_EQ(write(e.host, past_slices, {0}), tlm::TLM_GENERIC_ERROR_RESPONSE);
  EXPECT_EQ(last_error(), std::pair(ErrorCode::PolygonSize, past_slices));
  // A value wider than its field: Z past kZNone. (A colour channel past
  // alpha_bits is refused too, but at this hardware's 16 bits every
  // 16-bit half fits.)
  EXPECT_EQ(write(e.host, rm::kPolyZBase + 4, {golden::kZNone + 1}), tlm::TLM_GENERIC_ERROR_RESPONSE);
  EXPECT_EQ(last_error(), std::pair(ErrorCode::FieldRange, rm::kPolyZBase + 4));
  // Write-only, and not while a frame runs.
  EXPECT_EQ(transact(e.host, tlm::TLM_READ_COMMAND, rm::kPolyZBase, {0}).status, tlm::TLM_COMMAND_ERROR_RESPONSE);
  EXPECT_EQ(last_error().first, ErrorCode::WriteOnly);
  e.backend.is_busy = true;
  EXPECT_EQ(write(e.host, rm::kPolyZBase, {0}), tlm::TLM_GENERIC_ERROR_RESPONSE);
  EXPECT_EQ(last_error().first, ErrorCode::Busy);
  e.backend.is_busy = false;

  // START with images of another size than the frame's: refused, no frame.
  for (const auto& [size, reg] : {std::pair{std::array{w + 1, h, slices}, rm::kPolySize},
                                  std::pair{std::array{w, h - 1, slices}, rm::kPolySize + 4},
                                  std::pair{std::array{w, h, slices + 1}, rm::kPolySize + 8}}) {
    sized(size[0], size[1], size[2]);
    EXPECT_EQ(transact(e.host, tlm::TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}).status,
              tlm::TLM_GENERIC_ERROR_RESPONSE);
    EXPECT_EQ(last_error(), std::pair(ErrorCode::PolygonSize, reg));
    EXPECT_TRUE(e.backend.frames.empty());
  }

  // Malformed slab lines: each refuses START naming the first word of the line at fault.
  const golden::SlabImage* slab = nullptr;
  size_t k = 0;
  for (; k < s.frame.slabs.size() && !slab; ++k)
    if (!s.frame.slabs[k].empty()) slab = &s.frame.slabs[k];
  ASSERT_NE(slab, nullptr);
  --k;
  const std::vector<uint32_t> good = encode_slab_stream(*slab);
  const uint64_t base = rm::kPolySlabBase + k * rm::kPolySlabStride;
  struct Bad {
    const char* what;
    std::vector<uint32_t> stream;
    uint64_t addr;
  };
  std::vector<Bad> bad;
  {
    std::vector<uint32_t> short_line = good;  // the first line claims one pixel flit less
    short_line[0] -= 4;
    bad.push_back({"a line without its last pixel", short_line, base});
    std::vector<uint32_t> truncated(good.begin(), good.end() - 1);
    size_t at = 0, last = 0;
    while (at < truncated.size()) last = at, at += 1 + (truncated[at] + 1) / 2;
    bad.push_back({"a stream ending inside its last line", truncated, base + 4 * last});
    std::vector<uint32_t> extra = good;
    extra.push_back(0);
    bad.push_back({"a word past the last line", extra, base + 4 * good.size()});
  }
  for (const Bad& b : bad) {
    SCOPED_TRACE(b.what);
    sized(w, h, slices);
    sc_time delay = SC_ZERO_TIME;
    write_words(e.host.target(), base, b.stream.data(), b.stream.size(), delay);
    EXPECT_EQ(transact(e.host, tlm::TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}).status,
              tlm::TLM_GENERIC_ERROR_RESPONSE);
    EXPECT_EQ(last_error(), std::pair(ErrorCode::PolygonImage, b.addr));
    EXPECT_TRUE(e.backend.frames.empty());
  }
  // The same stream as encoded is taken.
  sized(w, h, slices);
  sc_time delay = SC_ZERO_TIME;
  write_words(e.host.target(), base, good.data(), good.size(), delay);
  start_frame_over_tlm(e.host.target(), delay);
  ASSERT_EQ(e.backend.polygons.size(), 1u);
  ASSERT_TRUE(e.backend.polygons[0].has_value());
  EXPECT_EQ(e.backend.polygons[0]->slabs[k].line(0, 0), slab->line(0, 0));
  fresh(e.host, e.backend);
}

// ---- Errors ---------------------------------------------------------------------------

namespace {

struct ErrorCase {
  std::string name;
  std::function<void(Env&)> prepare;  // after reset, before the transaction
  tlm::tlm_command cmd;
  uint64_t addr;
  std::vector<uint32_t> data;
  unsigned len = 0;
  bool byte_enables = false;
  unsigned streaming = 0;
  tlm::tlm_response_status status;
  ErrorCode code;
  uint64_t error_addr;
};

void set_volume_and_view(Env& e, std::vector<uint32_t> dims) {
  ASSERT_EQ(write(e.host, rm::kVolDim, dims), tlm::TLM_OK_RESPONSE);
  ASSERT_EQ(write(e.host, rm::kDimX, dims), tlm::TLM_OK_RESPONSE);
}

std::vector<ErrorCase> error_cases() {
  using tlm::TLM_READ_COMMAND;
  using tlm::TLM_WRITE_COMMAND;
  const auto none = [](Env&) {};
  const auto dims = [](Env& e) { set_volume_and_view(e, {10, 10, 10}); };
  const auto busy = [](Env& e) { set_volume_and_view(e, {10, 10, 10}); e.backend.is_busy = true; };
  const auto addr_err = tlm::TLM_ADDRESS_ERROR_RESPONSE;
  const auto burst = tlm::TLM_BURST_ERROR_RESPONSE;
  const auto cmd_err = tlm::TLM_COMMAND_ERROR_RESPONSE;
  const auto gen = tlm::TLM_GENERIC_ERROR_RESPONSE;
  const uint64_t class_end = rm::kClassBase + 8 * 4096;
  return {
      {"hole in register space", none, TLM_READ_COMMAND, 0x00C, {0}, 0, false, 0, addr_err, ErrorCode::Unmapped, 0x00C},
      {"write to a hole", none, TLM_WRITE_COMMAND, 0x148, {0}, 0, false, 0, addr_err, ErrorCode::Unmapped, 0x148},
      {"burst into a hole", none, TLM_WRITE_COMMAND, rm::kCropSlab - 4, {0, 0}, 0, false, 0, addr_err, ErrorCode::Unmapped, rm::kCropSlab - 4},
      {"between windows", none, TLM_READ_COMMAND, 0x5000, {0}, 0, false, 0, addr_err, ErrorCode::Unmapped, 0x5000},
      {"class entry past 2^voxel_bits", none, TLM_WRITE_COMMAND, class_end, {0}, 0, false, 0, addr_err, ErrorCode::Unmapped, class_end},
      {"burst past the class table", none, TLM_WRITE_COMMAND, class_end - 8, {0, 0, 0, 0}, 0, false, 0, addr_err, ErrorCode::Unmapped, class_end},
      {"voxel past max_dim^3", none, TLM_WRITE_COMMAND, rm::kVolumeBase + 2 * 64 * 64 * 64, {0}, 0, false, 0, addr_err, ErrorCode::Unmapped, rm::kVolumeBase + 2 * 64 * 64 * 64},
      {"beyond the slab window", none, TLM_READ_COMMAND, rm::kSlabBase + rm::kSlabSize, {0}, 0, false, 0, addr_err, ErrorCode::Unmapped, rm::kSlabBase + rm::kSlabSize},
      {"slab past max_dim^3", none, TLM_READ_COMMAND, rm::kSlabBase + 2 * 64 * 64 * 64, {0}, 0, false, 0, addr_err, ErrorCode::Unmapped, rm::kSlabBase + 2 * 64 * 64 * 64},
      {"length 3", none, TLM_WRITE_COMMAND, rm::kMode, {0}, 3, false, 0, burst, ErrorCode::Alignment, rm::kMode},
      {"length 6", none, TLM_READ_COMMAND, rm::kDimX, {0, 0}, 6, false, 0, burst, ErrorCode::Alignment, rm::kDimX},
      {"unaligned address", none, TLM_READ_COMMAND, rm::kDimX + 2, {0}, 0, false, 0, burst, ErrorCode::Alignment, rm::kDimX + 2},
      {"streaming width", none, TLM_WRITE_COMMAND, rm::kDimX, {1, 1}, 0, false, 4, burst, ErrorCode::Streaming, rm::kDimX},
      {"byte enables", none, TLM_WRITE_COMMAND, rm::kDimX, {1}, 0, true, 0, tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE, ErrorCode::ByteEnable, rm::kDimX},
      {"CTRL in a burst", none, TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlClearError, 0}, 0, false, 0, burst, ErrorCode::CtrlInBurst, rm::kCtrl},
      {"write STATUS", none, TLM_WRITE_COMMAND, rm::kStatus, {0}, 0, false, 0, cmd_err, ErrorCode::ReadOnly, rm::kStatus},
      {"write FRAME_COUNT", none, TLM_WRITE_COMMAND, rm::kFrameCountLo, {0}, 0, false, 0, cmd_err, ErrorCode::ReadOnly, rm::kFrameCountLo},
      {"write ID_MAGIC", none, TLM_WRITE_COMMAND, rm::kIdMagic, {0}, 0, false, 0, cmd_err, ErrorCode::ReadOnly, rm::kIdMagic},
      {"write a precision register", none, TLM_WRITE_COMMAND, rm::kPrecision + 8, {20}, 0, false, 0, cmd_err, ErrorCode::ReadOnly, rm::kPrecision + 8},
      {"write the base plane", none, TLM_WRITE_COMMAND, rm::kBaseBase, {0}, 0, false, 0, cmd_err, ErrorCode::ReadOnly, rm::kBaseBase},
      {"read the volume", dims, TLM_READ_COMMAND, rm::kVolumeBase, {0}, 0, false, 0, cmd_err, ErrorCode::WriteOnly, rm::kVolumeBase},
      {"perm not a permutation", none, TLM_WRITE_COMMAND, rm::kPerm, {0x00}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kPerm},
      {"perm axis 3", none, TLM_WRITE_COMMAND, rm::kPerm, {0x0D}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kPerm},
      {"perm reserved bits", none, TLM_WRITE_COMMAND, rm::kPerm, {0x64}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kPerm},
      {"dim 0", none, TLM_WRITE_COMMAND, rm::kDimY, {0}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kDimY},
      {"dim > max_dim", none, TLM_WRITE_COMMAND, rm::kDimZ, {65}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kDimZ},
      {"volume dim > max_dim", none, TLM_WRITE_COMMAND, rm::kVolDim, {1, 65, 1}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kVolDim + 4},
      {"supersampling 0", none, TLM_WRITE_COMMAND, rm::kSupersampling, {0}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kSupersampling},
      {"supersampling 9", none, TLM_WRITE_COMMAND, rm::kSupersampling, {9}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kSupersampling},
      {"flip bit 3", none, TLM_WRITE_COMMAND, rm::kFlip, {8}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kFlip},
      {"blend mode 3", none, TLM_WRITE_COMMAND, rm::kMode, {3u << rm::kModeBlendShift}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kMode},
      {"mode reserved bit", none, TLM_WRITE_COMMAND, rm::kMode, {1u << 7}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kMode},
      {"crop mask 9 bits", none, TLM_WRITE_COMMAND, rm::kCropMask, {0x100}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kCropMask},
      {"cut flags bit 1", none, TLM_WRITE_COMMAND, rm::kCutFlags, {2}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kCutFlags},
      {"ke wider than coef_bits", none, TLM_WRITE_COMMAND, rm::kKe, {1u << 10}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kKe},
      {"specular colour wider than alpha_bits", none, TLM_WRITE_COMMAND, rm::kSpecularColor + 8, {1u << golden::Precision{}.alpha_bits}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kSpecularColor + 8},
      {"eye +128", none, TLM_WRITE_COMMAND, rm::kEye, {128}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kEye},
      {"eye -128", none, TLM_WRITE_COMMAND, rm::kEye + 4, {static_cast<uint32_t>(-128)}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kEye + 4},
      {"eye not sign-extended", none, TLM_WRITE_COMMAND, rm::kEye + 8, {0xFF}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kEye + 8},
      {"class word bits 31:24", none, TLM_WRITE_COMMAND, rm::kClassBase, {0x0001'0000, 0, 0x0100'0000, 0}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kClassBase + 8},
      {"class alpha wider than alpha_bits", none, TLM_WRITE_COMMAND, rm::kClassBase + 4, {1u << golden::Precision{}.alpha_bits}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kClassBase + 4},
      {"GmLUT wider than gmlut_bits", none, TLM_WRITE_COMMAND, rm::kGmLutBase, {0x100}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kGmLutBase},
      {"map wider than map_bits", none, TLM_WRITE_COMMAND, rm::kSpecularBase + 4, {0x10000}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kSpecularBase + 4},
      {"CTRL reserved bit", none, TLM_WRITE_COMMAND, rm::kCtrl, {8}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kCtrl},
      {"voxel wider than voxel_bits", dims, TLM_WRITE_COMMAND, rm::kVolumeBase, {0, 0x1000'0000}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kVolumeBase + 4},
      {"voxel past the volume", dims, TLM_WRITE_COMMAND, rm::kVolumeBase + 2 * 998, {0, 0}, 0, false, 0, gen, ErrorCode::VoxelOutOfVolume, rm::kVolumeBase + 2 * 1000},
      {"volume before VOL_DIM", none, TLM_WRITE_COMMAND, rm::kVolumeBase, {0}, 0, false, 0, gen, ErrorCode::VolumeDimsUnset, rm::kVolumeBase},
      {"subvolume 8", none, TLM_WRITE_COMMAND, rm::kVolIndex, {8}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kVolIndex},
      {"select subvolume 8", none, TLM_WRITE_COMMAND, rm::kVolSelect, {8}, 0, false, 0, gen, ErrorCode::FieldRange, rm::kVolSelect},
      {"slab before VOL_DIM", none, TLM_WRITE_COMMAND, rm::kSlabBase, {0}, 0, false, 0, gen, ErrorCode::VolumeDimsUnset, rm::kSlabBase},
      {"empty slab", dims, TLM_READ_COMMAND, rm::kSlabBase, {0}, 0, false, 0, gen, ErrorCode::SlabOutOfVolume, rm::kSlabBase},
      {"slab past its subvolume",
       [](Env& e) { set_volume_and_view(e, {10, 10, 10});
                    ASSERT_EQ(write(e.host, rm::kSlab, {8, 0, 0, 3, 1, 1}), tlm::TLM_OK_RESPONSE); },
       TLM_WRITE_COMMAND, rm::kSlabBase, {0}, 0, false, 0, gen, ErrorCode::SlabOutOfVolume, rm::kSlabBase},
      {"voxel past the slab",
       [](Env& e) { set_volume_and_view(e, {10, 10, 10});
                    ASSERT_EQ(write(e.host, rm::kSlab, {1, 2, 3, 2, 1, 1}), tlm::TLM_OK_RESPONSE); },
       TLM_WRITE_COMMAND, rm::kSlabBase, {0, 0}, 0, false, 0, gen, ErrorCode::SlabOutOfVolume, rm::kSlabBase + 4},
      {"START of a subvolume without VOL_DIM",
       [](Env& e) { set_volume_and_view(e, {10, 10, 10});
                    ASSERT_EQ(write(e.host, rm::kVolSelect, {3}), tlm::TLM_OK_RESPONSE); },
       TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::VolumeDimsUnset, rm::kCtrl},
      {"START before VOL_DIM", none, TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::VolumeDimsUnset, rm::kCtrl},
      {"START with view and volume apart",
       [](Env& e) { ASSERT_EQ(write(e.host, rm::kVolDim, {10, 10, 10}), tlm::TLM_OK_RESPONSE);
                    ASSERT_EQ(write(e.host, rm::kDimX, {10, 10, 11}), tlm::TLM_OK_RESPONSE); },
       TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::ViewMismatch, rm::kCtrl},
      // A start far into x (a block's may be deep): the rays' last offset
      // puts the base plane past BASE_MAX.
      {"START with a base plane past BASE_MAX",
       [](Env& e) { set_volume_and_view(e, {10, 10, 10});
                    ASSERT_EQ(write(e.host, rm::address_of("X_START"), {0, 64}), tlm::TLM_OK_RESPONSE); },
       TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::BasePlaneTooLarge, rm::kCtrl},
      // A parallel view's rays move forwards by at most a voxel a slice,
      // from a start at or past 0 (golden::dda_out_of_range()):
      // a negative shear read and wrote outside the ray memory.
      {"START with a negative start",
       [](Env& e) { set_volume_and_view(e, {10, 10, 10});
                    ASSERT_EQ(write(e.host, rm::kYStartHi, {0xFFFF'FFFF}), tlm::TLM_OK_RESPONSE); },
       TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::FieldRange, rm::address_of("Y_START")},
      {"START with a negative shear",
       [](Env& e) { set_volume_and_view(e, {10, 10, 10});
                    ASSERT_EQ(write(e.host, rm::address_of("X_STEP"), {0xFFF8'0000, 0xFFFF'FFFF}), tlm::TLM_OK_RESPONSE); },
       TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::FieldRange, rm::address_of("X_STEP")},
      {"START with a shear past a voxel a slice",
       [](Env& e) { set_volume_and_view(e, {10, 10, 10});
                    const uint64_t one = uint64_t{1} << golden::Precision{}.dda_frac_bits;
                    ASSERT_EQ(write(e.host, rm::address_of("Y_STEP"),
                                    {static_cast<uint32_t>(one + 1), static_cast<uint32_t>((one + 1) >> 32)}),
                              tlm::TLM_OK_RESPONSE); },
       TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::FieldRange, rm::address_of("Y_STEP")},
      {"START with a negative falloff",
       [](Env& e) { set_volume_and_view(e, {10, 10, 10});
                    ASSERT_EQ(write(e.host, rm::kMode, {rm::kModeCut}), tlm::TLM_OK_RESPONSE);
                    ASSERT_EQ(write(e.host, rm::kCutFalloffLo, {0xFFFF'FFFF, 0xFFFF'FFFF}), tlm::TLM_OK_RESPONSE); },
       TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::CutFalloffNegative, rm::kCtrl},
      // Perspective's spacing is divided by (the rays' positions and the box
      // filter): refused before anything divides by zero or past the box.
      {"START in perspective with SCALE_START below one",
       [](Env& e) { set_volume_and_view(e, {10, 10, 10});
                    ASSERT_EQ(write(e.host, rm::kMode, {rm::kModePerspective}), tlm::TLM_OK_RESPONSE); },
       TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::FieldRange, rm::address_of("SCALE_START")},
      {"START in perspective with the last slice's rays past 3 voxels apart",
       [](Env& e) { set_volume_and_view(e, {10, 10, 10});
                    const uint64_t one = uint64_t{1} << golden::Precision{}.dda_frac_bits;
                    const uint64_t step = (2 * one) / 9 + 1;  // 10 slices: 1 + 9 step > 3
                    ASSERT_EQ(write(e.host, rm::kMode, {rm::kModePerspective}), tlm::TLM_OK_RESPONSE);
                    ASSERT_EQ(write(e.host, rm::address_of("SCALE_START"),
                                    {static_cast<uint32_t>(one), static_cast<uint32_t>(one >> 32),
                                     static_cast<uint32_t>(step), static_cast<uint32_t>(step >> 32)}),
                              tlm::TLM_OK_RESPONSE); },
       TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::FieldRange, rm::address_of("SCALE_STEP")},
      {"START refused by the backend", [](Env& e) { set_volume_and_view(e, {10, 10, 10}); e.backend.refuse = true; },
       TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::BackendFailure, rm::kCtrl},
      {"START while busy", busy, TLM_WRITE_COMMAND, rm::kCtrl, {rm::kCtrlStart}, 0, false, 0, gen, ErrorCode::Busy, rm::kCtrl},
      {"volume write while busy", busy, TLM_WRITE_COMMAND, rm::kVolumeBase, {0}, 0, false, 0, gen, ErrorCode::Busy, rm::kVolumeBase},
      {"slab read while busy", busy, TLM_READ_COMMAND, rm::kSlabBase, {0}, 0, false, 0, gen, ErrorCode::Busy, rm::kSlabBase},
      {"base-plane read while busy", busy, TLM_READ_COMMAND, rm::kBaseBase, {0}, 0, false, 0, gen, ErrorCode::Busy, rm::kBaseBase},
      {"pixel past the base plane", [](Env& e) { e.backend.plane.width = 3; e.backend.plane.height = 2;
                                                 e.backend.plane.rgba.assign(24, 1); },
       TLM_READ_COMMAND, rm::kBaseBase + 8 * 5, {0, 0, 0}, 0, false, 0, gen, ErrorCode::PixelOutOfImage, rm::kBaseBase + 8 * 6},
  };
}

}  // namespace

TEST(HostInterface, EveryErrorPathGivesItsResponseAndSetsTheErrorBit) {
  Env& e = env();
  for (const ErrorCase& c : error_cases()) {
    SCOPED_TRACE(c.name);
    fresh(e.host, e.backend);
    c.prepare(e);
    const golden::Registers before = e.host.decoded();
    unsigned char enables[8] = {0xFF, 0xFF, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF};
    const Raw r = transact(e.host, c.cmd, c.addr, c.data, c.len, c.byte_enables ? enables : nullptr, c.streaming);
    EXPECT_EQ(r.status, c.status);
    EXPECT_EQ(r.delay, e.host.config().bus_period) << "a refused transaction costs its address cycle";
    EXPECT_EQ(read(e.host, rm::kStatus) & rm::kStatusError, rm::kStatusError);
    EXPECT_EQ(read(e.host, rm::kLastError), static_cast<uint32_t>(c.code))
        << rm::error_name(static_cast<ErrorCode>(read(e.host, rm::kLastError)));
    EXPECT_EQ(read(e.host, rm::kErrorAddrLo) | uint64_t{read(e.host, rm::kErrorAddrHi)} << 32, c.error_addr);
    // A refused transaction changes nothing.
    expect_registers_equal(e.host.decoded(), before, c.name);
    EXPECT_EQ(e.backend.frames.size(), 0u);
    EXPECT_EQ(std::count(e.backend.writes_per_voxel.begin(), e.backend.writes_per_voxel.end(), 1), 0);
    // Except that a backend refusing the frame has already been given the dims.
    if (c.code != ErrorCode::BackendFailure) {
      EXPECT_EQ(e.backend.dims_calls, 0);
    }
    // The error stays until cleared.
    EXPECT_EQ(write(e.host, rm::kMode, {0}), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(read(e.host, rm::kStatus) & rm::kStatusError, rm::kStatusError);
    ASSERT_EQ(write(e.host, rm::kCtrl, {rm::kCtrlClearError}), tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(read(e.host, rm::kStatus) & rm::kStatusError, 0u);
    EXPECT_EQ(read(e.host, rm::kLastError), 0u);
  }
  fresh(e.host, e.backend);
}

// Every field narrower than its register takes both ends of its hardware
// range and refuses one past either (what the register can express): a
// 32-bit register at the write, a 64-bit one at START, which sees both words.
TEST(HostInterface, EveryFieldTakesItsLimitsAndRefusesOnePast) {
  Env& e = env();
  const HardwareParams& hw = e.host.config().hw;
  int narrow = 0;
  for (const rm::Register& reg : rm::kRegisters) {
    const std::optional<rm::Limits> l = rm::limits(reg, hw);
    if (!reg.set || !l) continue;
    const int64_t reg_lo = reg.words == 2 ? INT64_MIN : (reg.sign == rm::Sign::Unsigned ? 0 : INT32_MIN);
    const int64_t reg_hi = reg.words == 2 ? INT64_MAX : (reg.sign == rm::Sign::Unsigned ? UINT32_MAX : INT32_MAX);
    auto attempt = [&](int64_t v) {
      fresh(e.host, e.backend);
      set_volume_and_view(e, {10, 10, 10});
      const auto u = static_cast<uint64_t>(v);
      std::vector<uint32_t> words{static_cast<uint32_t>(u)};
      if (reg.words == 2) words.push_back(static_cast<uint32_t>(u >> 32));
      tlm::tlm_response_status s = write(e.host, reg.addr, words);
      if (s == tlm::TLM_OK_RESPONSE && reg.words == 2) s = write(e.host, rm::kCtrl, {rm::kCtrlStart});
      return s;
    };
    if (l->lo == reg_lo && l->hi == reg_hi) continue;  // the whole register: the DDA, bounded at START
    for (const int64_t v : {l->lo, l->hi}) {
      SCOPED_TRACE(std::string(reg.name) + " = " + std::to_string(v));
      EXPECT_EQ(attempt(v), tlm::TLM_OK_RESPONSE);
    }
    for (const int64_t v : {l->lo - (l->lo > reg_lo), l->hi + (l->hi < reg_hi)}) {
      if (v >= l->lo && v <= l->hi) continue;  // the register holds no value past this end
      SCOPED_TRACE(std::string(reg.name) + " = " + std::to_string(v));
      ++narrow;
      EXPECT_EQ(attempt(v), tlm::TLM_GENERIC_ERROR_RESPONSE);
      EXPECT_EQ(read(e.host, rm::kLastError), static_cast<uint32_t>(ErrorCode::FieldRange));
      EXPECT_EQ(read(e.host, rm::kErrorAddrLo), reg.addr);
      EXPECT_EQ(e.backend.frames.size(), 0u);
    }
  }
  EXPECT_GE(narrow, 45) << "values one past a field that its register can express";
}

TEST(HostInterface, RegisterWritesWhileBusyAreTakenForTheNextFrame) {
  Env& e = env();
  fresh(e.host, e.backend);
  e.backend.is_busy = true;
  EXPECT_EQ(write(e.host, rm::kSupersampling, {4}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(write(e.host, rm::kClassBase, {0x10203, 0x456}), tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(e.host.decoded().supersampling, 4);
  e.backend.is_busy = false;
}

TEST(HostInterface, IgnoreCommandChecksTheAddressOnly) {
  Env& e = env();
  reset(e.host);
  EXPECT_EQ(transact(e.host, tlm::TLM_IGNORE_COMMAND, rm::kMode, {0xFFFF'FFFF}).status, tlm::TLM_OK_RESPONSE);
  EXPECT_EQ(read(e.host, rm::kMode), 0u);
  EXPECT_EQ(transact(e.host, tlm::TLM_IGNORE_COMMAND, 0x00C, {0}).status, tlm::TLM_ADDRESS_ERROR_RESPONSE);
  ASSERT_EQ(write(e.host, rm::kCtrl, {rm::kCtrlClearError}), tlm::TLM_OK_RESPONSE);
}

// ---- Host-side errors ---------------------------------------------------------------

namespace {

std::string host_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const HostError& e) {
    return e.what();
  }
  return "(no HostError)";
}

}  // namespace

TEST(HostProgram, RefusesRegisterSetsTheHardwareCannotTake) {
  Env& e = env();
  const SceneSetup s = default_precision_scenes()[0];
  sc_time delay = SC_ZERO_TIME;
  EXPECT_NE(host_error([&] { program_over_tlm(e.host8.target(), s.regs, s.volume, delay); })
                .find("regs.p.voxel_bits = 12, the hardware's is 8"),
            std::string::npos);
  golden::Volume wrong = s.volume;
  std::swap(wrong.dim[0], wrong.dim[2]);
  EXPECT_NE(host_error([&] { program_over_tlm(e.host.target(), s.regs, wrong, delay); }).find("regs.dim["),
            std::string::npos);
  golden::Registers r = s.regs;
  r.gm_lut.resize(5);
  EXPECT_NE(host_error([&] { program_over_tlm(e.host.target(), r, s.volume, delay); })
                .find("regs.gm_lut has 5 entries"),
            std::string::npos);
  r = s.regs;
  r.diffuse_map.clear();
  EXPECT_NE(host_error([&] { program_over_tlm(e.host.target(), r, s.volume, delay); }).find("regs.diffuse_map"),
            std::string::npos);
  // Values only the interface checks come back as its refusal, named.
  r = s.regs;
  r.supersampling = 9;
  const std::string msg = host_error([&] { program_over_tlm(e.host.target(), r, s.volume, delay); });
  EXPECT_NE(msg.find("SUPERSAMPLING (0x114) = 0x9"), std::string::npos) << msg;
  EXPECT_NE(msg.find("GENERIC_ERROR"), std::string::npos) << msg;
  EXPECT_NE(msg.find("out of range"), std::string::npos) << msg;
  ASSERT_EQ(write(e.host, rm::kCtrl, {rm::kCtrlClearError}), tlm::TLM_OK_RESPONSE);
}

// ---- Timing and debug transport -------------------------------------------------------

TEST(HostInterface, DelayIsOneAddressCyclePlusOneCyclePerWord) {
  Env& e = env();
  reset(e.host);
  const sc_time old = e.host.config().bus_period;
  e.host.set_bus_period(sc_time(10, SC_NS));
  EXPECT_EQ(transact(e.host, tlm::TLM_WRITE_COMMAND, rm::kDimX, {1, 2, 3}).delay, sc_time(40, SC_NS));
  EXPECT_EQ(transact(e.host, tlm::TLM_READ_COMMAND, rm::kMode, {0}).delay, sc_time(20, SC_NS));
  EXPECT_EQ(transact(e.host, tlm::TLM_READ_COMMAND, rm::kClassBase, std::vector<uint32_t>(256)).delay,
            sc_time(2570, SC_NS));
  EXPECT_EQ(transact(e.host, tlm::TLM_READ_COMMAND, 0x00C, {0}).delay, sc_time(10, SC_NS));
  e.host.set_bus_period(old);
  // Delays accumulate onto what the initiator passes in.
  sc_time delay(5, SC_NS);
  write_word(e.host.target(), rm::kMode, 0, delay);
  EXPECT_EQ(delay, sc_time(5, SC_NS) + 2 * old);
  ASSERT_EQ(write(e.host, rm::kCtrl, {rm::kCtrlClearError}), tlm::TLM_OK_RESPONSE);
}

TEST(HostInterface, DebugTransportHasNoSideEffects) {
  Env& e = env();
  fresh(e.host, e.backend);
  set_volume_and_view(e, {10, 10, 10});
  auto dbg = [&](tlm::tlm_command cmd, uint64_t addr, std::vector<uint32_t>& words) {
    tlm::tlm_generic_payload t;
    t.set_command(cmd);
    t.set_address(addr);
    t.set_data_ptr(reinterpret_cast<unsigned char*>(words.data()));
    t.set_data_length(static_cast<unsigned>(4 * words.size()));
    return e.host.target().transport_dbg(t);
  };
  std::vector<uint32_t> w = {0x12};
  EXPECT_EQ(dbg(tlm::TLM_WRITE_COMMAND, rm::kPerm, w), 4u);
  EXPECT_EQ(e.host.decoded().perm, (std::array<int, 3>{2, 0, 1}));
  w = {0};
  EXPECT_EQ(dbg(tlm::TLM_READ_COMMAND, rm::kPerm, w), 4u);
  EXPECT_EQ(w[0], 0x12u);
  w = {rm::kCtrlStart};
  EXPECT_EQ(dbg(tlm::TLM_WRITE_COMMAND, rm::kCtrl, w), 0u);
  EXPECT_EQ(e.backend.frames.size(), 0u);
  w = {0x0001'0001};
  EXPECT_EQ(dbg(tlm::TLM_WRITE_COMMAND, rm::kVolumeBase, w), 0u);
  w = {0};
  EXPECT_EQ(dbg(tlm::TLM_READ_COMMAND, 0x00C, w), 0u);
  w = {9};
  EXPECT_EQ(dbg(tlm::TLM_WRITE_COMMAND, rm::kSupersampling, w), 0u);
  EXPECT_EQ(read(e.host, rm::kStatus) & rm::kStatusError, 0u) << "debug errors are not recorded";
}

TEST(HostInterface, ConstructionRefusesParametersTheMapCannotHold) {
  HardwareParams hw;
  hw.max_dim = 2048;
  EXPECT_THROW(check_hardware_params(hw), std::invalid_argument);
  hw = HardwareParams{};
  hw.precision.voxel_bits = 17;
  EXPECT_THROW(check_hardware_params(hw), std::invalid_argument);
  hw = HardwareParams{};
  hw.pipelines = 0;
  EXPECT_THROW(check_hardware_params(hw), std::invalid_argument);
  EXPECT_NO_THROW(check_hardware_params(HardwareParams{narrow_precision(), 3, 32}));
}

// Last: sc_start() ends elaboration, after which no test may build modules.
TEST(HostInterface, ZFrameProgrammedFromAnScThreadThroughABoundSocket) {
  Env& e = env();
  fresh(e.host, e.backend);
  const SceneSetup s = default_precision_scenes()[2];
  e.backend.render = true;
  e.backend.frame_time = sc_time(5, sc_core::SC_US);
  e.thread.regs = &s.regs;
  e.thread.vol = &s.volume;
  sc_core::sc_start();
  ASSERT_TRUE(e.thread.finished);
  EXPECT_EQ(sc_core::sc_time_stamp(), e.thread.annotated + e.thread.polls * sc_time(1, sc_core::SC_US));
  EXPECT_GE(e.thread.polls, 1) << "the frame takes 5 us of simulated time";
  EXPECT_EQ(e.thread.final_status, rm::kStatusDone);
  // Bus time: at least one cycle per voxel pair and table word.
  const double words = s.volume.size() / 2.0 + 2.0 * s.regs.classification.size();
  EXPECT_GE(e.thread.annotated, e.host.config().bus_period * words);
  const golden::BasePlane want = golden::render_fixed(s.volume, s.regs);
  EXPECT_EQ(e.thread.result.rgba, want.rgba);
  e.backend.render = false;
}
