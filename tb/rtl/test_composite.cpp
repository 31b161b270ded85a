// RTL equivalence tests of the compositor datapath, cube4_composite:
// cropping, block window, cut plane and blend, against golden
// crop_and_cut() (golden/pipeline.hpp) and blend()
// (golden/units/composite.hpp); with polygons, the Z test and the double
// composition against golden sample_before_z() and double_composite()
// (golden/units/composite_polygon.hpp).
//
// Driven cycle by cycle, back to back and with random valid gaps (junk data
// in the gaps); the predecessor accumulator of a sample is driven
// kAccDelay cycles after the sample, as the unit's contract says, and junk
// in the other cycles. Every output is compared with the golden result of
// the input that entered kLatency cycles earlier (rtl_check.hpp). Frame
// registers (mode, crop, window, cut) change only after the pipeline has drained.
//
// CUBE4_RTL_VECTORS overrides the random vector count (default 1,000,000).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "Vcube4_composite.h"
#include "Vcube4_composite_narrow.h"
#include "Vcube4_composite_nocut.h"
#include "Vcube4_composite_nopoly.h"
#include "Vcube4_composite_volumepro.h"
#include "golden/host_driver.hpp"
#include "golden/pipeline.hpp"
#include "golden/scene_io.hpp"
#include "golden/units/composite_polygon.hpp"
#include "golden/volume_io.hpp"
#include "systemc/rtl/vl_context.hpp"
#include "tb/rtl/hybrid_scene.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;
using rtl::Random;

constexpr int kLatency = 7;
constexpr int kAccDelay = 6;

// The unit's widths: the golden precision plus the RTL's register widths.
struct Widths {
  g::Precision p;
  int pos_bits = 16;       // cube4_composite PosBits
  int cut_coef_bits = 12;  // cube4_composite CutCoefBits
  int inv_bits() const { return p.alpha_bits + g::kCutInvShift; }
  int64_t pos_max() const { return (int64_t{1} << pos_bits) - 1; }
  int64_t amax() const { return g::max_unsigned(p.alpha_bits); }
  int acc_bits() const { return g::acc_bits(p); }
  int64_t accmax() const { return g::max_unsigned(acc_bits()); }
  int64_t vmax() const { return g::max_unsigned(p.voxel_bits); }
  int64_t wmax() const { return g::max_unsigned(p.weight_bits); }
};
const Widths kW;  // the defaults

// Other widths (rtl/groups/shader.cmake verilates Vcube4_composite_narrow
// with the same values).
Widths narrow_widths() {
  Widths w;
  w.p.voxel_bits = 10;
  w.p.weight_bits = 6;
  w.p.alpha_bits = 14;
  w.p.cut_bits = 24;
  w.pos_bits = 12;
  w.cut_coef_bits = 12;
  return w;
}
// VolumePro's compositor (Vcube4_composite_volumepro): the accumulator is
// the sample's width, every product rounded to it.
Widths volumepro_widths() {
  Widths w;
  w.p.alpha_bits = 12;
  w.p.acc_guard_bits = 0;
  return w;
}
const char* kVolumeProPrecisionJson = R"(, "precision": {"alpha_bits": 12, "acc_guard_bits": 0})";

const char* kNarrowPrecisionJson =
    R"(, "precision": {"voxel_bits": 10, "weight_bits": 6, "alpha_bits": 14, "cut_bits": 24})";

template <class T>
void put(T& port, int64_t v, int bits) {
  rtl::put_bits(port, 0, bits, static_cast<uint64_t>(v));
}

// Frame registers of the compositor.
struct Config {
  g::BlendMode mode = g::BlendMode::Composite;
  uint8_t mode_bits = 0;  // as driven (3 also means composite)
  bool crop_enabled = false;
  g::CropRegs crop;
  bool cut_enabled = false;
  g::CutRegs cut;
  bool window_enabled = false;
  g::WindowRegs window;
  bool poly_enabled = false;  // polygons (the blend mode is then composite)
};

struct CompIn {
  g::ShadedSample s;  // rgb, alpha, value; visible is decided in the unit
  int32_t x = 0, y = 0, z = 0;
  uint32_t wx = 0, wy = 0, wz = 0;
  g::RayAcc acc;
  // Polygons: the sample's slice, its ray's depth, the slab pixel behind it.
  uint32_t k = 0, ray_z = g::kZNone;
  g::Pixel slab;
  Config cfg;
  Fields fields() const {
    const g::CropRegs& c = cfg.crop;
    const g::CutRegs& k = cfg.cut;
    return {{"red", s.rgb[0]},
            {"green", s.rgb[1]},
            {"blue", s.rgb[2]},
            {"alpha", s.alpha},
            {"value", s.value},
            {"x", x},
            {"y", y},
            {"z", z},
            {"wx", wx},
            {"wy", wy},
            {"wz", wz},
            {"acc_red", acc.r},
            {"acc_green", acc.g},
            {"acc_blue", acc.b},
            {"acc_alpha", acc.a},
            {"acc_value", acc.value},
            {"acc_selected", acc.valid},
            {"blend_mode", cfg.mode_bits},
            {"crop_enabled", cfg.crop_enabled},
            {"crop_x_lo", c.slab[0][0]},
            {"crop_x_hi", c.slab[0][1]},
            {"crop_y_lo", c.slab[1][0]},
            {"crop_y_hi", c.slab[1][1]},
            {"crop_z_lo", c.slab[2][0]},
            {"crop_z_hi", c.slab[2][1]},
            {"crop_mask", c.mask},
            {"cut_enabled", cfg.cut_enabled},
            {"cut_a", k.a},
            {"cut_b", k.b},
            {"cut_c", k.c},
            {"cut_dmin", k.dmin},
            {"cut_dmax", k.dmax},
            {"cut_falloff", k.falloff},
            {"cut_inv_falloff", static_cast<int64_t>(k.inv_falloff)},
            {"cut_keep_inside", k.keep_inside},
            {"window_enabled", cfg.window_enabled},
            {"window_x_lo", cfg.window.range[0][0]},
            {"window_x_hi", cfg.window.range[0][1]},
            {"window_y_lo", cfg.window.range[1][0]},
            {"window_y_hi", cfg.window.range[1][1]},
            {"window_z_lo", cfg.window.range[2][0]},
            {"window_z_hi", cfg.window.range[2][1]},
            {"poly_enabled", cfg.poly_enabled},
            {"k", this->k},
            {"ray_z", ray_z},
            {"slab_red", slab.r},
            {"slab_green", slab.g},
            {"slab_blue", slab.b},
            {"slab_alpha", slab.a}};
  }
};

