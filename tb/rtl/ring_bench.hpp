// What the three ring testbenches (test_interp_ring.cpp,
// test_gradient_ring.cpp, test_composite_ring.cpp) share: the ring sizes the
// CMake groups verilate, the golden frames (scene, registers, every sample
// and gradient golden computed), the voxel stream in the system's pass
// order (formed by the system's own FramePlan), the check that a frame fits
// a ring, the first-mismatch report, the views every ring is run through and
// the view's JSON. The rings' input ports are bound in
// systemc/rtl/unit_streams.hpp, for the system and these tests alike.
#pragma once
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "golden/host_driver.hpp"
#include "golden/permuted_volume.hpp"
#include "golden/pipeline.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "systemc/core/beats.hpp"
#include "systemc/core/frame_plan.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace cube4::rtl {

// A verilated ring: p pipelines, storage for nx, ny up to max_dim
// (rtl/groups/*.cmake verilate the same values).
struct RingParams {
  int p;
  int max_dim;
  int beam_depth() const { return (max_dim + p - 1) / p; }
  int slice_depth() const { return max_dim * beam_depth(); }
  int dim_bits() const {  // the rings' position outputs: $clog2(MaxDim + NumPipes)
    int b = 0;
    while ((1 << b) < max_dim + p) ++b;
    return b;
  }
};
constexpr RingParams kRingP1{1, 24}, kRingP2{2, 16}, kRingP4{4, 256}, kRingP5{5, 12};

// Whether every frame's beam and slice fit the ring's storage (each one that
// does not is a test failure); `names` gets the frames' names for the trace.
template <class Frame>
bool frames_fit(const RingParams& rp, const std::vector<const Frame*>& frames, std::string& names) {
  bool fit = true;
  for (const Frame* f : frames) {
    names += (names.empty() ? "" : " + ") + f->name;
    const int B = (f->nx + rp.p - 1) / rp.p;
    if (B > rp.beam_depth()) ADD_FAILURE() << f->name << ": the beam does not fit the ring's beam storage";
    if (B * f->ny > rp.slice_depth()) ADD_FAILURE() << f->name << ": the slice does not fit the ring's slice storage";
    fit = fit && B <= rp.beam_depth() && B * f->ny <= rp.slice_depth();
  }
  return fit;
}

// The first mismatch of a ring whose pipeline q emits column x = j*p + q:
// the cycle, the pipeline, what was wrong and, if one was due, which
// output (`output` of x, y, slice k) of which frame.
template <class Frame, class Expect>
std::string mismatch_report(uint64_t cycle, int pipe, int p, const std::vector<const Frame*>& frames,
                            const Expect* due, const char* output, const std::string& what,
                            const std::string& detail) {
  std::ostringstream o;
  o << "first mismatch at cycle " << cycle << ", pipeline " << pipe << ": " << what;
  if (due) {
    const Frame& f = *frames[static_cast<size_t>(due->frame)];
    o << "\n  frame " << due->frame << " (" << f.name << ", dim " << f.nx << "x" << f.ny << "x" << f.nz << "), "
      << output << " x=" << due->j * p + pipe << " y=" << due->y << " slice k=" << due->k;
  }
  if (!detail.empty()) o << "\n  " << detail;
  return o.str();
}

// Whether pipeline `pipe`'s valid_o agrees with the output due this cycle
// (nullptr: none) and one is due; a disagreement goes to
// fail(cycle, pipe, due, what, detail).
template <class Due, class Fail>
bool output_due(bool valid, const Due* due, uint64_t cycle, int pipe, const std::string& output, Fail& fail) {
  if (valid != (due != nullptr))
    fail(cycle, pipe, due, due ? "valid_o low, a " + output + " was due" : "valid_o high with no " + output + " due",
         "");
  return valid && due;
}

