#include "systemc/core/system.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>
#include <systemc>

#include "golden/perspective_dataflow.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/perspective_frame.hpp"
#include "systemc/core/pixel_memory.hpp"
#include "systemc/core/polygon_source.hpp"
#include "systemc/core/schedules.hpp"
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
#include "systemc/tlm/tlm_composite_persp.hpp"
#include "systemc/tlm/tlm_gradient_persp.hpp"
#include "systemc/tlm/tlm_interp_persp.hpp"
#include "systemc/tlm/tlm_shade_persp.hpp"
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

int simulation_threads(const SystemConfig& cfg) {
  // Waveforms are one thread's: on two the front runs some cycles past the
  // frame's end, and its units' traces would hold them.
  if (!cfg.trace.file.empty()) return 1;
  if (cfg.threads > 0) return std::min(cfg.threads, 2);
  // The hand-over costs the front more than TLM shading and compositing
  // cost on one thread (docs/performance.md): two only for RTL ones.
  const bool rtl_back = cfg.levels[static_cast<size_t>(Unit::Shade)] == Level::Rtl ||
                        cfg.levels[static_cast<size_t>(Unit::Composite)] == Level::Rtl;
  return rtl_back && std::thread::hardware_concurrency() >= 2 ? 2 : 1;
}

void check_perspective_levels(const golden::Registers& r, const SystemConfig& cfg);

