#include "systemc/core/perspective_frame.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "golden/permuted_volume.hpp"
#include "golden/perspective.hpp"
#include "systemc/core/pass_gate.hpp"

namespace cube4::sysc {
namespace {

// The unit's samples of a frame by slice and ray, as the renderer asks for
// them; with the count of each ray's arrivals (one per frame streamed).
// Which rays sample a slice, and what they should sample, is golden's
// (perspective_slice()), whatever weight generator the unit ran with.
class RaySamples final : public golden::PerspectiveSamples {
 public:
  RaySamples(const FramePlan& plan, const golden::Volume& vol, int frames, bool check)
      : plan_(plan), pv_(vol, plan.r.perm, plan.r.flip), frames_(frames), check_(check),
        slices_(static_cast<size_t>(plan.K)) {
    for (int k = 0; k < plan.K; ++k) {
      const golden::PerspectiveSlice& s = golden_.emplace_back(golden::perspective_slice(plan.r, k));
      Slice& out = slices_[static_cast<size_t>(k)];
      out.width = s.rays_x.empty() ? 0 : s.rays_x.hi - s.rays_x.lo;
      const int64_t height = s.rays_y.empty() ? 0 : s.rays_y.hi - s.rays_y.lo;
      const auto n = static_cast<size_t>(out.width * height);
      out.value.assign(n, 0);
      out.vtag.assign(n, 0);
      out.count.assign(n, 0);
    }
  }

  uint32_t sample(int k, int64_t u, int64_t v) const override { return at(k, u, v, &Slice::value); }
  uint32_t vtag(int k, int64_t u, int64_t v) const override { return at(k, u, v, &Slice::vtag); }

  // One sample that left the unit on some lane.
  void take(uint32_t k, int64_t u, int64_t v, uint32_t value, uint32_t vtag) {
    ++taken_;
    if (k >= static_cast<uint32_t>(plan_.K) || !golden::samples(slice(k), u, v)) {
      fail(static_cast<int>(k), u, v, "no sample (the ray does not sample the slice)", describe(value, vtag));
      return;
    }
    Slice& s = slices_[k];
    const size_t i = index(k, u, v);
    if (++s.count[i] > frames_) {
      fail(static_cast<int>(k), u, v, "the ray's sample " + std::to_string(frames_) + " time(s) a stream",
           "one more: " + describe(value, vtag));
      return;
    }
    if (s.count[i] > 1 && (s.value[i] != value || s.vtag[i] != vtag)) {
      fail(static_cast<int>(k), u, v, describe(s.value[i], s.vtag[i]) + " (the frame before's)", describe(value, vtag));
      return;
    }
    s.value[i] = static_cast<uint16_t>(value);
    s.vtag[i] = static_cast<uint8_t>(vtag);
    if (check_) {
      const uint32_t want = expected(k, u, v), want_tag = expected_tag(k, u, v);
      if (want != value || want_tag != vtag) fail(static_cast<int>(k), u, v, describe(want, want_tag), describe(value, vtag));
    }
  }

  // After the stream: the first ray that did not leave `frames` times.
  void check_complete() {
    for (int k = 0; k < plan_.K && !first_; ++k) {
      const golden::PerspectiveSlice& s = slice(static_cast<uint32_t>(k));
      const Slice& got = slices_[static_cast<size_t>(k)];
      for (size_t i = 0; i < got.count.size(); ++i)
        if (got.count[i] != frames_) {
          const int64_t u = s.rays_x.lo + static_cast<int64_t>(i) % got.width;
          const int64_t v = s.rays_y.lo + static_cast<int64_t>(i) / got.width;
          fail(k, u, v, "the ray's sample " + std::to_string(frames_) + " time(s)",
               std::to_string(got.count[i]) + " time(s)");
          return;
        }
    }
  }

  uint64_t taken() const { return taken_; }
  const std::optional<Mismatch>& first() const { return first_; }