struct View {
  const char* name;
  std::array<double, 3> dir, up;
};
// The six base planes exactly (all weights but wz zero, dx = dy = 0), each
// base plane again seen off axis (every weight, realign base and ray offset
// moves: the x±1 and y±1 paths and the ring wraps matter), 45-degree views
// (ties between axes) and an oblique one.
inline const std::vector<View> kViews = {
    {"+x", {1, 0, 0}, {0, 1, 0}},          {"-x", {-1, 0, 0}, {0, 1, 0}},
    {"+y", {0, 1, 0}, {0, 0, 1}},          {"-y", {0, -1, 0}, {0, 0, 1}},
    {"+z", {0, 0, 1}, {0, 1, 0}},          {"-z", {0, 0, -1}, {0, 1, 0}},
    {"+x tilted", {1, 0.3, -0.45}, {0, 1, 0}},   {"-x tilted", {-1, -0.2, 0.35}, {0, 1, 0}},
    {"+y tilted", {0.25, 1, 0.4}, {0, 0, 1}},    {"-y tilted", {-0.4, -1, -0.3}, {0, 0, 1}},
    {"+z tilted", {0.35, -0.3, 1}, {0, 1, 0}},   {"-z tilted", {-0.3, 0.45, -1}, {0, 1, 0}},
    {"45 xz", {1, 0, 1}, {0, 1, 0}},       {"45 xyz", {-1, 1, 1}, {0, 1, 0}},
    {"oblique", {0.7, -0.6, 1}, {0, 1, 0}},
};
// Volume sizes: every permutation of them appears across the views, and
// every one fits the smallest ring (p = 5, MaxDim 12).
inline const std::array<std::array<int, 3>, 3> kSizes = {{{9, 7, 6}, {12, 5, 8}, {7, 11, 10}}};

inline std::string vec_json(const std::array<double, 3>& d) {
  std::ostringstream s;
  s << '[' << d[0] << ", " << d[1] << ", " << d[2] << ']';
  return s.str();
}
// A scene's "view" object for a direction and an up vector.
inline std::string direction_json(const std::array<double, 3>& d, const std::array<double, 3>& up) {
  return R"({"direction": )" + vec_json(d) + R"(, "up": )" + vec_json(up) + "}";
}

// A random scene for the rings: a direction (never zero) with an up vector
// off it, a volume of 1..12 voxels per axis (fits every ring), S in 1..8.
struct RandomScene {
  std::array<double, 3> dir, up;
  std::array<int, 3> size;
  int S;
};
inline RandomScene random_scene(Random& rng) {
  RandomScene r;
  for (double& d : r.dir) d = static_cast<double>(rng.range(-100, 100)) / 100.0;
  r.dir[rng.range(0, 2)] = rng.chance(0.5) ? 1.0 : -1.0;
  const bool up_z = std::abs(r.dir[1]) >= std::abs(r.dir[0]) && std::abs(r.dir[1]) >= std::abs(r.dir[2]);
  r.up = up_z ? std::array<double, 3>{0, 0, 1} : std::array<double, 3>{0, 1, 0};
  r.size = {static_cast<int>(rng.range(1, 12)), static_cast<int>(rng.range(1, 12)), static_cast<int>(rng.range(1, 12))};
  r.S = static_cast<int>(rng.range(1, 8));
  return r;
}

// ===========================================================================
// Golden frames.

// A scene as the host driver programs it: the volume and the registers.
struct RingFrame {
  std::string name;
  golden::Volume vol;
  golden::Registers regs;
  int nx = 0, ny = 0, nz = 0, S = 1, K = 0;  // permuted volume, supersampling, sample slices

  void load(const std::string& json, const char* file, std::string frame_name) {
    const golden::Scene scene = golden::parse_scene(json, file);
    golden::Volume v = golden::load_volume(scene.volume, scene.precision.voxel_bits, ".");
    golden::load_tags(scene, v, ".");  // none without "tags"
    const golden::Registers r = golden::program_host(scene, v).regs;
    name = std::move(frame_name);
    use(std::move(v), r);
  }
  // Another volume and registers for the frame (a block of a partition).
  void use(golden::Volume v, const golden::Registers& r) {
    vol = std::move(v);
    regs = r;
    nx = regs.dim[0];
    ny = regs.dim[1];
    nz = regs.dim[2];
    S = regs.supersampling;
    K = regs.sample_slices();
  }
};

