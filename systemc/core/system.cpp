#include "systemc/core/system.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <sstream>
#include <systemc>

#include "systemc/core/frame_plan.hpp"
#include "systemc/core/link.hpp"
#include "systemc/core/pixel_memory.hpp"
#include "systemc/core/stream_checker.hpp"
#include "systemc/core/stream_former.hpp"
#include "systemc/core/voxel_memory.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/tlm/gradient_bypass.hpp"
#include "systemc/tlm/tlm_composite.hpp"
#include "systemc/tlm/tlm_frame.hpp"
#include "systemc/tlm/tlm_gradient.hpp"
#include "systemc/tlm/tlm_interp.hpp"
#include "systemc/tlm/tlm_shade.hpp"

#ifdef CUBE4_HAVE_RTL
#include "systemc/rtl/rtl_model.hpp"
#endif

namespace cube4::sysc {

std::string Mismatch::describe() const {
  std::ostringstream s;
  s << unit_name(unit) << " unit, slice " << slice << ", sample (" << x << ", " << y << "): expected " << expected
    << ", got " << got;
  return s.str();
}

namespace {

// The units of one frame (plain objects: a frame creates them afresh).
struct FrameUnits {
  std::unique_ptr<StreamFormer> former;
  std::unique_ptr<InterpIf> interp;
  std::unique_ptr<GradientIf> gradient;
  std::unique_ptr<ShadeIf> shade;
  std::unique_ptr<CompositeIf> composite;
  StreamChecker* checker = nullptr;
  golden::Progress progress;
  uint64_t total_beats = 1;
};

// The clocked top: one process per unit, registered links between them.
// SystemC elaborates once per process, so the top is built on the first
// frame and each frame plugs its units in (sc_pause() ends a frame).
SC_MODULE(CycleTop) {
  sc_core::sc_clock clk{"clk", sc_core::sc_time(1, sc_core::SC_NS)};
  Link<VoxelBeat> voxels{"voxels"};
  Link<SampleBeat> samples{"samples"};
  Link<GradientBeat> gradients{"gradients"};
  Link<ShadedBeat> shaded{"shaded"};

  FrameUnits* u = nullptr;
  uint64_t cycle = 0, done_cycle = 0;
  uint64_t last_valid[4] = {0, 0, 0, 0};  // last cycle each link carried a beat
  bool done = false;
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
    cycle = done_cycle = 0;
    for (uint64_t& c : last_valid) c = 0;
    done = false;
    error = nullptr;
    voxels.reset();
    samples.reset();
    gradients.reset();
    shaded.reset();
  }

  template <class F>
  void guarded(F&& f) {
    if (done || error) return;
    try {
      f();
    } catch (...) {
      error = std::current_exception();
      sc_core::sc_pause();
    }
  }

  void former_step() {
    guarded([&] {
      ++cycle;
      const VoxelBeat b = u->former->next();
      if (b.valid) last_valid[0] = cycle;
      voxels.write(b);
      if (u->progress && (cycle & 0xffff) == 0)
        u->progress(std::min(1.0, static_cast<double>(cycle) / static_cast<double>(u->total_beats)));
    });
  }
  void interp_step() {
    guarded([&] {
      SampleBeat out;
      u->interp->clock(voxels.read(), out);
      if (u->checker) u->checker->samples(out);
      if (out.valid) last_valid[1] = cycle;
      samples.write(out);
    });
  }
  void gradient_step() {
    guarded([&] {
      GradientBeat out;
      u->gradient->clock(samples.read(), out);
      if (u->checker) u->checker->gradients(out);
      if (out.valid) last_valid[2] = cycle;
      gradients.write(out);
    });
  }
  void shade_step() {
    guarded([&] {
      ShadedBeat out;
      u->shade->clock(gradients.read(), out);
      if (u->checker) u->checker->shaded(out);
      if (out.valid) last_valid[3] = cycle;
      shaded.write(out);
    });
  }
  void composite_step() {
    guarded([&] {
      CompositeOut out;
      u->composite->clock(shaded.read(), out);
      if (out.frame_done) {
        done = true;
        done_cycle = cycle;
        sc_core::sc_pause();
      }
    });
  }
};

CycleTop& cycle_top() {
  static CycleTop* top = new CycleTop("cube4");  // lives as long as the SystemC kernel
  return *top;
}

void check_rtl_precision(const golden::Registers& r) {
  const golden::Precision d;
  const golden::Precision& p = r.p;
  if (p.voxel_bits != d.voxel_bits || p.weight_bits != d.weight_bits || p.gradient_bits != d.gradient_bits ||
      p.gradient_shift != d.gradient_shift || p.magnitude_bits != d.magnitude_bits ||
      p.nr_iterations != d.nr_iterations || p.color_bits != d.color_bits || p.alpha_bits != d.alpha_bits ||
      p.gmlut_bits != d.gmlut_bits || p.map_face_res != d.map_face_res || p.map_bits != d.map_bits ||
      p.map_frac_bits != d.map_frac_bits || p.coef_bits != d.coef_bits || p.coef_frac_bits != d.coef_frac_bits ||
      p.eye_bits != d.eye_bits || p.cut_bits != d.cut_bits)
    throw std::invalid_argument("precision: the system's RTL is verilated with the default widths "
                                "(docs/fixed-point.md); run other widths with --model tlm");
  if (r.dim[0] > kRtlMaxDim || r.dim[1] > kRtlMaxDim)
    throw std::invalid_argument("volume: permuted " + std::to_string(r.dim[0]) + "x" + std::to_string(r.dim[1]) +
                                " exceeds the RTL rings' storage (MaxDim " + std::to_string(kRtlMaxDim) + ")");
}

}  // namespace