struct AccOut {
  g::RayAcc acc;
  bool operator==(const AccOut& o) const { return acc == o.acc; }
  Fields fields() const {
    return {{"red", acc.r},     {"green", acc.g},     {"blue", acc.b},
            {"alpha", acc.a},   {"value", acc.value}, {"selected", acc.valid}};
  }
};

// The frame registers as golden holds them.
g::Registers registers_of(const Config& c, const g::Precision& p) {
  g::Registers r;
  r.p = p;
  r.blend = c.mode;
  r.crop_enabled = c.crop_enabled;
  r.crop = c.crop;
  r.cut_enabled = c.cut_enabled;
  r.cut = c.cut;
  r.window_enabled = c.window_enabled;
  r.window = c.window;
  return r;
}

// The golden composition: golden crop_and_cut() (cropping, block window,
// cut plane) of the sample at its position, then blend(); with polygons the
// Z test and double_composite() instead of blend().
g::RayAcc golden_composite(const CompIn& in, const g::Precision& p) {
  g::SliceControl sc;
  sc.z_voxel = in.z;
  sc.wx = in.wx;
  sc.wy = in.wy;
  sc.wz = in.wz;
  g::ShadedSample s = in.s;
  s.visible = true;
  s = g::crop_and_cut(registers_of(in.cfg, p), sc, in.x, in.y, s);
  if (in.cfg.poly_enabled)
    return g::double_composite(in.acc, s, g::sample_before_z(static_cast<int>(in.k), in.ray_z), in.slab, p);
  return g::blend(in.cfg.mode, in.acc, s, p);
}

template <class M>
class CompositeBench {
 public:
  // has_cut_plane = false: a variant without cut-plane hardware (HasCutPlane
  // = 0), which equals golden with the cut plane off whatever cut_enabled_i says;
  // has_polygons = false likewise (HasPolygons = 0, poly_enabled_i ignored).
  explicit CompositeBench(const Widths& widths = kW, const std::string& name = "cube4_composite",
                          bool has_cut_plane = true, bool has_polygons = true)
      : m(cube4::rtl::make_dut<M>()), sb(name, kLatency), w(widths), has_cut_plane_(has_cut_plane),
        has_polygons_(has_polygons), junk_(9001) {
    m->valid_i = 0;
    rtl::reset(*m);
  }
  ~CompositeBench() { m->final(); }

  void configure(const Config& c) {
    drain();
    cfg = c;
    put(m->blend_mode_i, c.mode_bits, 2);
    m->crop_enabled_i = c.crop_enabled;
    put(m->crop_x_lo_i, c.crop.slab[0][0], w.pos_bits);
    put(m->crop_x_hi_i, c.crop.slab[0][1], w.pos_bits);
    put(m->crop_y_lo_i, c.crop.slab[1][0], w.pos_bits);
    put(m->crop_y_hi_i, c.crop.slab[1][1], w.pos_bits);
    put(m->crop_z_lo_i, c.crop.slab[2][0], w.pos_bits);
    put(m->crop_z_hi_i, c.crop.slab[2][1], w.pos_bits);
    put(m->crop_mask_i, c.crop.mask, 8);
    m->cut_enabled_i = c.cut_enabled;
    put(m->cut_a_i, c.cut.a, w.cut_coef_bits);
    put(m->cut_b_i, c.cut.b, w.cut_coef_bits);
    put(m->cut_c_i, c.cut.c, w.cut_coef_bits);
    put(m->cut_dmin_i, c.cut.dmin, w.p.cut_bits);
    put(m->cut_dmax_i, c.cut.dmax, w.p.cut_bits);
    put(m->cut_falloff_i, c.cut.falloff, w.p.cut_bits);
    put(m->cut_inv_falloff_i, static_cast<int64_t>(c.cut.inv_falloff), w.inv_bits());
    m->cut_keep_inside_i = c.cut.keep_inside;
    m->window_enabled_i = c.window_enabled;
    put(m->window_x_lo_i, c.window.range[0][0], w.pos_bits);
    put(m->window_x_hi_i, c.window.range[0][1], w.pos_bits);
    put(m->window_y_lo_i, c.window.range[1][0], w.pos_bits);
    put(m->window_y_hi_i, c.window.range[1][1], w.pos_bits);
    put(m->window_z_lo_i, c.window.range[2][0], w.pos_bits);
    put(m->window_z_hi_i, c.window.range[2][1], w.pos_bits);
    m->poly_enabled_i = c.poly_enabled;
  }

  void step(bool valid, CompIn in) {
    in.cfg = cfg;
    if (!has_cut_plane_) in.cfg.cut_enabled = false;
    if (!has_polygons_) in.cfg.poly_enabled = false;
    const g::Precision& p = w.p;
    const int a = p.alpha_bits, ab = w.acc_bits();
    m->valid_i = valid;
    put(m->red_i, in.s.rgb[0], a);
    put(m->green_i, in.s.rgb[1], a);
    put(m->blue_i, in.s.rgb[2], a);
    put(m->alpha_i, in.s.alpha, a);
    put(m->value_i, in.s.value, p.voxel_bits);
    put(m->x_i, in.x, w.pos_bits);
    put(m->y_i, in.y, w.pos_bits);
    put(m->z_i, in.z, w.pos_bits);
    put(m->wx_i, in.wx, p.weight_bits);
    put(m->wy_i, in.wy, p.weight_bits);
    put(m->wz_i, in.wz, p.weight_bits);
    put(m->slice_k_i, in.k, 16);
    put(m->ray_z_i, in.ray_z, g::kZBits);
    // The accumulator and slab pixel of the sample driven kAccDelay cycles
    // ago, else junk.
    g::RayAcc acc;
    g::Pixel slab;
    if (!pending_.empty() && pending_.front().cycle + kAccDelay == cycle) {
      acc = pending_.front().acc;
      slab = pending_.front().slab;
      pending_.pop_front();
    } else {
      slab = {static_cast<uint16_t>(junk_.bits(a)), static_cast<uint16_t>(junk_.bits(a)),
              static_cast<uint16_t>(junk_.bits(a)), static_cast<uint16_t>(junk_.bits(a))};
      acc.r = static_cast<uint32_t>(junk_.bits(ab));
      acc.g = static_cast<uint32_t>(junk_.bits(ab));
      acc.b = static_cast<uint32_t>(junk_.bits(ab));
      acc.a = static_cast<uint32_t>(junk_.bits(ab));
      acc.value = static_cast<uint16_t>(junk_.bits(p.voxel_bits));
      acc.valid = junk_.chance(0.5);
    }
    put(m->acc_red_i, acc.r, ab);
    put(m->acc_green_i, acc.g, ab);
    put(m->acc_blue_i, acc.b, ab);
    put(m->acc_alpha_i, acc.a, ab);
    put(m->acc_value_i, acc.value, p.voxel_bits);
    m->acc_selected_i = acc.valid;
    put(m->slab_red_i, slab.r, a);
    put(m->slab_green_i, slab.g, a);
    put(m->slab_blue_i, slab.b, a);
    put(m->slab_alpha_i, slab.a, a);
    rtl::settle(*m);
    sb.observe(cycle, m->valid_o, read());
    if (valid) {
      const g::RayAcc expected = golden_composite(in, p);
      count(in, expected);
      sb.expect(cycle, in, {expected});
      pending_.push_back({cycle, in.acc, in.slab});
      ++vectors;
    }
    rtl::rise(*m);
    ++cycle;
  }

