#include "systemc/core/schedules.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <systemc>
#include <thread>

#include "systemc/core/clocked_tops.hpp"
#include "systemc/core/cycle_pipe.hpp"
#include "systemc/core/edge_clock.hpp"
#include "systemc/core/link.hpp"

#ifdef CUBE4_HAVE_RTL
// verilated.h calls sc_time_stamp() unqualified once SystemC is included.
using sc_core::sc_time_stamp;
#include <verilated.h>
#endif

namespace cube4::sysc {
namespace {

// One clock edge of each unit: it sees its input link's value of this cycle
// and returns its output (the next link's value in the next cycle). Every
// schedule below calls these, so they simulate the same machine. `cycle`:
// the cycle the edge ends, as the loop that clocks the unit counts it (the
// stream former's counter, u.cycle, on one thread).
VoxelBeat former_edge(FrameUnits& u) {
  ++u.cycle;
  // A pass starts only once its slice's slab image is in the buffer.
  if (u.gate && u.gate->holds(*u.former, u.cycle)) return VoxelBeat{};
  const VoxelBeat b = u.former->next();
  if (b.valid) u.last_valid[0] = u.cycle;
  if (u.progress && (u.cycle & 0xffff) == 0)
    u.progress(std::min(1.0, static_cast<double>(u.cycle) / static_cast<double>(u.total_beats)));
  return b;
}
// Each edge writes its beat into `out` (the plain loop's own variable, no
// copy a cycle) or returns it (for a channel's write).
void interp_edge(FrameUnits& u, const VoxelBeat& in, SampleBeat& out) {
  u.interp->clock(in, out);
  if (u.checker) u.checker->samples(out);
  if (out.valid) u.last_valid[1] = u.cycle;
}
SampleBeat interp_edge(FrameUnits& u, const VoxelBeat& in) {
  SampleBeat out;
  interp_edge(u, in, out);
  return out;
}
void gradient_edge(FrameUnits& u, const SampleBeat& in, GradientBeat& out) {
  u.gradient->clock(in, out);
  if (u.checker) u.checker->gradients(out);
  if (out.valid) u.last_valid[2] = u.cycle;
}
GradientBeat gradient_edge(FrameUnits& u, const SampleBeat& in) {
  GradientBeat out;
  gradient_edge(u, in, out);
  return out;
}
// `front`: with two threads, the shaded beat's lanes the front's shading
// units gave (pipelines front_first_lane .. p - 1), merged before the
// beat leaves.
void shade_edge(FrameUnits& u, const GradientBeat& in, uint64_t cycle, ShadedBeat& out, const ShadedBeat* front = nullptr) {
  u.shade->clock(in, out);
  if (front)
    for (size_t k = static_cast<size_t>(u.front_first_lane); k < static_cast<size_t>(u.p); ++k) {
      out.red[k] = front->red[k];
      out.green[k] = front->green[k];
      out.blue[k] = front->blue[k];
      out.alpha[k] = front->alpha[k];
      out.value[k] = front->value[k];
    }
  if (u.checker) u.checker->shaded(out);
  if (out.valid) u.last_shaded = cycle;
}
ShadedBeat shade_edge(FrameUnits& u, const GradientBeat& in, uint64_t cycle, const ShadedBeat* front = nullptr) {
  ShadedBeat out;
  shade_edge(u, in, cycle, out, front);
  return out;
}
void composite_edge(FrameUnits& u, const ShadedBeat& in, uint64_t cycle) {
  CompositeOut out;
  u.composite->clock(in, out);
  if (out.frame_done) {
    u.frame_done_cycles.push_back(cycle);
    if (static_cast<int>(u.frame_done_cycles.size()) == u.frames) {
      u.done = true;
      u.done_cycle = cycle;
    }
  }
}

// What the front hands the back each cycle: the gradient beat it wrote,
// and its shading units' lanes of the shaded beat of that cycle.
struct FrontCycle {
  GradientBeat gradients;
  ShadedBeat shaded;
};

// The back: shading (pipelines below front_first_lane) and compositing on
// a thread of their own, a cycle at a time as the front hands them over.
// done() once the frame's last pixel is written; the front may have run
// some cycles further by then, which must have carried no beat (finish()
// checks it).
class BackEnd {
 public:
  explicit BackEnd(FrameUnits& u) : u_(u), thread_([this] { run(); }) {}
  ~BackEnd() {
    pipe_.close();
    if (thread_.joinable()) thread_.join();
  }
  BackEnd(const BackEnd&) = delete;
  BackEnd& operator=(const BackEnd&) = delete;

