// RTL equivalence tests of the classification and shading units:
// cube4_shade_classify, cube4_shade_cube_coord, cube4_shade_reflection,
// cube4_shade_reflectance, cube4_shade_phong and their top, cube4_shade.
//
// Every unit is driven cycle by cycle (back to back and with random valid
// gaps, junk on the data inputs in the gaps); every output is compared with
// the golden function (golden/units/*.hpp, golden/pipeline.hpp) of the input
// that entered `latency` cycles earlier (rtl_check.hpp's Scoreboard). Tables
// are loaded through the units' write ports: random contents, and the tables
// the real host driver builds for a synthetic sphere scene (program_host).
// Frame registers (modes, coefficients, eye, tables) change only between
// blocks, after the pipeline has drained, as the units' contracts require.
//
// CUBE4_RTL_VECTORS overrides the random vector count per unit (default
// 1,000,000); CUBE4_SEED the seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "Vcube4_shade_classify.h"
#include "Vcube4_shade_classify_t2.h"
#include "Vcube4_shade_t2.h"
#include "Vcube4_shade_cube_coord.h"
#include "Vcube4_shade_phong.h"
#include "Vcube4_shade_reflectance.h"
#include "Vcube4_shade_reflection.h"
#include "Vcube4_shade.h"
#include "Vcube4_shade_small.h"
#include "Vcube4_shade_wide.h"
#include "Vcube4_shade_noshade.h"
#include "golden/host_driver.hpp"
#include "golden/pipeline.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "systemc/rtl/unit_registers.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Field;
using rtl::Fields;
using rtl::Random;

const g::Precision kP;  // VolumePro widths: the RTL defaults

// Port access with the width taken from the precision (any container type).
template <class T>
void put(T& port, int64_t v, int bits) {
  rtl::put_bits(port, 0, bits, static_cast<uint64_t>(v));
}
template <class T>
int64_t get_signed(const T& port, int bits) {
  return rtl::sign_extend(rtl::get_bits(port, 0, bits), bits);
}
template <class T>
int64_t get(const T& port, int bits) {
  return static_cast<int64_t>(rtl::get_bits(port, 0, bits));
}

int clog2(int64_t v) {
  int b = 0;
  while ((int64_t{1} << b) < v) ++b;
  return b;
}

// ---------------------------------------------------------------------------
// A verilated valid-only unit with its scoreboard. In one cycle: drive the
// inputs (valid or a gap with junk data), settle, check the outputs against
// the result due from `latency` cycles earlier, queue the golden result of
// this cycle's input, clock.
template <class M, class In, class Out>
class Bench {
 public:
  Bench(const std::string& unit, int latency)
      : m(cube4::rtl::make_dut<M>()), sb(unit, latency), latency_(latency) {}
  virtual ~Bench() { m->final(); }

  void start() {
    m->valid_i = 0;
    rtl::reset(*m);
  }
  void step(bool valid, const In& in) {
    m->valid_i = valid;
    drive(in);
    rtl::settle(*m);
    sb.observe(cycle, m->valid_o, read());
    if (valid) {
      sb.expect(cycle, in, golden(in));
      ++vectors;
    }
    rtl::rise(*m);
    ++cycle;
  }
  // A cycle with valid low and the inputs left as they are (write ports).
  void idle() {
    m->valid_i = 0;
    rtl::settle(*m);
    sb.observe(cycle, m->valid_o, read());
    rtl::rise(*m);
    ++cycle;
  }
  // Empties the pipeline: frame registers may change afterwards.
  void drain() {
    for (int i = 0; i <= latency_; ++i) idle();
  }
  ::testing::AssertionResult result() {
    drain();
    sb.finish();
    std::printf("  %s (%llu cycles)\n", sb.report().c_str(), static_cast<unsigned long long>(cycle));
    if (sb.ok()) return ::testing::AssertionSuccess() << sb.report();
    return ::testing::AssertionFailure() << sb.report();
  }

  cube4::rtl::Dut<M> m;
  rtl::Scoreboard<In, Out> sb;
  uint64_t cycle = 0;
  uint64_t vectors = 0;

 protected:
  virtual void drive(const In& in) = 0;
  virtual Out read() = 0;
  virtual Out golden(const In& in) = 0;

 private:
  int latency_;
};

// Valid pattern of a block: back to back, or with random gaps.
struct Gaps {
  double p_gap = 0;
  bool valid(Random& rnd) const { return p_gap == 0 || !rnd.chance(p_gap); }
};
Gaps random_gaps(Random& rnd) {
  const double g[] = {0.0, 0.05, 0.2, 0.5};
  return {g[rnd.range(0, 3)]};
}

// ---------------------------------------------------------------------------
// Stimulus shared by the units.

// Gradients: uniform, small, extreme (±127 and neighbours), ties between
// axes, face edges and corners (|in-plane| = |major|), one-hot, zero.
g::Gradient random_gradient(Random& rnd, const g::Precision& p, bool allow_min = false) {
  const int64_t max = g::max_signed(p.gradient_bits);
  const int64_t lo = allow_min ? -max - 1 : -max;
  auto sgn = [&](int64_t v) { return rnd.chance(0.5) ? -v : v; };
  int64_t v[3];
  switch (rnd.range(0, 7)) {
    case 0:
    case 1:
      for (auto& c : v) c = rnd.range(lo, max);
      break;
    case 2:
      for (auto& c : v) c = rnd.range(-8, 8);
      break;
    case 3: {
      const int64_t e[] = {-max, -max + 1, -1, 0, 1, max - 1, max};
      for (auto& c : v) c = e[rnd.range(0, 6)];
      if (allow_min && rnd.chance(0.2)) v[rnd.range(0, 2)] = lo;
      break;
    }
    case 4: {  // ties: two or three components of equal magnitude
      const int64_t m = rnd.range(0, max);
      for (auto& c : v) c = rnd.range(-m, m);
      const int i = static_cast<int>(rnd.range(0, 2));
      v[i] = sgn(m);
      v[(i + 1 + rnd.range(0, 1)) % 3] = sgn(m);
      if (rnd.chance(0.3)) v[(i + 2) % 3] = sgn(m);
      break;
    }
    case 5: {  // face edge: an in-plane component equal to the major one
      const int64_t m = rnd.range(1, max);
      const int i = static_cast<int>(rnd.range(0, 2));
      v[i] = sgn(m);
      v[(i + 1) % 3] = rnd.chance(0.5) ? sgn(m) : rnd.range(-m, m);
      v[(i + 2) % 3] = rnd.chance(0.5) ? sgn(m) : rnd.range(-m, m);
      break;
    }
    case 6:  // one-hot or zero
      v[0] = v[1] = v[2] = 0;
      if (rnd.chance(0.8)) v[rnd.range(0, 2)] = rnd.range(lo, max);
      break;
    default:  // a random direction at a random length
    {
      const double len = rnd.range(1, max);
      double d[3], n2 = 0;
      for (auto& c : d) {
        c = static_cast<double>(rnd.range(-1000, 1000));
        n2 += c * c;
      }
      const double n = n2 > 0 ? std::sqrt(n2) : 1;
      for (int i = 0; i < 3; ++i) v[i] = std::llround(d[i] / n * len);
    }
  }
  return {static_cast<int32_t>(v[0]), static_cast<int32_t>(v[1]), static_cast<int32_t>(v[2])};
}

