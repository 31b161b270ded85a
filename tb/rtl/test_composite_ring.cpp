// RTL tests of the compositing unit with its ray storage and ray alignment:
// cube4_composite_ring (p = 1, 2, 4, 5 pipelines) against the golden
// renderer's base plane.
//
// Each scene is built with the golden host driver. Its shaded samples come
// from golden render_fixed() itself: a SampleProbe collects every sample's
// ShadedSample from a render with cropping and the cut plane switched off
// (shade_sample() applies them last, so these are exactly the samples the
// compositor receives: rgb, α, value before cropping and cut plane; the
// ring applies both from the frame registers). The samples are streamed
// into the verilated ring cycle by cycle, slice by slice, beam by beam,
// partial beam by partial beam, with the slice control of golden
// slice_control(); the pixels the ring emits are collected into a base
// plane, which must equal golden render_fixed()'s (with cropping and cut
// plane) bit for bit in all four channels. Besides, every pixel must appear
// exactly in the cycle the unit's contract gives (7 cycles after the
// sample that ends its ray; which samples end a ray is golden ray_leaves()
// of the next slice, or the last slice), on the sample's pipeline, once.
// Random idle cycles between partial beams, junk on every input while
// valid_i is low and junk samples in the padding columns (x >= nx) check
// that only valid_i and real columns matter. Nothing here re-implements the
// compositing.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "Vcube4_composite_ring.h"
#include "Vcube4_composite_ring_p1.h"
#include "Vcube4_composite_ring_p2.h"
#include "Vcube4_composite_ring_p5.h"
#include "golden/pipeline.hpp"
#include "golden/renderers.hpp"
#include "tb/rtl/ring_bench.hpp"
#include "golden/blocks.hpp"
#include "golden/units/composite_polygon.hpp"
#include "tb/rtl/hybrid_scene.hpp"
#include "systemc/rtl/polygon_streams.hpp"
#include "systemc/rtl/unit_registers.hpp"
#include "systemc/rtl/unit_streams.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace sysc = cube4::sysc;
using namespace cube4::rtl;  // the shared bench: rtl_check.hpp, ring_bench.hpp

// Ring parameters, as in rtl/groups/composite.cmake.
// The ring is verilated with the golden defaults (its parameters' defaults).
constexpr g::Precision kDefaults{};
constexpr int kVoxelBits = kDefaults.voxel_bits, kWeightBits = kDefaults.weight_bits,
              kAlphaBits = kDefaults.alpha_bits, kPosBits = g::kPositionBits;
// From a sample to the pixel of the ray it ends.
constexpr int kLatency = 7;


// ===========================================================================
// Scenes and the golden results.

struct Sample {
  uint32_t r = 0, g = 0, b = 0, a = 0, value = 0;
};

struct Frame : RingFrame {
  g::BasePlane golden;  // render_fixed(), with cropping, cut plane and accumulators
  int last_ix = 0, last_iy = 0;
  std::vector<g::SliceControl> ctrl;  // per sample slice
  std::vector<Sample> samples;        // [(k * ny + y) * nx + x], before cropping and cut plane
  const Sample& at(int k, int x, int y) const { return samples[(static_cast<size_t>(k) * ny + y) * nx + x]; }
  // Coverage: pixels that are not zero, pixels that cropping and the cut
  // plane change, slices with dx = 1 / dy = 1.
  int lit_pixels = 0, clipped_pixels = 0, dx_slices = 0, dy_slices = 0;
  // A hybrid scene's polygon images (Cube-5), made by the host rasteriser
  // with the ring's p lanes; null: no polygons.
  std::shared_ptr<g::PolygonFrame> poly;
};

void finish_frame(Frame* f);

// Every shaded sample of the render, once.
struct Collect : g::SampleProbe {
  Frame& f;
  std::vector<int> count;
  bool all_visible = true;
  explicit Collect(Frame& fr) : f(fr), count(fr.samples.size(), 0) {}
  void sample(int, int, const g::SliceControl&, uint32_t, const g::Gradient&) override {}
  void shaded(int x, int y, const g::SliceControl& c, const g::ShadedSample& s) override {
    const size_t i = (static_cast<size_t>(c.k) * f.ny + y) * f.nx + x;
    f.samples[i] = {s.rgb[0], s.rgb[1], s.rgb[2], s.alpha, s.value};
    ++count[i];
    if (!s.visible) all_visible = false;
  }
};


// What is rendered, besides volume and view: blend mode, shading, cropping,
// cut plane (JSON members of the scene).
struct Effects {
  const char* name;
  const char* json;
};
// Low opacities and coloured transfer functions, so every sample of a ray
// leaves a trace in the composited pixel.
const char* kTransfer =
    R"("transfer": {"color": [[0, 1, 0.2, 0], [0.5, 0, 1, 0.3], [1, 0.1, 0, 1]],)"
    R"( "opacity": [[0, 0.02], [0.4, 0.1], [1, 0.35]]})";
const std::vector<Effects> kEffects = {
    {"composite shaded", R"("shading": true)"},
    {"mip", R"("shading": false, "blend": "mip")"},
    {"minip", R"("shading": false, "blend": "minip")"},
    {"composite cropped", R"("shading": true, "cropping": {"x": [2, 8], "y": [1, 9], "combine": "cross"})"},
    {"composite cut plane",
     R"("shading": false, "cut_plane": {"normal": [1, 0.5, 1], "dmin": 5, "dmax": 9, "falloff": 2.5})"},
    {"mip cropped and cut",
     R"("shading": false, "blend": "mip", "cropping": {"z": [1, 4], "x": [3, 20], "combine": "union", "invert": true},)"
     R"( "cut_plane": {"normal": [-0.3, 1, 0.2], "dmin": 2, "dmax": 5, "falloff": 1.5, "keep": "outside"})"},
    {"minip cut plane",
     R"("shading": false, "blend": "minip", "cut_plane": {"normal": [0.2, 0.1, 1], "dmin": 1, "dmax": 4, "falloff": 0})"},
};