  void drain() {
    for (int i = 0; i <= kLatency; ++i) step(false, junk_sample());
  }
  ::testing::AssertionResult result() {
    drain();
    sb.finish();
    std::printf("  %s (%llu cycles)\n    covered: %s\n", sb.report().c_str(), static_cast<unsigned long long>(cycle),
                coverage.str().c_str());
    if (sb.ok()) return ::testing::AssertionSuccess() << sb.report();
    return ::testing::AssertionFailure() << sb.report();
  }

  // What the checked samples exercised (from golden values only).
  struct Coverage {
    uint64_t crop_hidden = 0, crop_shown = 0, window_hidden = 0, window_shown = 0, d_saturated = 0, cut_full = 0, cut_zero = 0, cut_ramp = 0,
             extreme_taken = 0, extreme_kept = 0, extreme_tie = 0, ftb_saturated = 0, ftb_opaque = 0,
             z_hidden = 0, z_shown = 0, z_on_sample = 0, slab_blank = 0, slab_shown = 0;
    std::string str() const {
      return "crop hidden/shown " + std::to_string(crop_hidden) + "/" + std::to_string(crop_shown) +
             ", window hidden/shown " + std::to_string(window_hidden) + "/" + std::to_string(window_shown) +
             ", cut factor one/zero/ramp " + std::to_string(cut_full) + "/" + std::to_string(cut_zero) + "/" +
             std::to_string(cut_ramp) + ", d saturated " + std::to_string(d_saturated) +
             ", MIP/MinIP taken/kept/ties " + std::to_string(extreme_taken) + "/" + std::to_string(extreme_kept) +
             "/" + std::to_string(extreme_tie) + ", front-to-back colour saturated " + std::to_string(ftb_saturated) +
             ", opaque accumulator " + std::to_string(ftb_opaque) + ", Z hidden/shown/on the sample " +
             std::to_string(z_hidden) + "/" + std::to_string(z_shown) + "/" + std::to_string(z_on_sample) +
             ", slab pixel blank/shown " + std::to_string(slab_blank) + "/" + std::to_string(slab_shown);
    }
  } coverage;

  cube4::rtl::Dut<M> m;
  rtl::Scoreboard<CompIn, AccOut> sb;
  Widths w;
  Config cfg;
  uint64_t cycle = 0, vectors = 0;

 private:
  AccOut read() const {
    AccOut o;
    o.acc.r = static_cast<uint32_t>(m->red_o);
    o.acc.g = static_cast<uint32_t>(m->green_o);
    o.acc.b = static_cast<uint32_t>(m->blue_o);
    o.acc.a = static_cast<uint32_t>(m->alpha_o);
    o.acc.value = static_cast<uint16_t>(m->value_o);
    o.acc.valid = m->selected_o;
    return o;
  }
  void count(const CompIn& in, const g::RayAcc& out) {
    const g::Precision& p = w.p;
    Coverage& c = coverage;
    if (in.cfg.crop_enabled) ++(g::crop_visible(in.x, in.y, in.z, in.cfg.crop) ? c.crop_shown : c.crop_hidden);
    if (in.cfg.window_enabled) ++(g::window_inside(in.x, in.y, in.z, in.cfg.window) ? c.window_shown : c.window_hidden);
    if (in.cfg.cut_enabled) {
      const int wb = p.weight_bits;
      const int64_t d = g::cut_distance(in.cfg.cut, (int64_t{in.x} << wb) + in.wx, (int64_t{in.y} << wb) + in.wy,
                                        (int64_t{in.z} << wb) + in.wz, p);
      if (std::abs(d) == g::max_signed(p.cut_bits)) ++c.d_saturated;
      const uint32_t f = g::cut_factor(d, in.cfg.cut, p);
      ++(f == w.amax() ? c.cut_full : f == 0 ? c.cut_zero : c.cut_ramp);
    }
    if (in.cfg.poly_enabled) {
      ++(g::sample_before_z(static_cast<int>(in.k), in.ray_z) ? c.z_shown : c.z_hidden);
      if (in.ray_z == in.k << g::kZFracBits) ++c.z_on_sample;
      ++(g::blank(in.slab) ? c.slab_blank : c.slab_shown);
    }
    if (in.cfg.mode == g::BlendMode::Mip || in.cfg.mode == g::BlendMode::MinIp) {
      ++(out == in.acc ? c.extreme_kept : c.extreme_taken);
      if (in.acc.valid && in.s.value == in.acc.value) ++c.extreme_tie;
    } else {
      if (in.acc.a == w.accmax()) ++c.ftb_opaque;
      for (uint32_t ch : {out.r, out.g, out.b})
        if (ch == w.accmax()) ++c.ftb_saturated;
    }
  }

  CompIn junk_sample() {
    CompIn in;
    const int a = w.p.alpha_bits;
    in.s.rgb = {static_cast<uint32_t>(junk_.bits(a)), static_cast<uint32_t>(junk_.bits(a)),
                static_cast<uint32_t>(junk_.bits(a))};
    in.s.alpha = static_cast<uint32_t>(junk_.bits(a));
    in.x = static_cast<int32_t>(junk_.bits(w.pos_bits));
    return in;
  }

  bool has_cut_plane_ = true, has_polygons_ = true;
  struct Pending {
    uint64_t cycle;
    g::RayAcc acc;
    g::Pixel slab;
  };
  std::deque<Pending> pending_;
  Random junk_;
};

// ---------------------------------------------------------------------------
// Stimulus.

g::RayAcc random_acc(Random& rnd, const Widths& w) {
  g::RayAcc a;
  a.r = static_cast<uint32_t>(rnd.edgy(w.accmax(), 0.2));
  a.g = static_cast<uint32_t>(rnd.edgy(w.accmax(), 0.2));
  a.b = static_cast<uint32_t>(rnd.edgy(w.accmax(), 0.2));
  a.a = static_cast<uint32_t>(rnd.edgy(w.accmax(), 0.3));
  a.value = static_cast<uint16_t>(rnd.edgy(w.vmax(), 0.1));
  a.valid = rnd.chance(0.7);
  return a;
}