// A synthetic sphere scene, programmed by the real host driver.
g::HostProgram sphere_program(const std::string& extra_json, g::Volume* volume_out = nullptr) {
  const std::string json =
      R"({"volume": {"synthetic": "sphere", "size": [24, 24, 24]}, "view": {"rotate": [20, 30, 0]})" +
      (extra_json.empty() ? std::string() : ", " + extra_json) + "}";
  const g::Scene s = g::parse_scene(json, "test_shade sphere scene");
  g::Volume v = g::make_synthetic(s.volume, s.precision.voxel_bits);
  g::HostProgram h = g::program_host(s, v);
  if (volume_out) *volume_out = std::move(v);
  return h;
}

const char* kShadedSphere =
    R"("transfer": {"color": [[0, 1, 0.6, 0.3], [1, 0.2, 0.6, 1]], "opacity": [[0, 0], [0.4, 0], [0.6, 1], [1, 1]]},)"
    R"("lights": [{"direction": [0.5, 0.5, 1], "intensity": 0.8}, {"direction": [-1, 0, 0.3], "intensity": 0.3}],)"
    R"("material": {"ke": 0.1, "kd": 0.8, "ks": 0.5, "exponent": 32},)"
    R"("gm_lut": [[0, 0], [0.3, 0.5], [1, 1]],)"
    R"("gradient_modulation": {"opacity": true, "diffuse": true, "specular": true})";

// ===========================================================================
// cube4_shade_classify
// ===========================================================================
// `tag`: the sample's voxel tag (bela §III), 0 without tags; vtag is it
// delayed with the sample.
struct ClassIn {
  uint32_t sample = 0, mag = 0;
  bool magnitude = false, gm_opacity = false;
  uint32_t tag = 0;
  Fields fields() const {
    return {{"sample", sample}, {"grad_mag", mag}, {"magnitude", magnitude}, {"gm_opacity", gm_opacity}, {"tag", tag}};
  }
};
struct ClassOut {
  uint32_t r = 0, gr = 0, b = 0, a = 0, gm = 0, vtag = 0;
  bool operator==(const ClassOut& o) const {
    return r == o.r && gr == o.gr && b == o.b && a == o.a && gm == o.gm && vtag == o.vtag;
  }
  Fields fields() const { return {{"red", r}, {"green", gr}, {"blue", b}, {"alpha", a}, {"gm", gm}, {"vtag", vtag}}; }
};

// M: cube4_shade_classify verilated with p's widths (tag_bits: VoxelTagBits).
template <class M = Vcube4_shade_classify>
class ClassifyBench : public Bench<M, ClassIn, ClassOut> {
  using Base = Bench<M, ClassIn, ClassOut>;
  using Base::m;
  using Base::drain;
  using Base::step;

 public:
  static constexpr int kLatency = 2;
  explicit ClassifyBench(const g::Precision& precision = kP, const char* unit = "cube4_shade_classify")
      : Base(unit, kLatency), p(precision) {
    m->class_we_i = 0;
    m->gmlut_we_i = 0;
    this->start();
  }
  void load(const std::vector<g::ClassEntry>& cls, const std::vector<uint16_t>& gm) {
    drain();
    table = cls;
    gmlut = gm;
    auto tick = [this] { this->idle(); };
    rtl::load_class_table(*m, p, cls, tick);
    rtl::load_gm_lut(*m, p, gm, tick);
  }
  void modes(bool magnitude, bool gm_opacity) {
    drain();
    m->magnitude_i = magnitude;
    m->gm_opacity_i = gm_opacity;
  }
  void sample(bool valid, uint32_t sample, uint32_t mag, uint32_t tag = 0) {
    step(valid, {sample, mag, static_cast<bool>(m->magnitude_i), static_cast<bool>(m->gm_opacity_i), tag});
  }

  g::Precision p;
  std::vector<g::ClassEntry> table;
  std::vector<uint16_t> gmlut;

 protected:
  void drive(const ClassIn& in) override {
    put(m->sample_i, in.sample, p.voxel_bits);
    put(m->grad_mag_i, in.mag, p.magnitude_bits);
    m->vtag_i = in.tag;
  }
  ClassOut read() override {
    return {static_cast<uint32_t>(m->red_o), static_cast<uint32_t>(m->green_o),
            static_cast<uint32_t>(m->blue_o), static_cast<uint32_t>(m->alpha_o),
            static_cast<uint32_t>(m->gm_o),  static_cast<uint32_t>(m->vtag_o)};
  }
  // As golden shade_sample() composes them.
  ClassOut golden(const ClassIn& in) override {
    const uint32_t one = static_cast<uint32_t>(g::max_unsigned(p.alpha_bits));
    const g::ClassEntry& e = g::classify(table, in.tag, in.sample, p);
    const uint32_t gm = in.magnitude ? g::gm_unit(gmlut[in.mag], p) : one;
    const uint32_t alpha = in.gm_opacity ? g::modulate_alpha(e.a, gm, p) : e.a;
    const g::Rgb rgb = g::widen_color(e.r, e.g, e.b, p);
    return {rgb[0], rgb[1], rgb[2], alpha, gm, in.tag};
  }
};

std::vector<g::ClassEntry> random_class_table(Random& rnd, const g::Precision& p) {
  std::vector<g::ClassEntry> t(size_t{1} << (p.voxel_bits + p.tag_bits));
  const int64_t cmax = g::max_unsigned(p.color_bits), amax = g::max_unsigned(p.alpha_bits);
  for (auto& e : t) {
    e.r = static_cast<uint16_t>(rnd.edgy(cmax, 0.2));
    e.g = static_cast<uint16_t>(rnd.edgy(cmax, 0.2));
    e.b = static_cast<uint16_t>(rnd.edgy(cmax, 0.2));
    e.a = static_cast<uint16_t>(rnd.edgy(amax, 0.3));
  }
  return t;
}
std::vector<uint16_t> random_gmlut(Random& rnd, const g::Precision& p) {
  std::vector<uint16_t> t(size_t{1} << p.magnitude_bits);
  for (auto& v : t) v = static_cast<uint16_t>(rnd.edgy(g::max_unsigned(p.gmlut_bits), 0.3));
  return t;
}

TEST(RtlShadeClassify, EveryAlphaTimesEveryGmLutValue) {
  // Identity tables: sample i has alpha i, |g| = j reads GmLUT value j, so
  // the exhaustive (sample, |g|) sweep covers every product of the modulation.
  ClassifyBench<> b;
  const g::Precision& p = b.p;
  std::vector<g::ClassEntry> cls(size_t{1} << p.voxel_bits);
  for (size_t i = 0; i < cls.size(); ++i)
    cls[i] = {static_cast<uint16_t>(i & 255), static_cast<uint16_t>(255 - (i & 255)),
              static_cast<uint16_t>(i >> 4), static_cast<uint16_t>(i)};
  std::vector<uint16_t> gm(size_t{1} << p.magnitude_bits);
  for (size_t i = 0; i < gm.size(); ++i) gm[i] = static_cast<uint16_t>(i);
  b.load(cls, gm);
  Random rnd(101);
  for (int mode = 3; mode >= 0; --mode) {
    b.modes(mode & 1, mode >> 1 & 1);
    const Gaps gaps{mode == 3 ? 0.0 : 0.1};
    for (uint32_t s = 0; s < cls.size(); ++s)
      for (uint32_t j = 0; j < gm.size(); j += (mode == 3 ? 1 : 17)) b.sample(gaps.valid(rnd), s, j);
  }
  EXPECT_TRUE(b.result());
  std::printf("classify exhaustive: %llu vectors\n", static_cast<unsigned long long>(b.vectors));
}