// A frame per scene JSON, built once per test program (the golden renders
// are the slow part of a ring test).
template <class F, class Build>
const F& cached_frame(const std::string& key, Build&& build) {
  static std::map<std::string, std::unique_ptr<F>> cache;
  auto& slot = cache[key];
  if (!slot) {
    auto f = std::make_unique<F>();
    build(*f);
    slot = std::move(f);
  }
  return *slot;
}

// A frame with every sample golden render_fixed() interpolated and, when the
// gradient unit runs (regs.gradient), its gradient, collected by a
// SampleProbe; the volume in the pipelines' permuted axes.
struct SampleFrame : RingFrame {
  std::unique_ptr<golden::PermutedVolume> pv;  // refers to vol
  std::vector<uint32_t> samples;               // [(k * ny + y) * nx + x]
  std::vector<uint32_t> vtags;                 // the samples' voxel tags (bela §III), same index
  std::vector<golden::Gradient> gradients;
  size_t index(int k, int y, int x) const { return (static_cast<size_t>(k) * ny + y) * nx + x; }
};

// Every sample once, with the slice control the renderer used: it must be
// slice_control()'s, which the streams are formed from.
struct SampleCollect : golden::SampleProbe {
  SampleFrame& f;
  std::vector<int> count;
  bool control_ok = true;
  explicit SampleCollect(SampleFrame& fr) : f(fr), count(fr.samples.size(), 0) {}
  void sample(int x, int y, const golden::SliceControl& c, uint32_t value, const golden::Gradient& gr) override {
    const size_t i = f.index(c.k, y, x);
    f.samples[i] = value;
    f.gradients[i] = gr;
    ++count[i];
    const golden::SliceControl e = golden::slice_control(f.regs, c.k);
    auto same = [](const golden::Realign& a, const golden::Realign& b) {
      return a.base == b.base && a.weight == b.weight;
    };
    if (e.wx != c.wx || e.wy != c.wy || e.wz != c.wz || e.z_voxel != c.z_voxel || !same(e.behind_x, c.behind_x) ||
        !same(e.behind_y, c.behind_y) || !same(e.ahead_x, c.ahead_x) || !same(e.ahead_y, c.ahead_y))
      control_ok = false;
  }
  void tagged(int x, int y, const golden::SliceControl& c, uint32_t tag) override {
    f.vtags[f.index(c.k, y, x)] = tag;
  }
};

// A noise volume of `size` seen along `dir`, unshaded, with the gradient
// unit on or off: the scenes of the interpolation and gradient rings.
// vtag_bits > 0: with voxel tags of that width (bela §III), labelled by
// value bands and a box so that neighbouring voxels' tags differ. voxel_z:
// VolumePro's z gradient (z_gradient voxel_differences).
inline const SampleFrame& sample_frame(const std::string& name, const std::array<int, 3>& size,
                                       const std::array<double, 3>& dir, const std::array<double, 3>& up, int S,
                                       int seed, bool gradient, int vtag_bits = 0, bool voxel_z = false) {
  std::ostringstream js;
  js << R"({"volume": {"synthetic": "noise", "size": [)" << size[0] << ", " << size[1] << ", " << size[2]
     << R"(], "seed": )" << seed << R"(}, "view": )" << direction_json(dir, up) << R"(, "supersampling": )" << S
     << R"(, "shading": false)";
  if (vtag_bits > 0) {
    const int top = (1 << vtag_bits) - 1;
    js << R"(, "precision": {"tag_bits": )" << vtag_bits << R"(}, "tags": {"label": [)"
       << R"({"tag": 1, "threshold": [0, 0.3]}, )"
       << R"({"tag": )" << top << R"(, "threshold": [0.3, 0.6]}, )"
       << R"({"tag": )" << (top + 1) / 2 << R"(, "box": {"min": [0, 0, 0], "max": [2, 3, 1]}}]})";
  }
  if (voxel_z) js << R"(, "z_gradient": "voxel_differences")";
  js << "}";
  const std::string json = js.str();
  return cached_frame<SampleFrame>(json + (gradient ? " gradient" : ""), [&](SampleFrame& f) {
    std::ostringstream n;
    n << name << " size " << size[0] << "x" << size[1] << "x" << size[2] << " S=" << S;
    f.load(json, "ring_scene.json", n.str());
    f.regs.gradient = gradient;  // on: the probe sees every sample's gradient; off: no zero pass
    f.pv = std::make_unique<golden::PermutedVolume>(f.vol, f.regs.perm, f.regs.flip);
    EXPECT_EQ(f.pv->dim(), f.regs.dim);
    f.samples.assign(static_cast<size_t>(f.K) * f.ny * f.nx, 0);
    f.gradients.assign(f.samples.size(), golden::Gradient{});
    f.vtags.assign(f.samples.size(), 0);
    SampleCollect probe(f);
    golden::render_fixed(f.vol, f.regs, nullptr, {}, &probe);
    for (int c : probe.count)
      if (c != 1) ADD_FAILURE() << f.name << ": the golden probe saw a sample " << c << " times";
    EXPECT_TRUE(probe.control_ok) << f.name << ": probe slice control differs from slice_control()";
  });
}