CompIn random_sample(Random& rnd, const Widths& w, int64_t pos_max) {
  CompIn in;
  const int64_t amax = w.amax();
  in.s.rgb = {static_cast<uint32_t>(rnd.edgy(amax, 0.2)), static_cast<uint32_t>(rnd.edgy(amax, 0.2)),
              static_cast<uint32_t>(rnd.edgy(amax, 0.2))};
  in.s.alpha = static_cast<uint32_t>(rnd.edgy(amax, 0.3));
  in.acc = random_acc(rnd, w);
  // Ties with the accumulator (MIP/MinIP) and neighbours.
  in.s.value = static_cast<uint32_t>(rnd.chance(0.3)
                                         ? std::clamp<int64_t>(in.acc.value + rnd.range(-1, 1), 0, w.vmax())
                                         : rnd.edgy(w.vmax(), 0.1));
  in.x = static_cast<int32_t>(rnd.range(0, pos_max));
  in.y = static_cast<int32_t>(rnd.range(0, pos_max));
  in.z = static_cast<int32_t>(rnd.range(0, pos_max));
  in.wx = static_cast<uint32_t>(rnd.edgy(w.wmax(), 0.1));
  in.wy = static_cast<uint32_t>(rnd.edgy(w.wmax(), 0.1));
  in.wz = static_cast<uint32_t>(rnd.edgy(w.wmax(), 0.1));
  // Polygons: depths on, next to and far from the sample's slice; slab
  // pixels blank, premultiplied (as the host makes them) or any bits.
  in.k = static_cast<uint32_t>(rnd.chance(0.5) ? rnd.range(0, 40) : rnd.edgy((1 << 15) - 1, 0.1));
  const int64_t kz = int64_t{in.k} << g::kZFracBits;
  in.ray_z = static_cast<uint32_t>(rnd.chance(0.6)  ? std::clamp<int64_t>(kz + rnd.range(-2, 2), 0, g::kZNone)
                                   : rnd.chance(0.3) ? g::kZNone
                                                     : rnd.range(0, g::kZNone));
  if (rnd.chance(0.4)) {
    in.slab = {};
  } else if (rnd.chance(0.7)) {
    const g::Rgb c{static_cast<uint32_t>(rnd.edgy(amax, 0.2)), static_cast<uint32_t>(rnd.edgy(amax, 0.2)),
                   static_cast<uint32_t>(rnd.edgy(amax, 0.2))};
    in.slab = g::polygon_pixel(c, static_cast<uint32_t>(rnd.edgy(amax, 0.3)), w.p);
  } else {
    in.slab = {static_cast<uint16_t>(rnd.edgy(amax, 0.2)), static_cast<uint16_t>(rnd.edgy(amax, 0.2)),
               static_cast<uint16_t>(rnd.edgy(amax, 0.2)), static_cast<uint16_t>(rnd.edgy(amax, 0.2))};
  }
  return in;
}

// Host computation of inv_falloff (host_driver.cpp's formula in integers).
uint64_t inv_falloff(int64_t falloff, const g::Precision& p) {
  if (falloff <= 0) return 0;
  const int64_t num = g::max_unsigned(p.alpha_bits) << g::kCutInvShift;
  return static_cast<uint64_t>((num + falloff / 2) / falloff);
}

// Uniform in [0, 2^b) for a random b in [0, max_bits].
int64_t log_uniform(Random& rnd, int max_bits) {
  const int b = static_cast<int>(rnd.range(0, max_bits));
  return b == 0 ? 0 : rnd.range(0, (int64_t{1} << b) - 1);
}

const uint8_t kMasks[] = {0x80, 0xFE, 0xE8, 0x7F, 0x01, 0x00, 0xFF, 0x17};

// An inclusive range of positions, for crop slabs and window bounds.
std::array<int32_t, 2> random_slab(Random& rnd, const Widths& w, int64_t pos_max) {
  if (rnd.chance(0.1)) return {1, 0};  // empty (the host's encoding of a slab outside the volume)
  if (rnd.chance(0.1)) return {0, static_cast<int32_t>(w.pos_max())};
  int32_t lo = static_cast<int32_t>(rnd.range(0, pos_max)), hi = static_cast<int32_t>(rnd.range(0, pos_max));
  if (lo > hi) std::swap(lo, hi);
  return {lo, hi};
}

Config random_config(Random& rnd, const Widths& w, int64_t pos_max) {
  const g::Precision& p = w.p;
  Config c;
  c.mode_bits = static_cast<uint8_t>(rnd.range(0, 3));
  c.mode = static_cast<g::BlendMode>(c.mode_bits);
  c.crop_enabled = rnd.chance(0.5);
  for (auto& s : c.crop.slab) s = random_slab(rnd, w, pos_max);
  c.crop.mask = rnd.chance(0.5) ? kMasks[rnd.range(0, 7)] : static_cast<uint8_t>(rnd.bits(8));
  c.window_enabled = rnd.chance(0.4);
  for (auto& s : c.window.range) s = random_slab(rnd, w, pos_max);
  c.cut_enabled = rnd.chance(0.6);
  const int64_t cmax = (int64_t{1} << (w.cut_coef_bits - 1)) - 1;
  if (rnd.chance(0.5)) {  // a host-like unit normal, 2^10 scale
    double d[3], n2 = 0;
    for (auto& v : d) {
      v = static_cast<double>(rnd.range(-1000, 1000));
      n2 += v * v;
    }
    const double n = n2 > 0 ? std::sqrt(n2) : 1;
    c.cut.a = static_cast<int32_t>(std::lround(d[0] / n * 1024));
    c.cut.b = static_cast<int32_t>(std::lround(d[1] / n * 1024));
    c.cut.c = static_cast<int32_t>(std::lround(d[2] / n * 1024));
  } else {
    c.cut.a = static_cast<int32_t>(rnd.range(-cmax - 1, cmax));
    c.cut.b = static_cast<int32_t>(rnd.range(-cmax - 1, cmax));
    c.cut.c = static_cast<int32_t>(rnd.range(-cmax - 1, cmax));
  }
  // The slab around the distance of a random position in the block's range.
  const int wb = p.weight_bits;
  const int64_t d0 = g::cut_distance(c.cut, rnd.range(0, pos_max) << wb, rnd.range(0, pos_max) << wb,
                                     rnd.range(0, pos_max) << wb, p);
  const int64_t dlim = g::max_signed(p.cut_bits);
  c.cut.dmin = std::clamp<int64_t>(d0 - log_uniform(rnd, 28), -dlim - 1, dlim);
  c.cut.dmax = std::clamp<int64_t>(c.cut.dmin + log_uniform(rnd, 28), -dlim - 1, dlim);
  if (rnd.chance(0.05)) std::swap(c.cut.dmin, c.cut.dmax);  // an empty slab: dmin > dmax
  c.cut.falloff = rnd.chance(0.1) ? 0 : log_uniform(rnd, std::min(30, p.cut_bits - 1));
  c.cut.inv_falloff = inv_falloff(c.cut.falloff, p);
  if (rnd.chance(0.2) && c.cut.falloff > 0) {
    // Any register value for which golden's int64 product cannot overflow.
    const int64_t lim = std::min<int64_t>((int64_t{1} << w.inv_bits()) - 1, (int64_t{1} << 62) / c.cut.falloff);
    c.cut.inv_falloff = static_cast<uint64_t>(rnd.range(0, lim));
  }
  c.cut.keep_inside = rnd.chance(0.6);
  // Polygons need the composite blend (mode 0, or 3, which also means it).
  c.poly_enabled = rnd.chance(0.4);
  if (c.poly_enabled) {
    c.mode_bits = rnd.chance(0.8) ? 0 : 3;
    c.mode = static_cast<g::BlendMode>(c.mode_bits);
  }
  return c;
}