// A million random samples (and tags, with tags) over random tables and modes.
template <class M>
void classify_random(ClassifyBench<M>& b, Random& rnd) {
  const g::Precision& p = b.p;
  const long n = rtl::vector_count(1000000);
  const long block = 20000;
  for (long done = 0; done < n;) {
    if (done % (5 * block) == 0) b.load(random_class_table(rnd, p), random_gmlut(rnd, p));
    b.modes(rnd.chance(0.7), rnd.chance(0.7));
    const Gaps gaps = random_gaps(rnd);
    for (long i = 0; i < block && done < n; ++i) {
      const bool v = gaps.valid(rnd);
      const auto sample = static_cast<uint32_t>(rnd.bits(p.voxel_bits));
      const auto mag = static_cast<uint32_t>(rnd.bits(p.magnitude_bits));
      b.sample(v, sample, mag, p.tag_bits > 0 ? static_cast<uint32_t>(rnd.bits(p.tag_bits)) : 0);
      done += v;
    }
  }
  EXPECT_GE(b.vectors, static_cast<uint64_t>(n));
}

TEST(RtlShadeClassify, RandomTablesAndModes) {
  ClassifyBench<> b;
  Random rnd(102);
  classify_random(b, rnd);
  EXPECT_TRUE(b.result());
}

// Voxel tags (bela §III): 2-bit tags widen the table to {tag, sample}; a
// million random samples of random tags over random tables and modes, and
// the tagged spheres' table as the host driver builds it.
g::Precision tagged_precision() {
  g::Precision p = kP;
  p.tag_bits = 2;
  return p;
}

TEST(RtlShadeClassify, VoxelTagsAddressTheirOwnEntries) {
  ClassifyBench<Vcube4_shade_classify_t2> b(tagged_precision(), "cube4_shade_classify_t2");
  const g::Precision& p = b.p;
  Random rnd(104);
  classify_random(b, rnd);
  // Two classes of their own and the scene's for tags 0 and 3.
  const g::Scene s = g::parse_scene(R"({"volume": {"synthetic": "spheres", "size": [16, 16, 16]},
      "precision": {"tag_bits": 2}, "tags": {"classes": [
        {"tag": 1, "color": [[0, 1, 0.15, 0.1], [1, 1, 0.15, 0.1]]},
        {"tag": 2, "color": [[0, 0.1, 0.2, 0.9], [1, 0.1, 0.2, 0.9]], "opacity": [[0, 0], [0.5, 0.9], [1, 0.9]]}]}})",
                                    "tagged spheres");
  g::Volume vol = g::make_synthetic(s.volume, s.precision.voxel_bits);
  const g::HostProgram h = g::program_host(s, vol);
  ASSERT_EQ(h.regs.p.tag_bits, p.tag_bits);
  b.load(h.regs.classification, std::vector<uint16_t>(size_t{1} << p.magnitude_bits, 0));
  b.modes(false, false);
  for (uint32_t t = 0; t < 4; ++t)
    for (uint32_t v = 0; v < (1u << p.voxel_bits); ++v) b.sample(true, v, 0, t);
  EXPECT_TRUE(b.result());
}

TEST(RtlShadeClassify, HostDriverTables) {
  ClassifyBench<> b;
  const g::HostProgram h = sphere_program(kShadedSphere);
  ASSERT_TRUE(h.regs.magnitude && h.regs.gm_opacity);
  b.load(h.regs.classification, h.regs.gm_lut);
  b.modes(h.regs.magnitude, h.regs.gm_opacity);
  Random rnd(103);
  for (int i = 0; i < 200000; ++i)
    b.sample(!rnd.chance(0.1), static_cast<uint32_t>(rnd.bits(kP.voxel_bits)),
             static_cast<uint32_t>(rnd.bits(kP.magnitude_bits)));
  EXPECT_TRUE(b.result());
}

// ===========================================================================
// cube4_shade_cube_coord
// ===========================================================================
struct VecIn {
  int32_t x = 0, y = 0, z = 0;
  Fields fields() const { return {{"x", x}, {"y", y}, {"z", z}}; }
};
struct CoordOut {
  g::CubeCoord c;
  bool operator==(const CoordOut& o) const {
    return c.valid == o.c.valid && c.face == o.c.face && c.u == o.c.u && c.v == o.c.v &&
           c.wu == o.c.wu && c.wv == o.c.wv;
  }
  Fields fields() const {
    return {{"coord_valid", c.valid}, {"face", c.face}, {"u", c.u}, {"v", c.v}, {"wu", c.wu}, {"wv", c.wv}};
  }
};

class CubeCoordBench : public Bench<Vcube4_shade_cube_coord, VecIn, CoordOut> {
 public:
  // 1 + ceil((clog2(res) + W) / DivBitsPerStage), by default DivBitsPerStage = 2.
  static int latency_of(const g::Precision& p, int div_bits = 2) {
    return 1 + (clog2(p.map_face_res) + p.weight_bits + div_bits - 1) / div_bits;
  }
  CubeCoordBench() : Bench("cube4_shade_cube_coord", latency_of(kP)) { start(); }
  void vec(bool valid, int32_t x, int32_t y, int32_t z) { step(valid, {x, y, z}); }
  g::Precision p = kP;

 protected:
  void drive(const VecIn& in) override {
    put(m->x_i, in.x, p.gradient_bits);
    put(m->y_i, in.y, p.gradient_bits);
    put(m->z_i, in.z, p.gradient_bits);
  }
  CoordOut read() override {
    CoordOut o;
    o.c.valid = m->coord_valid_o;
    o.c.face = static_cast<int>(m->face_o);
    o.c.u = m->u_o;
    o.c.v = m->v_o;
    o.c.wu = m->wu_o;
    o.c.wv = m->wv_o;
    return o;
  }
  CoordOut golden(const VecIn& in) override { return {g::cube_coordinates(in.x, in.y, in.z, p)}; }
};

// Named corner cases: every face, its edges, corners and ties, the zero vector.
std::vector<g::Gradient> cube_corner_cases(int max) {
  std::vector<g::Gradient> v;
  const int vals[] = {-max, -max + 1, -1, 0, 1, max - 1, max};
  for (int x : vals)
    for (int y : vals)
      for (int z : vals) v.push_back({x, y, z});
  // Ties and edges at every magnitude.
  for (int m = 1; m <= max; ++m)
    for (int sx : {-1, 1})
      for (int sy : {-1, 1})
        for (int sz : {-1, 1}) {
          v.push_back({sx * m, sy * m, sz * m});        // corner: three-way tie
          v.push_back({sx * m, sy * m, sz * (m - 1)});  // x/y tie
          v.push_back({sx * m, sy * (m - 1), sz * m});  // x/z tie
          v.push_back({sx * (m - 1), sy * m, sz * m});  // y/z tie
          v.push_back({sx * m, sy * (m / 2), sz * m});  // x/z tie, mid edge
          v.push_back({sx * m, 0, 0});                  // face centres
          v.push_back({0, sy * m, 0});
          v.push_back({0, 0, sz * m});
        }
  v.push_back({0, 0, 0});
  return v;
}