  // The front's half of a cycle: its shading lanes of the beat `gradients`
  // (the link's value this cycle), then `front_edges`, which clocks the
  // gradient unit and returns its beat. A cycle the front did not finish
  // (it threw) is not handed over.
  template <class FrontEdges>
  void front_cycle(const GradientBeat& gradients, FrontEdges&& front_edges) {
    FrontCycle& c = pipe_.next();
    try {
      if (u_.front_shade) u_.front_shade->clock(gradients, c.shaded);
      c.gradients = front_edges();
    } catch (...) {
      pipe_.discard();
      throw;
    }
  }
  bool done() const { return pipe_.stopped(); }

  // After the front stops (the back is done, or the front threw
  // `front_error`): waits for the back and gives the frame's outcome.
  void finish(std::exception_ptr front_error) {
    const uint64_t front_cycle = u_.cycle;
    pipe_.close();
    thread_.join();
    // An error on one side ends the frame at its cycle; the other side's
    // later cycles were never simulated by one thread.
    if (back_error_ && (!front_error || back_cycle_ <= front_cycle)) std::rethrow_exception(back_error_);
    if (front_error && !u_.done) std::rethrow_exception(front_error);
    // Cycles the front ran past the frame's end carried no beat, so the
    // links' last beats, the checker and the voxel reads are one thread's.
    if (u_.done && (u_.last_valid[0] > u_.done_cycle || u_.last_valid[1] >= u_.done_cycle ||
                    u_.last_valid[2] >= u_.done_cycle))
      throw std::logic_error("system: the front units carried beats after the frame's last pixel");
  }

 private:
  void run() {
#ifdef CUBE4_HAVE_RTL
    if (u_.back_ctx) Verilated::threadContextp(u_.back_ctx);
#endif
    uint64_t cycle = 0;
    try {
      GradientBeat gradients;
      ShadedBeat shaded;
      for (; ; ++cycle) {
        composite_edge(u_, shaded, cycle);
        if (u_.done) break;
        const FrontCycle* c = pipe_.pop();
        if (!c) break;  // the front stopped first (it threw)
        shaded = shade_edge(u_, gradients, cycle, u_.front_shade ? &c->shaded : nullptr);
        gradients = c->gradients;
      }
    } catch (...) {
      back_error_ = std::current_exception();
      back_cycle_ = cycle;
    }
    pipe_.stop();
  }