// ---------------------------------------------------------------------------
// Test bodies, for any widths.

template <class M>
void composite_random(const Widths& w, const std::string& name, long n) {
  CompositeBench<M> b(w, name);
  Random rnd(701);
  const long block = 4000;
  for (long done = 0; done < n;) {
    const int64_t pos_max = rnd.chance(0.8) ? 63 : w.pos_max();
    b.configure(random_config(rnd, w, pos_max));
    const double gap = rnd.chance(0.5) ? 0.0 : 0.25;
    for (long i = 0; i < block && done < n; ++i) {
      const bool v = !rnd.chance(gap);
      b.step(v, random_sample(rnd, w, pos_max));
      done += v;
    }
  }
  EXPECT_TRUE(b.result());
  EXPECT_GE(b.vectors, static_cast<uint64_t>(n));
  const auto& c = b.coverage;
  for (uint64_t k : {c.crop_hidden, c.crop_shown, c.window_hidden, c.window_shown, c.d_saturated, c.cut_full, c.cut_zero, c.cut_ramp, c.extreme_taken,
                     c.extreme_kept, c.extreme_tie, c.ftb_saturated, c.ftb_opaque, c.z_hidden, c.z_shown,
                     c.z_on_sample, c.slab_blank, c.slab_shown})
    EXPECT_GT(k, 0u) << "random stimulus missed a case: " << c.str();
}

// Samples at every combination of positions one before, on and one after
// each bound of the three inclusive ranges (crop slabs or a window).
template <class M>
void sweep_bounds(CompositeBench<M>& b, Random& rnd, const Widths& w,
                  const std::array<std::array<int32_t, 2>, 3>& ranges) {
  std::array<std::vector<int32_t>, 3> pos;
  for (int i = 0; i < 3; ++i)
    for (int64_t v : {int64_t{ranges[i][0]} - 1, int64_t{ranges[i][0]}, int64_t{ranges[i][0]} + 1,
                      int64_t{ranges[i][1]} - 1, int64_t{ranges[i][1]}, int64_t{ranges[i][1]} + 1})
      if (v >= 0 && v <= w.pos_max()) pos[i].push_back(static_cast<int32_t>(v));
  for (int32_t x : pos[0])
    for (int32_t y : pos[1])
      for (int32_t z : pos[2]) {
        CompIn in = random_sample(rnd, w, 63);
        in.x = x;
        in.y = y;
        in.z = z;
        b.step(!rnd.chance(0.1), in);
      }
}

template <class M>
void composite_crop_boundaries(const Widths& w, const std::string& name) {
  CompositeBench<M> b(w, name);
  Random rnd(702);
  const int32_t top = static_cast<int32_t>(w.pos_max());
  const std::vector<std::array<std::array<int32_t, 2>, 3>> slab_sets = {
      {{{10, 20}, {30, 40}, {50, 60}}},
      {{{0, 0}, {7, 7}, {0, top}}},      // one-voxel slabs, the whole axis
      {{{1, 0}, {top, top}, {0, 1}}},    // empty (the host's encoding), the top edge
  };
  for (const auto& slabs : slab_sets) {
    std::vector<uint8_t> masks;
    for (int j = 0; j < 8; ++j) masks.push_back(static_cast<uint8_t>(1 << j));
    for (uint8_t mk : kMasks) masks.push_back(mk);
    for (uint8_t mask : masks) {
      Config c;
      c.crop_enabled = true;
      c.crop.slab = slabs;
      c.crop.mask = mask;
      c.mode_bits = static_cast<uint8_t>(rnd.range(0, 2));
      c.mode = static_cast<g::BlendMode>(c.mode_bits);
      b.configure(c);
      sweep_bounds(b, rnd, w, slabs);
    }
  }
  EXPECT_TRUE(b.result());
}

// The block window's bounds on every axis, alone and with cropping: each
// position one before, on and one after each bound, and the empty window.
template <class M>
void composite_window_boundaries(const Widths& w, const std::string& name) {
  CompositeBench<M> b(w, name);
  Random rnd(706);
  const int32_t top = static_cast<int32_t>(w.pos_max());
  const std::vector<std::array<std::array<int32_t, 2>, 3>> windows = {
      {{{1, 9}, {4, 4}, {0, 20}}},
      {{{0, top}, {2, 6}, {top, top}}},
      {{{1, 0}, {0, 5}, {3, 8}}},  // empty along x: nothing composites
  };
  for (const auto& win : windows)
    for (bool crop : {false, true}) {
      Config c;
      c.window_enabled = true;
      c.window.range = win;
      c.crop_enabled = crop;
      c.crop.slab = {{{0, 5}, {0, top}, {3, 30}}};
      c.crop.mask = 0xFE;  // union: visible in any slab
      c.mode_bits = static_cast<uint8_t>(rnd.range(0, 2));
      c.mode = static_cast<g::BlendMode>(c.mode_bits);
      b.configure(c);
      sweep_bounds(b, rnd, w, win);
    }
  EXPECT_TRUE(b.result());
  EXPECT_GT(b.coverage.window_hidden, 0u);
  EXPECT_GT(b.coverage.window_shown, 0u);
}

