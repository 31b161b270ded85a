// RTL tests of the interpolation unit with its delay storage and
// near-neighbour links: cube4_delay_ram against a model of its contract, and
// cube4_interp_ring (p = 1, 2, 4, 5 pipelines) against the golden renderer.
//
// The ring test builds scenes with the golden host driver, streams the
// permuted volume into the verilated ring cycle by cycle in the order of
// docs/rtl-interp.md (sample slice by sample slice, beam by beam including
// the zero beam y = ny, partial beam by partial beam, with the slice
// weights of golden slice_control()), and compares every output sample of
// every pipeline with the value golden render_fixed() computed for the same
// (x, y, k_s) (collected with a SampleProbe), together with its flags, its
// tag and the cycle it appears in. Random idle cycles between partial
// beams, and junk on every input while valid_i is low, check that only
// valid_i moves the unit. Nothing here re-implements the interpolation.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "Vcube4_delay_ram_d1.h"
#include "Vcube4_delay_ram_d13.h"
#include "Vcube4_interp_ring.h"
#include "Vcube4_interp_ring_p1.h"
#include "Vcube4_interp_ring_p2.h"
#include "Vcube4_interp_ring_p5.h"
#include "golden/host_driver.hpp"
#include "golden/pipeline.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "tb/rtl/ring_bench.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
using namespace cube4::rtl;  // the shared bench: rtl_check.hpp, ring_bench.hpp

// Ring parameters, as in rtl/groups/interp.cmake.
constexpr int kVoxelBits = 12;  // ring defaults
constexpr int kTagBits = 8;
// From a valid input to its sample, when the next input follows at once or
// the input ends a beam: the alignment register, then cube4_interp's 3.
constexpr int kLatency = 4;


// ===========================================================================
// cube4_delay_ram against its contract: rdata_o is always the entry under
// the pointer; a step writes it (if write_i) and moves the pointer on, to 0
// after depth_i - 1, after MaxDepth - 1 or with last_i; clear_i sets it to 0.

template <class M>
void test_delay_ram(const char* unit, int max_depth) {
  constexpr int W = 10;
  auto m = std::make_unique<M>();
  cube4::rtl::reset(*m);
  cube4::rtl::Checker c(unit);
  Random rng(0x51 + max_depth);
  std::vector<int64_t> mem(max_depth, -1);  // -1: never written
  int ptr = 0, depth = max_depth;
  uint64_t cycle = 0;
  auto step = [&](bool clear, bool advance, bool last, bool write, uint32_t wdata) {
    m->depth_i = depth;
    m->clear_i = clear;
    m->advance_i = advance;
    m->last_i = last;
    m->write_i = write;
    m->wdata_i = wdata;
    cube4::rtl::settle(*m);
    const int64_t exp = mem[ptr];
    const int64_t got = m->rdata_o;
    if (exp >= 0)
      c.check_lazy(cycle, exp == got,
                   [&] { return cube4::rtl::Fields{{"ptr", ptr}, {"depth", depth}, {"clear", clear}, {"advance", advance},
                                                   {"last", last}, {"write", write}, {"wdata", wdata}}; },
                   [&] { return cube4::rtl::Fields{{"rdata", exp}}; }, [&] { return cube4::rtl::Fields{{"rdata", got}}; });
    cube4::rtl::rise(*m);
    ++cycle;
    if (clear) {
      ptr = 0;
    } else if (advance) {
      if (write) mem[ptr] = wdata;
      ptr = (last || ptr + 1 == depth || ptr == max_depth - 1) ? 0 : ptr + 1;
    }
  };
  // Directed: a FIFO of every depth D, with idle cycles between the steps:
  // each step reads what the step D steps earlier wrote.
  for (int d = 1; d <= max_depth; ++d) {
    depth = d;
    step(true, false, false, false, 0);
    std::vector<uint32_t> in;
    for (int t = 0; t < 6 * d + 5; ++t) {
      while (rng.chance(0.3)) step(false, false, rng.chance(0.5), rng.chance(0.5), rng.bits(W));
      const uint32_t v = rng.bits(W);
      // The step's read, before step() clocks it: the value of step t - d.
      m->depth_i = depth;
      m->clear_i = 0;
      m->advance_i = 1;
      m->last_i = 0;
      m->write_i = 1;
      m->wdata_i = v;
      cube4::rtl::settle(*m);
      if (t >= d) c.check(cycle, {{"depth", d}, {"step", t}}, {{"rdata", in[t - d]}}, {{"rdata", int64_t{m->rdata_o}}});
      in.push_back(v);
      step(false, true, false, true, v);
    }
  }
  // Random: depth changes (with and without clear), laps ended by last_i,
  // steps without writes (re-reading a lap), idle cycles.
  const long n = cube4::rtl::vector_count(300000);
  for (long i = 0; i < n; ++i) {
    if (rng.chance(0.002)) depth = static_cast<int>(rng.range(1, max_depth));
    step(rng.chance(0.003), rng.chance(0.7), rng.chance(0.03), rng.chance(0.8), rng.bits(W));
  }
  m->final();
  EXPECT_TRUE(c.ok()) << c.report();
  std::printf("  %s: %llu reads checked\n", unit, static_cast<unsigned long long>(c.checked()));
}