// Six frames of different sizes, permutations and S, for streams of
// frames back to back without a reset: the first two and the last two
// have the same beams (one view's permutation, another S), so each pair
// follows with no zero pass between (ends_stream()); the others change
// shape.
inline std::vector<const SampleFrame*> back_to_back_frames(bool gradient) {
  return {&sample_frame("+z tilted", {9, 7, 6}, {0.35, -0.3, 1}, {0, 1, 0}, 2, 21, gradient),
          &sample_frame("+z tilted again", {9, 7, 6}, {-0.2, 0.25, 1}, {0, 1, 0}, 1, 25, gradient),
          &sample_frame("-y tilted", {12, 5, 8}, {-0.4, -1, -0.3}, {0, 0, 1}, 3, 22, gradient),
          &sample_frame("oblique", {7, 11, 10}, {0.7, -0.6, 1}, {0, 1, 0}, 1, 23, gradient),
          &sample_frame("-x tilted", {9, 7, 6}, {-1, -0.2, 0.35}, {0, 1, 0}, 2, 24, gradient),
          &sample_frame("-x tilted again", {9, 7, 6}, {-1, 0.3, -0.2}, {0, 1, 0}, 3, 26, gradient)};
}

// Frames whose slices fill the storage of the small rings to the last entry
// (ny * ceil(nx/p) = SliceDepth, for p = 2, 5 and 1) and whose beams fill
// the beam delay (ceil(nx/p) = BeamDepth); a frame that does not is a
// failure of the test's own set-up.
struct FullStorageFrames {
  const SampleFrame *p2, *p5, *p1;
};
inline FullStorageFrames full_storage_frames(bool gradient) {
  const FullStorageFrames f{&sample_frame("+z tilted", {16, 16, 3}, {0.2, 0.3, 1}, {0, 1, 0}, 2, 31, gradient),
                            &sample_frame("-z tilted", {15, 12, 3}, {0.3, -0.2, -1}, {0, 1, 0}, 3, 32, gradient),
                            &sample_frame("+z tilted", {24, 24, 2}, {0.45, 0.2, 1}, {0, 1, 0}, 2, 33, gradient)};
  EXPECT_EQ((f.p2->nx + 1) / 2 * f.p2->ny, kRingP2.slice_depth());
  EXPECT_EQ((f.p5->nx + 4) / 5 * f.p5->ny, kRingP5.slice_depth());
  EXPECT_EQ(f.p1->nx * f.p1->ny, kRingP1.slice_depth());
  return f;
}

// ===========================================================================
// The voxel stream: what the system's stream former sends the interpolation
// ring, frame after frame (pass order, flags and weights from FramePlan),
// with idle cycles and junk where the ring must ignore its inputs.

// From a valid input to its sample, when the next input follows at once or
// the input ends a beam: the alignment register, then cube4_interp's 3
// (docs/rtl-interp.md).
constexpr int kInterpLatency = 4;