template <class M>
void composite_cut_boundaries(const Widths& w, const std::string& name) {
  CompositeBench<M> b(w, name);
  const g::Precision& p = w.p;
  Random rnd(703);
  const int wb = p.weight_bits;
  const int64_t wmask = w.wmax();
  const int64_t xmax = (w.pos_max() << wb) | wmask;  // the largest X = (x << W) + wx
  const int64_t falloffs[] = {0, 1, 2, 255, 256, 4096, 3 << 16, (int64_t{1} << 24) + 5};
  // d = X, Y or Z (one coefficient 1 or -1): every distance is reachable.
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {1, -1})
      for (bool thin : {false, true})
        for (int64_t falloff : falloffs)
          for (bool keep : {true, false}) {
            if (falloff > g::max_unsigned(p.cut_bits)) continue;  // outside the falloff register
            Config c;
            c.cut_enabled = true;
            c.mode_bits = static_cast<uint8_t>(rnd.range(0, 3));
            c.mode = static_cast<g::BlendMode>(c.mode_bits);
            (axis == 0 ? c.cut.a : axis == 1 ? c.cut.b : c.cut.c) = sign;
            const int64_t base = xmax / 4;  // room for a falloff below dmin
            c.cut.dmin = sign * (base + 7);
            c.cut.dmax = sign * (base + (thin ? 7 : (int64_t{50} << wb) + 3));
            if (c.cut.dmin > c.cut.dmax) std::swap(c.cut.dmin, c.cut.dmax);
            c.cut.falloff = falloff;
            c.cut.inv_falloff = inv_falloff(falloff, p);
            c.cut.keep_inside = keep;
            b.configure(c);
            std::vector<int64_t> ds;
            for (int64_t e : {c.cut.dmin, c.cut.dmax})
              for (int64_t off : {int64_t{0}, falloff})
                for (int64_t k : {-1, 0, 1}) {
                  ds.push_back(e - off + k);
                  ds.push_back(e + off + k);
                }
            for (int i = 0; i < 16; ++i) ds.push_back(rnd.range(c.cut.dmin - falloff - 2, c.cut.dmax + falloff + 2));
            const uint64_t ramp_before = b.coverage.cut_ramp;
            for (int64_t d : ds) {
              const int64_t pos = d * sign;  // the X (or Y, Z) at that distance
              if (pos < 0 || pos > xmax) continue;
              CompIn in = random_sample(rnd, w, 63);
              int32_t* coord[3] = {&in.x, &in.y, &in.z};
              uint32_t* weight[3] = {&in.wx, &in.wy, &in.wz};
              *coord[axis] = static_cast<int32_t>(pos >> wb);
              *weight[axis] = static_cast<uint32_t>(pos & wmask);
              b.step(true, in);
            }
            if (falloff > 1) {
              EXPECT_GT(b.coverage.cut_ramp, ramp_before) << "no sample in the fall-off ramp";
            }
          }
  // Saturated distances: |a X + b Y + c Z| beyond 2^(cut_bits-1) - 1.
  const int64_t dmax = g::max_signed(p.cut_bits);
  const int32_t cmax = static_cast<int32_t>((int64_t{1} << (w.cut_coef_bits - 1)) - 1);
  for (int sign : {1, -1})
    for (int64_t lo : {dmax - 3, dmax, -dmax - 1})
      for (int64_t falloff : {int64_t{0}, int64_t{10}, int64_t{1} << (p.cut_bits - 1)}) {
        Config c;
        c.cut_enabled = true;
        c.cut.a = c.cut.b = c.cut.c = sign > 0 ? cmax : -cmax - 1;
        c.cut.dmin = sign > 0 ? lo : -dmax - 1;
        c.cut.dmax = sign > 0 ? dmax : std::min(lo, -dmax + 3);
        c.cut.falloff = falloff;
        c.cut.inv_falloff = inv_falloff(falloff, p);
        c.cut.keep_inside = rnd.chance(0.5);
        b.configure(c);
        for (int i = 0; i < 200; ++i) {
          CompIn in = random_sample(rnd, w, w.pos_max());
          if (i < 100) in.x = in.y = in.z = static_cast<int32_t>(w.pos_max() - rnd.range(0, 3));
          b.step(true, in);
        }
      }
  EXPECT_TRUE(b.result());
}

template <class M>
void composite_ties_and_extremes(const Widths& w, const std::string& name) {
  CompositeBench<M> b(w, name);
  Random rnd(704);
  const int64_t amax = w.amax(), vmax = w.vmax(), accmax = w.accmax();
  const uint16_t aedge[] = {0, 1, static_cast<uint16_t>(amax / 2), static_cast<uint16_t>(amax - 1),
                            static_cast<uint16_t>(amax)};
  // The accumulator's edges are those of its own, wider domain.
  const uint32_t accedge[] = {0, 1, static_cast<uint32_t>(accmax / 2), static_cast<uint32_t>(accmax - 1),
                              static_cast<uint32_t>(accmax)};
  const uint16_t vedge[] = {0, 1, static_cast<uint16_t>(vmax / 2), static_cast<uint16_t>(vmax - 1),
                            static_cast<uint16_t>(vmax)};
  for (uint8_t mode : {0, 1, 2, 3})
    for (bool crop : {false, true}) {
      Config c;
      c.mode_bits = mode;
      c.mode = static_cast<g::BlendMode>(mode);
      c.crop_enabled = crop;  // with cropping, every sample at x = 1 is invisible
      const int32_t top = static_cast<int32_t>(w.pos_max());
      c.crop.slab = {{{0, 0}, {0, top}, {0, top}}};
      c.crop.mask = 0x80;
      b.configure(c);
      for (uint16_t acc_value : vedge)
        for (int dv : {-1, 0, 1})
          for (bool selected : {false, true})
            for (uint32_t acc_a : accedge)
              for (uint16_t alpha : aedge) {
                CompIn in = random_sample(rnd, w, 63);
                in.acc.value = acc_value;
                in.s.value = static_cast<uint32_t>(std::clamp<int64_t>(acc_value + dv, 0, vmax));
                in.acc.valid = selected;
                in.acc.a = acc_a;
                in.acc.r = in.acc.g = in.acc.b = accedge[rnd.range(0, 4)];
                in.s.alpha = alpha;
                in.s.rgb = {aedge[rnd.range(0, 4)], static_cast<uint32_t>(amax), 0};
                in.x = static_cast<int32_t>(rnd.range(0, 1));
                b.step(!rnd.chance(0.1), in);
              }
    }
  EXPECT_TRUE(b.result());
}

