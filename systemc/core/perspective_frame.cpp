#include "systemc/core/perspective_frame.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <systemc>
#include <string>
#include <vector>

#include "golden/permuted_volume.hpp"
#include "golden/perspective.hpp"
#include "systemc/core/clocked_tops.hpp"
#include "systemc/core/edge_clock.hpp"
#include "systemc/core/link.hpp"
#include "systemc/core/frame_rays.hpp"
#include "systemc/core/pass_gate.hpp"
#include "systemc/core/ray_gradients.hpp"
#include "systemc/tlm/gradient_bypass.hpp"
#include "systemc/tlm/tlm_gradient_persp.hpp"
#include "systemc/tlm/tlm_shade.hpp"

namespace cube4::sysc {
namespace {

// The unit's samples of a frame by slice and ray, as the renderer asks for
// them; with the count of each ray's arrivals (one per frame streamed).
// Which rays sample a slice, and what they should sample, is golden's
// (FrameRays), whatever weight generator the unit ran with.
class RaySamples final : public golden::PerspectiveSamples {
 public:
  RaySamples(const FramePlan& plan, const FrameRays& rays, const golden::Volume& vol, int frames, bool check)
      : plan_(plan), rays_(rays), pv_(vol, plan.r.perm, plan.r.flip), frames_(frames), check_(check),
        slices_(static_cast<size_t>(rays.slices())) {
    for (int k = 0; k < rays.slices(); ++k) {
      Slice& out = slices_[static_cast<size_t>(k)];
      out.value.assign(rays.count(k), 0);
      out.vtag.assign(rays.count(k), 0);
      if (plan.zdiff) out.zdiff.assign(rays.count(k), 0);
      out.count.assign(rays.count(k), 0);
    }
  }

  uint32_t sample(int k, int64_t u, int64_t v) const override { return at(k, u, v, &Slice::value); }
  uint32_t vtag(int k, int64_t u, int64_t v) const override { return at(k, u, v, &Slice::vtag); }
  // With VolumePro's z gradient, the sample's filtered voxel z difference.
  int32_t z_difference(int k, int64_t u, int64_t v) const {
    return slices_[static_cast<size_t>(k)].zdiff[rays_.index(k, u, v)];
  }

  // One sample that left the unit on some lane (zdiff: 0 without plan.zdiff).
  void take(uint32_t slice, int64_t u, int64_t v, uint32_t value, uint32_t vtag, int32_t zdiff) {
    ++taken_;
    const auto k = static_cast<int>(slice);
    const Got got{value, vtag, zdiff};
    if (!rays_.samples(k, u, v)) {
      fail(k, u, v, "no sample (the ray does not sample the slice)", describe(got));
      return;
    }
    Slice& s = slices_[slice];
    const size_t i = rays_.index(k, u, v);
    if (++s.count[i] > frames_) {
      fail(k, u, v, "the ray's sample " + std::to_string(frames_) + " time(s) a stream", "one more: " + describe(got));
      return;
    }
    const Got before{s.value[i], s.vtag[i], plan_.zdiff ? s.zdiff[i] : 0};
    if (s.count[i] > 1 && !(before == got)) {
      fail(k, u, v, describe(before) + " (the frame before's)", describe(got));
      return;
    }
    s.value[i] = static_cast<uint16_t>(value);
    s.vtag[i] = static_cast<uint8_t>(vtag);
    if (plan_.zdiff) s.zdiff[i] = zdiff;
    if (check_) {
      const Got want{expected(k, u, v), expected_tag(k, u, v), expected_z_difference(k, u, v)};
      if (!(want == got)) fail(k, u, v, describe(want), describe(got));
    }
  }

  // After the stream: the first ray that did not leave `frames` times.
  void check_complete() {
    for (int k = 0; k < rays_.slices() && !first_; ++k) {
      const Slice& got = slices_[static_cast<size_t>(k)];
      for (size_t i = 0; i < got.count.size(); ++i)
        if (got.count[i] != frames_) {
          fail(k, rays_.u_of(k, i), rays_.v_of(k, i), "the ray's sample " + std::to_string(frames_) + " time(s)",
               std::to_string(got.count[i]) + " time(s)");
          return;
        }
    }
  }

  uint64_t taken() const { return taken_; }
  const std::optional<Mismatch>& first() const { return first_; }

