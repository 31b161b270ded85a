#include "systemc/core/system.hpp"

#include <optional>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <sstream>
#include <systemc>

#include "systemc/core/clocked_tops.hpp"
#include "systemc/core/edge_clock.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/link.hpp"
#include "systemc/core/pixel_memory.hpp"
#include "systemc/core/polygon_source.hpp"
#include "systemc/core/stream_checker.hpp"
#include "systemc/core/stream_former.hpp"
#include "systemc/core/voxel_memory.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/tlm/gradient_bypass.hpp"
#include "systemc/tlm/tlm_addr.hpp"
#include "systemc/tlm/tlm_composite.hpp"
#include "systemc/tlm/tlm_frame.hpp"
#include "systemc/tlm/tlm_gradient.hpp"
#include "systemc/tlm/tlm_interp.hpp"
#include "systemc/tlm/tlm_shade.hpp"

#ifdef CUBE4_HAVE_RTL
#include "systemc/rtl/rtl_model.hpp"
#include "systemc/rtl/vl_context.hpp"
#include "systemc/rtl/vl_coverage.hpp"
#endif

namespace cube4::sysc {

std::string Mismatch::describe() const {
  std::ostringstream s;
  s << unit_name(unit) << " unit, slice " << slice << ", sample (" << x << ", " << y << "): expected " << expected
    << ", got " << got;
  return s.str();
}

namespace {

// The units of one frame (plain objects: a frame creates them afresh) and
// the frame's progress through them.
struct FrameUnits {
  std::unique_ptr<AddrIf> addr;
  std::unique_ptr<StreamFormer> former;
  std::unique_ptr<InterpIf> interp;
  std::unique_ptr<GradientIf> gradient;
  std::unique_ptr<ShadeIf> shade;
  std::unique_ptr<CompositeIf> composite;
  StreamChecker* checker = nullptr;
  PolygonSource* polygons = nullptr;  // a hybrid frame's slab images in time
  int released_pass = -1;             // frame * passes + pass: the pass the source let start
  uint64_t release_at = 0;
  uint64_t first_frame_stalls = 0;
  golden::Progress progress;
  uint64_t total_beats = 1;
  uint64_t cycle = 0, done_cycle = 0;
  uint64_t last_valid[4] = {0, 0, 0, 0};  // last cycle each link carried a beat
  int frames = 1;
  std::vector<uint64_t> frame_done_cycles;  // the cycle each frame's last pixel was written
  bool done = false;
};

// One clock edge of each unit: it sees its input link's value of this cycle
// and returns its output (the next link's value in the next cycle). Both
// schedules below call these, so they simulate the same machine.
VoxelBeat former_edge(FrameUnits& u) {
  ++u.cycle;
  if (u.polygons && !u.former->done()) {
    // A pass starts only once its slice's slab image is in the buffer: the
    // stream waits at its first beat (an invalid beat a cycle).
    const StreamFormer::Upcoming n = u.former->upcoming();
    const int id = n.frame * u.former->passes() + n.pass;
    if (n.first_of_pass && id != u.released_pass) {
      if (n.pass == 0 && n.frame == 1) u.first_frame_stalls = u.polygons->stall_cycles();
      u.release_at = u.polygons->release(n.pass, u.cycle);
      u.released_pass = id;
    }
    if (u.cycle < u.release_at) return VoxelBeat{};
  }
  const VoxelBeat b = u.former->next();
  if (b.valid) u.last_valid[0] = u.cycle;
  if (u.progress && (u.cycle & 0xffff) == 0)
    u.progress(std::min(1.0, static_cast<double>(u.cycle) / static_cast<double>(u.total_beats)));
  return b;
}
SampleBeat interp_edge(FrameUnits& u, const VoxelBeat& in) {
  SampleBeat out;
  u.interp->clock(in, out);
  if (u.checker) u.checker->samples(out);
  if (out.valid) u.last_valid[1] = u.cycle;
  return out;
}
GradientBeat gradient_edge(FrameUnits& u, const SampleBeat& in) {
  GradientBeat out;
  u.gradient->clock(in, out);
  if (u.checker) u.checker->gradients(out);
  if (out.valid) u.last_valid[2] = u.cycle;
  return out;
}
ShadedBeat shade_edge(FrameUnits& u, const GradientBeat& in) {
  ShadedBeat out;
  u.shade->clock(in, out);
  if (u.checker) u.checker->shaded(out);
  if (out.valid) u.last_valid[3] = u.cycle;
  return out;
}
void composite_edge(FrameUnits& u, const ShadedBeat& in) {
  CompositeOut out;
  u.composite->clock(in, out);
  if (out.frame_done) {
    u.frame_done_cycles.push_back(u.cycle);
    if (static_cast<int>(u.frame_done_cycles.size()) == u.frames) {
      u.done = true;
      u.done_cycle = u.cycle;
    }
  }
}

// The clocked top: one process per unit, registered links between them.
// SystemC elaborates once per process, so the top is built on the first
// frame and each frame plugs its units in (sc_pause() ends a frame).
SC_MODULE(CycleTop) {
  EdgeClock clk{"clk", sc_core::sc_time(1, sc_core::SC_NS)};
  Link<VoxelBeat> voxels{"voxels"};
  Link<SampleBeat> samples{"samples"};
  Link<GradientBeat> gradients{"gradients"};
  Link<ShadedBeat> shaded{"shaded"};

  FrameUnits* u = nullptr;
  std::exception_ptr error;

  SC_CTOR(CycleTop) {
    SC_METHOD(former_step);
    sensitive << clk.posedge_event();
    dont_initialize();
    SC_METHOD(interp_step);
    sensitive << clk.posedge_event();
    dont_initialize();
    SC_METHOD(gradient_step);
    sensitive << clk.posedge_event();
    dont_initialize();
    SC_METHOD(shade_step);
    sensitive << clk.posedge_event();
    dont_initialize();
    SC_METHOD(composite_step);
    sensitive << clk.posedge_event();
    dont_initialize();
  }

  void start(FrameUnits& units) {
    u = &units;
    error = nullptr;
    voxels.reset();
    samples.reset();
    gradients.reset();
    shaded.reset();
  }

  // Between frames (while the composition network runs on the same
  // clock) no frame is plugged in.
  void stop() { u = nullptr; }

  template <class F>
  void guarded(F&& f) {
    if (!u || u->done || error) return;
    try {
      f();
    } catch (...) {
      error = std::current_exception();
      sc_core::sc_pause();
    }
  }

  void former_step() { guarded([&] { voxels.write(former_edge(*u)); }); }
  void interp_step() { guarded([&] { samples.write(interp_edge(*u, voxels.read())); }); }
  void gradient_step() { guarded([&] { gradients.write(gradient_edge(*u, samples.read())); }); }
  void shade_step() { guarded([&] { shaded.write(shade_edge(*u, gradients.read())); }); }
  void composite_step() {
    guarded([&] {
      composite_edge(*u, shaded.read());
      if (u->done) sc_core::sc_pause();
    });
  }
};

// The same machine without the SystemC kernel: the links are plain
// registers, and each edge runs the units from the last to the first, so
// every unit reads its link before its producer overwrites it. The ceiling
// for the system's speed at a given level mix (docs/performance.md).
void run_plain(FrameUnits& u) {
  VoxelBeat voxels;
  SampleBeat samples;
  GradientBeat gradients;
  ShadedBeat shaded;
  while (!u.done) {
    composite_edge(u, shaded);
    if (u.done) break;
    shaded = shade_edge(u, gradients);
    gradients = gradient_edge(u, samples);
    samples = interp_edge(u, voxels);
    voxels = former_edge(u);
  }
}

// Both clocked tops, built together (clocked_tops.hpp); they live as long
// as the SystemC kernel.
struct ClockedTops {
  CycleTop* cycle;
  sc_core::sc_module* network;
};
ClockedTops& clocked_tops() {
  static ClockedTops tops = [] {
    auto* top = new CycleTop("cube4");
    return ClockedTops{top, build_network_top(top->clk)};
  }();
  return tops;
}
CycleTop& cycle_top() { return *clocked_tops().cycle; }

}  // namespace

sc_core::sc_module& network_top() { return *clocked_tops().network; }

void check_system_limits(const golden::Registers& r, const SystemConfig& cfg) {
  if (cfg.frames < 1) throw std::invalid_argument("frames: " + std::to_string(cfg.frames) + " (at least 1)");
  const FramePlan plan(r, cfg.p);  // p, supersampling and the stream tag's slices
  if (cfg.all_tlm() && !cfg.cycle_level) return;
  if (cfg.p > kMaxLanes)
    throw std::invalid_argument("pipelines: " + std::to_string(cfg.p) + " (a cycle-level run takes at most " +
                                std::to_string(kMaxLanes) + "; --model tlm takes any)");
  if (cfg.all_tlm()) return;
  require_rtl(cfg.p);
  // Voxel tags (bela §III) run on the units verilated with tag hardware
  // (kRtlVoxelTagBits wide, for CMake's CUBE4_SYSTEM_TAG_PIPES); every other
  // width is the default one.
  if (r.p.tag_bits > 0 && (cfg.levels[static_cast<size_t>(Unit::Interp)] == Level::Rtl ||
                           cfg.levels[static_cast<size_t>(Unit::Gradient)] == Level::Rtl))
    require_rtl_tags(cfg.p, r.p.tag_bits);
  golden::Precision widths = r.p;
  widths.tag_bits = 0;
  if (const golden::PrecisionField* f = golden::first_difference(widths, golden::Precision{}, true))
    throw std::invalid_argument(std::string("precision: ") + f->key + " = " + std::to_string(r.p.*f->member) +
                                ", but the system's RTL is verilated with the default widths "
                                "(docs/fixed-point.md); run other widths with --model tlm");
  // The address generator's dimension registers (cube4_pkg::DimBits).
  if (cfg.levels[static_cast<size_t>(Unit::Addr)] == Level::Rtl)
    for (int axis = 0; axis < 3; ++axis)
      if (r.dim[axis] >= (1 << kRtlAddrDimBits))
        throw std::invalid_argument(
            "volume: a dimension of " + std::to_string(r.dim[axis]) + " voxels, more than the RTL address "
            "generator's " + std::to_string(kRtlAddrDimBits) + "-bit dimension registers hold (at most " +
            std::to_string((1 << kRtlAddrDimBits) - 1) + "; DimBits in rtl/cube4_pkg.sv); run the address "
            "generation at TLM (--model tlm, or mixed: without addr)");
  // The rings keep beams and slices of the permuted x and y; a gradient
  // unit the scene does not need is not run at all.
  const bool gradient_runs = r.gradient || cfg.simulate_unneeded;
  for (const Unit u : {Unit::Interp, Unit::Gradient, Unit::Composite}) {
    if (cfg.levels[static_cast<size_t>(u)] != Level::Rtl || (u == Unit::Gradient && !gradient_runs)) continue;
    for (int axis = 0; axis < 2; ++axis)
      if (r.dim[axis] > kRtlMaxDim)
        throw std::invalid_argument(
            std::string("volume: the view's permuted ") + (axis == 0 ? "x" : "y") + " axis has " +
            std::to_string(r.dim[axis]) + " voxels, more than the " + unit_name(u) +
            " ring's storage at RTL holds (MaxDim " + std::to_string(kRtlMaxDim) +
            " per axis); run the " + unit_name(u) +
            " unit at TLM (--model tlm, or mixed: without it), split the volume into sub-cubes that fit "
            "(--blocks AxBxC), choose a view whose permuted x and y fit, or build larger rings (CMake "
            "-DCUBE4_SYSTEM_MAX_DIM=N)");
  }
}

// Only the compositing unit sees the polygons; at RTL it needs the ring
// verilated with polygon hardware for the frame's p.
void check_polygon_levels(const SystemConfig& cfg) {
  if (cfg.levels[static_cast<size_t>(Unit::Composite)] == Level::Rtl) require_rtl_polygons(cfg.p);
}

// Perspective registers drive only the loosely timed transaction (the
// golden perspective renderer); the per-unit models and the RTL rings
// stream parallel projection's samples.
void check_perspective_levels(const golden::Registers& r, const SystemConfig& cfg) {
  if (r.perspective && (!cfg.all_tlm() || cfg.cycle_level))
    throw std::invalid_argument(
        "perspective: the system model renders perspective frames loosely timed with every unit at transaction "
        "level only (--model tlm); the units' clocked models and RTL are not built for it yet "
        "(docs/perspective.md)");
}

// VolumePro's z gradient is golden's so far: the gradient units' TLM and
// RTL models take the 12-neighbourhood.
void check_z_gradient_levels(const golden::Registers& r, const SystemConfig& cfg) {
  if (r.gradient && r.z_gradient != golden::ZGradient::Abc && (!cfg.all_tlm() || cfg.cycle_level))
    throw std::invalid_argument(
        "z_gradient voxel_differences: the system model renders it loosely timed with every unit at transaction "
        "level only (--model tlm); the gradient unit's clocked model and RTL take the 12-neighbourhood "
        "(docs/fixed-point.md)");
}

SystemResult run_frame(const golden::Registers& r, const golden::Volume& vol, const SystemConfig& cfg,
                       const golden::Progress& progress, const golden::PolygonFrame* polygons) {
  const auto t0 = std::chrono::steady_clock::now();
  // A scene without gradients does not run the gradient unit (and its
  // frame has no zero pass), unless asked to simulate it anyway (to measure
  // what skipping saves): its gradients are then computed and not used.
  golden::Registers forced;
  const golden::Registers* rs = &r;
  if (cfg.simulate_unneeded && !r.gradient) {
    forced = r;
    forced.gradient = true;
    rs = &forced;
  }
  if (polygons) check_polygon_levels(cfg);
  check_perspective_levels(r, cfg);
  check_z_gradient_levels(*rs, cfg);
  check_system_limits(*rs, cfg);
  const FramePlan plan(*rs, cfg.p);
  SystemResult res;
  res.levels = cfg.levels;
  res.simulated = {true, rs->gradient, true, true, true};
  auto not_needed = [&](bool needed, Unit u, const std::string& what) {
    if (needed) return;
    if (cfg.levels[static_cast<size_t>(u)] == Level::Tlm || (cfg.all_tlm() && !cfg.cycle_level))
      res.skipped.push_back(what);
    else
      res.unused.push_back(what + " (inside the verilated " + unit_name(u) + " unit: computed, not used)");
  };
  if (!rs->gradient) res.skipped.push_back("gradient unit and the frame's zero pass (the scene needs no gradients)");
  // The RTL shading unit has a variant without shading and magnitude
  // hardware, used when the scene needs neither.
  const bool lean_shade = !r.shading && !r.magnitude && !cfg.simulate_unneeded;
  if (lean_shade) {
    res.skipped.push_back("gradient magnitude");
    res.skipped.push_back("reflectance maps, reflection vector and Phong shading");
    not_needed(false, Unit::Shade, "GmLUT");
  } else {
    not_needed(r.magnitude, Unit::Shade, "gradient magnitude and GmLUT");
    not_needed(r.shading, Unit::Shade, "reflectance maps and Phong shading");
    not_needed(r.specular, Unit::Shade, "specular reflection vector and map");
  }
  // The RTL compositing ring has a variant without cut-plane hardware.
  if (!r.cut_enabled) {
    if (cfg.simulate_unneeded)
      not_needed(false, Unit::Composite, "cut-plane logic");
    else
      res.skipped.push_back("cut-plane logic");
  }
  not_needed(r.crop_enabled, Unit::Composite, "cropping logic");
  not_needed(r.window_enabled, Unit::Composite, "block-window logic (a partitioned volume's)");
  const CycleCount cc = frame_cycles(*rs, cfg.p);
  res.stream_cycles = cc.stream;
  res.samples = static_cast<uint64_t>(plan.nx) * plan.ny * plan.K;

  std::unique_ptr<StreamChecker> checker;
  if (cfg.check) checker = std::make_unique<StreamChecker>(plan, vol);

  // The slab images' connection (Ideal: no wait, no source).
  std::unique_ptr<PolygonSource> source;
  if (polygons && cfg.polygon_engine.connection != golden::PolygonConnection::Ideal)
    source = std::make_unique<PolygonSource>(plan, cfg.polygon_work ? *cfg.polygon_work : golden::polygon_work(*polygons),
                                             cfg.polygon_engine, cfg.clock_hz);
  if (polygons) res.polygon_connection = polygon_connection_name(cfg.polygon_engine.connection);

  if (cfg.all_tlm() && !cfg.cycle_level) {
    res.plane = run_tlm_frame(plan, vol, progress, cfg.accumulators, polygons);
    if (source) res.polygon_stall_cycles = source->stalls_of_frame(plan.pass_beats());
    res.frame_cycles = cc.latency + res.polygon_stall_cycles;
    for (int pass = 0; pass < plan.passes; ++pass)
      if (plan.pass_voxel_slice(pass) < plan.nz) res.voxel_reads += static_cast<uint64_t>(plan.ny) * plan.B * plan.p;
  } else {
#ifdef CUBE4_HAVE_RTL
    rtl::ScopedVerilatedContext ctx(cfg.seed, !cfg.trace.file.empty(), cfg.assertions);
    VerilatedContext* rtl_ctx = ctx.get();
#else
    VerilatedContext* rtl_ctx = nullptr;  // require_rtl() refused every RTL unit
#endif
    VoxelMemory mem(vol, cfg.p);
    PixelMemory pixels(r, cfg.accumulators);
    FrameUnits u;
    u.frames = cfg.frames;
    bool rtl[kUnits];
    for (int i = 0; i < kUnits; ++i) rtl[i] = cfg.levels[static_cast<size_t>(i)] == Level::Rtl;
    // The weight generator runs at RTL with the interpolation unit, the
    // first unit to read its weights: every unit then reads the slice
    // controls cube4_dda produced (`up`); the checker keeps golden's (plan).
    std::optional<FramePlan> rtl_plan;
    if (rtl[static_cast<int>(Unit::Interp)]) {
      rtl_plan.emplace(*rs, cfg.p, kUserTagBits, 0, rtl_slice_controls(*rs, *rtl_ctx));
      res.weight_generator = Level::Rtl;
    }
    const FramePlan& up = rtl_plan ? *rtl_plan : plan;
    const golden::SkewTraversal traversal{r.perm, r.flip};
    if (rtl[static_cast<int>(Unit::Addr)]) {
      u.addr = make_rtl_addr(up, mem.layout(), *rtl_ctx, cfg.trace);
    } else {
      u.addr = std::make_unique<TlmAddr>(mem.layout(), traversal);
    }
    u.former = std::make_unique<StreamFormer>(up, mem, *u.addr, cfg.frames);
    u.interp = rtl[0] ? make_rtl_interp(up, *rtl_ctx, cfg.trace) : std::make_unique<TlmInterp>(up);
    // Gradients and shading of samples that cannot change their ray are
    // don't-cares when only TLM shading and compositing read them.
    const bool skip_transparent = !checker && !rtl[2] && !rtl[3];
    if (!rs->gradient) {
      u.gradient = std::make_unique<GradientBypass>(up);
    } else {
      u.gradient = rtl[1] ? make_rtl_gradient(up, *rtl_ctx, cfg.trace)
                          : std::make_unique<TlmGradient>(up, skip_transparent);
    }
    u.shade = rtl[2] ? make_rtl_shade(up, *rtl_ctx, cfg.trace, cfg.simulate_unneeded)
                     : std::make_unique<TlmShade>(up, skip_transparent);
    u.composite = rtl[3] ? make_rtl_composite(up, pixels, *rtl_ctx, cfg.trace, cfg.simulate_unneeded, polygons)
                         : std::make_unique<TlmComposite>(up, pixels, polygons);
    u.checker = checker.get();
    u.polygons = source.get();
    u.progress = progress;
    u.total_beats = cc.stream * static_cast<uint64_t>(cfg.frames) + cc.flush;
    if (cfg.kernel == Kernel::SystemC) {
      CycleTop& top = cycle_top();
      top.start(u);
      sc_core::sc_start();
      top.stop();
      if (top.error) std::rethrow_exception(top.error);
    } else {
      run_plain(u);
    }
    if (!u.done) throw std::logic_error("system: the simulation stopped before the frame's last pixel");
    res.frame_cycles = u.frame_done_cycles.front();
    if (source) res.polygon_stall_cycles = u.frames > 1 ? u.first_frame_stalls : source->stall_cycles();
    if (u.frames > 1) res.measured_interval = u.frame_done_cycles[1] - u.frame_done_cycles[0];
    res.last_beat = {u.last_valid[0], u.last_valid[1], u.last_valid[2], u.last_valid[3]};
    res.simulated_cycles = u.done_cycle;
    res.voxel_reads = mem.reads();
    res.plane = pixels.plane();
#ifdef CUBE4_HAVE_RTL
    rtl::write_coverage(*rtl_ctx);  // while the models live (a coverage build's; else nothing)
#endif
  }
  res.stream_cycles += res.polygon_stall_cycles;
  if (checker) res.mismatch = checker->first_mismatch();
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (progress) progress(1.0);
  return res;
}

}  // namespace cube4::sysc