TEST(RtlDelayRam, MatchesModelDepth13) { test_delay_ram<Vcube4_delay_ram_d13>("cube4_delay_ram (MaxDepth 13)", 13); }
TEST(RtlDelayRam, MatchesModelDepth1) { test_delay_ram<Vcube4_delay_ram_d1>("cube4_delay_ram (MaxDepth 1)", 1); }

// ===========================================================================
// The ring against the golden renderer.

// A scene, its registers and every sample the golden renderer computed.
struct Frame {
  std::string name;
  g::Volume vol;
  g::Registers regs;
  int nx = 0, ny = 0, nz = 0, S = 1, K = 0;
  std::vector<uint32_t> samples;  // [(k * ny + y) * nx + x]

  // The permuted volume exactly as golden/render_fixed.cpp's PermutedAccess
  // reads it: permuted axis i walks object axis perm[i], backwards if flip[i].
  int64_t origin = 0;
  std::array<int64_t, 3> stride{};
  uint32_t voxel(int x, int y, int z) const {
    if (x >= nx || y >= ny || z >= nz) return 0;
    return vol.data[static_cast<size_t>(origin + stride[0] * x + stride[1] * y + stride[2] * z)];
  }
};

struct Collect : g::SampleProbe {
  Frame& f;
  std::vector<int> count;
  bool control_ok = true;
  explicit Collect(Frame& fr) : f(fr), count(fr.samples.size(), 0) {}
  void sample(int x, int y, const g::SliceControl& c, uint32_t value, const g::Gradient&) override {
    const size_t i = (static_cast<size_t>(c.k) * f.ny + y) * f.nx + x;
    f.samples[i] = value;
    ++count[i];
    const g::SliceControl e = g::slice_control(f.regs, c.k);
    if (e.wx != c.wx || e.wy != c.wy || e.wz != c.wz || e.z_voxel != c.z_voxel) control_ok = false;
  }
};


const Frame& frame(const std::string& name, const std::array<int, 3>& size, const std::array<double, 3>& dir,
                   const std::array<double, 3>& up, int S, int seed) {
  static std::map<std::string, std::unique_ptr<Frame>> cache;
  std::ostringstream js;
  js << R"({"volume": {"synthetic": "noise", "size": [)" << size[0] << ", " << size[1] << ", " << size[2]
     << R"(], "seed": )" << seed << R"(}, "view": )" << direction_json(dir, up) << R"(, "supersampling": )" << S
     << R"(, "shading": false})";
  const std::string json = js.str();
  auto& slot = cache[json];
  if (slot) return *slot;
  auto f = std::make_unique<Frame>();
  const g::Scene scene = g::parse_scene(json, "test_interp.json");
  f->vol = g::load_volume(scene.volume, scene.precision.voxel_bits, ".");
  f->regs = g::program_host(scene, f->vol).regs;
  std::ostringstream n;
  n << name << " size " << size[0] << "x" << size[1] << "x" << size[2] << " S=" << S;
  f->name = n.str();
  f->nx = f->regs.dim[0];
  f->ny = f->regs.dim[1];
  f->nz = f->regs.dim[2];
  f->S = f->regs.supersampling;
  f->K = f->regs.sample_slices();
  const int64_t object_stride[3] = {1, f->vol.dim[0], int64_t{f->vol.dim[0]} * f->vol.dim[1]};
  for (int i = 0; i < 3; ++i) {
    f->stride[i] = object_stride[f->regs.perm[i]] * (f->regs.flip[i] ? -1 : 1);
    if (f->regs.flip[i]) f->origin += (f->regs.dim[i] - 1) * object_stride[f->regs.perm[i]];
  }
  f->samples.assign(static_cast<size_t>(f->K) * f->ny * f->nx, 0);
  Collect probe(*f);
  g::render_fixed(f->vol, f->regs, nullptr, {}, &probe);
  for (int c : probe.count)
    if (c != 1) ADD_FAILURE() << f->name << ": the golden probe saw a sample " << c << " times";
  EXPECT_TRUE(probe.control_ok) << f->name << ": probe slice control differs from slice_control()";
  slot = std::move(f);
  return *slot;
}