 private:
  struct Slice {
    std::vector<uint16_t> value;
    std::vector<uint8_t> vtag;
    std::vector<int32_t> zdiff;  // plan.zdiff only
    std::vector<int> count;
  };
  // What a lane gave for a ray.
  struct Got {
    uint32_t value, vtag;
    int32_t zdiff;
    bool operator==(const Got& o) const { return value == o.value && vtag == o.vtag && zdiff == o.zdiff; }
  };
  template <class T>
  uint32_t at(int k, int64_t u, int64_t v, std::vector<T> Slice::*field) const {
    return (slices_[static_cast<size_t>(k)].*field)[rays_.index(k, u, v)];
  }
  uint32_t expected(int k, int64_t u, int64_t v) const {
    const golden::PerspectiveSlice& s = rays_.slice(k);
    return golden::perspective_sample(plan_.r, s, u, v,
                                      [&](int x, int y, int dz) { return pv_.at(x, y, s.z_voxel + dz); });
  }
  uint32_t expected_tag(int k, int64_t u, int64_t v) const {
    if (plan_.r.p.tag_bits == 0) return 0;
    const golden::PerspectiveSlice& s = rays_.slice(k);
    const golden::TagVoxel t = golden::perspective_tag_voxel(plan_.r, s, u, v);
    return pv_.tag_at(t.x, t.y, s.z_voxel + t.dz);
  }
  int32_t expected_z_difference(int k, int64_t u, int64_t v) const {
    if (!plan_.zdiff) return 0;
    const golden::PerspectiveSlice& s = rays_.slice(k);
    return golden::perspective_z_difference(plan_.r, s, u, v, [&](int x, int y, int dz) {
      const int z = s.z_voxel + dz;
      return golden::voxel_z_difference(pv_.at(x, y, z + 1), pv_.at(x, y, z - 1));
    });
  }
  std::string describe(const Got& g) const {
    return std::to_string(g.value) + (plan_.r.p.tag_bits > 0 ? " (voxel tag " + std::to_string(g.vtag) + ")" : "") +
           (plan_.zdiff ? " (z difference " + std::to_string(g.zdiff) + ")" : "");
  }
  void fail(int k, int64_t u, int64_t v, const std::string& expected, const std::string& got) {
    if (!first_) first_ = Mismatch{Unit::Interp, k, static_cast<int>(u), static_cast<int>(v), expected, got};
  }

  const FramePlan& plan_;
  const FrameRays& rays_;
  golden::PermutedVolume pv_;
  int frames_;
  bool check_;
  std::vector<Slice> slices_;
  uint64_t taken_ = 0;
  std::optional<Mismatch> first_;
};

// The stream and the units a clock at a time, on either schedule. The
// former's edge makes the beat the link holds for the next clock (none
// while a polygon gate holds the stream); each unit's edge takes its
// link's beat of the clock before and gives the beat for the next unit's:
// the interpolation unit's samples are kept in `samples`, the gradient
// unit's gradients in `gradients`, and the compositor's frame ends in the
// result.
class PerspectiveStream {
 public:
  PerspectiveStream(const PerspectiveFrameInput& in, StreamFormer& former, const PerspectiveUnits& units,
                    RaySamples& samples, RayGradients& gradients, PerspectiveFrameResult& res)
      : in_(in), former_(former), units_(units), gradient_(units.gradient), samples_(samples),
        gradients_(gradients), res_(res),
        total_(static_cast<uint64_t>(in.frames) * static_cast<uint64_t>(in.plan.passes - in.plan.first_pass()) *
                   in.plan.pass_beats() +
               static_cast<uint64_t>(in.plan.flush_beams()) * in.plan.B),
        drain_(1 + 4 + 1 + TlmGradientPersp::kLatency +
               (units.shade ? 1 + static_cast<uint64_t>(shade_latency(in.plan.r.p)) + 1 + TlmCompositePersp::kLatency
                            : 0)) {
    if (in.source) gate_.emplace(*in.source);
    if (!gradient_ && units.shade) gradient_ = &bypass_;
  }

  void former_edge(uint64_t cycle, VoxelBeat& beat) {
    if (!former_.done() && !(gate_ && gate_->holds(former_, cycle))) {
      beat = former_.next();
      res_.last_beat_cycle = cycle;
    }
    idle_ = former_.done() && !beat.valid ? idle_ + 1 : 0;
    if (in_.progress && (cycle & 0xffff) == 0)
      in_.progress(std::min(1.0, static_cast<double>(cycle) / static_cast<double>(total_)));
  }