TEST(RtlShadeCubeCoord, CornerCases) {
  CubeCoordBench b;
  Random rnd(201);
  for (int pass = 0; pass < 2; ++pass)
    for (const g::Gradient& v : cube_corner_cases(127)) b.vec(pass == 0 || !rnd.chance(0.3), v.x, v.y, v.z);
  // Every face is reached.
  std::array<int, 6> faces{};
  for (const g::Gradient& v : cube_corner_cases(127)) {
    const g::CubeCoord c = g::cube_coordinates(v.x, v.y, v.z, kP);
    if (c.valid) ++faces[c.face];
  }
  for (int f = 0; f < 6; ++f) EXPECT_GT(faces[f], 0) << "face " << f;
  EXPECT_TRUE(b.result());
}

TEST(RtlShadeCubeCoord, Exhaustive) {
  // Every 8-bit vector, -128 included (outside the golden gradient range,
  // inside the RTL's): 16.8 million, with valid gaps.
  CubeCoordBench b;
  Random rnd(202);
  const int lo = -(1 << (kP.gradient_bits - 1)), hi = (1 << (kP.gradient_bits - 1)) - 1;
  for (int x = lo; x <= hi; ++x)
    for (int y = lo; y <= hi; ++y)
      for (int z = lo; z <= hi; ++z) {
        if ((z & 15) == 0 && rnd.chance(0.3)) b.vec(false, static_cast<int32_t>(rnd.bits(8)) - 128, 0, 0);
        b.vec(true, x, y, z);
      }
  EXPECT_TRUE(b.result());
  std::printf("cube_coord exhaustive: %llu vectors\n", static_cast<unsigned long long>(b.vectors));
}

TEST(RtlShadeCubeCoord, Random) {
  CubeCoordBench b;
  Random rnd(203);
  const long n = rtl::vector_count(1000000);
  Gaps gaps;
  for (long done = 0; done < n;) {
    if (done % 10000 == 0) gaps = random_gaps(rnd);
    const bool v = gaps.valid(rnd);
    const g::Gradient gr = random_gradient(rnd, kP, true);
    b.vec(v, gr.x, gr.y, gr.z);
    done += v;
  }
  EXPECT_TRUE(b.result());
}

// ===========================================================================
// cube4_shade_reflection
// ===========================================================================
struct ReflIn {
  g::Gradient n;
  g::Eye eye{0, 0, 0};
  Fields fields() const {
    return {{"x", n.x}, {"y", n.y}, {"z", n.z}, {"eye_x", eye[0]}, {"eye_y", eye[1]}, {"eye_z", eye[2]}};
  }
};
struct VecOut {
  g::Gradient v;
  bool operator==(const VecOut& o) const { return v == o.v; }
  Fields fields() const { return {{"x", v.x}, {"y", v.y}, {"z", v.z}}; }
};

class ReflectionBench : public Bench<Vcube4_shade_reflection, ReflIn, VecOut> {
 public:
  static constexpr int kLatency = 4;
  ReflectionBench() : Bench("cube4_shade_reflection", kLatency) { start(); }
  void set_eye(const g::Eye& e) {
    drain();
    eye = e;
    put(m->eye_x_i, e[0], p.eye_bits);
    put(m->eye_y_i, e[1], p.eye_bits);
    put(m->eye_z_i, e[2], p.eye_bits);
  }
  void vec(bool valid, const g::Gradient& n) { step(valid, {n, eye}); }
  g::Precision p = kP;
  g::Eye eye{0, 0, 0};

 protected:
  void drive(const ReflIn& in) override {
    put(m->x_i, in.n.x, p.gradient_bits);
    put(m->y_i, in.n.y, p.gradient_bits);
    put(m->z_i, in.n.z, p.gradient_bits);
  }
  VecOut read() override {
    return {{static_cast<int32_t>(get_signed(m->x_o, p.gradient_bits)),
             static_cast<int32_t>(get_signed(m->y_o, p.gradient_bits)),
             static_cast<int32_t>(get_signed(m->z_o, p.gradient_bits))}};
  }
  VecOut golden(const ReflIn& in) override { return {g::reflection_vector(in.n, in.eye, p)}; }
};

g::Eye random_eye(Random& rnd, const g::Precision& p) {
  const int64_t max = g::max_signed(p.eye_bits);
  if (rnd.chance(0.5)) {  // a unit direction scaled like the host's eye_perm
    double d[3], n2 = 0;
    for (auto& c : d) {
      c = static_cast<double>(rnd.range(-1000, 1000));
      n2 += c * c;
    }
    const double n = n2 > 0 ? std::sqrt(n2) : 1;
    return {static_cast<int32_t>(std::lround(d[0] / n * max)), static_cast<int32_t>(std::lround(d[1] / n * max)),
            static_cast<int32_t>(std::lround(d[2] / n * max))};
  }
  const int64_t lo = rnd.chance(0.1) ? -max - 1 : -max;
  return {static_cast<int32_t>(rnd.range(lo, max)), static_cast<int32_t>(rnd.range(lo, max)),
          static_cast<int32_t>(rnd.range(lo, max))};
}

TEST(RtlShadeReflection, CornerCases) {
  ReflectionBench b;
  const int m = 127;
  const std::vector<g::Eye> eyes = {{0, 0, m},   {0, 0, -m},   {m, m, m}, {-m, -m, -m}, {-128, -128, -128},
                                    {m, -m, 0},  {0, 0, 0},    {1, 0, 0}, {73, -73, 73},
                                    sphere_program(kShadedSphere).regs.eye};
  const int vals[] = {-128, -127, -126, -1, 0, 1, 126, 127};
  for (const g::Eye& e : eyes) {
    b.set_eye(e);
    for (int x : vals)
      for (int y : vals)
        for (int z : vals) b.vec(true, {x, y, z});
  }
  EXPECT_TRUE(b.result());
}

TEST(RtlShadeReflection, Random) {
  ReflectionBench b;
  Random rnd(301);
  const long n = rtl::vector_count(1000000);
  const long block = 5000;
  for (long done = 0; done < n;) {
    b.set_eye(random_eye(rnd, kP));
    const Gaps gaps = random_gaps(rnd);
    for (long i = 0; i < block && done < n; ++i) {
      const bool v = gaps.valid(rnd);
      b.vec(v, random_gradient(rnd, kP, rnd.chance(0.05)));
      done += v;
    }
  }
  EXPECT_TRUE(b.result());
}

// ===========================================================================
// cube4_shade_reflectance
// ===========================================================================
struct MapIn {
  g::CubeCoord c;
  std::array<uint32_t, 4> entries{};  // the map's (u,v), (u+1,v), (u,v+1), (u+1,v+1), for reports
  Fields fields() const {
    return {{"coord_valid", c.valid}, {"face", c.face},        {"u", c.u},           {"v", c.v},
            {"wu", c.wu},             {"wv", c.wv},            {"map00", entries[0]}, {"map10", entries[1]},
            {"map01", entries[2]},    {"map11", entries[3]}};
  }
};
struct ValueOut {
  uint32_t value = 0;
  bool operator==(const ValueOut& o) const { return value == o.value; }
  Fields fields() const { return {{"value", value}}; }
};