struct VoxelStreamOptions {
  double stall = 0;   // probability of idle cycles before a partial beam
  int max_gap = 3;    // 1 .. max_gap idle cycles each time
  bool junk = false;  // random voxels in the zero beam and the zero pass, random weights in the zero pass
                      // (one set for the pass: the interpolation unit's stream keeps a pass's weights)
  int vtag_bits = 0;  // voxel tag width: the stream's voxels are the words {tag, value} (bela §III)
};

// A partial beam of samples the interpolation ring emits (every pipeline
// at once; pipeline q: x = j*p + q).
struct PassSample {
  uint64_t cycle;
  int frame, k, y, j;  // k: the pass (sample slice k, or K for the zero pass)
  sysc::BeamFlags f;
  uint64_t tag;
};

struct VoxelStream {
  std::vector<sysc::VoxelBeat> beats;  // one per cycle
  std::vector<PassSample> samples;     // by cycle
  uint64_t valid = 0, idle = 0, last_input = 0;
};

// A beat with valid low and anything elsewhere.
inline sysc::VoxelBeat junk_voxel_beat(Random& rng, int p, int voxel_bits, int tag_bits) {
  sysc::VoxelBeat b;
  b.f.beam_start = rng.chance(0.5);
  b.f.beam_end = rng.chance(0.5);
  b.f.slice_start = rng.chance(0.5);
  b.f.slice_end = rng.chance(0.5);
  b.wx = rng.range(0, 256);
  b.wy = rng.range(0, 256);
  b.wz = rng.chance(0.5) ? 0 : rng.range(0, 256);
  b.tag = rng.bits(tag_bits);
  for (int q = 0; q < p; ++q) b.voxel[static_cast<size_t>(q)] = static_cast<uint16_t>(rng.bits(voxel_bits));
  return b;
}

// Whether frame fi ends a stream (FramePlan::passes_in_stream: its zero
// pass and flush beam follow it): it is the last, or the next one has other
// beams (B or ny), which cannot follow it back to back.
inline bool ends_stream(const std::vector<sysc::FramePlan>& plans, size_t fi) {
  return fi + 1 == plans.size() || plans[fi + 1].B != plans[fi].B || plans[fi + 1].ny != plans[fi].ny;
}