  void interp_edge(uint64_t cycle, const VoxelBeat& link, RaySampleBeat& out) {
    units_.interp.clock(link, out);
    for (int k = 0; out.valid && k < in_.plan.p; ++k) {
      if (!(out.valid >> k & 1)) continue;
      const auto i = static_cast<size_t>(k);
      samples_.take(out.tag[i], out.u[i], out.v[i], out.sample[i], out.vtag[i], out.zdiff[i]);
      res_.last_sample_cycle = cycle;
    }
  }

  void gradient_edge(uint64_t cycle, const RaySampleBeat& link, RayGradientBeat& out) {
    if (!gradient_) return;
    gradient_->clock(link, out);
    if (!units_.gradient) return;  // the bypass's zero gradients are not the scene's
    for (int k = 0; out.valid && k < in_.plan.p; ++k) {
      if (!(out.valid >> k & 1)) continue;
      const auto i = static_cast<size_t>(k);
      gradients_.take(out.tag[i], out.u[i], out.v[i], golden::Gradient{out.gx[i], out.gy[i], out.gz[i]});
      res_.last_gradient_cycle = cycle;
    }
  }

  void shade_edge(const RayGradientBeat& link, RayShadedBeat& out) {
    if (units_.shade) units_.shade->clock(link, out);
  }

  void composite_edge(uint64_t cycle, const RayShadedBeat& link) {
    if (!units_.composite) return;
    CompositeOut out;
    units_.composite->clock(link, out);
    if (out.frame_done) res_.frame_done_cycles.push_back(cycle);
  }

  // After the former's last beat: the links, the units' drain and a margin
  // in which nothing more may leave.
  bool finished() const { return idle_ >= drain_ + kMargin; }

  uint64_t first_frame_stalls() const { return gate_ ? gate_->first_frame_stalls(in_.frames) : 0; }