// One cycle of the input stream.
struct Beat {
  bool valid = false, beam_start = false, beam_end = false, slice_start = false, slice_end = false;
  uint32_t wx = 0, wy = 0, wz = 0, tag = 0;
  std::vector<uint32_t> voxel;  // one per pipeline
};

// A sample every pipeline must emit in `cycle` (pipeline k: x = j*p + k).
struct Expect {
  uint64_t cycle;
  int frame, k, y, j;
  bool beam_start, beam_end, slice_start, slice_end;
  uint32_t tag;
};

struct StreamOptions {
  double stall = 0;       // probability of idle cycles before a partial beam
  int max_gap = 3;        // 1 .. max_gap idle cycles each time
  bool junk_zero_beam = false;  // random voxels in beam ny (the unit ignores them)
};

struct Stream {
  std::vector<Beat> beats;
  std::vector<Expect> expects;
  uint64_t valid_beats = 0, idle_beats = 0, expected_valid = 0;
  uint64_t last_input = 0;
};

Stream make_stream(const std::vector<const Frame*>& frames, int p, const StreamOptions& opt, Random& rng) {
  Stream s;
  auto junk = [&] {
    Beat b;
    b.valid = false;
    b.beam_start = rng.chance(0.5);
    b.beam_end = rng.chance(0.5);
    b.slice_start = rng.chance(0.5);
    b.slice_end = rng.chance(0.5);
    b.wx = rng.range(0, 256);
    b.wy = rng.range(0, 256);
    b.wz = rng.chance(0.5) ? 0 : rng.range(0, 256);
    b.tag = rng.bits(kTagBits);
    for (int k = 0; k < p; ++k) b.voxel.push_back(rng.bits(kVoxelBits));
    return b;
  };
  for (size_t fi = 0; fi < frames.size(); ++fi) {
    const Frame& f = *frames[fi];
    const int B = (f.nx + p - 1) / p;
    s.expected_valid += static_cast<uint64_t>(f.ny + 1) * B * f.K;
    for (int k = 0; k < f.K; ++k) {
      const g::SliceControl c = g::slice_control(f.regs, k);
      // The voxel slice this sample slice needs last: the one it lies on
      // (wz = 0), else the one behind it (zero beyond the volume).
      const int z_in = c.wz == 0 ? c.z_voxel : c.z_voxel + 1;
      for (int y = 0; y <= f.ny; ++y)
        for (int j = 0; j < B; ++j) {
          if (opt.stall > 0 && rng.chance(opt.stall)) {
            const int gap = static_cast<int>(rng.range(1, opt.max_gap));
            for (int i = 0; i < gap; ++i) s.beats.push_back(junk());
            s.idle_beats += gap;
          }
          Beat b;
          b.valid = true;
          b.beam_start = j == 0;
          b.beam_end = j == B - 1;
          b.slice_start = y == 0;
          b.slice_end = y == f.ny;
          b.wx = c.wx;
          b.wy = c.wy;
          b.wz = c.wz;
          b.tag = static_cast<uint32_t>(k + 61 * fi) & ((1u << kTagBits) - 1);
          for (int q = 0; q < p; ++q)
            b.voxel.push_back(y == f.ny ? (opt.junk_zero_beam ? rng.bits(kVoxelBits) : 0)
                                        : f.voxel(j * p + q, y, z_in));
          s.beats.push_back(b);
          ++s.valid_beats;
          if (y > 0)
            s.expects.push_back({s.beats.size() - 1, static_cast<int>(fi), k, y - 1, j, j == 0, j == B - 1,
                                 y == 1, y == f.ny, b.tag});
        }
    }
  }
  s.last_input = s.beats.size() - 1;
  // The sample of a column leaves the alignment register with the next valid
  // input, or one cycle later if the column ends a beam; 3 more cycles in
  // cube4_interp.
  std::vector<uint64_t> next_valid(s.beats.size(), 0);
  uint64_t nv = ~uint64_t{0};
  for (size_t i = s.beats.size(); i-- > 0;) {
    next_valid[i] = nv;
    if (s.beats[i].valid) nv = i;
  }
  for (Expect& e : s.expects) {
    const uint64_t t = e.cycle;
    e.cycle = (e.beam_end ? t + 1 : next_valid[t]) + (kLatency - 1);
  }
  return s;
}