struct VolumeSpec {
  const char* kind;  // "sphere" or "noise"
  std::array<int, 3> size;
  int seed;
};

// block >= 0: that block of the volume cut 2x2x2 (golden/blocks.hpp): its
// volume and its registers, with the block window.
const Frame& frame(const VolumeSpec& vs, const std::array<double, 3>& dir, const std::array<double, 3>& up, int S,
                   const Effects& fx, const std::string& view_name, int block = -1) {
  std::ostringstream js;
  js << R"({"volume": {"synthetic": ")" << vs.kind << R"(", "size": [)" << vs.size[0] << ", " << vs.size[1] << ", "
     << vs.size[2] << "]";
  if (std::string(vs.kind) == "noise") js << R"(, "seed": )" << vs.seed;
  js << R"(}, "view": {"direction": )" << vec_json(dir) << R"(, "up": )" << vec_json(up) << R"(, "ray_offset": [0.3, 0.6]})"
     << R"(, "supersampling": )" << S << ", " << kTransfer << ", " << fx.json << "}";
  const std::string json = js.str();
  return cached_frame<Frame>(json + " block " + std::to_string(block), [&](Frame& fr) {
    Frame* f = &fr;
    std::ostringstream n;
    n << fx.name << ", " << vs.kind << " " << vs.size[0] << "x" << vs.size[1] << "x" << vs.size[2] << ", view "
      << view_name << ", S=" << S;
    if (block >= 0) n << ", block " << block << " of 2x2x2";
    f->load(json, "test_composite_ring.json", n.str());
    if (block >= 0) {
      const g::BlockPlan plan = g::plan_blocks(f->regs, f->vol.dim, {2, 2, 2}, "test blocks");
      const g::Block& b = plan.blocks.at(static_cast<size_t>(block));
      f->use(g::block_volume(f->vol, b), b.regs);
      EXPECT_TRUE(f->regs.window_enabled) << f->name;
    }
    finish_frame(f);
  });
}

// The golden results of a loaded frame: its base plane (with polygons, if
// any) and the samples the compositor receives (without cropping, cut
// plane, window and polygons: every sample of every ray, shaded).
void finish_frame(Frame* f) {
  const g::Registers& r = f->regs;
  const g::Volume& vol = f->vol;
  // Pixel (x - ix + last_ix, y - iy + last_iy): the last slice's offsets
  // and a polygon scene's margins.
  f->last_ix = r.base_origin_x();
  f->last_iy = r.base_origin_y();
  for (int k = 0; k < f->K; ++k) f->ctrl.push_back(g::slice_control(r, k));
  // The golden base plane, and the samples the compositor receives.
  g::FixedOptions with_acc;
  with_acc.accumulators = true;
  with_acc.polygons = f->poly.get();
  f->golden = g::render_fixed(vol, r, with_acc);
  g::Registers open = r;
  open.crop_enabled = false;
  open.cut_enabled = false;
  open.window_enabled = false;
  f->samples.assign(static_cast<size_t>(f->K) * f->ny * f->nx, Sample{});
  Collect probe(*f);
  const g::BasePlane unclipped = g::render_fixed(vol, open, nullptr, {}, &probe);
  for (size_t i = 0; i < f->golden.rgba.size(); i += 4) {
    bool lit = false, clipped = false;
    for (int c = 0; c < 4; ++c) {
      lit |= f->golden.rgba[i + c] != 0;
      clipped |= f->golden.rgba[i + c] != unclipped.rgba[i + c];
    }
    f->lit_pixels += lit;
    f->clipped_pixels += clipped;
  }
  for (const g::SliceControl& c : f->ctrl) {
    f->dx_slices += c.dx;
    f->dy_slices += c.dy;
  }
  for (int c : probe.count)
    if (c != 1) ADD_FAILURE() << f->name << ": the golden probe saw a sample " << c << " times";
  EXPECT_TRUE(probe.all_visible) << f->name << ": a sample is invisible without cropping and cut plane";
  // The stream's preconditions: offsets that move by 0 or 1 per slice, in
  // the RTL's position range.
  for (const g::SliceControl& c : f->ctrl) {
    EXPECT_TRUE(c.dx == 0 || c.dx == 1) << f->name << ": dx = " << c.dx << " in slice " << c.k;
    EXPECT_TRUE(c.dy == 0 || c.dy == 1) << f->name << ": dy = " << c.dy << " in slice " << c.k;
    EXPECT_TRUE(c.ix >= 0 && c.iy >= 0 && c.ix <= f->last_ix && c.iy <= f->last_iy) << f->name;
  }
  if (!f->poly) {
    EXPECT_EQ(f->golden.width, f->nx + f->last_ix);
    EXPECT_EQ(f->golden.height, f->ny + f->last_iy);
  }
}

// A hybrid scene (volume and polygons) for a ring of p pipelines: its slab
// lines are the ring's lanes ("pipelines": p).
const Frame& polygon_frame(const std::string& scene_json, int p, const std::string& name) {
  const std::string json = scene_json.substr(0, scene_json.rfind('}')) + R"(, "pipelines": )" + std::to_string(p) + "}";
  return cached_frame<Frame>(json, [&](Frame& fr) {
    const HybridScene h = hybrid_scene(json, "test_composite_ring polygon scene");
    fr.name = name + ", p=" + std::to_string(p);
    fr.use(h.volume, h.host.regs);
    fr.poly = std::make_shared<g::PolygonFrame>(h.frame);
    finish_frame(&fr);
  });
}