SystemResult run_frame(const golden::Registers& r, const golden::Volume& vol, const SystemConfig& cfg,
                       const golden::Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const FramePlan plan(r, cfg.p);
  SystemResult res;
  res.levels = cfg.levels;
  res.simulated = {true, r.gradient, true, true};
  if (!r.gradient) res.skipped.push_back("gradient unit (no gradients: no shading, no gradient-magnitude modulation)");
  if (!r.magnitude) res.skipped.push_back(cfg.levels[2] == Level::Tlm ? "gradient magnitude and GmLUT"
                                                                      : "GmLUT modulation (RTL: computed, unused)");
  if (!r.shading) res.skipped.push_back(cfg.levels[2] == Level::Tlm ? "reflectance maps and Phong shading"
                                                                    : "reflectance maps (RTL: computed, unused)");
  if (!r.cut_enabled) res.skipped.push_back(cfg.levels[3] == Level::Tlm ? "cut-plane logic" : "cut-plane logic (RTL: computed, unused)");
  if (!r.crop_enabled) res.skipped.push_back(cfg.levels[3] == Level::Tlm ? "cropping logic" : "cropping logic (RTL: computed, unused)");
  const CycleCount cc = frame_cycles(r, cfg.p);
  res.stream_cycles = cc.stream;
  res.samples = static_cast<uint64_t>(plan.nx) * plan.ny * plan.K;

  std::unique_ptr<StreamChecker> checker;
  if (cfg.check) checker = std::make_unique<StreamChecker>(plan, vol);

  if (cfg.all_tlm()) {
    res.plane = run_tlm_frame(plan, vol, progress);
    res.frame_cycles = cc.latency;
    for (int pass = 0; pass < plan.passes; ++pass)
      if (plan.pass_voxel_slice(pass) < plan.nz) res.voxel_reads += static_cast<uint64_t>(plan.ny) * plan.B * plan.p;
  } else {
    check_rtl_precision(r);
    require_rtl(cfg.p);
#ifdef CUBE4_HAVE_RTL
    VerilatedContext ctx;
    if (!cfg.trace.file.empty()) ctx.traceEverOn(true);
    VoxelMemory mem(vol, cfg.p);
    PixelMemory pixels(r);
    FrameUnits u;
    u.former = std::make_unique<StreamFormer>(plan, mem);
    const bool rtl[kUnits] = {cfg.levels[0] == Level::Rtl, cfg.levels[1] == Level::Rtl, cfg.levels[2] == Level::Rtl,
                              cfg.levels[3] == Level::Rtl};
    u.interp = rtl[0] ? make_rtl_interp(plan, ctx, cfg.trace) : std::make_unique<TlmInterp>(plan);
    if (!r.gradient) {
      u.gradient = std::make_unique<GradientBypass>(plan);
    } else {
      u.gradient = rtl[1] ? make_rtl_gradient(plan, ctx, cfg.trace) : std::make_unique<TlmGradient>(plan);
    }
    u.shade = rtl[2] ? make_rtl_shade(plan, ctx, cfg.trace) : std::make_unique<TlmShade>(plan);
    u.composite = rtl[3] ? make_rtl_composite(plan, pixels, ctx, cfg.trace)
                         : std::make_unique<TlmComposite>(plan, pixels);
    u.checker = checker.get();
    u.progress = progress;
    u.total_beats = cc.stream;
    CycleTop& top = cycle_top();
    top.start(u);
    sc_core::sc_start();
    if (top.error) std::rethrow_exception(top.error);
    if (!top.done) throw std::logic_error("system: the simulation stopped before the frame's last pixel");
    res.frame_cycles = top.done_cycle;
    if (std::getenv("CUBE4_DEBUG_CYCLES"))
      std::fprintf(stderr, "last beats: former %llu interp %llu gradient %llu shade %llu done %llu\n", (unsigned long long)top.last_valid[0], (unsigned long long)top.last_valid[1], (unsigned long long)top.last_valid[2], (unsigned long long)top.last_valid[3], (unsigned long long)top.done_cycle);
    res.simulated_cycles = top.done_cycle;
    res.voxel_reads = mem.reads();
    res.plane = pixels.plane();
#endif
  }
  if (checker) res.mismatch = checker->first_mismatch();
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (progress) progress(1.0);
  return res;
}

}  // namespace cube4::sysc

// libsystemc.so's main() calls sc_main(); the programs that link the system
// model have a main() of their own, which the linker prefers, and start the
// kernel from run_frame(). The library still needs the symbol to link.
int sc_main(int, char**) {
  std::fprintf(stderr, "cube4: sc_main is not an entry point of this program\n");
  return 1;
}