// Crop and cut registers from the real host driver (permuted for the view),
// positions and slice weights of every sample of the scene's slices.
template <class M>
void composite_host(const Widths& w, const std::string& name, const std::string& precision_json) {
  CompositeBench<M> b(w, name);
  Random rnd(705);
  const std::string scenes[] = {
      R"("cropping": {"x": [3, 15], "y": [5, 20], "combine": "cross"},
         "cut_plane": {"normal": [1, 0, 1], "dmin": 10, "dmax": 16, "falloff": 3, "keep": "outside"})",
      R"("cropping": {"z": [0, 9], "combine": "union", "invert": true}, "blend": "mip",
         "cut_plane": {"normal": [0.2, -1, 0.4], "dmin": -2, "dmax": 9.5, "falloff": 0})",
      R"("blend": "minip", "supersampling": 3,
         "cut_plane": {"normal": [-1, 2, 3], "dmin": 5, "dmax": 5, "falloff": 12.5})",
  };
  for (const std::string& extra : scenes) {
    const std::string json = R"({"volume": {"synthetic": "sphere", "size": [24, 20, 28]},)"
                             R"( "view": {"rotate": [25, 140, 10], "ray_offset": [0.3, 0.7]}, )" +
                             extra + precision_json + "}";
    const g::Scene s = g::parse_scene(json, "test_composite scene");
    const g::Volume vol = g::make_synthetic(s.volume, s.precision.voxel_bits);
    const g::HostProgram h = g::program_host(s, vol);
    const g::Registers& r = h.regs;
    Config c;
    c.mode = r.blend;
    c.mode_bits = static_cast<uint8_t>(r.blend);
    c.crop_enabled = r.crop_enabled;
    c.crop = r.crop;
    c.cut_enabled = r.cut_enabled;
    c.cut = r.cut;
    ASSERT_TRUE(c.cut_enabled);
    // The host's values lie in the RTL's register domain.
    const int64_t cmax = (int64_t{1} << (w.cut_coef_bits - 1)) - 1;
    for (int32_t k : {c.cut.a, c.cut.b, c.cut.c}) ASSERT_LE(std::abs(int64_t{k}), cmax);
    ASSERT_LE(std::abs(c.cut.dmin), g::max_signed(w.p.cut_bits));
    ASSERT_LE(std::abs(c.cut.dmax), g::max_signed(w.p.cut_bits));
    ASSERT_LT(c.cut.inv_falloff, uint64_t{1} << w.inv_bits());
    b.configure(c);
    for (int k = 0; k < r.sample_slices(); ++k) {
      const g::SliceControl sc = g::slice_control(r, k);
      for (int y = 0; y < r.dim[1]; ++y)
        for (int x = 0; x < r.dim[0]; ++x) {
          CompIn in = random_sample(rnd, w, 63);
          in.x = x;
          in.y = y;
          in.z = sc.z_voxel;
          in.wx = sc.wx;
          in.wy = sc.wy;
          in.wz = sc.wz;
          b.step(!rnd.chance(0.1), in);
        }
    }
  }
  EXPECT_TRUE(b.result());
}

// ---------------------------------------------------------------------------

TEST(RtlComposite, Random) { composite_random<Vcube4_composite>(kW, "cube4_composite", rtl::vector_count(1000000)); }

TEST(RtlComposite, CropSlabBoundariesForEveryMaskBit) {
  composite_crop_boundaries<Vcube4_composite>(kW, "cube4_composite");
}

TEST(RtlComposite, BlockWindowBoundaries) {
  composite_window_boundaries<Vcube4_composite>(kW, "cube4_composite");
}

TEST(RtlComposite, CutPlaneBoundaries) { composite_cut_boundaries<Vcube4_composite>(kW, "cube4_composite"); }

TEST(RtlComposite, MipMinIpTiesAndAlphaExtremes) {
  composite_ties_and_extremes<Vcube4_composite>(kW, "cube4_composite");
}

TEST(RtlComposite, HostDriverCropAndCut) { composite_host<Vcube4_composite>(kW, "cube4_composite", ""); }

// Random frames (random_config: cut plane and polygons on in the registers
// part of the time) through a variant without some hardware, whose bench
// turns that effect off in golden.
template <class M>
void random_frames(CompositeBench<M>& b, uint64_t salt) {
  Random rnd(salt);
  long n = 0;
  const long total = rtl::vector_count(300000);
  while (n < total) {
    b.configure(random_config(rnd, kW, 63));
    for (int i = 0; i < 3000; ++i) {
      const bool v = !rnd.chance(0.2);
      b.step(v, random_sample(rnd, kW, 63));
      n += v;
    }
  }
  EXPECT_TRUE(b.result());
}

// Without cut-plane hardware (HasCutPlane = 0, what the system uses for
// scenes without a cut plane): random frames with the cut plane enabled in
// the registers half the time, which the variant ignores; golden has it off.
TEST(RtlComposite, WithoutCutPlaneHardware) {
  CompositeBench<Vcube4_composite_nocut> b(kW, "cube4_composite (HasCutPlane=0)", false);
  random_frames(b, 907);
  EXPECT_GT(b.coverage.crop_hidden, 0u);
  EXPECT_GT(b.coverage.ftb_opaque, 0u);
  EXPECT_EQ(b.coverage.cut_ramp + b.coverage.cut_zero, 0u) << "the variant must see no cut plane";
}

// Without polygon hardware (HasPolygons = 0, what the system uses for
// scenes without polygons): random frames with polygons enabled in the
// registers 40 % of the time, which the variant ignores; golden has none.
TEST(RtlComposite, WithoutPolygonHardware) {
  CompositeBench<Vcube4_composite_nopoly> b(kW, "cube4_composite (HasPolygons=0)", true, false);
  random_frames(b, 909);
  EXPECT_GT(b.coverage.cut_ramp, 0u);
  EXPECT_EQ(b.coverage.z_hidden + b.coverage.slab_shown, 0u) << "the variant must see no polygons";
}

// The Z test's edges: a ray depth one below, on and one above the sample's
// slice (on the sample: hidden, the surface wins the tie), 0, kZNone, for
// slices 0, 1, a middle one and the last allowed (2^15 - 1); slab pixels
// blank, opaque and at the edges of α; accumulators empty, opaque and in
// between; with cropping (an invisible sample still gets its slab pixel).
template <class M>
void composite_z_and_slab_edges(const Widths& w, const std::string& name) {
  CompositeBench<M> b(w, name);
  Random rnd(711);
  const int64_t amax = w.amax();
  const uint32_t accedge[] = {0, 1, static_cast<uint32_t>(w.accmax() / 2), static_cast<uint32_t>(w.accmax())};
  std::vector<g::Pixel> slabs = {g::Pixel{}};
  for (int64_t alpha : {int64_t{1}, amax / 2, amax - 1, amax})
    for (int64_t c : {int64_t{0}, int64_t{1}, amax}) {
      const auto u = static_cast<uint32_t>(c);
      slabs.push_back(g::polygon_pixel({u, static_cast<uint32_t>(amax), 0}, static_cast<uint32_t>(alpha), w.p));
    }
  for (bool crop : {false, true}) {
    Config c;
    c.poly_enabled = true;
    c.crop_enabled = crop;  // with cropping, every sample at x = 1 is invisible
    const int32_t top = static_cast<int32_t>(w.pos_max());
    c.crop.slab = {{{0, 0}, {0, top}, {0, top}}};
    c.crop.mask = 0x80;
    b.configure(c);
    for (uint32_t k : {0u, 1u, 77u, (1u << 15) - 1})
      for (int64_t z : {int64_t{k} * 256 - 1, int64_t{k} * 256, int64_t{k} * 256 + 1, int64_t{0}, int64_t{g::kZNone}})
        for (const g::Pixel& slab : slabs)
          for (uint32_t acc_a : accedge) {
            if (z < 0) continue;
            CompIn in = random_sample(rnd, w, 63);
            in.k = k;
            in.ray_z = static_cast<uint32_t>(z);
            in.slab = slab;
            in.acc.a = acc_a;
            in.acc.r = in.acc.g = in.acc.b = std::min(acc_a, accedge[rnd.range(0, 3)]);
            in.x = static_cast<int32_t>(rnd.range(0, 1));
            b.step(!rnd.chance(0.1), in);
          }
  }
  EXPECT_TRUE(b.result());
  EXPECT_GT(b.coverage.z_on_sample, 0u);
  EXPECT_GT(b.coverage.z_hidden, 0u);
  EXPECT_GT(b.coverage.ftb_saturated + b.coverage.ftb_opaque, 0u);
}