// ===========================================================================
// The stream.

// Frame registers of the compositor (changed only while nothing is in flight).
// A frame's registers; the ring sees the compositing ones.
struct Config {
  g::Registers r;
  bool polygons = false;
  bool operator==(const Config& o) const {
    const g::CutRegs &c = r.cut, &d = o.r.cut;
    return polygons == o.polygons && r.blend == o.r.blend && r.crop_enabled == o.r.crop_enabled && r.crop.slab == o.r.crop.slab &&
           r.crop.mask == o.r.crop.mask && r.window_enabled == o.r.window_enabled &&
           r.window.range == o.r.window.range && r.cut_enabled == o.r.cut_enabled && c.a == d.a && c.b == d.b &&
           c.c == d.c && c.dmin == d.dmin && c.dmax == d.dmax && c.falloff == d.falloff &&
           c.inv_falloff == d.inv_falloff && c.keep_inside == d.keep_inside;
  }
};

Config config_of(const Frame& f) { return Config{f.regs, f.poly != nullptr}; }

// One cycle of the input stream: what the system's RTL wrapper drives
// (systemc/rtl/unit_streams.hpp), and which frame's slice it belongs to.
struct Beat {
  CompositeControl c;
  sysc::ShadedBeat lanes;  // one shaded sample per pipeline
  PolygonBeat poly;        // their rays' polygon data (a polygon frame)
  int config = 0;          // index into Stream::configs
  int frame = -1, k = -1;  // of a valid beat, for reports
};

// A pixel pipeline `pipe` must emit in `cycle`.
struct Expect {
  uint64_t cycle;
  int pipe, frame, k, x, y, u, v;
};

struct StreamOptions {
  double stall = 0;  // probability of idle cycles before a partial beam
  int max_gap = 3;   // 1 .. max_gap idle cycles each time
};

struct Stream {
  std::vector<Beat> beats;
  std::vector<Config> configs;
  std::vector<Expect> expects;  // by cycle, then pipeline
  uint64_t valid_beats = 0, idle_beats = 0, expected_valid = 0;
  uint64_t last_input = 0;
};

Stream make_stream(const std::vector<const Frame*>& frames, int p, const StreamOptions& opt, Random& rng) {
  Stream s;
  auto put_sample = [](sysc::ShadedBeat& lanes, int q, const Sample& v) {
    const auto i = static_cast<size_t>(q);
    lanes.red[i] = static_cast<uint16_t>(v.r);
    lanes.green[i] = static_cast<uint16_t>(v.g);
    lanes.blue[i] = static_cast<uint16_t>(v.b);
    lanes.alpha[i] = static_cast<uint16_t>(v.a);
    lanes.value[i] = static_cast<uint16_t>(v.value);
  };
  auto junk_sample = [&] {
    return Sample{static_cast<uint32_t>(rng.bits(kAlphaBits)), static_cast<uint32_t>(rng.bits(kAlphaBits)),
                  static_cast<uint32_t>(rng.bits(kAlphaBits)), static_cast<uint32_t>(rng.bits(kAlphaBits)),
                  static_cast<uint32_t>(rng.bits(kVoxelBits))};
  };
  auto junk = [&](int config) {
    Beat b;
    CompositeControl& c = b.c;
    for (bool* f : {&c.f.beam_start, &c.f.beam_end, &c.f.slice_start, &c.f.slice_end, &c.first_slice, &c.last_slice,
                    &c.dx, &c.dy, &c.next_dx, &c.next_dy})
      *f = rng.chance(0.5);
    for (uint32_t* v : {&c.ix, &c.iy, &c.x, &c.y, &c.z, &c.nx, &c.last_ix, &c.last_iy})
      *v = static_cast<uint32_t>(rng.bits(kPosBits));
    for (uint32_t* v : {&c.wx, &c.wy, &c.wz}) *v = static_cast<uint32_t>(rng.bits(kWeightBits));
    b.config = config;
    for (int q = 0; q < p; ++q) put_sample(b.lanes, q, junk_sample());
    return b;
  };
  for (size_t fi = 0; fi < frames.size(); ++fi) {
    const Frame& f = *frames[fi];
    const sysc::FramePlan plan(f.regs, p);
    const Config cfg = config_of(f);
    if (s.configs.empty() || !(s.configs.back() == cfg)) {
      // New compositor registers: drain the samples in flight first.
      if (!s.configs.empty())
        for (int i = 0; i < kLatency; ++i) s.beats.push_back(junk(static_cast<int>(s.configs.size()) - 1));
      if (!s.configs.empty()) s.idle_beats += kLatency;
      s.configs.push_back(cfg);
    }
    const int config = static_cast<int>(s.configs.size()) - 1;
    const int B = plan.B;
    s.expected_valid += static_cast<uint64_t>(f.K) * f.ny * B;
    for (int k = 0; k < f.K; ++k) {
      const g::SliceControl& c = f.ctrl[k];
      const bool last = k == f.K - 1;
      for (int y = 0; y < f.ny; ++y)
        for (int j = 0; j < B; ++j) {
          if (opt.stall > 0 && rng.chance(opt.stall)) {
            const int gap = static_cast<int>(rng.range(1, opt.max_gap));
            for (int i = 0; i < gap; ++i) s.beats.push_back(junk(config));
            s.idle_beats += gap;
          }
          Beat b;
          // The interpolation pass's flags, less the zero beam: the samples'
          // (docs/rtl-composite.md).
          sysc::BeamFlags flags = plan.step(k, y, j).f;
          flags.slice_end = y == f.ny - 1;
          b.c = composite_control(plan, k, flags, j * p, y);
          if (last) {  // the next slice's steps are ignored in the last slice
            b.c.next_dx = rng.chance(0.5);
            b.c.next_dy = rng.chance(0.5);
          }
          b.config = config;
          b.frame = static_cast<int>(fi);
          b.k = k;
          for (int q = 0; q < p; ++q) {
            const int x = j * p + q;
            put_sample(b.lanes, q, x < f.nx ? f.at(k, x, y) : junk_sample());  // padding: any value
            // The ray's Z, front and back pixels, by its base-plane pixel.
            if (f.poly && x < f.nx) put_ray(b.poly, q, *f.poly, x - c.ix + f.last_ix, y - c.iy + f.last_iy);
          }
          b.poly.slice = static_cast<uint32_t>(k);
          s.beats.push_back(b);
          ++s.valid_beats;
          // The rays this step ends (golden: no successor in slice k+1, or
          // the last slice), pixel (x - ix(k) + ix_last, y - iy(k) + iy_last).
          for (int q = 0; q < p; ++q) {
            const int x = j * p + q;
            if (x >= f.nx) continue;
            if (!last && !g::ray_leaves(x, y, f.ctrl[k + 1].dx, f.ctrl[k + 1].dy, f.nx, f.ny)) continue;
            s.expects.push_back({s.beats.size() - 1 + kLatency, q, static_cast<int>(fi), k, x, y,
                                 x - c.ix + f.last_ix, y - c.iy + f.last_iy});
          }
        }
    }
  }
  s.last_input = s.beats.size() - 1;
  return s;
}