struct RunResult {
  bool ok = true;
  std::string report;
  uint64_t checked = 0, cycles = 0, last_output = 0;
};

template <class M>
RunResult run_ring(M& m, int p, const std::vector<const Frame*>& frames, const Stream& s, Random& rng) {
  RunResult r;
  cube4::rtl::reset(m);
  auto fail = [&](uint64_t cycle, int pipe, const Expect* e, const std::string& what, const std::string& detail) {
    if (!r.ok) return;
    r.ok = false;
    r.report = mismatch_report(cycle, pipe, p, frames, e, "sample of", what, detail);
  };
  size_t ei = 0;
  const uint64_t end = s.beats.size() + 2 * kLatency;
  for (uint64_t cycle = 0; cycle < end; ++cycle) {
    Beat idle;
    const Beat* b = &idle;
    if (cycle < s.beats.size()) {
      b = &s.beats[cycle];
    } else {
      idle.wz = rng.range(0, 256);
      idle.tag = rng.bits(kTagBits);
      for (int k = 0; k < p; ++k) idle.voxel.push_back(rng.bits(kVoxelBits));
    }
    m.valid_i = b->valid;
    m.beam_start_i = b->beam_start;
    m.beam_end_i = b->beam_end;
    m.slice_start_i = b->slice_start;
    m.slice_end_i = b->slice_end;
    m.wx_i = b->wx;
    m.wy_i = b->wy;
    m.wz_i = b->wz;
    m.tag_i = b->tag;
    for (int k = 0; k < p; ++k) put_bits(m.voxel_i, k * kVoxelBits, kVoxelBits, b->voxel[k]);
    cube4::rtl::settle(m);

    const Expect* e = ei < s.expects.size() && s.expects[ei].cycle == cycle ? &s.expects[ei] : nullptr;
    for (int k = 0; k < p; ++k) {
      const bool valid = get_bits(m.valid_o, k, 1);
      if (!e) {
        if (valid) fail(cycle, k, nullptr, "valid_o high with no sample due", "");
        continue;
      }
      if (!valid) {
        fail(cycle, k, e, "valid_o low, a sample was due", "");
        continue;
      }
      const Frame& f = *frames[e->frame];
      const int x = e->j * p + k;
      // Columns x >= nx are the zero padding: their samples are 0.
      const uint32_t exp = x < f.nx ? f.samples[(static_cast<size_t>(e->k) * f.ny + e->y) * f.nx + x] : 0;
      const uint32_t got = static_cast<uint32_t>(get_bits(m.sample_o, k * kVoxelBits, kVoxelBits));
      const bool bs = get_bits(m.beam_start_o, k, 1), be = get_bits(m.beam_end_o, k, 1);
      const bool ss = get_bits(m.slice_start_o, k, 1), se = get_bits(m.slice_end_o, k, 1);
      const uint32_t tag = static_cast<uint32_t>(get_bits(m.tag_o, k * kTagBits, kTagBits));
      if (got != exp || bs != e->beam_start || be != e->beam_end || ss != e->slice_start || se != e->slice_end ||
          tag != e->tag) {
        std::ostringstream d;
        d << "expected: sample=" << exp << " beam_start=" << e->beam_start << " beam_end=" << e->beam_end
          << " slice_start=" << e->slice_start << " slice_end=" << e->slice_end << " tag=" << e->tag
          << "\n  got:      sample=" << got << " beam_start=" << bs << " beam_end=" << be << " slice_start=" << ss
          << " slice_end=" << se << " tag=" << tag;
        fail(cycle, k, e, "output differs", d.str());
      } else {
        ++r.checked;
      }
      if (x < f.nx) r.last_output = cycle;
    }
    if (e) ++ei;
    cube4::rtl::rise(m);
  }
  if (ei != s.expects.size())
    fail(end, 0, &s.expects[ei], std::to_string(s.expects.size() - ei) + " samples never appeared", "");
  r.cycles = end;
  return r;
}