class ReflectanceBench : public Bench<Vcube4_shade_reflectance, MapIn, ValueOut> {
 public:
  static constexpr int kLatency = 3;
  ReflectanceBench() : Bench("cube4_shade_reflectance", kLatency) {
    m->we_i = 0;
    start();
  }
  void load(const std::vector<uint32_t>& m_) {
    drain();
    map = m_;
    for (size_t i = 0; i < map.size(); ++i) {
      m->we_i = 1;
      put(m->waddr_i, static_cast<int64_t>(i), clog2(6 * p.map_face_res * p.map_face_res));
      put(m->wdata_i, map[i], p.map_bits);
      idle();
    }
    m->we_i = 0;
  }
  void look_up(bool valid, const g::CubeCoord& c) {
    MapIn in{c, {}};
    if (c.valid) {
      const int res = p.map_face_res;
      in.entries = {map[g::map_index(c.face, c.u, c.v, res)], map[g::map_index(c.face, c.u + 1, c.v, res)],
                    map[g::map_index(c.face, c.u, c.v + 1, res)], map[g::map_index(c.face, c.u + 1, c.v + 1, res)]};
    }
    step(valid, in);
  }
  g::Precision p = kP;
  std::vector<uint32_t> map;

 protected:
  void drive(const MapIn& in) override {
    const int cell = clog2(p.map_face_res);
    m->coord_valid_i = in.c.valid;
    put(m->face_i, in.c.face, 3);
    put(m->u_i, in.c.u, cell);
    put(m->v_i, in.c.v, cell);
    put(m->wu_i, in.c.wu, p.weight_bits + 1);
    put(m->wv_i, in.c.wv, p.weight_bits + 1);
  }
  ValueOut read() override { return {static_cast<uint32_t>(get(m->value_o, p.map_bits))}; }
  ValueOut golden(const MapIn& in) override { return {g::reflectance_lookup(map, in.c, p)}; }
};

std::vector<uint32_t> random_map(Random& rnd, const g::Precision& p) {
  std::vector<uint32_t> map(static_cast<size_t>(6) * p.map_face_res * p.map_face_res);
  const int64_t max = g::max_unsigned(p.map_bits);
  for (auto& v : map)
    v = static_cast<uint32_t>(rnd.chance(0.5) ? rnd.edgy(max, 0.3)
                                              : rnd.range(0, std::min<int64_t>(max, 2 << p.map_frac_bits)));
  return map;
}

g::CubeCoord random_coord(Random& rnd, const g::Precision& p) {
  g::CubeCoord c;
  const int64_t wmax = int64_t{1} << p.weight_bits;
  c.valid = !rnd.chance(0.05);
  if (!c.valid && rnd.chance(0.5)) {  // junk in the other fields, as a gap would have
    c.face = static_cast<int>(rnd.bits(3));
    c.u = static_cast<uint32_t>(rnd.bits(clog2(p.map_face_res)));
    c.v = static_cast<uint32_t>(rnd.bits(clog2(p.map_face_res)));
    c.wu = static_cast<uint32_t>(rnd.bits(p.weight_bits + 1));
    c.wv = static_cast<uint32_t>(rnd.bits(p.weight_bits + 1));
    return c;
  }
  if (!c.valid) return c;
  c.face = static_cast<int>(rnd.range(0, 5));
  c.u = static_cast<uint32_t>(rnd.range(0, p.map_face_res - 2));
  c.v = static_cast<uint32_t>(rnd.range(0, p.map_face_res - 2));
  c.wu = static_cast<uint32_t>(rnd.edgy(wmax, 0.2));
  c.wv = static_cast<uint32_t>(rnd.edgy(wmax, 0.2));
  return c;
}

TEST(RtlShadeReflectance, EveryCellAndWeightCorner) {
  ReflectanceBench b;
  Random rnd(401);
  b.load(random_map(rnd, kP));
  const uint32_t w1 = 1u << kP.weight_bits;
  const uint32_t ws[] = {0, 1, w1 / 2 - 1, w1 / 2, w1 - 1, w1};
  for (int face = 0; face < 6; ++face)
    for (int v = 0; v <= kP.map_face_res - 2; ++v)
      for (int u = 0; u <= kP.map_face_res - 2; ++u)
        for (uint32_t wu : ws)
          for (uint32_t wv : ws) {
            g::CubeCoord c;
            c.valid = true;
            c.face = face;
            c.u = static_cast<uint32_t>(u);
            c.v = static_cast<uint32_t>(v);
            c.wu = wu;
            c.wv = wv;
            b.look_up(!rnd.chance(0.1), c);
          }
  b.look_up(true, g::CubeCoord{});  // the zero vector: no light
  EXPECT_TRUE(b.result());
}

TEST(RtlShadeReflectance, RandomMapsAndCoordinates) {
  ReflectanceBench b;
  Random rnd(402);
  const long n = rtl::vector_count(1000000);
  const long block = 50000;
  for (long done = 0; done < n;) {
    b.load(random_map(rnd, kP));
    const Gaps gaps = random_gaps(rnd);
    for (long i = 0; i < block && done < n; ++i) {
      const bool v = gaps.valid(rnd);
      b.look_up(v, random_coord(rnd, kP));
      done += v;
    }
  }
  EXPECT_TRUE(b.result());
}

TEST(RtlShadeReflectance, HostDriverMaps) {
  ReflectanceBench b;
  Random rnd(403);
  const g::HostProgram h = sphere_program(kShadedSphere);
  for (const std::vector<uint32_t>* map : {&h.regs.diffuse_map, &h.regs.specular_map}) {
    ASSERT_EQ(map->size(), static_cast<size_t>(6 * kP.map_face_res * kP.map_face_res));
    b.load(*map);
    for (int i = 0; i < 100000; ++i) {
      const g::Gradient gr = random_gradient(rnd, kP);
      b.look_up(!rnd.chance(0.1), g::cube_coordinates(gr.x, gr.y, gr.z, kP));
    }
  }
  EXPECT_TRUE(b.result());
}

// ===========================================================================
// cube4_shade_phong
// ===========================================================================
struct PhongIn {
  g::Rgb color{0, 0, 0};
  uint32_t id = 0, is = 0, gd = 0, gs = 0;
  g::ShadeCoefs k;
  Fields fields() const {
    return {{"red", color[0]}, {"green", color[1]}, {"blue", color[2]}, {"id", id},
            {"is", is},        {"gd", gd},          {"gs", gs},         {"ke", k.ke},
            {"kd", k.kd},      {"ks", k.ks},        {"spec_red", k.specular[0]},
            {"spec_green", k.specular[1]},          {"spec_blue", k.specular[2]}};
  }
};
struct RgbOut {
  g::Rgb rgb{0, 0, 0};
  bool operator==(const RgbOut& o) const { return rgb == o.rgb; }
  Fields fields() const { return {{"red", rgb[0]}, {"green", rgb[1]}, {"blue", rgb[2]}}; }
};

class PhongBench : public Bench<Vcube4_shade_phong, PhongIn, RgbOut> {
 public:
  static constexpr int kLatency = 3;
  PhongBench() : Bench("cube4_shade_phong", kLatency) { start(); }
  void coefs(const g::ShadeCoefs& c) {
    drain();
    k = c;
    put(m->ke_i, c.ke, p.coef_bits);
    put(m->kd_i, c.kd, p.coef_bits);
    put(m->ks_i, c.ks, p.coef_bits);
    put(m->spec_red_i, c.specular[0], p.alpha_bits);
    put(m->spec_green_i, c.specular[1], p.alpha_bits);
    put(m->spec_blue_i, c.specular[2], p.alpha_bits);
  }
  void sample(bool valid, PhongIn in) {
    in.k = k;
    step(valid, in);
  }
  g::Precision p = kP;
  g::ShadeCoefs k;