// ===========================================================================
// Running a ring.

struct RunResult {
  bool ok = true;
  std::string report;
  uint64_t pixels = 0, last_pixel = 0;
  std::vector<g::BasePlane> planes;  // what the ring emitted, per frame
};

template <class M>
void drive_config(M& m, const Config& c) {
  drive_composite_registers(m, c.r, c.polygons);
}

template <class M>
RunResult run_ring(M& m, int p, const std::vector<const Frame*>& frames, const Stream& s, Random& rng) {
  RunResult r;
  for (const Frame* f : frames) {
    g::BasePlane bp;
    bp.width = f->golden.width;
    bp.height = f->golden.height;
    bp.bits = f->golden.bits;
    bp.rgba.assign(f->golden.rgba.size(), 0);
    if (f->poly)  // the host's start: front over back where no ray comes (golden start_polygons)
      for (size_t i = 0; i < f->poly->front.size(); ++i) {
        const g::Pixel px = g::leave_with_polygons(g::pixel_to_acc(f->poly->front[i], f->regs.p), f->poly->back[i],
                                                   f->regs.p);
        bp.rgba[i * 4] = px.r;
        bp.rgba[i * 4 + 1] = px.g;
        bp.rgba[i * 4 + 2] = px.b;
        bp.rgba[i * 4 + 3] = px.a;
      }
    r.planes.push_back(std::move(bp));
  }
  std::vector<std::vector<uint8_t>> written(frames.size());
  for (size_t i = 0; i < frames.size(); ++i)
    written[i].assign(static_cast<size_t>(frames[i]->golden.width) * frames[i]->golden.height, 0);

  // Each pipeline's slab line source (one polygon frame per run).
  std::vector<SlabLineSource> slab_src;
  for (const Frame* f : frames)
    if (f->poly) {
      if (frames.size() != 1) throw std::logic_error("a polygon frame runs alone");
      for (int q = 0; q < p; ++q) slab_src.emplace_back(*f->poly, q, p);
    }

  m.valid_i = 0;
  drive_config(m, s.configs.front());
  cube4::rtl::reset(m);
  auto fail = [&](const std::string& text) {
    if (!r.ok) return;
    r.ok = false;
    r.report = text;
  };
  auto rgba_str = [](const uint16_t* px) {
    std::ostringstream o;
    o << "(" << px[0] << ", " << px[1] << ", " << px[2] << ", " << px[3] << ")";
    return o.str();
  };
  size_t ei = 0;
  const uint64_t end = s.beats.size() + 2 * kLatency;
  Beat idle;
  for (uint64_t cycle = 0; cycle < end; ++cycle) {
    const Beat* b = &idle;
    if (cycle < s.beats.size()) {
      b = &s.beats[cycle];
    } else {
      idle.config = static_cast<int>(s.configs.size()) - 1;
      idle.c.x = static_cast<uint32_t>(rng.bits(kPosBits));
      for (int q = 0; q < p; ++q) idle.lanes.alpha[static_cast<size_t>(q)] = static_cast<uint16_t>(rng.bits(kAlphaBits));
    }
    drive_config(m, s.configs[static_cast<size_t>(b->config)]);
    drive_composite_stream(m, b->c, b->lanes, p, kDefaults);
    drive_composite_polygons(m, b->poly, p, kAlphaBits);
    for (const SlabLineSource& src : slab_src) src.present(m);
    cube4::rtl::settle(m);
    std::vector<int> consumed(slab_src.size());
    std::vector<bool> line(slab_src.size());
    for (size_t q = 0; q < slab_src.size(); ++q) {
      consumed[q] = static_cast<int>(get_bits(m.slab_consume_o, static_cast<int>(q) * 3, 3));
      line[q] = get_bits(m.slab_line_o, static_cast<int>(q), 1) != 0;
    }

    for (int q = 0; q < p; ++q) {
      const Expect* e =
          ei < s.expects.size() && s.expects[ei].cycle == cycle && s.expects[ei].pipe == q ? &s.expects[ei] : nullptr;
      const bool valid = get_bits(m.pixel_valid_o, q, 1);
      // The sample that entered kLatency cycles ago, for reports.
      const Beat* src = cycle >= static_cast<uint64_t>(kLatency) && cycle - kLatency < s.beats.size()
                            ? &s.beats[cycle - kLatency]
                            : nullptr;
      std::ostringstream where;
      where << "cycle " << cycle << ", pipeline " << q;
      if (src && src->c.valid)
        where << ", sample of frame " << src->frame << " (" << frames[src->frame]->name << ") slice k=" << src->k
              << " x=" << src->c.x + q << " y=" << src->c.y;
      if (!valid) {
        if (e) {
          std::ostringstream o;
          o << "pixel (u=" << e->u << ", v=" << e->v << ") of ray x=" << e->x << " y=" << e->y << " not emitted: "
            << "pixel_valid_o low at " << where.str() << "; it was due from slice k=" << e->k;
          fail(o.str());
          ++ei;
        }
        continue;
      }
      const int u = static_cast<int>(get_bits(m.pixel_u_o, q * kPosBits, kPosBits));
      const int v = static_cast<int>(get_bits(m.pixel_v_o, q * kPosBits, kPosBits));
      const uint16_t got[4] = {static_cast<uint16_t>(get_bits(m.pixel_red_o, q * kAlphaBits, kAlphaBits)),
                               static_cast<uint16_t>(get_bits(m.pixel_green_o, q * kAlphaBits, kAlphaBits)),
                               static_cast<uint16_t>(get_bits(m.pixel_blue_o, q * kAlphaBits, kAlphaBits)),
                               static_cast<uint16_t>(get_bits(m.pixel_alpha_o, q * kAlphaBits, kAlphaBits))};
      if (!e) {
        std::ostringstream o;
        o << "pixel (u=" << u << ", v=" << v << ") = " << rgba_str(got) << " emitted with none due, at "
          << where.str();
        fail(o.str());
        continue;
      }
      ++ei;
      ++r.pixels;
      r.last_pixel = cycle;
      const Frame& f = *frames[e->frame];
      if (u != e->u || v != e->v) {
        std::ostringstream o;
        o << "pixel address: expected (u=" << e->u << ", v=" << e->v << "), got (u=" << u << ", v=" << v
          << ") at " << where.str() << ", emitted in slice k=" << e->k;
        fail(o.str());
        continue;
      }
      const size_t pix = static_cast<size_t>(v) * f.golden.width + u;
      if (written[e->frame][pix]++) {
        std::ostringstream o;
        o << "pixel (u=" << u << ", v=" << v << ") emitted twice, the second time at " << where.str();
        fail(o.str());
      }
      uint16_t* dst = &r.planes[e->frame].rgba[pix * 4];
      for (int c = 0; c < 4; ++c) dst[c] = got[c];
      const uint16_t* exp = &f.golden.rgba[pix * 4];
      if (exp[0] != got[0] || exp[1] != got[1] || exp[2] != got[2] || exp[3] != got[3]) {
        std::ostringstream o;
        o << "first mismatching pixel (u=" << u << ", v=" << v << "): expected (r, g, b, a) = " << rgba_str(exp)
          << ", got " << rgba_str(got) << "\n  emitted in slice k=" << e->k << " of " << f.K << " (ray x=" << e->x
          << " y=" << e->y << "), " << where.str();
        fail(o.str());
      }
      // The same ray's accumulator: the partial image of a block.
      const g::RayAcc acc = composite_pixel_acc(m, q, kDefaults);
      const g::RayAcc& want = f.golden.acc[pix];
      if (!(acc == want)) {
        std::ostringstream o;
        o << "first mismatching accumulator of pixel (u=" << u << ", v=" << v << "): expected (r, g, b, a, value, "
          << "selected) = (" << want.r << ", " << want.g << ", " << want.b << ", " << want.a << ", " << want.value
          << ", " << want.valid << "), got (" << acc.r << ", " << acc.g << ", " << acc.b << ", " << acc.a << ", "
          << acc.value << ", " << acc.valid << ") at " << where.str();
        fail(o.str());
      }
    }
    cube4::rtl::rise(m);
    for (size_t q = 0; q < slab_src.size(); ++q) slab_src[q].clocked(consumed[q], line[q]);
  }
  // Every decoder read its line of every beam of every slice.
  for (size_t q = 0; q < slab_src.size(); ++q)
    if (slab_src[q].lines() != static_cast<size_t>(frames[0]->K) * frames[0]->ny)
      fail("pipeline " + std::to_string(q) + " started " + std::to_string(slab_src[q].lines()) + " slab lines of " +
           std::to_string(frames[0]->K * frames[0]->ny));
  if (ei != s.expects.size()) {
    const Expect& e = s.expects[ei];
    std::ostringstream o;
    o << s.expects.size() - ei << " pixels never appeared; first (u=" << e.u << ", v=" << e.v << ") of slice k=" << e.k
      << ", due in cycle " << e.cycle;
    fail(o.str());
  }
  // The whole base planes (pixels golden never writes stay zero in both).
  for (size_t fi = 0; fi < frames.size() && r.ok; ++fi) {
    const g::BasePlane& gb = frames[fi]->golden;
    for (size_t i = 0; i < gb.rgba.size() / 4; ++i) {
      const uint16_t* exp = &gb.rgba[i * 4];
      const uint16_t* got = &r.planes[fi].rgba[i * 4];
      if (exp[0] == got[0] && exp[1] == got[1] && exp[2] == got[2] && exp[3] == got[3]) continue;
      std::ostringstream o;
      o << "first mismatching pixel (u=" << i % gb.width << ", v=" << i / gb.width << ") of frame " << fi << " ("
        << frames[fi]->name << "): expected " << rgba_str(exp) << ", got " << rgba_str(got)
        << (written[fi][i] ? "" : " (never emitted)");
      fail(o.str());
      break;
    }
  }
  return r;
}