  FrameUnits& u_;
  CyclePipe<FrontCycle> pipe_;
  std::exception_ptr back_error_;
  uint64_t back_cycle_ = 0;
  std::thread thread_;  // last: starts once the rest is built
};

bool finished(const FrameUnits& u, const BackEnd* back) { return back ? back->done() : u.done; }

// The clocked top: registered links between the units, and work at the
// clock's rising edge that clocks each unit in turn. The links keep the
// previous edge's beats, so the order changes nothing a unit sees. The
// work runs inside the clock's own process (EdgeClock::at_each_edge): one
// process activation a cycle, where a process per unit had taken six
// (docs/performance.md, "Simulation speed of the system model"). SystemC
// elaborates once per process, so the top is built on the first frame and
// each frame plugs its units in (sc_pause() ends a frame). With two
// threads the edge clocks only the front's units.
SC_MODULE(CycleTop) {
  EdgeClock clk{"clk", sc_core::sc_time(1, sc_core::SC_NS)};
  Link<VoxelBeat> voxels{"voxels", clk};
  Link<SampleBeat> samples{"samples", clk};
  Link<GradientBeat> gradients{"gradients", clk};
  Link<ShadedBeat> shaded{"shaded", clk};

  FrameUnits* u = nullptr;
  BackEnd* back = nullptr;
  std::exception_ptr error;

  SC_CTOR(CycleTop) { clk.at_each_edge([this] { edge(); }); }

  void start(FrameUnits& units, BackEnd* back_end) {
    u = &units;
    back = back_end;
    error = nullptr;
    voxels.reset();
    samples.reset();
    gradients.reset();
    shaded.reset();
  }

  // Between frames (while the composition network runs on the same
  // clock) no frame is plugged in.
  void stop() {
    u = nullptr;
    back = nullptr;
  }

  template <class F>
  void guarded(F&& f) {
    if (!u || error) return;
    if (finished(*u, back)) {
      sc_core::sc_pause();
      return;
    }
    try {
      f();
    } catch (...) {
      error = std::current_exception();
      sc_core::sc_pause();
    }
  }

  // From the last unit to the first, as the plain loop runs them.
  void edge() {
    guarded([&] {
      if (!back) {
        composite_edge(*u, shaded.read(), u->cycle);
        if (u->done) {
          sc_core::sc_pause();
          return;
        }
        shade_edge(*u, gradients.read(), u->cycle, shaded.next());
        gradient_edge(*u, samples.read(), gradients.next());
      } else {
        back->front_cycle(gradients.read(), [&] {
          const GradientBeat g = gradient_edge(*u, samples.read());
          gradients.write(g);
          return g;
        });
      }
      interp_edge(*u, voxels.read(), samples.next());
      voxels.write(former_edge(*u));
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
    composite_edge(u, shaded, u.cycle);
    if (u.done) break;
    // Each beat is overwritten once the unit behind has taken it.
    shade_edge(u, gradients, u.cycle, shaded);
    gradient_edge(u, samples, gradients);
    interp_edge(u, voxels, samples);
    voxels = former_edge(u);
  }
}

// The plain loop's front, the back on its own thread.
void run_plain_front(FrameUnits& u, BackEnd& back) {
  VoxelBeat voxels;
  SampleBeat samples;
  GradientBeat gradients;
  while (!back.done()) {
    back.front_cycle(gradients, [&] {
      gradients = gradient_edge(u, samples);
      return gradients;
    });
    samples = interp_edge(u, voxels);
    voxels = former_edge(u);
  }
}

// Both clocked tops, built together (clocked_tops.hpp); they live as long
// as the SystemC kernel.
struct ClockedTops {
  CycleTop* cycle;
  sc_core::sc_module* network;
  sc_core::sc_module* perspective;
};
ClockedTops& clocked_tops() {
  static ClockedTops tops = [] {
    auto* top = new CycleTop("cube4");
    return ClockedTops{top, build_network_top(top->clk), build_perspective_top(top->clk)};
  }();
  return tops;
}
CycleTop& cycle_top() { return *clocked_tops().cycle; }

void run_systemc(FrameUnits& u, BackEnd* back) {
  CycleTop& top = cycle_top();
  top.start(u, back);
  sc_core::sc_start();
  top.stop();
  if (top.error) std::rethrow_exception(top.error);
}

}  // namespace

sc_core::sc_module& network_top() { return *clocked_tops().network; }
sc_core::sc_module& perspective_top() { return *clocked_tops().perspective; }

void run_units(FrameUnits& u, Kernel kernel) {
  if (!u.threaded) {
    if (kernel == Kernel::SystemC)
      run_systemc(u, nullptr);
    else
      run_plain(u);
    return;
  }
#ifdef CUBE4_HAVE_RTL
  if (u.front_ctx) Verilated::threadContextp(u.front_ctx);
#endif
  BackEnd back(u);
  std::exception_ptr front_error;
  try {
    if (kernel == Kernel::SystemC)
      run_systemc(u, &back);
    else
      run_plain_front(u, back);
  } catch (...) {
    front_error = std::current_exception();
  }
  back.finish(front_error);
}

}  // namespace cube4::sysc