 protected:
  void drive(const PhongIn& in) override {
    put(m->red_i, in.color[0], p.alpha_bits);
    put(m->green_i, in.color[1], p.alpha_bits);
    put(m->blue_i, in.color[2], p.alpha_bits);
    put(m->id_i, in.id, p.map_bits);
    put(m->is_i, in.is, p.map_bits);
    put(m->gd_i, in.gd, p.alpha_bits);
    put(m->gs_i, in.gs, p.alpha_bits);
  }
  RgbOut read() override {
    return {{static_cast<uint32_t>(m->red_o), static_cast<uint32_t>(m->green_o), static_cast<uint32_t>(m->blue_o)}};
  }
  RgbOut golden(const PhongIn& in) override { return {g::phong(in.color, in.id, in.is, in.gd, in.gs, in.k, p)}; }
};

g::ShadeCoefs random_coefs(Random& rnd, const g::Precision& p) {
  g::ShadeCoefs k;
  const int64_t cmax = g::max_unsigned(p.coef_bits), one = int64_t{1} << p.coef_frac_bits;
  auto coef = [&] { return static_cast<uint32_t>(rnd.chance(0.5) ? rnd.edgy(cmax, 0.3) : rnd.range(0, one)); };
  k.ke = coef();
  k.kd = coef();
  k.ks = coef();
  for (auto& s : k.specular) s = static_cast<uint32_t>(rnd.edgy(g::max_unsigned(p.alpha_bits), 0.3));
  return k;
}

PhongIn random_phong_in(Random& rnd, const g::Precision& p) {
  PhongIn in;
  const int64_t amax = g::max_unsigned(p.alpha_bits), mmax = g::max_unsigned(p.map_bits);
  const int64_t mone = int64_t{1} << p.map_frac_bits;
  for (auto& c : in.color) c = static_cast<uint32_t>(rnd.edgy(amax, 0.2));
  in.id = static_cast<uint32_t>(rnd.chance(0.5) ? rnd.edgy(mmax, 0.2) : rnd.range(0, std::min(mmax, 2 * mone)));
  in.is = static_cast<uint32_t>(rnd.chance(0.5) ? rnd.edgy(mmax, 0.2) : rnd.range(0, std::min(mmax, 2 * mone)));
  in.gd = static_cast<uint32_t>(rnd.edgy(amax, 0.3));
  in.gs = static_cast<uint32_t>(rnd.edgy(amax, 0.3));
  return in;
}

TEST(RtlShadePhong, SaturationAndZeros) {
  PhongBench b;
  const uint32_t amax = 4095, mmax = 65535, cmax = 1023;
  const std::vector<g::ShadeCoefs> ks = {
      {cmax, cmax, cmax, {amax, amax, amax}},  // everything saturates
      {0, 0, 0, {0, 0, 0}},                    // black
      {256, 0, 0, {0, 0, 0}},                  // ke = 1.0: colour unchanged
      {0, 256, 0, {0, 0, 0}},                  // pure diffuse
      {0, 0, 256, {amax, 0, amax / 2}},        // pure specular
      {38, 218, 90, {amax, amax, amax}},       // the default material
  };
  const uint32_t colors[] = {0, 1, 2048, 4094, amax};
  const uint32_t maps[] = {0, 1, 255, 256, 257, 1024, mmax - 1, mmax};
  const uint32_t gms[] = {0, 1, 2048, 4094, amax};
  for (const g::ShadeCoefs& k : ks) {
    b.coefs(k);
    for (uint32_t c : colors)
      for (uint32_t id : maps)
        for (uint32_t is : maps)
          for (uint32_t gm : gms) {
            PhongIn in;
            in.color = {c, amax - c, c / 2};
            in.id = id;
            in.is = is;
            in.gd = gm;
            in.gs = amax - gm;
            b.sample(true, in);
          }
  }
  EXPECT_TRUE(b.result());
}

TEST(RtlShadePhong, Random) {
  PhongBench b;
  Random rnd(501);
  const long n = rtl::vector_count(1000000);
  const long block = 10000;
  for (long done = 0; done < n;) {
    b.coefs(random_coefs(rnd, kP));
    const Gaps gaps = random_gaps(rnd);
    for (long i = 0; i < block && done < n; ++i) {
      const bool v = gaps.valid(rnd);
      b.sample(v, random_phong_in(rnd, kP));
      done += v;
    }
  }
  EXPECT_TRUE(b.result());
}

// ===========================================================================
// cube4_shade: the whole unit against golden shade_sample()
// ===========================================================================
struct ShaderIn {
  g::Neighbourhood n;  // what the golden shade_sample() is given
  g::Gradient grad;    // what the RTL is given: the gradient unit's output ...
  uint32_t mag = 0;    // ... and the magnitude unit's
  uint32_t modes = 0;  // gradient, magnitude, shading, specular, gm_opacity, gm_diffuse, gm_specular
  g::ShadeCoefs k;
  g::Eye eye{0, 0, 0};
  Fields fields() const {
    return {{"sample", n.centre},          {"grad_x", grad.x},
            {"grad_y", grad.y},            {"grad_z", grad.z},
            {"grad_mag", mag},             {"gradient", modes & 1},
            {"magnitude", modes >> 1 & 1}, {"shading", modes >> 2 & 1},
            {"specular", modes >> 3 & 1},  {"gm_opacity", modes >> 4 & 1},
            {"gm_diffuse", modes >> 5 & 1}, {"gm_specular", modes >> 6 & 1},
            {"ke", k.ke},                  {"kd", k.kd},
            {"ks", k.ks},                  {"spec_red", k.specular[0]},
            {"spec_green", k.specular[1]}, {"spec_blue", k.specular[2]},
            {"eye_x", eye[0]},             {"eye_y", eye[1]},
            {"eye_z", eye[2]},             {"tag", n.tag}};
  }
};
struct ShadedOut {
  g::Rgb rgb{0, 0, 0};
  uint32_t alpha = 0, value = 0;
  bool operator==(const ShadedOut& o) const { return rgb == o.rgb && alpha == o.alpha && value == o.value; }
  Fields fields() const {
    return {{"red", rgb[0]}, {"green", rgb[1]}, {"blue", rgb[2]}, {"alpha", alpha}, {"value", value}};
  }
};

bool same_entries(const std::vector<g::ClassEntry>& a, const std::vector<g::ClassEntry>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const g::ClassEntry& x, const g::ClassEntry& y) {
    return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a;
  });
}

template <class M>
class ShaderBench : public Bench<M, ShaderIn, ShadedOut> {
  using Base = Bench<M, ShaderIn, ShadedOut>;

 public:
  // reflection 4 + cube_coord 1 + ceil((clog2(res) + W) / DivBitsPerStage) + reflectance 3 + phong 3
  static int latency_of(const g::Precision& p, int div_bits) { return 10 + CubeCoordBench::latency_of(p, div_bits); }
  // has_shading = false: a variant without shading hardware (HasShading =
  // 0), which equals golden with shading off whatever shading_i says.
  ShaderBench(const std::string& name, const g::Precision& prec, int div_bits, bool has_shading = true)
      : Base(name, latency_of(prec, div_bits)), p(prec), has_shading_(has_shading) {
    M& m = *this->m;
    m.class_we_i = m.gmlut_we_i = m.dmap_we_i = m.smap_we_i = 0;
    this->start();
  }