// Streams the frames into ring M and checks everything.
template <class M>
void check_ring(const RingParams& rp, const std::vector<const Frame*>& frames, const StreamOptions& opt,
                uint64_t salt, uint64_t* pixels_checked = nullptr) {
  std::string what;
  ASSERT_TRUE(frames_fit(rp, frames, what));
  SCOPED_TRACE("p=" + std::to_string(rp.p) + (opt.stall > 0 ? ", stalls" : ", no stalls") + ": " + what);
  Random rng(salt);
  const Stream s = make_stream(frames, rp.p, opt, rng);
  auto m = cube4::rtl::make_dut<M>();
  const RunResult r = run_ring(*m, rp.p, frames, s, rng);
  m->final();
  EXPECT_TRUE(r.ok) << r.report;
  if (!r.ok) return;
  // Cycle counts: K * ny * ceil(nx/p) input cycles per frame plus the idle
  // ones; every ray emitted once; the last pixel (the last sample's ray)
  // kLatency cycles after the last input.
  uint64_t rays = 0;
  for (const Frame* f : frames) {
    // Rays: one per base-plane pixel that some ray reaches.
    uint64_t n = 0;
    for (int k = 0; k < f->K; ++k) {
      const bool last = k == f->K - 1;
      for (int y = 0; y < f->ny; ++y)
        for (int x = 0; x < f->nx; ++x)
          n += last || g::ray_leaves(x, y, f->ctrl[k + 1].dx, f->ctrl[k + 1].dy, f->nx, f->ny);
    }
    rays += n;
  }
  EXPECT_EQ(s.valid_beats, s.expected_valid);
  EXPECT_EQ(s.beats.size(), s.valid_beats + s.idle_beats);
  EXPECT_EQ(r.pixels, rays);
  EXPECT_EQ(r.last_pixel, s.last_input + kLatency);
  if (pixels_checked) *pixels_checked += r.pixels;
}