 private:
  struct Slice {
    int64_t width = 0;
    std::vector<uint16_t> value;
    std::vector<uint8_t> vtag;
    std::vector<int> count;
  };
  const golden::PerspectiveSlice& slice(uint32_t k) const { return golden_[k]; }
  size_t index(uint32_t k, int64_t u, int64_t v) const {
    const golden::PerspectiveSlice& s = slice(k);
    return static_cast<size_t>((v - s.rays_y.lo) * slices_[k].width + (u - s.rays_x.lo));
  }
  template <class T>
  uint32_t at(int k, int64_t u, int64_t v, std::vector<T> Slice::*field) const {
    return (slices_[static_cast<size_t>(k)].*field)[index(static_cast<uint32_t>(k), u, v)];
  }
  uint32_t expected(uint32_t k, int64_t u, int64_t v) const {
    const golden::PerspectiveSlice& s = slice(k);
    return golden::perspective_sample(plan_.r, s, u, v,
                                      [&](int x, int y, int dz) { return pv_.at(x, y, s.z_voxel + dz); });
  }
  uint32_t expected_tag(uint32_t k, int64_t u, int64_t v) const {
    if (plan_.r.p.tag_bits == 0) return 0;
    const golden::PerspectiveSlice& s = slice(k);
    const golden::TagVoxel t = golden::perspective_tag_voxel(plan_.r, s, u, v);
    return pv_.tag_at(t.x, t.y, s.z_voxel + t.dz);
  }
  std::string describe(uint32_t value, uint32_t vtag) const {
    return std::to_string(value) + (plan_.r.p.tag_bits > 0 ? " (voxel tag " + std::to_string(vtag) + ")" : "");
  }
  void fail(int k, int64_t u, int64_t v, const std::string& expected, const std::string& got) {
    if (first_) return;
    Mismatch m;
    m.unit = Unit::Interp;
    m.slice = k;
    m.x = static_cast<int>(u);
    m.y = static_cast<int>(v);
    m.expected = expected;
    m.got = got;
    first_ = m;
  }

  const FramePlan& plan_;
  std::vector<golden::PerspectiveSlice> golden_;
  golden::PermutedVolume pv_;
  int frames_;
  bool check_;
  std::vector<Slice> slices_;
  uint64_t taken_ = 0;
  std::optional<Mismatch> first_;
};

}  // namespace

PerspectiveFrameResult run_perspective_frame(const PerspectiveFrameInput& in, StreamFormer& former,
                                             PerspInterpIf& interp) {
  const FramePlan& plan = in.plan;
  RaySamples samples(plan, in.vol, in.frames, in.check);
  PerspectiveFrameResult res;
  // The former's beats, then the link and the unit's drain (4 cycles) and
  // a margin in which nothing more may leave.
  const uint64_t total = static_cast<uint64_t>(in.frames) * plan.passes * plan.pass_beats() +
                         static_cast<uint64_t>(plan.flush_beams()) * plan.B;
  constexpr uint64_t kDrain = 1 + 4, kMargin = 8;
  VoxelBeat link;
  RaySampleBeat out;
  std::optional<PassGate> gate;
  if (in.source) gate.emplace(*in.source);
  uint64_t cycle = 0, idle = 0;
  while (idle < kDrain + kMargin) {
    ++cycle;
    VoxelBeat beat;
    if (!former.done() && !(gate && gate->holds(former, cycle))) {
      beat = former.next();
      res.last_beat_cycle = cycle;
    }
    interp.clock(link, out);
    link = beat;
    for (int k = 0; out.valid && k < plan.p; ++k) {
      if (!(out.valid >> k & 1)) continue;
      const auto i = static_cast<size_t>(k);
      samples.take(out.tag[i], out.u[i], out.v[i], out.sample[i], out.vtag[i]);
      res.last_sample_cycle = cycle;
    }
    idle = former.done() && !link.valid ? idle + 1 : 0;
    if (in.progress && (cycle & 0xffff) == 0)
      in.progress(std::min(1.0, static_cast<double>(cycle) / static_cast<double>(total)));
  }
  samples.check_complete();
  if (gate) res.polygon_stall_cycles = gate->first_frame_stalls(in.frames);
  res.beats = former.beats();
  res.cycles = cycle;
  res.samples = samples.taken();
  res.mismatch = samples.first();
  if (res.mismatch && !in.check)
    throw std::logic_error("perspective interpolation (" + std::string(level_name(interp.level())) +
                           "): " + res.mismatch->describe());
  // The rest of the pipeline, loosely timed, on the unit's samples.
  golden::FixedOptions opt;
  opt.accumulators = in.accumulators;
  opt.polygons = in.polygons;
  opt.given_samples = &samples;
  res.plane = golden::render_perspective(in.vol, plan.r, opt);
  return res;
}

}  // namespace cube4::sysc