  // Loads tables and frame registers (the pipeline drains first). The
  // golden side uses a copy with cropping and the cut plane off: those act
  // in the compositor.
  void program(const g::Registers& regs) {
    this->drain();
    M& m = *this->m;
    auto tick = [this] { this->idle(); };
    if (!same_entries(r.classification, regs.classification)) rtl::load_class_table(m, p, regs.classification, tick);
    if (r.gm_lut != regs.gm_lut) rtl::load_gm_lut(m, p, regs.gm_lut, tick);
    if (r.diffuse_map != regs.diffuse_map) rtl::load_map(m, p, rtl::Map::Diffuse, regs.diffuse_map, tick);
    if (r.specular_map != regs.specular_map) rtl::load_map(m, p, rtl::Map::Specular, regs.specular_map, tick);
    if (p.tag_bits > 0) rtl::load_materials(m, p, regs.tag_coefs, tick);
    r = regs;
    r.crop_enabled = false;
    r.cut_enabled = false;
    rtl::drive_shade_registers(m, regs);
    if (!has_shading_) r.shading = false;
    modes = (r.gradient ? 1u : 0u) | (r.magnitude ? 2u : 0u) | (r.shading ? 4u : 0u) | (r.specular ? 8u : 0u) |
            (r.gm_opacity ? 16u : 0u) | (r.gm_diffuse ? 32u : 0u) | (r.gm_specular ? 64u : 0u);
  }

  // One sample: the RTL gets the gradient and magnitude the upstream units
  // would deliver (zero when the gradient unit is off, as golden Gradient{}).
  void sample(bool valid, const g::Neighbourhood& n) {
    ShaderIn in;
    in.n = n;
    if (r.gradient) in.grad = g::sample_gradient(r, c, n);
    in.mag = g::gradient_magnitude(in.grad, p);
    in.modes = modes;
    in.k = r.coefs_of(n.tag);
    in.eye = r.eye;
    this->step(valid, in);
  }

  g::Precision p;
  bool has_shading_ = true;
  g::Registers r;
  g::SliceControl c;  // weights irrelevant: the 2x2 neighbourhoods are flat
  uint32_t modes = 0;

 protected:
  void drive(const ShaderIn& in) override {
    M& m = *this->m;
    put(m.sample_i, in.n.centre, p.voxel_bits);
    put(m.grad_x_i, in.grad.x, p.gradient_bits);
    put(m.grad_y_i, in.grad.y, p.gradient_bits);
    put(m.grad_z_i, in.grad.z, p.gradient_bits);
    put(m.grad_mag_i, in.mag, p.magnitude_bits);
    if (p.tag_bits > 0) put(m.vtag_i, in.n.tag, p.tag_bits);
  }
  ShadedOut read() override {
    M& m = *this->m;
    return {{static_cast<uint32_t>(get(m.red_o, p.alpha_bits)), static_cast<uint32_t>(get(m.green_o, p.alpha_bits)),
             static_cast<uint32_t>(get(m.blue_o, p.alpha_bits))},
            static_cast<uint32_t>(get(m.alpha_o, p.alpha_bits)),
            static_cast<uint32_t>(get(m.value_o, p.voxel_bits))};
  }
  ShadedOut golden(const ShaderIn& in) override {
    const g::ShadedSample s = g::shade_sample(r, c, 0, 0, in.n);
    return {s.rgb, s.alpha, s.value};
  }
};

// A neighbourhood whose golden gradient is exactly `gr` (|components| <=
// 2^(GradientBits-1) - 1): differences of gr << gradient_shift, flat 2x2
// neighbourhoods ahead and behind (supersampling 1).
g::Neighbourhood neighbourhood_for(const g::Gradient& gr, uint32_t centre, const g::Precision& p) {
  g::Neighbourhood n;
  n.centre = centre;
  const int sh = p.gradient_shift;
  auto pair = [&](int32_t comp, uint32_t& lo, uint32_t& hi) {
    const int64_t d = int64_t{comp} << sh;
    lo = static_cast<uint32_t>(d >= 0 ? 0 : -d);
    hi = static_cast<uint32_t>(lo + d);
  };
  pair(gr.x, n.left, n.right);
  pair(gr.y, n.up, n.down);
  uint32_t behind = 0, ahead = 0;
  pair(gr.z, behind, ahead);
  n.behind = {behind, behind, behind, behind};
  n.ahead = {ahead, ahead, ahead, ahead};
  return n;
}

g::Neighbourhood random_neighbourhood(Random& rnd, const g::Precision& p) {
  const uint32_t sample = static_cast<uint32_t>(rnd.bits(p.voxel_bits));
  if (rnd.chance(0.25)) {  // anything at all: large differences saturate
    g::Neighbourhood n;
    n.centre = sample;
    for (uint32_t* v : {&n.left, &n.right, &n.up, &n.down}) *v = static_cast<uint32_t>(rnd.bits(p.voxel_bits));
    for (auto& v : n.behind) v = static_cast<uint32_t>(rnd.bits(p.voxel_bits));
    for (auto& v : n.ahead) v = static_cast<uint32_t>(rnd.bits(p.voxel_bits));
    if (p.tag_bits > 0) n.tag = static_cast<uint32_t>(rnd.bits(p.tag_bits));
    return n;
  }
  g::Neighbourhood n = neighbourhood_for(random_gradient(rnd, p), sample, p);
  if (p.tag_bits > 0) n.tag = static_cast<uint32_t>(rnd.bits(p.tag_bits));
  return n;
}

// With tags: a material per tag, entry 0 the frame registers' (as the host driver sets them).
void random_materials(Random& rnd, g::Registers& r) {
  r.tag_coefs.clear();
  for (int t = 0; r.p.tag_bits > 0 && t < (1 << r.p.tag_bits); ++t)
    r.tag_coefs.push_back(t == 0 ? r.coefs : random_coefs(rnd, r.p));
}

// Random tables and frame registers; modes from `bits` (ShaderIn::modes order).
g::Registers random_registers(Random& rnd, const g::Precision& p, uint32_t bits) {
  g::Registers r;
  r.p = p;
  r.classification = random_class_table(rnd, p);
  r.gm_lut = random_gmlut(rnd, p);
  r.diffuse_map = random_map(rnd, p);
  r.specular_map = random_map(rnd, p);
  r.coefs = random_coefs(rnd, p);
  random_materials(rnd, r);
  r.eye = random_eye(rnd, p);
  r.gradient = bits & 1;
  r.magnitude = bits >> 1 & 1;
  r.shading = bits >> 2 & 1;
  r.specular = bits >> 3 & 1;
  r.gm_opacity = bits >> 4 & 1;
  r.gm_diffuse = bits >> 5 & 1;
  r.gm_specular = bits >> 6 & 1;
  return r;
}