// Volumes (each fits the smallest ring, p = 5 with MaxDim 12, in every
// permutation).
const std::vector<VolumeSpec> kVolumes = {
    {"sphere", {12, 12, 12}, 0}, {"noise", {9, 7, 5}, 3}, {"noise", {7, 11, 6}, 4}};

// Every view, S = 1, 2, 3, each with an effect set and a volume, without and
// with stalls.
template <class M>
void ring_matrix(const RingParams& rp) {
  Timer t("p=" + std::to_string(rp.p) + " matrix");
  uint64_t pixels = 0, lit = 0, clipped = 0, dx = 0, dy = 0;
  int runs = 0;
  for (size_t v = 0; v < kViews.size(); ++v)
    for (int S : {1, 2, 3}) {
      const Effects& fx = kEffects[(v * 3 + S) % kEffects.size()];
      const VolumeSpec& vs = kVolumes[(v + S) % kVolumes.size()];
      const Frame& f = frame(vs, kViews[v].dir, kViews[v].up, S, fx, kViews[v].name);
      lit += f.lit_pixels;
      clipped += f.clipped_pixels;
      dx += f.dx_slices;
      dy += f.dy_slices;
      if (std::string(fx.json).find("cut") != std::string::npos ||
          std::string(fx.json).find("crop") != std::string::npos) {
        EXPECT_GT(f.clipped_pixels, 0) << f.name << ": cropping and cut plane change no pixel";
      }
      for (bool stalls : {false, true}) {
        StreamOptions opt;
        opt.stall = stalls ? 0.3 : 0;
        check_ring<M>(rp, {&f}, opt, 1000 * rp.p + 10 * v + S + (stalls ? 5 : 0), &pixels);
        ++runs;
        if (::testing::Test::HasFailure()) return;
      }
    }
  std::printf("  p=%d: %d runs, %llu golden base-plane pixels matched (per pass over the views: %llu not zero, "
              "%llu changed by cropping or cut plane; slices with dx = 1: %llu, dy = 1: %llu)\n",
              rp.p, runs, static_cast<unsigned long long>(pixels), static_cast<unsigned long long>(lit),
              static_cast<unsigned long long>(clipped), static_cast<unsigned long long>(dx),
              static_cast<unsigned long long>(dy));
  EXPECT_GT(lit, pixels / 4);
  EXPECT_GT(dx, 0u);
  EXPECT_GT(dy, 0u);
}

// Hybrid scenes (Cube-5): a tilted opaque plane through the volume (samples
// at or behind it hidden, some exactly on its depth), a translucent plane
// exactly on a slab boundary and another tilted one (slab images), planes
// in front of and behind the volume and beside it (front and back pixels,
// rays that meet no sample); the ring's base plane equals golden
// render_fixed() with the PolygonFrame, every pixel and accumulator, in the
// cycle the unit's contract gives; with and without idle cycles.
const char* kHybridScene = R"({"volume": {"synthetic": "sphere", "size": [12, 10, 11]}, "supersampling": 2,
    "view": {"rotate": [20, 35, 5]}, "shading": true,
    "transfer": {"color": [[0, 1, 0.2, 0], [0.5, 0, 1, 0.3], [1, 0.1, 0, 1]], "opacity": [[0, 0.02], [0.4, 0.1], [1, 0.35]]},
    "polygons": [
      {"shape": "plane", "size": [8, 8], "transform": {"rotate": [10, 5, 0], "translate": [6, 5, 7.0]},
       "color": [0.9, 0.2, 0.1], "opacity": 1},
      {"shape": "plane", "size": [9, 9], "transform": {"translate": [6, 5, 3.0]},
       "color": [0.1, 0.3, 1], "opacity": 0.4, "lit": false},
      {"shape": "plane", "size": [7, 9], "transform": {"rotate": [0, 30, 0], "translate": [5, 4, 5.5]},
       "color": [0.2, 1, 0.3], "opacity": 0.3},
      {"shape": "plane", "size": [20, 20], "transform": {"translate": [6, 5, -3]},
       "color": [1, 1, 0.2], "opacity": 0.25, "lit": false},
      {"shape": "plane", "size": [20, 20], "transform": {"translate": [6, 5, 15]},
       "color": [0.3, 0.3, 0.9], "opacity": 1, "lit": false}]})";