// The frames back to back, frame i formed by plans[i] (its p, passes and
// tags) from the voxels of frames[i]; tag(i, pass) is the tag its beats
// carry (pass >= 0: a priming pass's is 0, or junk). Passes and frames follow back to back; a frame that ends a stream
// (ends_stream()) is followed by its zero pass (gradient unit on) and a
// flush beam. A frame with shorter beams than the one before starts after
// the difference in idle cycles (the next pass's beam 0 is the gradient
// ring's zero beam of the last slice).
inline VoxelStream voxel_stream(const std::vector<const SampleFrame*>& frames,
                                const std::vector<sysc::FramePlan>& plans,
                                const std::function<uint64_t(int frame, int pass)>& tag, int voxel_bits, int tag_bits,
                                const VoxelStreamOptions& opt, Random& rng) {
  VoxelStream s;
  auto idle = [&](int n) {
    for (int i = 0; i < n; ++i)
      s.beats.push_back(junk_voxel_beat(rng, plans.front().p, voxel_bits + opt.vtag_bits, tag_bits));
    s.idle += static_cast<uint64_t>(n);
  };
  std::vector<PassSample> due;  // with the index of the beat that produces them
  // The pass whose last sample beam the next beam emits (docs/rtl-interp.md,
  // "Passes back to back"): frame, pass, tag, or frame -1 for none.
  struct Open {
    int frame = -1, pass = 0;
    uint64_t tag = 0;
    int ny = 0;
  } open;
  for (size_t fi = 0; fi < frames.size(); ++fi) {
    const SampleFrame& f = *frames[fi];
    const sysc::FramePlan& plan = plans[fi];
    const int p = plan.p;
    if (fi > 0) idle(plans[fi - 1].B - plan.B);
    const bool ends = ends_stream(plans, fi);
    const int passes = plan.passes_in_stream(ends);
    for (int pass = plan.first_pass(); pass < passes; ++pass) {
      // A priming pass (VolumePro's z gradient) gives no samples: its tag is
      // never seen, and junk shows it.
      const bool prime = plan.prime_pass(pass);
      const uint64_t pass_tag =
          prime ? (opt.junk ? rng.bits(tag_bits) : 0) : tag(static_cast<int>(fi), pass);
      const bool zero = plan.zero_pass(pass);
      const bool junk_weights = zero && opt.junk;
      const auto junk_wx = junk_weights ? static_cast<uint32_t>(rng.range(0, 256)) : 0u;
      const auto junk_wy = junk_weights ? static_cast<uint32_t>(rng.range(0, 256)) : 0u;
      const int beams = plan.beams(ends && pass + 1 == passes);
      for (int y = 0; y < beams; ++y)
        for (int j = 0; j < plan.B; ++j) {
          if (opt.stall > 0 && rng.chance(opt.stall)) idle(static_cast<int>(rng.range(1, opt.max_gap)));
          const sysc::PassStep st = plan.step(pass, y, j);
          sysc::VoxelBeat b;
          b.valid = true;
          b.f = st.f;
          // A flush beam's weights are ignored: junk ones show it.
          const bool junk_flush = opt.junk && st.f.flush;
          b.wx = junk_weights ? junk_wx : junk_flush ? static_cast<uint32_t>(rng.range(0, 256)) : st.wx;
          b.wy = junk_weights ? junk_wy : junk_flush ? static_cast<uint32_t>(rng.range(0, 256)) : st.wy;
          b.wz = junk_flush ? static_cast<uint32_t>(rng.range(0, 256)) : st.wz;
          b.tag = junk_flush ? rng.bits(tag_bits) : pass_tag;
          for (int q = 0; q < p; ++q) {
            const int x = j * p + q;  // zero outside the volume
            uint32_t v = st.reads ? f.pv->at(x, y, st.voxel_slice) : 0;
            if (st.reads && opt.vtag_bits > 0) v |= uint32_t{f.pv->tag_at(x, y, st.voxel_slice)} << voxel_bits;
            if (opt.junk && (y == plan.ny || zero)) v = static_cast<uint32_t>(rng.bits(voxel_bits + opt.vtag_bits));
            b.voxel[static_cast<size_t>(q)] = static_cast<uint16_t>(v);
          }
          s.beats.push_back(b);
          ++s.valid;
          sysc::BeamFlags of;
          of.beam_start = st.f.beam_start;
          of.beam_end = st.f.beam_end;
          if (y == 0 || y == plan.ny) {  // the open pass's last sample beam, if any
            if (open.frame >= 0) {
              of.slice_start = open.ny == 1;
              of.slice_end = true;
              due.push_back({s.beats.size() - 1, open.frame, open.pass, open.ny - 1, j, of, open.tag});
            }
          } else if (!prime) {
            of.slice_start = y == 1;
            due.push_back({s.beats.size() - 1, static_cast<int>(fi), pass, y - 1, j, of, pass_tag});
          }
          if (st.f.beam_end && (y == 0 || y == plan.ny)) open.frame = -1;
          if (st.f.beam_end && y == plan.ny - 1 && !prime) open = {static_cast<int>(fi), pass, pass_tag, plan.ny};
        }
    }
  }
  s.last_input = s.beats.size() - 1;
  // The sample of a column leaves the alignment register with the next valid
  // input, or one cycle later if the column ends a beam.
  std::vector<uint64_t> next_valid(s.beats.size(), 0);
  uint64_t nv = ~uint64_t{0};
  for (size_t i = s.beats.size(); i-- > 0;) {
    next_valid[i] = nv;
    if (s.beats[i].valid) nv = i;
  }
  for (PassSample& e : due) {
    const uint64_t t = e.cycle;
    e.cycle = (e.f.beam_end ? t + 1 : next_valid[t]) + (kInterpLatency - 1);
  }
  s.samples = std::move(due);
  return s;
}

}  // namespace cube4::rtl