// Streams the frames back to back into ring M and checks everything.
template <class M>
void check_ring(const RingParams& rp, const std::vector<const Frame*>& frames, const StreamOptions& opt,
                uint64_t salt, uint64_t* samples_checked = nullptr) {
  std::string what;
  ASSERT_TRUE(frames_fit(rp, frames, what));
  SCOPED_TRACE("p=" + std::to_string(rp.p) + (opt.stall > 0 ? ", stalls" : ", no stalls") + ": " + what);
  Random rng(salt);
  const Stream s = make_stream(frames, rp.p, opt, rng);
  auto m = std::make_unique<M>();
  const RunResult r = run_ring(*m, rp.p, frames, s, rng);
  m->final();
  EXPECT_TRUE(r.ok) << r.report;
  if (!r.ok) return;
  // Every sample of every frame, once per pipeline; the samples of columns
  // x < nx are exactly the golden samples.
  uint64_t expected_samples = 0, golden_samples = 0;
  for (const Frame* f : frames) {
    expected_samples += static_cast<uint64_t>(f->K) * f->ny * ((f->nx + rp.p - 1) / rp.p) * rp.p;
    golden_samples += f->samples.size();
  }
  EXPECT_EQ(r.checked, expected_samples);
  // Cycle count: (ny + 1) * ceil(nx/p) * K input cycles per frame plus the
  // idle ones; the last sample 4 cycles after the last input.
  EXPECT_EQ(s.valid_beats, s.expected_valid);
  EXPECT_EQ(s.beats.size(), s.valid_beats + s.idle_beats);
  EXPECT_EQ(r.last_output, s.last_input + kLatency);
  if (samples_checked) *samples_checked += golden_samples;
}


// Every view, S = 1, 2, 3, without and with stalls (junk in the zero beam
// with stalls).
template <class M>
void ring_matrix(const RingParams& rp) {
  Timer t("p=" + std::to_string(rp.p) + " matrix");
  uint64_t samples = 0;
  int runs = 0;
  for (size_t v = 0; v < kViews.size(); ++v)
    for (int S : {1, 2, 3}) {
      const Frame& f = frame(kViews[v].name, kSizes[(v + S) % kSizes.size()], kViews[v].dir, kViews[v].up, S,
                             static_cast<int>(3 + v));
      for (bool stalls : {false, true}) {
        StreamOptions opt;
        opt.stall = stalls ? 0.3 : 0;
        opt.junk_zero_beam = stalls;
        check_ring<M>(rp, {&f}, opt, 1000 * rp.p + 10 * v + S + (stalls ? 5 : 0), &samples);
        ++runs;
        if (::testing::Test::HasFailure()) return;
      }
    }
  std::printf("  p=%d: %d runs, %llu golden samples matched in all\n", rp.p, runs,
              static_cast<unsigned long long>(samples));
}

TEST(RtlInterpRing, P1MatchesGoldenSamples) { ring_matrix<Vcube4_interp_ring_p1>(kRingP1); }
TEST(RtlInterpRing, P2MatchesGoldenSamples) { ring_matrix<Vcube4_interp_ring_p2>(kRingP2); }
TEST(RtlInterpRing, P4MatchesGoldenSamples) { ring_matrix<Vcube4_interp_ring>(kRingP4); }
TEST(RtlInterpRing, P5MatchesGoldenSamples) { ring_matrix<Vcube4_interp_ring_p5>(kRingP5); }