template <class M>
void polygon_ring(const RingParams& rp, uint64_t salt) {
  const Frame& f = polygon_frame(kHybridScene, rp.p, "hybrid sphere");
  ASSERT_TRUE(f.poly);
  const g::PolygonFrame::Counts& c = f.poly->counts;
  EXPECT_GT(c.opaque, 0u);
  EXPECT_GT(c.in_front, 0u);
  EXPECT_GT(c.in_slabs, 0u);
  EXPECT_GT(c.behind, 0u);
  // The polygons change the picture: the same frame without them differs
  // in many pixels (so a ring that ignored a polygon path would fail).
  const g::BasePlane plain = g::render_fixed(f.vol, f.regs, g::FixedOptions{});
  int changed = 0;
  for (size_t i = 0; i < plain.rgba.size(); i += 4)
    changed += !std::equal(&plain.rgba[i], &plain.rgba[i] + 4, &f.golden.rgba[i]);
  EXPECT_GT(changed, static_cast<int>(plain.rgba.size() / 4 / 2)) << "pixels the polygons change";
  for (double stall : {0.0, 0.3}) check_ring<M>(rp, {&f}, StreamOptions{stall, 3}, salt);
}

TEST(RtlCompositeRing, PolygonsP1) { polygon_ring<Vcube4_composite_ring_p1>(kRingP1, 801); }
TEST(RtlCompositeRing, PolygonsP4) { polygon_ring<Vcube4_composite_ring>(kRingP4, 804); }
TEST(RtlCompositeRing, PolygonsP5) { polygon_ring<Vcube4_composite_ring_p5>(kRingP5, 805); }

TEST(RtlCompositeRing, P1MatchesGoldenBasePlane) { ring_matrix<Vcube4_composite_ring_p1>(kRingP1); }
TEST(RtlCompositeRing, P2MatchesGoldenBasePlane) { ring_matrix<Vcube4_composite_ring_p2>(kRingP2); }
TEST(RtlCompositeRing, P4MatchesGoldenBasePlane) { ring_matrix<Vcube4_composite_ring>(kRingP4); }
TEST(RtlCompositeRing, P5MatchesGoldenBasePlane) { ring_matrix<Vcube4_composite_ring_p5>(kRingP5); }

void all_rings_check(const std::vector<const Frame*>& frames, const StreamOptions& opt, uint64_t salt) {
  check_ring<Vcube4_composite_ring_p1>(kRingP1, frames, opt, salt + 1);
  check_ring<Vcube4_composite_ring_p2>(kRingP2, frames, opt, salt + 2);
  check_ring<Vcube4_composite_ring>(kRingP4, frames, opt, salt + 4);
  check_ring<Vcube4_composite_ring_p5>(kRingP5, frames, opt, salt + 5);
}

// Blocks of a partitioned volume (golden/blocks.hpp): the window keeps the
// border's samples out of the rays, and the pixel ports carry every ray's
// accumulator (the partial image) as well as its pixel. Blocks from the
// front, the middle and the back of the plan (each with a border, so with
// a window: the last block of an unshaded frame has none), from four base
// planes,
// shaded, MIP and with cropping and the cut plane; back to back too.
TEST(RtlCompositeRing, BlocksOfAPartitionedVolume) {
  Timer t("blocks of a partitioned volume");
  const VolumeSpec cube{"noise", {16, 16, 16}, 41};
  const Frame& a = frame(cube, {0.35, -0.3, 1}, {0, 1, 0}, 1, kEffects[0], "+z tilted", 0);
  const Frame& b = frame(cube, {-1, -0.2, 0.35}, {0, 1, 0}, 2, kEffects[1], "-x tilted", 5);
  const Frame& c = frame(cube, {-0.4, -1, -0.3}, {0, 0, 1}, 1, kEffects[5], "-y tilted", 6);
  const Frame& d = frame(cube, {0.3, 0.45, -1}, {0, 1, 0}, 1, kEffects[3], "-z tilted", 7);
  for (const Frame* f : {&a, &b, &c, &d}) {
    EXPECT_GT(f->clipped_pixels, 0) << f->name << ": the window changes no pixel";
    StreamOptions opt;
    opt.stall = 0.2;
    all_rings_check({f}, opt, 7100);
    if (::testing::Test::HasFailure()) return;
  }
  all_rings_check({&a, &b, &c, &d}, StreamOptions{}, 7200);
}

// Frames back to back without a reset: with the same compositor registers
// no idle cycle at all between frames (nx, the offsets and the slice
// control change with the data); with different registers the stream
// drains for 7 cycles between them.
TEST(RtlCompositeRing, BackToBackFrames) {
  Timer t("back-to-back frames");
  const Effects& shaded = kEffects[0];
  const Effects& mip = kEffects[1];
  const Frame& a = frame(kVolumes[0], {0.35, -0.3, 1}, {0, 1, 0}, 2, shaded, "+z tilted");
  const Frame& b = frame(kVolumes[1], {-0.4, -1, -0.3}, {0, 0, 1}, 3, shaded, "-y tilted");
  const Frame& c = frame(kVolumes[2], {0.7, -0.6, 1}, {0, 1, 0}, 1, shaded, "oblique");
  const Frame& d = frame(kVolumes[1], {-1, -0.2, 0.35}, {0, 1, 0}, 2, shaded, "-x tilted");
  const Frame& e = frame(kVolumes[2], {1, 0, 1}, {0, 1, 0}, 1, mip, "45 xz");
  const Frame& h = frame(kVolumes[0], {-0.3, 0.45, -1}, {0, 1, 0}, 1, kEffects[5], "-z tilted");
  for (double stall : {0.0, 0.25}) {
    StreamOptions opt;
    opt.stall = stall;
    all_rings_check({&a, &b, &c, &d}, opt, 70);
    all_rings_check({&a, &e, &h, &b, &e}, opt, 80);
    if (::testing::Test::HasFailure()) return;
  }
}