 private:
  static constexpr uint64_t kMargin = 8;
  const PerspectiveFrameInput& in_;
  StreamFormer& former_;
  const PerspectiveUnits& units_;
  PerspGradientIf* gradient_;  // the unit's, or the bypass
  PerspGradientBypass bypass_;
  RaySamples& samples_;
  RayGradients& gradients_;
  PerspectiveFrameResult& res_;
  uint64_t total_, drain_;
  std::optional<PassGate> gate_;
  uint64_t idle_ = 0;
};

// Returns the cycles clocked.
uint64_t run_plain(PerspectiveStream& stream) {
  VoxelBeat voxels;
  RaySampleBeat samples;
  RayGradientBeat gradients;
  RayShadedBeat shaded;
  uint64_t cycle = 0;
  while (!stream.finished()) {
    ++cycle;
    VoxelBeat next_voxels;
    RaySampleBeat next_samples;
    RayGradientBeat next_gradients;
    RayShadedBeat next_shaded;
    stream.former_edge(cycle, next_voxels);
    stream.interp_edge(cycle, voxels, next_samples);
    stream.gradient_edge(cycle, samples, next_gradients);
    stream.shade_edge(gradients, next_shaded);
    stream.composite_edge(cycle, shaded);
    voxels = next_voxels;
    samples = next_samples;
    gradients = next_gradients;
    shaded = next_shaded;
  }
  return cycle;
}

// The SystemC schedule: one process on the machine's clock that clocks
// the former and each unit, registered links between them (as CycleTop,
// schedules.cpp, says why one). SystemC elaborates once, so the top is
// built with the machine's (clocked_tops.hpp) and each frame plugs its
// stream in; idle, the process waits for the next frame instead of waking
// every cycle.
SC_MODULE(PerspectiveTop) {
  const EdgeClock& clk_;  // first: the links read its edges
  Link<VoxelBeat> link{"voxels", clk_};
  Link<RaySampleBeat> samples{"samples", clk_};
  Link<RayGradientBeat> gradients{"gradients", clk_};
  Link<RayShadedBeat> shaded{"shaded", clk_};
  PerspectiveStream* run = nullptr;
  std::exception_ptr error;
  sc_core::sc_event go;
  uint64_t cycle = 0;

  PerspectiveTop(sc_core::sc_module_name name, const EdgeClock& clk) : sc_core::sc_module(name), clk_(clk) {
    SC_METHOD(edge);
    sensitive << clk.posedge_event();
    dont_initialize();
  }
  SC_HAS_PROCESS(PerspectiveTop);

  void start(PerspectiveStream& s) {
    run = &s;
    error = nullptr;
    cycle = 0;
    edge_ = sc_core::SC_ZERO_TIME;
    first_ = true;
    link.reset();
    samples.reset();
    gradients.reset();
    shaded.reset();
    go.notify(sc_core::SC_ZERO_TIME);
  }
  void stop() { run = nullptr; }

  // A frame's first edge is the wake-up by `go`; each rising edge after it
  // one more.
  void tick() {
    const sc_core::sc_time now = sc_core::sc_time_stamp();
    if (first_ || now != edge_) ++cycle;
    first_ = false;
    edge_ = now;
  }
  template <class F>
  void guarded(F&& f) {
    if (!run) {
      next_trigger(go);
      return;
    }
    if (error) return;
    try {
      tick();
      f();
    } catch (...) {
      error = std::current_exception();
      sc_core::sc_pause();
    }
  }
  // Each unit in turn, from the last to the first; the links keep the
  // previous edge's beats, so the order changes nothing a unit sees.
  void edge() {
    guarded([&] {
      run->composite_edge(cycle, shaded.read());
      run->shade_edge(gradients.read(), shaded.next());
      run->gradient_edge(cycle, samples.read(), gradients.next());
      run->interp_edge(cycle, link.read(), samples.next());
      VoxelBeat& beat = link.next();
      beat = VoxelBeat{};
      run->former_edge(cycle, beat);
      if (run->finished()) sc_core::sc_pause();
    });
  }

 private:
  sc_core::sc_time edge_;
  bool first_ = true;
};

uint64_t run_systemc(PerspectiveStream& stream) {
  auto& top = dynamic_cast<PerspectiveTop&>(perspective_top());
  top.start(stream);
  sc_core::sc_start();
  top.stop();
  if (top.error) std::rethrow_exception(top.error);
  return top.cycle;
}

}  // namespace

sc_core::sc_module* build_perspective_top(const EdgeClock& clk) { return new PerspectiveTop("cube4_perspective", clk); }

PerspectiveFrameResult run_perspective_frame(const PerspectiveFrameInput& in, StreamFormer& former,
                                             const PerspectiveUnits& units) {
  const FramePlan& plan = in.plan;
  if ((units.shade == nullptr) != (units.composite == nullptr))
    throw std::logic_error("run_perspective_frame: shading and compositing are clocked together or not at all");
  const FrameRays rays(plan.r);
  RaySamples samples(plan, rays, in.vol, in.frames, in.check);
  RayGradients gradients(plan, rays, in.frames);
  PerspectiveFrameResult res;
  PerspectiveStream stream(in, former, units, samples, gradients, res);
  res.cycles = in.kernel == Kernel::SystemC ? run_systemc(stream) : run_plain(stream);
  samples.check_complete();
  if (units.gradient)
    gradients.finish(samples, in.check, [&samples](int k, int64_t u, int64_t v) { return samples.z_difference(k, u, v); });
  res.polygon_stall_cycles = stream.first_frame_stalls();
  res.beats = former.beats();
  res.samples = samples.taken();
  res.gradients = gradients.taken();
  res.mismatch = samples.first() ? samples.first() : gradients.first();
  if (res.mismatch && !in.check) {
    const bool interpolation = res.mismatch->unit == Unit::Interp;
    throw std::logic_error(std::string(interpolation ? "perspective interpolation (" : "perspective gradient (") +
                           level_name(interpolation ? units.interp.level() : units.gradient->level()) +
                           "): " + res.mismatch->describe());
  }
  if (units.composite) {
    if (res.frame_done_cycles.size() != static_cast<size_t>(in.frames))
      throw std::logic_error("perspective compositing: " + std::to_string(res.frame_done_cycles.size()) + " of " +
                             std::to_string(in.frames) + " frame(s) ended (" +
                             std::to_string(units.composite->samples_per_frame()) + " samples a frame)");
    res.plane = units.composite->plane();
    return res;
  }
  // Shading and compositing loosely timed, on the units' samples and gradients.
  golden::FixedOptions opt;
  opt.accumulators = in.accumulators;
  opt.polygons = in.polygons;
  opt.given_samples = &samples;
  if (units.gradient) opt.given_gradients = &gradients;
  res.plane = golden::render_perspective(in.vol, plan.r, opt);
  return res;
}

}  // namespace cube4::sysc