TEST(RtlComposite, DepthExactlyOnASampleAndSlabPixelEdges) {
  composite_z_and_slab_edges<Vcube4_composite>(kW, "cube4_composite");
}

// A hybrid scene from the host: a tilted opaque plane (some of its depths
// fall exactly on a sample: "on the sample" in the coverage) and a tilted
// translucent one in front of it, rasterised by golden
// (golden/polygons.hpp); every sample of the scene's slices with
// its ray's Z (frame.z) and the slab pixel behind it (decode_beam of its
// slab image): the values the unit will receive at RTL.
TEST(RtlComposite, HostPolygonFrame) {
  const std::string json =
      R"({"volume": {"synthetic": "sphere", "size": [12, 10, 14]}, "supersampling": 2,
          "view": {"rotate": [20, 35, 5]},
          "polygons": [
            {"shape": "plane", "size": [30, 30], "transform": {"rotate": [10, 0, 0], "translate": [6, 5, 2.0]},
             "color": [0.9, 0.2, 0.1], "opacity": 1},
            {"shape": "plane", "size": [30, 30], "transform": {"rotate": [0, 15, 0], "translate": [6, 5, 8.0]},
             "color": [0.1, 0.3, 1], "opacity": 0.4, "lit": false}]})";
  const rtl::HybridScene hs = rtl::hybrid_scene(json, "test_composite polygon scene");
  const g::PolygonFrame& f = hs.frame;
  const g::Registers& r = hs.host.regs;
  std::printf("  fragments: opaque %llu, translucent %llu, hidden %llu, in front %llu, in slabs %llu, behind %llu\n",
              static_cast<unsigned long long>(f.counts.opaque), static_cast<unsigned long long>(f.counts.translucent),
              static_cast<unsigned long long>(f.counts.hidden), static_cast<unsigned long long>(f.counts.in_front),
              static_cast<unsigned long long>(f.counts.in_slabs), static_cast<unsigned long long>(f.counts.behind));
  ASSERT_GT(f.counts.in_slabs, 0u);
  ASSERT_GT(f.counts.opaque, 0u);
  CompositeBench<Vcube4_composite> b(kW, "cube4_composite (host polygon frame)");
  Random rnd(712);
  Config c;
  c.poly_enabled = true;
  b.configure(c);
  std::vector<g::Pixel> beam(static_cast<size_t>(r.dim[0]));
  for (int k = 0; k < r.sample_slices(); ++k) {
    const g::SliceControl sc = g::slice_control(r, k);
    const g::SlabImage& slab = f.slabs[static_cast<size_t>(k)];
    for (int y = 0; y < r.dim[1]; ++y) {
      slab.decode_beam(y, beam.data());
      for (int x = 0; x < r.dim[0]; ++x) {
        const int u = x - sc.ix + r.base_origin_x(), v = y - sc.iy + r.base_origin_y();
        CompIn in = random_sample(rnd, kW, 63);
        in.x = x;
        in.y = y;
        in.z = sc.z_voxel;
        in.k = static_cast<uint32_t>(k);
        in.ray_z = f.z[static_cast<size_t>(v) * static_cast<size_t>(f.width) + static_cast<size_t>(u)];
        in.slab = beam[static_cast<size_t>(x)];
        b.step(!rnd.chance(0.1), in);
      }
    }
  }
  EXPECT_TRUE(b.result());
  EXPECT_GT(b.coverage.z_hidden, 0u);
  EXPECT_GT(b.coverage.slab_shown, 0u);
}

TEST(RtlComposite, OtherWidths) {
  const Widths w = narrow_widths();
  const std::string name = "cube4_composite (narrow widths)";
  composite_random<Vcube4_composite_narrow>(w, name, 300000);
  composite_crop_boundaries<Vcube4_composite_narrow>(w, name);
  composite_window_boundaries<Vcube4_composite_narrow>(w, name);
  composite_cut_boundaries<Vcube4_composite_narrow>(w, name);
  composite_ties_and_extremes<Vcube4_composite_narrow>(w, name);
  composite_host<Vcube4_composite_narrow>(w, name, kNarrowPrecisionJson);
}

TEST(RtlComposite, VolumeProWidthsWithoutGuardBits) {
  const Widths w = volumepro_widths();
  const std::string name = "cube4_composite (AlphaBits=12, AccGuardBits=0)";
  composite_random<Vcube4_composite_volumepro>(w, name, 300000);
  composite_ties_and_extremes<Vcube4_composite_volumepro>(w, name);
  composite_host<Vcube4_composite_volumepro>(w, name, kVolumeProPrecisionJson);
}

}  // namespace

namespace {

// What the system model relies on for X-randomisation (systemc/core/system.cpp
// seeds one VerilatedContext per frame): with random reset, the registers the
// RTL does not reset start from the context's seed, so two seeds are two
// initial states, and one seed is one.
TEST(RtlComposite, RandomResetFollowsTheContextsSeed) {
  auto initial_state = [](int seed) {
    cube4::rtl::ScopedVerilatedContext ctx;
    ctx->randReset(2);
    ctx->randSeed(seed);
    Vcube4_composite m(ctx.get(), "seeded");
    m.eval();
    // Output registers of stage 7 are not reset (only the valid chain is).
    return std::array<uint64_t, 4>{uint64_t{m.red_o}, uint64_t{m.green_o}, uint64_t{m.blue_o}, uint64_t{m.alpha_o}};
  };
  EXPECT_EQ(initial_state(1), initial_state(1));
  EXPECT_NE(initial_state(1), initial_state(2));
}

}  // namespace