// Slices of one to a few steps: ny = 1 with nx <= p makes a lap of a single
// step, where the predecessor was written in the cycle before it is read
// (the bypass); single beams (no y-1 candidate) and single columns.
TEST(RtlCompositeRing, TinySlices) {
  Timer t("tiny slices");
  const std::vector<VolumeSpec> vols = {{"noise", {1, 1, 6}, 11}, {"noise", {2, 1, 5}, 12}, {"noise", {1, 3, 4}, 13},
                                        {"noise", {3, 2, 7}, 14}, {"noise", {6, 1, 3}, 15}, {"noise", {1, 1, 1}, 16}};
  int runs = 0;
  for (size_t i = 0; i < vols.size(); ++i)
    for (size_t v : {size_t{4}, size_t{6}, size_t{10}, size_t{13}, size_t{14}})
      for (int S : {1, 3}) {
        const Frame& f =
            frame(vols[i], kViews[v].dir, kViews[v].up, S, kEffects[(i + v + S) % kEffects.size()], kViews[v].name);
        for (double stall : {0.0, 0.3}) {
          StreamOptions opt;
          opt.stall = stall;
          all_rings_check({&f}, opt, 300 + 20 * i + v + S);
          ++runs;
          if (::testing::Test::HasFailure()) return;
        }
      }
  std::printf("  %d runs, each through p = 1, 2, 4, 5\n", runs);
}

// Slices that fill the ray slice store to its last entry (ny * ceil(nx/p) =
// SliceDepth) and beams that fill the beam delay (ceil(nx/p) = BeamDepth).
TEST(RtlCompositeRing, FullStorage) {
  Timer t("full storage");
  const Frame& f2 = frame({"sphere", {16, 16, 3}, 0}, {0.2, 0.3, 1}, {0, 1, 0}, 2, kEffects[0], "+z tilted");
  ASSERT_EQ((f2.nx + 1) / 2 * f2.ny, kRingP2.slice_depth());
  const Frame& f5 = frame({"noise", {15, 12, 3}, 32}, {0.3, -0.2, -1}, {0, 1, 0}, 3, kEffects[4], "-z tilted");
  ASSERT_EQ((f5.nx + 4) / 5 * f5.ny, kRingP5.slice_depth());
  const Frame& f1 = frame({"noise", {24, 24, 2}, 33}, {0.45, 0.2, 1}, {0, 1, 0}, 2, kEffects[2], "+z tilted");
  ASSERT_EQ(f1.nx * f1.ny, kRingP1.slice_depth());
  for (double stall : {0.0, 0.3}) {
    StreamOptions opt;
    opt.stall = stall;
    check_ring<Vcube4_composite_ring_p2>(kRingP2, {&f2}, opt, 81);
    check_ring<Vcube4_composite_ring_p5>(kRingP5, {&f5}, opt, 85);
    check_ring<Vcube4_composite_ring_p1>(kRingP1, {&f1}, opt, 82);
  }
}

// Random scenes: direction, volume size (within every ring's storage), S up
// to VolumePro's 8, effects, stall rate; every ring.
TEST(RtlCompositeRing, RandomScenes) {
  Timer t("random scenes");
  Random rng(0xC0317E);
  const long n = cube4::rtl::vector_count(1000000) >= 1000000 ? 80 : 4;
  for (long i = 0; i < n; ++i) {
    const RandomScene sc = random_scene(rng);
    const VolumeSpec vs{rng.chance(0.3) ? "sphere" : "noise", sc.size, static_cast<int>(100 + i)};
    const Frame& f =
        frame(vs, sc.dir, sc.up, sc.S, kEffects[rng.range(0, static_cast<int64_t>(kEffects.size()) - 1)], "random " + std::to_string(i));
    StreamOptions opt;
    opt.stall = rng.chance(0.5) ? 0 : static_cast<double>(rng.range(1, 60)) / 100.0;
    opt.max_gap = static_cast<int>(rng.range(1, 5));
    all_rings_check({&f}, opt, 500 + 10 * i);
    if (::testing::Test::HasFailure()) return;
  }
  std::printf("  %ld random scenes, each through p = 1, 2, 4, 5\n", n);
}

// A larger volume through the default ring (p = 4, 256^3 storage), up to
// VolumePro's 8-fold supersampling, every blend mode, with cropping and cut
// plane.
TEST(RtlCompositeRing, LargerVolumeP4) {
  Timer t("larger volume, p=4");
  const VolumeSpec vs{"sphere", {37, 30, 14}, 0};
  int i = 0;
  for (int S : {1, 4, 8})
    for (size_t fx : {size_t{0}, size_t{5}, size_t{2}}) {
      const Frame& f = frame(vs, {0.55, 0.4, -1}, {0, 1, 0}, S, kEffects[fx], "oblique");
      StreamOptions opt;
      opt.stall = 0.1;
      check_ring<Vcube4_composite_ring>(kRingP4, {&f}, opt, 90 + i++);
    }
}

}  // namespace