template <class M>
void shader_random(const std::string& name, const g::Precision& p, int div_bits, long n, bool has_shading = true) {
  ShaderBench<M> b(name, p, div_bits, has_shading);
  Random rnd(601);
  const long block = 8000;
  g::Registers regs;
  uint32_t combo = 0;
  for (long done = 0; done < n; ++combo) {
    // Every mode combination in turn; the tables change every 16 blocks,
    // the coefficients and the eye every block.
    if (combo % 16 == 0) {
      regs = random_registers(rnd, p, 0);
    } else {
      regs.coefs = random_coefs(rnd, p);
      random_materials(rnd, regs);
      regs.eye = random_eye(rnd, p);
    }
    const uint32_t bits = combo % 8 == 7 ? 0x7Fu : static_cast<uint32_t>(rnd.bits(7));
    regs.gradient = (bits & 1) != 0 || combo % 3 != 0;  // mostly on: shading needs it
    regs.magnitude = bits >> 1 & 1;
    regs.shading = bits >> 2 & 1;
    regs.specular = bits >> 3 & 1;
    regs.gm_opacity = bits >> 4 & 1;
    regs.gm_diffuse = bits >> 5 & 1;
    regs.gm_specular = bits >> 6 & 1;
    b.program(regs);
    const Gaps gaps = random_gaps(rnd);
    for (long i = 0; i < block && done < n; ++i) {
      const bool v = gaps.valid(rnd);
      b.sample(v, random_neighbourhood(rnd, p));
      done += v;
    }
  }
  EXPECT_TRUE(b.result());
  EXPECT_GE(b.vectors, static_cast<uint64_t>(n));
}

TEST(RtlShade, RandomTablesAndModes) {
  shader_random<Vcube4_shade>("cube4_shade", kP, 2, rtl::vector_count(1000000));
}

// Voxel tags (bela §III): 2-bit tags, random per sample, address their own
// classification entries and shade with their own material.
TEST(RtlShade, VoxelTagsClassifyAndShadeByTheirTag) {
  shader_random<Vcube4_shade_t2>("cube4_shade (2-bit tags)", tagged_precision(), 2, rtl::vector_count(1000000));
}

// Without shading hardware (HasShading = 0, what the system uses for scenes
// without shading): every mode combination, shading_i random and ignored.
TEST(RtlShade, WithoutShadingHardware) {
  shader_random<Vcube4_shade_noshade>("cube4_shade (HasShading=0)", kP, 2, rtl::vector_count(300000), false);
}

// The host driver's tables and registers for sphere scenes, and samples
// from the sphere itself (voxel neighbourhoods, the golden gradient).
template <class M>
void shader_host(const std::string& name, const g::Precision& p, int div_bits, const std::string& precision_json) {
  ShaderBench<M> b(name, p, div_bits);
  Random rnd(602);
  const std::string variants[] = {
      kShadedSphere,
      // Shaded, no specular, no modulation.
      R"("material": {"ke": 0.2, "kd": 1.5, "ks": 0})",
      // Unshaded MIP: no gradient at all.
      R"("shading": false, "blend": "mip")",
      // Opacity modulation only, strong specular.
      R"("gradient_modulation": {"opacity": true},)"
      R"( "material": {"ke": 0, "kd": 0.5, "ks": 3.5, "specular_color": [1, 0.5, 0]})",
  };
  for (const std::string& extra : variants) {
    g::Volume vol;
    const g::HostProgram h = sphere_program(extra + precision_json, &vol);
    b.program(h.regs);
    const auto& d = vol.dim;
    auto at = [&](int x, int y, int z) -> uint32_t {
      if (x < 0 || y < 0 || z < 0 || x >= d[0] || y >= d[1] || z >= d[2]) return 0;
      return vol.at(x, y, z);
    };
    for (int z = 0; z < d[2]; ++z)
      for (int y = 0; y < d[1]; ++y)
        for (int x = 0; x < d[0]; ++x) {
          g::Neighbourhood n;
          n.centre = at(x, y, z);
          n.left = at(x - 1, y, z);
          n.right = at(x + 1, y, z);
          n.up = at(x, y - 1, z);
          n.down = at(x, y + 1, z);
          n.behind = {at(x, y, z - 1), at(x + 1, y, z - 1), at(x, y + 1, z - 1), at(x + 1, y + 1, z - 1)};
          n.ahead = {at(x, y, z + 1), at(x + 1, y, z + 1), at(x, y + 1, z + 1), at(x + 1, y + 1, z + 1)};
          b.sample(!rnd.chance(0.1), n);
        }
    // And random samples and gradients through the same tables.
    for (int i = 0; i < 50000; ++i) b.sample(!rnd.chance(0.1), random_neighbourhood(rnd, p));
  }
  EXPECT_TRUE(b.result());
}

TEST(RtlShade, HostDriverSphereScenes) { shader_host<Vcube4_shade>("cube4_shade", kP, 2, ""); }

// Other widths (rtl/groups/shader.cmake verilates cube4_shade with the same
// values): odd colour/alpha/GmLUT ratios, a non-power-of-two map face, a
// 3-bit-per-stage divider; and the smallest widths: GmLUT wider than alpha,
// 2x2 map faces, no coefficient fraction bits, a 1-bit-per-stage divider.
g::Precision wide_precision() {
  g::Precision p;
  p.voxel_bits = 10;
  p.weight_bits = 6;
  p.gradient_bits = 10;
  p.gradient_shift = 1;
  p.magnitude_bits = 9;
  p.color_bits = 5;
  p.alpha_bits = 14;
  p.gmlut_bits = 10;
  p.map_face_res = 5;
  p.map_bits = 20;
  p.map_frac_bits = 11;
  p.coef_bits = 12;
  p.coef_frac_bits = 9;
  p.eye_bits = 10;
  return p;
}
const char* kWidePrecisionJson =
    R"(, "precision": {"voxel_bits": 10, "weight_bits": 6, "gradient_bits": 10, "gradient_shift": 1,)"
    R"( "magnitude_bits": 9, "color_bits": 5, "alpha_bits": 14, "gmlut_bits": 10, "map_face_res": 5,)"
    R"( "map_bits": 20, "map_frac_bits": 11, "coef_bits": 12, "coef_frac_bits": 9, "eye_bits": 10})";

g::Precision small_precision() {
  g::Precision p;
  p.voxel_bits = 8;
  p.weight_bits = 2;
  p.gradient_bits = 4;
  p.gradient_shift = 5;
  p.magnitude_bits = 4;
  p.color_bits = 8;
  p.alpha_bits = 8;
  p.gmlut_bits = 16;
  p.map_face_res = 2;
  p.map_bits = 8;
  p.map_frac_bits = 7;
  p.coef_bits = 4;
  p.coef_frac_bits = 0;
  p.eye_bits = 4;
  return p;
}
const char* kSmallPrecisionJson =
    R"(, "precision": {"voxel_bits": 8, "weight_bits": 2, "gradient_bits": 4, "gradient_shift": 5,)"
    R"( "magnitude_bits": 4, "color_bits": 8, "alpha_bits": 8, "gmlut_bits": 16, "map_face_res": 2,)"
    R"( "map_bits": 8, "map_frac_bits": 7, "coef_bits": 4, "coef_frac_bits": 0, "eye_bits": 4})";

TEST(RtlShade, OtherWidthsWide) {
  shader_random<Vcube4_shade_wide>("cube4_shade (wide widths)", wide_precision(), 3, 300000);
  shader_host<Vcube4_shade_wide>("cube4_shade (wide widths)", wide_precision(), 3, kWidePrecisionJson);
}

TEST(RtlShade, OtherWidthsSmall) {
  shader_random<Vcube4_shade_small>("cube4_shade (small widths)", small_precision(), 1, 300000);
  shader_host<Vcube4_shade_small>("cube4_shade (small widths)", small_precision(), 1, kSmallPrecisionJson);
}

}  // namespace