// Frames back to back without a reset between them (the stores re-align on
// every pass's zero beam), with stalls.
TEST(RtlInterpRing, BackToBackFrames) {
  Timer t("back-to-back frames");
  const Frame& a = frame("+z tilted", {9, 7, 6}, {0.35, -0.3, 1}, {0, 1, 0}, 2, 21);
  const Frame& b = frame("-y tilted", {12, 5, 8}, {-0.4, -1, -0.3}, {0, 0, 1}, 3, 22);
  const Frame& c = frame("oblique", {7, 11, 10}, {0.7, -0.6, 1}, {0, 1, 0}, 1, 23);
  const Frame& d = frame("-x tilted", {9, 7, 6}, {-1, -0.2, 0.35}, {0, 1, 0}, 2, 24);
  const std::vector<const Frame*> frames = {&a, &b, &c, &d};
  for (double stall : {0.0, 0.25}) {
    StreamOptions opt;
    opt.stall = stall;
    check_ring<Vcube4_interp_ring_p1>(kRingP1, frames, opt, 71);
    check_ring<Vcube4_interp_ring_p2>(kRingP2, frames, opt, 72);
    check_ring<Vcube4_interp_ring>(kRingP4, frames, opt, 74);
    check_ring<Vcube4_interp_ring_p5>(kRingP5, frames, opt, 75);
  }
}

// Slices that fill the slice store to its last entry (ny * ceil(nx/p) =
// SliceDepth) and beams that fill the beam delay (ceil(nx/p) = BeamDepth).
TEST(RtlInterpRing, FullStorage) {
  Timer t("full storage");
  const Frame& f2 = frame("+z tilted", {16, 16, 3}, {0.2, 0.3, 1}, {0, 1, 0}, 2, 31);
  ASSERT_EQ((f2.nx + 1) / 2 * f2.ny, kRingP2.slice_depth());
  const Frame& f5 = frame("-z tilted", {15, 12, 3}, {0.3, -0.2, -1}, {0, 1, 0}, 3, 32);
  ASSERT_EQ((f5.nx + 4) / 5 * f5.ny, kRingP5.slice_depth());
  const Frame& f1 = frame("+z tilted", {24, 24, 2}, {0.45, 0.2, 1}, {0, 1, 0}, 2, 33);
  ASSERT_EQ(f1.nx * f1.ny, kRingP1.slice_depth());
  for (double stall : {0.0, 0.3}) {
    StreamOptions opt;
    opt.stall = stall;
    check_ring<Vcube4_interp_ring_p2>(kRingP2, {&f2}, opt, 81);
    check_ring<Vcube4_interp_ring_p5>(kRingP5, {&f5}, opt, 85);
    check_ring<Vcube4_interp_ring_p1>(kRingP1, {&f1}, opt, 82);
  }
}

// Random scenes: direction, volume size (within every ring's storage), S up
// to VolumePro's 8, stall rate; every ring.
TEST(RtlInterpRing, RandomScenes) {
  Timer t("random scenes");
  Random rng(0x5CE4E);
  const long n = cube4::rtl::vector_count(1000000) >= 1000000 ? 200 : 4;
  uint64_t samples = 0;
  for (long i = 0; i < n; ++i) {
    const RandomScene sc = random_scene(rng);
    const Frame& f = frame("random " + std::to_string(i), sc.size, sc.dir, sc.up, sc.S, static_cast<int>(100 + i));
    StreamOptions opt;
    opt.stall = rng.chance(0.5) ? 0 : static_cast<double>(rng.range(1, 60)) / 100.0;
    opt.max_gap = static_cast<int>(rng.range(1, 5));
    opt.junk_zero_beam = rng.chance(0.5);
    check_ring<Vcube4_interp_ring_p1>(kRingP1, {&f}, opt, 200 + i, &samples);
    check_ring<Vcube4_interp_ring_p2>(kRingP2, {&f}, opt, 300 + i, &samples);
    check_ring<Vcube4_interp_ring>(kRingP4, {&f}, opt, 400 + i, &samples);
    check_ring<Vcube4_interp_ring_p5>(kRingP5, {&f}, opt, 500 + i, &samples);
    if (::testing::Test::HasFailure()) return;
  }
  std::printf("  %ld random scenes, each through p = 1, 2, 4, 5: %llu golden samples matched\n", n,
              static_cast<unsigned long long>(samples));
}

// A larger volume through the default ring (p = 4, 256^3 storage), every
// supersampling factor up to VolumePro's 8 for one view.
TEST(RtlInterpRing, LargerVolumeP4) {
  Timer t("larger volume, p=4");
  for (int S : {1, 4, 8}) {
    const Frame& f = frame("oblique", {37, 30, 14}, {0.55, 0.4, -1}, {0, 1, 0}, S, 41);
    StreamOptions opt;
    opt.stall = 0.1;
    check_ring<Vcube4_interp_ring>(kRingP4, {&f}, opt, 90 + S);
  }
}

}  // namespace