void check_system_limits(const golden::Registers& r, const SystemConfig& cfg) {
  if (cfg.frames < 1) throw std::invalid_argument("frames: " + std::to_string(cfg.frames) + " (at least 1)");
  check_perspective_levels(r, cfg);
  const FramePlan plan(r, cfg.p);  // p, supersampling and the stream tag's slices
  if (cfg.all_tlm() && !cfg.cycle_level) return;
  if (cfg.p > kMaxLanes)
    throw std::invalid_argument("pipelines: " + std::to_string(cfg.p) + " (a cycle-level run takes at most " +
                                std::to_string(kMaxLanes) + "; --model tlm takes any)");
  if (cfg.all_tlm()) return;
  require_rtl(cfg.p);
  // Voxel tags (bela §III) run on the units verilated with tag hardware
  // (kRtlVoxelTagBits wide, for CMake's CUBE4_SYSTEM_TAG_PIPES); every other
  // width is the build's (CMake's CUBE4_SYSTEM_WIDTHS).
  if (r.p.tag_bits > 0 && (cfg.levels[static_cast<size_t>(Unit::Interp)] == Level::Rtl ||
                           cfg.levels[static_cast<size_t>(Unit::Gradient)] == Level::Rtl))
    require_rtl_tags(cfg.p, r.p.tag_bits);
  require_rtl_widths(r.p, "the system's RTL");
  // The address generator's dimension registers (cube4_pkg::DimBits).
  if (cfg.levels[static_cast<size_t>(Unit::Addr)] == Level::Rtl)
    for (int axis = 0; axis < 3; ++axis)
      if (r.dim[axis] >= (1 << kRtlAddrDimBits))
        throw VolumeTooLarge(
            "volume: a dimension of " + std::to_string(r.dim[axis]) + " voxels, more than the RTL address "
            "generator's " + std::to_string(kRtlAddrDimBits) + "-bit dimension registers hold (at most " +
            std::to_string((1 << kRtlAddrDimBits) - 1) + "; DimBits in rtl/cube4_pkg.sv); run the address "
            "generation at TLM (--model tlm, or mixed: without addr), or split the volume into sub-cubes that "
            "fit (--blocks AxBxC)");
  // The rings keep beams and slices of the permuted x and y; a gradient
  // unit the scene does not need is not run at all.
  const bool gradient_runs = r.gradient || cfg.simulate_unneeded;
  for (const Unit u : {Unit::Interp, Unit::Gradient, Unit::Composite}) {
    if (cfg.levels[static_cast<size_t>(u)] != Level::Rtl || (u == Unit::Gradient && !gradient_runs)) continue;
    for (int axis = 0; axis < 2; ++axis)
      if (r.dim[axis] > kRtlMaxDim)
        throw VolumeTooLarge(
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
// verilated with polygon hardware for the frame's p, which the perspective
// compositing ring has not yet.
void check_polygon_levels(const SystemConfig& cfg, bool perspective) {
  if (cfg.levels[static_cast<size_t>(Unit::Composite)] != Level::Rtl) return;
  if (perspective)
    require_rtl_persp_polygons(cfg.p);
  else
    require_rtl_polygons(cfg.p);
}

// Perspective frames run loosely timed at TLM, or clocked, every unit at
// clocked TLM or RTL (systemc/core/perspective_frame.hpp); what the rings'
// plans cannot follow is refused here, before any voxel is read.
void check_perspective_levels(const golden::Registers& r, const SystemConfig& cfg) {
  if (!r.perspective || (cfg.all_tlm() && !cfg.cycle_level)) return;
  // VolumePro's z gradient needs the rings verilated with it (HasZDiff, HasVoxelZ).
  if (zdiff_stream(r) && (cfg.levels[static_cast<size_t>(Unit::Interp)] == Level::Rtl ||
                          cfg.levels[static_cast<size_t>(Unit::Gradient)] == Level::Rtl))
    require_rtl_persp_zdiff(cfg.p, r.p.tag_bits);
  // The compositing ring's plan (docs/perspective.md): every ray moves at
  // most its reach from slice to slice, and its last blend, that many
  // positions after its last gradient, falls within the stream.
  const int64_t move = golden::largest_home_move(golden::perspective_reach(r));
  if (move > kPerspectiveReach)
    throw std::invalid_argument(
        "\"view\": a ray's home moves " + std::to_string(move) + " cells from one slice to the next, more than the "
        "perspective compositing ring's reach " + std::to_string(kPerspectiveReach) +
        " at the clocked levels; raise \"supersampling\" (each step halves the moves), narrow \"fov\", or run "
        "--model tlm (docs/perspective.md)");
  const int64_t row = static_cast<int64_t>((r.dim[0] + cfg.p - 1) / cfg.p) * cfg.p;
  const int64_t passes = r.sample_slices() + (r.gradient ? 1 : 0) + (zdiff_stream(r) ? 1 : 0);  // the priming pass
  const int64_t stream_end = (passes * r.dim[1] +
                              stream_flush_beams(true, r.gradient)) * row;
  if (const int64_t last = last_ray_position(r, cfg.p); last >= 0 && last + kPerspectiveReach >= stream_end)
    throw std::invalid_argument(
        "volume: the view's permuted x axis has " + std::to_string(r.dim[0]) + " voxels, a beam of " +
        std::to_string(row) + " stream positions at p = " + std::to_string(cfg.p) +
        ": too short for the last ray's blend to fall within the stream's flush beams at the clocked levels; run "
        "--model tlm, or more pipelines (a beam is padded to a multiple of p)");
  const bool rtl_interp = cfg.levels[static_cast<size_t>(Unit::Interp)] == Level::Rtl;
  const bool rtl_gradient = r.gradient && cfg.levels[static_cast<size_t>(Unit::Gradient)] == Level::Rtl;
  // The gradient ring's preconditions (docs/rtl-gradient-persp.md): a
  // slice's neighbours within its four stores, a window within two beams.
  if (rtl_gradient) {
    const int nx = r.dim[0], ny = r.dim[1], row = (nx + cfg.p - 1) / cfg.p * cfg.p;
    if (ny < kRtlGradientPerspMinRows || row < kRtlGradientPerspMinRow)
      throw std::invalid_argument(
          "volume: the view's permuted y axis has " + std::to_string(ny) + " voxels and a beam " +
          std::to_string(row) + " stream positions (x " + std::to_string(nx) + " at p = " + std::to_string(cfg.p) +
          "); the RTL perspective gradient ring needs at least " + std::to_string(kRtlGradientPerspMinRows) +
          " rows and " + std::to_string(kRtlGradientPerspMinRow) +
          " positions a beam; run the gradient unit at TLM (--model mixed: without gradient)");
  }
  // The compositing ring's: at least six rows, a beam long enough for its
  // window (docs/rtl-composite-persp.md); polygons: check_polygon_levels().
  const bool rtl_composite = cfg.levels[static_cast<size_t>(Unit::Composite)] == Level::Rtl;
  if (rtl_composite) {
    if (r.dim[1] < kRtlGradientPerspMinRows || row < kRtlCompositePerspMinRow)
      throw std::invalid_argument(
          "volume: the view's permuted y axis has " + std::to_string(r.dim[1]) + " voxels and a beam " +
          std::to_string(row) + " stream positions (x " + std::to_string(r.dim[0]) + " at p = " +
          std::to_string(cfg.p) + "); the RTL perspective compositing ring needs at least " +
          std::to_string(kRtlGradientPerspMinRows) + " rows and " + std::to_string(kRtlCompositePerspMinRow) +
          " positions a beam; run the composite unit at TLM (--model mixed: without composite)");
  }
  if (rtl_interp || rtl_gradient || rtl_composite) {
    require_rtl_perspective(cfg.p);
    // Their tag variants: the p of both CUBE4_SYSTEM_PERSP_PIPES and _TAG_PIPES.
    require_rtl_tags(cfg.p, r.p.tag_bits);
  }
}

namespace {

// What a clocked frame runs with: the registers (`r` the scene's, `rs`
// those the units run: with a gradient unit forced on, see run_frame()),
// the verilated models' contexts (`back_ctx` the back thread's, or ctx),
// and what run_frame() made for it.
struct ClockedFrame {
  const golden::Registers& r;
  const golden::Registers& rs;
  const golden::Volume& vol;
  const SystemConfig& cfg;
  const FramePlan& plan;
  const CycleCount& cc;
  const golden::Progress& progress;
  const golden::PolygonFrame* polygons;
  VoxelMemory& mem;
  VerilatedContext* ctx;
  VerilatedContext* back_ctx;
  bool threaded;
  StreamChecker* checker;
  PolygonSource* source;
};

// A clocked perspective frame (check_perspective_levels() allowed it).
void run_perspective(const ClockedFrame& f, SystemResult& res) {
  const SystemConfig& cfg = f.cfg;
  // The weight generator runs at RTL with the interpolation unit, as in
  // parallel projection: the ring then reads cube4_dda's perspective slice
  // constants; the frame's check keeps golden's.
  std::optional<FramePlan> rtl_plan;
  if (cfg.levels[static_cast<size_t>(Unit::Interp)] == Level::Rtl) {
    rtl_plan.emplace(f.rs, cfg.p, kUserTagBits, 0, std::vector<golden::SliceControl>{},
                     rtl_perspective_slices(f.rs, *f.ctx));
    res.weight_generator = Level::Rtl;
  }
  const FramePlan& plan = rtl_plan ? *rtl_plan : f.plan;
  std::unique_ptr<AddrIf> addr;
  if (cfg.levels[static_cast<size_t>(Unit::Addr)] == Level::Rtl)
    addr = make_rtl_addr(plan, f.mem.layout(), *f.ctx, cfg.trace);
  else
    addr = std::make_unique<TlmAddr>(f.mem.layout(), golden::SkewTraversal{f.r.perm, f.r.flip});
  StreamFormer former(plan, f.mem, *addr, cfg.frames);
  std::unique_ptr<PerspInterpIf> interp;
  if (cfg.levels[static_cast<size_t>(Unit::Interp)] == Level::Rtl)
    interp = make_rtl_interp_persp(plan, *f.ctx, cfg.trace);
  else
    interp = std::make_unique<TlmInterpPersp>(plan);
  // The gradient ring at either level (check_perspective_levels() refuses
  // VolumePro's z gradient at any clocked level), shading at either level,
  // compositing (and the polygons' slabs) at TLM.
  std::unique_ptr<PerspGradientIf> gradient;
  if (f.r.gradient) {
    if (cfg.levels[static_cast<size_t>(Unit::Gradient)] == Level::Rtl)
      gradient = make_rtl_gradient_persp(plan, *f.ctx, cfg.trace);
    else
      gradient = std::make_unique<TlmGradientPersp>(plan);
  }
  std::unique_ptr<PerspShadeIf> shade;
  if (cfg.levels[static_cast<size_t>(Unit::Shade)] == Level::Rtl)
    shade = make_rtl_shade_persp(plan, *f.ctx, cfg.trace, cfg.simulate_unneeded);
  else
    shade = std::make_unique<TlmShadePersp>(plan);
  std::unique_ptr<PerspCompositor> composite;
  if (cfg.levels[static_cast<size_t>(Unit::Composite)] == Level::Rtl)
    composite = make_rtl_composite_persp(plan, cfg.accumulators, *f.ctx, cfg.trace, f.polygons);
  else
    composite = std::make_unique<TlmCompositePersp>(plan, cfg.accumulators, f.polygons);
  const PerspectiveFrameResult pr =
      run_perspective_frame({plan, f.vol, cfg.frames, cfg.check, cfg.accumulators, f.polygons, f.progress, f.source,
                             cfg.kernel},
                            former, PerspectiveUnits{*interp, gradient.get(), shade.get(), composite.get()});
  res.plane = pr.plane;
  res.polygon_stall_cycles = pr.polygon_stall_cycles;
  // Every unit clocked: the frame's cycles are measured, to its last pixel.
  res.frame_cycles = pr.frame_done_cycles.front();
  if (cfg.frames > 1) res.measured_interval = pr.frame_done_cycles[1] - pr.frame_done_cycles[0];
  res.last_beat = {pr.last_beat_cycle, pr.last_sample_cycle, pr.last_gradient_cycle, 0};
  res.simulated_cycles = pr.cycles;
  res.voxel_reads = f.mem.reads();
  res.mismatch = pr.mismatch;
  res.back_loosely_timed = false;
  res.gradient_clocked = gradient != nullptr;
}

// A clocked parallel frame: the units on the schedule of cfg.kernel.
void run_parallel(const ClockedFrame& f, SystemResult& res) {
  const SystemConfig& cfg = f.cfg;
  const FramePlan& plan = f.plan;
  const golden::Registers& rs = f.rs;
  PixelMemory pixels(f.r, cfg.accumulators);
  FrameUnits u;
  u.frames = cfg.frames;
  bool rtl[kUnits];
  for (int i = 0; i < kUnits; ++i) rtl[i] = cfg.levels[static_cast<size_t>(i)] == Level::Rtl;
  // The weight generator runs at RTL with the interpolation unit, the
  // first unit to read its weights: every unit then reads the slice
  // controls cube4_dda produced (`up`); the checker keeps golden's (plan).
  std::optional<FramePlan> rtl_plan;
  if (rtl[static_cast<int>(Unit::Interp)]) {
    rtl_plan.emplace(rs, cfg.p, kUserTagBits, 0, rtl_slice_controls(rs, *f.ctx));
    res.weight_generator = Level::Rtl;
  }
  const FramePlan& up = rtl_plan ? *rtl_plan : plan;
  const golden::SkewTraversal traversal{f.r.perm, f.r.flip};
  if (rtl[static_cast<int>(Unit::Addr)]) {
    u.addr = make_rtl_addr(up, f.mem.layout(), *f.ctx, cfg.trace);
  } else {
    u.addr = std::make_unique<TlmAddr>(f.mem.layout(), traversal);
  }
  u.former = std::make_unique<StreamFormer>(up, f.mem, *u.addr, cfg.frames);
  u.interp = rtl[0] ? make_rtl_interp(up, *f.ctx, cfg.trace) : std::make_unique<TlmInterp>(up);
  // Gradients and shading of samples that cannot change their ray are
  // don't-cares when only TLM shading and compositing read them.
  const bool skip_transparent = !f.checker && !rtl[2] && !rtl[3];
  // Nor those of samples on rays the TLM compositor has stopped, which the
  // units ahead of it ask it about: on one thread only, as it runs.
  std::unique_ptr<TlmComposite> tlm_composite;
  if (!rtl[3]) tlm_composite = std::make_unique<TlmComposite>(up, pixels, f.polygons);
  const TlmComposite* stops = f.threaded ? nullptr : tlm_composite.get();
  if (!rs.gradient) {
    u.gradient = std::make_unique<GradientBypass>(up);
  } else {
    u.gradient = rtl[1] ? make_rtl_gradient(up, *f.ctx, cfg.trace)
                        : std::make_unique<TlmGradient>(up, skip_transparent, stops);
  }
  // Two threads: the front keeps the RTL shading units of the upper
  // quarter of the pipelines (schedules.hpp), which evened the threads'
  // work best at p = 4 and 8 (docs/performance.md).
  u.threaded = f.threaded;
  u.p = cfg.p;
  u.front_first_lane = f.threaded && rtl[2] ? cfg.p - cfg.p / 4 : cfg.p;
  u.front_ctx = f.ctx;
  u.back_ctx = f.threaded ? f.back_ctx : nullptr;
  if (rtl[2]) {
    u.shade = make_rtl_shade(up, *f.back_ctx, cfg.trace, cfg.simulate_unneeded, 0, u.front_first_lane);
    if (u.front_first_lane < cfg.p)
      u.front_shade = make_rtl_shade(up, *f.ctx, cfg.trace, cfg.simulate_unneeded, u.front_first_lane, cfg.p);
  } else {
    u.shade = std::make_unique<TlmShade>(up, skip_transparent, stops);
  }
  if (rtl[3])
    u.composite = make_rtl_composite(up, pixels, *f.back_ctx, cfg.trace, cfg.simulate_unneeded, f.polygons, cfg.frames);
  else
    u.composite = std::move(tlm_composite);
  u.checker = f.checker;
  if (f.source) u.gate.emplace(*f.source);
  u.progress = f.progress;
  u.total_beats = f.cc.stream * static_cast<uint64_t>(cfg.frames) + f.cc.flush;
  run_units(u, cfg.kernel);
  if (!u.done) throw std::logic_error("system: the simulation stopped before the frame's last pixel");
  res.frame_cycles = u.frame_done_cycles.front();
  if (u.gate) res.polygon_stall_cycles = u.gate->first_frame_stalls(u.frames);
  if (u.frames > 1) res.measured_interval = u.frame_done_cycles[1] - u.frame_done_cycles[0];
  res.last_beat = {u.last_valid[0], u.last_valid[1], u.last_valid[2], u.last_shaded};
  res.simulated_cycles = u.done_cycle;
  res.voxel_reads = f.mem.reads();
  res.plane = pixels.plane();
}

}  // namespace

SystemResult run_frame(const golden::Registers& r, const golden::Volume& vol, const SystemConfig& cfg,
                       const golden::Progress& progress, const golden::PolygonFrame* polygons) {
  const auto t0 = std::chrono::steady_clock::now();
  golden::check_dda(r);
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
  if (polygons) check_polygon_levels(cfg, r.perspective);
  check_perspective_levels(r, cfg);
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
  if (r.perspective) {
    // What the same volume costs in parallel projection, for the report's
    // answer to whether perspective costs cycles (docs/perspective.md).
    golden::Registers parallel = *rs;
    parallel.perspective = false;
    const CycleCount pc = frame_cycles(parallel, cfg.p);
    res.parallel_frame_cycles = pc.latency;
    res.parallel_stream_cycles = pc.stream;
  }
  res.samples = r.perspective ? golden::perspective_samples(r) : static_cast<uint64_t>(plan.nx) * plan.ny * plan.K;

  std::unique_ptr<StreamChecker> checker;
  if (cfg.check && !r.perspective) checker = std::make_unique<StreamChecker>(plan, vol);

  // The slab images' connection (Ideal: no wait, no source).
  std::unique_ptr<PolygonSource> source;
  if (polygons && cfg.polygon_engine.connection != golden::PolygonConnection::Ideal)
    source = std::make_unique<PolygonSource>(plan, cfg.polygon_work ? *cfg.polygon_work : golden::polygon_work(*polygons),
                                             cfg.polygon_engine, cfg.clock_hz);
  if (polygons) res.polygon_connection = polygon_connection_name(cfg.polygon_engine.connection);

  if (cfg.all_tlm() && !cfg.cycle_level) {
    res.plane = run_tlm_frame(plan, vol, progress, cfg.accumulators, polygons);
    if (source) res.polygon_stall_cycles = source->stalls_of_frame(plan.pass_beats());
    res.frame_cycles = (cfg.frames > 1 ? cc.latency_followed : cc.latency) + res.polygon_stall_cycles;
    for (int pass = plan.first_pass(); pass < plan.passes; ++pass)
      if (plan.pass_voxel_slice(pass) < plan.nz) res.voxel_reads += static_cast<uint64_t>(plan.ny) * plan.B * plan.p;
  } else {
    // A perspective frame's units run on one thread (its stream is clocked
    // by one schedule); a parallel frame's back may take the second.
    const bool threaded = !r.perspective && simulation_threads(cfg) > 1;
    res.threads = threaded ? 2 : 1;
#ifdef CUBE4_HAVE_RTL
    rtl::ScopedVerilatedContext ctx(cfg.seed, !cfg.trace.file.empty(), cfg.assertions);
    // The back's models' own (schedules.hpp), made before any model so that
    // both threads' models draw their random reset as one thread's would.
    std::optional<rtl::ScopedVerilatedContext> back_ctx;
    if (threaded) back_ctx.emplace(cfg.seed, !cfg.trace.file.empty(), cfg.assertions);
    VerilatedContext* rtl_ctx = ctx.get();
    VerilatedContext* rtl_back_ctx = back_ctx ? back_ctx->get() : rtl_ctx;
#else
    VerilatedContext* rtl_ctx = nullptr;  // require_rtl() refused every RTL unit
    VerilatedContext* rtl_back_ctx = nullptr;
#endif
    VoxelMemory mem(vol, cfg.p);
    const ClockedFrame frame{r, *rs, vol, cfg, plan, cc, progress, polygons, mem,
                             rtl_ctx, rtl_back_ctx, threaded, checker.get(), source.get()};
    if (r.perspective) {
      run_perspective(frame, res);
    } else {
      run_parallel(frame, res);
    }
#ifdef CUBE4_HAVE_RTL
    // While the models live (a coverage build's; else nothing).
    rtl::write_coverage(*rtl_ctx);
    if (back_ctx) rtl::write_coverage(**back_ctx);
#endif
  }
  res.stream_cycles += res.polygon_stall_cycles;
  if (checker) res.mismatch = checker->first_mismatch();
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (progress) progress(1.0);
  return res;
}

}  // namespace cube4::sysc

