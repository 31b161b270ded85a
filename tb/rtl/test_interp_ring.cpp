// RTL tests of the interpolation unit with its delay storage and
// near-neighbour links: cube4_delay_ram against a model of its contract, and
// cube4_interp_ring (p = 1, 2, 4, 5 pipelines) against the golden renderer.
//
// The ring test builds scenes with the golden host driver, streams the
// permuted volume into the verilated ring cycle by cycle as the system's
// stream former does (FramePlan: docs/rtl-interp.md's order, sample slice by
// sample slice, beam by beam (passes back to back, a flush beam at the
// end), partial beam by partial beam, with the slice weights of golden slice_control()), and
// compares every output sample of
// every pipeline with the value golden render_fixed() computed for the same
// (x, y, k_s) (collected with a SampleProbe), together with its flags, its
// tag and the cycle it appears in. Random idle cycles between partial
// beams, and junk on every input while valid_i is low, check that only
// valid_i moves the unit. Nothing here re-implements the interpolation.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "Vcube4_delay_ram_d1.h"
#include "Vcube4_delay_ram_d13.h"
#include "Vcube4_interp_ring.h"
#include "Vcube4_interp_ring_p1.h"
#include "Vcube4_interp_ring_p2.h"
#include "Vcube4_interp_ring_p5.h"
#include "Vcube4_interp_ring_t4.h"
#include "golden/pipeline.hpp"
#include "systemc/rtl/unit_streams.hpp"
#include "tb/rtl/ring_bench.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace sysc = cube4::sysc;
using namespace cube4::rtl;  // the shared bench: rtl_check.hpp, ring_bench.hpp

// Ring parameters, as in rtl/groups/interp.cmake.
constexpr int kVoxelBits = 12;  // ring defaults
constexpr int kTagBits = 8;
// The ring with 4-bit voxel tags: p = 4, MaxDim = 16.
constexpr int kVoxelTagBits = 4;
constexpr RingParams kRingT4{4, 16};


// ===========================================================================
// cube4_delay_ram against its contract: rdata_o is always the entry under
// the pointer; a step writes it (if write_i) and moves the pointer on, to 0
// after depth_i - 1, after MaxDepth - 1 or with last_i; clear_i sets it to 0.

template <class M>
void test_delay_ram(const char* unit, int max_depth) {
  constexpr int W = 10;
  auto m = cube4::rtl::make_dut<M>();
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

const SampleFrame& frame(const std::string& name, const std::array<int, 3>& size, const std::array<double, 3>& dir,
                         const std::array<double, 3>& up, int S, int seed, int vtag_bits = 0) {
  return sample_frame(name, size, dir, up, S, seed, /*gradient=*/false, vtag_bits);
}

struct RunResult {
  bool ok = true;
  std::string report;
  uint64_t checked = 0, cycles = 0, last_output = 0;
};

// The stream of the frames, formed as the system forms it (FramePlan); the
// ring's TagBits carry the plan's user tag, 61 apart from frame to frame.
VoxelStream make_stream(const std::vector<const SampleFrame*>& frames, int p, const VoxelStreamOptions& opt,
                        Random& rng) {
  std::vector<sysc::FramePlan> plans;
  for (size_t fi = 0; fi < frames.size(); ++fi) plans.emplace_back(frames[fi]->regs, p, kTagBits, 61 * fi);
  return voxel_stream(frames, plans, [&](int fi, int pass) { return plans[static_cast<size_t>(fi)].user_tag(pass); },
                      kVoxelBits, kTagBits, opt, rng);
}

// vtag_bits: the ring's VoxelTagBits; its samples' tags are then checked too.
template <class M>
RunResult run_ring(M& m, int p, const std::vector<const SampleFrame*>& frames, const VoxelStream& s, Random& rng,
                   int vtag_bits) {
  RunResult r;
  cube4::rtl::reset(m);
  auto fail = [&](uint64_t cycle, int pipe, const PassSample* e, const std::string& what, const std::string& detail) {
    if (!r.ok) return;
    r.ok = false;
    r.report = mismatch_report(cycle, pipe, p, frames, e, "sample of", what, detail);
  };
  size_t ei = 0;
  const uint64_t end = s.beats.size() + 2 * kInterpLatency;
  for (uint64_t cycle = 0; cycle < end; ++cycle) {
    const int word_bits = kVoxelBits + vtag_bits;
    const sysc::VoxelBeat b = cycle < s.beats.size() ? s.beats[cycle] : junk_voxel_beat(rng, p, word_bits, kTagBits);
    drive_interp_stream(m, b, p, word_bits, kTagBits);
    cube4::rtl::settle(m);

    const PassSample* e = ei < s.samples.size() && s.samples[ei].cycle == cycle ? &s.samples[ei] : nullptr;
    for (int k = 0; k < p; ++k) {
      if (!output_due(get_bits(m.valid_o, k, 1), e, cycle, k, "sample", fail)) continue;
      const SampleFrame& f = *frames[static_cast<size_t>(e->frame)];
      const int x = e->j * p + k;
      // Columns x >= nx are the zero padding: their samples are 0.
      const uint32_t exp = x < f.nx ? f.samples[f.index(e->k, e->y, x)] : 0;
      const uint32_t got = static_cast<uint32_t>(get_bits(m.sample_o, k * kVoxelBits, kVoxelBits));
      const bool bs = get_bits(m.beam_start_o, k, 1), be = get_bits(m.beam_end_o, k, 1);
      const bool ss = get_bits(m.slice_start_o, k, 1), se = get_bits(m.slice_end_o, k, 1);
      const uint64_t tag = get_bits(m.tag_o, k * kTagBits, kTagBits);
      // Without tag hardware the lane is one bit, always 0.
      const int lane = vtag_bits > 0 ? vtag_bits : 1;
      const uint32_t exp_vtag = x < f.nx ? f.vtags[f.index(e->k, e->y, x)] : 0;
      const auto vtag = static_cast<uint32_t>(get_bits(m.vtag_o, k * lane, lane));
      if (got != exp || bs != e->f.beam_start || be != e->f.beam_end || ss != e->f.slice_start ||
          se != e->f.slice_end || tag != e->tag || vtag != exp_vtag) {
        std::ostringstream d;
        d << "expected: sample=" << exp << " beam_start=" << e->f.beam_start << " beam_end=" << e->f.beam_end
          << " slice_start=" << e->f.slice_start << " slice_end=" << e->f.slice_end << " tag=" << e->tag
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
  if (ei != s.samples.size())
    fail(end, 0, &s.samples[ei], std::to_string(s.samples.size() - ei) + " samples never appeared", "");
  r.cycles = end;
  return r;
}

// Streams the frames back to back into ring M and checks everything.
template <class M>
void check_ring(const RingParams& rp, const std::vector<const SampleFrame*>& frames, const VoxelStreamOptions& opt,
                uint64_t salt, uint64_t* samples_checked = nullptr) {
  std::string what;
  ASSERT_TRUE(frames_fit(rp, frames, what));
  SCOPED_TRACE("p=" + std::to_string(rp.p) + (opt.stall > 0 ? ", stalls" : ", no stalls") + ": " + what);
  Random rng(salt);
  const VoxelStream s = make_stream(frames, rp.p, opt, rng);
  auto m = cube4::rtl::make_dut<M>();
  const RunResult r = run_ring(*m, rp.p, frames, s, rng, opt.vtag_bits);
  m->final();
  EXPECT_TRUE(r.ok) << r.report;
  if (!r.ok) return;
  // Every sample of every frame, once per pipeline; the samples of columns
  // x < nx are exactly the golden samples.
  uint64_t expected_samples = 0, golden_samples = 0;
  uint64_t expected_valid = 0;
  for (size_t fi = 0; fi < frames.size(); ++fi) {
    const SampleFrame* f = frames[fi];
    const uint64_t B = static_cast<uint64_t>((f->nx + rp.p - 1) / rp.p);
    expected_samples += static_cast<uint64_t>(f->K) * f->ny * B * rp.p;
    expected_valid += static_cast<uint64_t>(f->ny) * B * f->K;
    // A flush beam after the last frame and before a frame of other beams.
    const bool last = fi + 1 == frames.size();
    if (last || (frames[fi + 1]->nx + rp.p - 1) / rp.p != static_cast<int>(B) || frames[fi + 1]->ny != f->ny)
      expected_valid += B;
    golden_samples += f->samples.size();
  }
  EXPECT_EQ(r.checked, expected_samples);
  // Cycle count: ny * ceil(nx/p) * K input cycles per frame (passes back to
  // back), the flush beams and the idle cycles; the last sample 4 cycles
  // after the last input.
  EXPECT_EQ(s.valid, expected_valid);
  EXPECT_EQ(s.beats.size(), s.valid + s.idle);
  EXPECT_EQ(r.last_output, s.last_input + kInterpLatency);
  if (samples_checked) *samples_checked += golden_samples;
}


// Every view, S = 1, 2, 3, without and with stalls (junk in the flush
// beam with stalls).
template <class M>
void ring_matrix(const RingParams& rp) {
  Timer t("p=" + std::to_string(rp.p) + " matrix");
  uint64_t samples = 0;
  int runs = 0;
  for (size_t v = 0; v < kViews.size(); ++v)
    for (int S : {1, 2, 3}) {
      const SampleFrame& f = frame(kViews[v].name, kSizes[(v + S) % kSizes.size()], kViews[v].dir, kViews[v].up, S,
                             static_cast<int>(3 + v));
      for (bool stalls : {false, true}) {
        VoxelStreamOptions opt;
        opt.stall = stalls ? 0.3 : 0;
        opt.junk = stalls;
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

// Frames back to back without a reset between them (the slice store's lap
// ends with each pass's last voxel; a frame of other beam length follows a
// flush beam), with stalls.
TEST(RtlInterpRing, BackToBackFrames) {
  Timer t("back-to-back frames");
  const std::vector<const SampleFrame*> frames = back_to_back_frames(/*gradient=*/false);
  for (double stall : {0.0, 0.25}) {
    VoxelStreamOptions opt;
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
  const FullStorageFrames full = full_storage_frames(/*gradient=*/false);
  ASSERT_FALSE(::testing::Test::HasFailure());
  const SampleFrame &f2 = *full.p2, &f5 = *full.p5, &f1 = *full.p1;
  for (double stall : {0.0, 0.3}) {
    VoxelStreamOptions opt;
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
    const SampleFrame& f = frame("random " + std::to_string(i), sc.size, sc.dir, sc.up, sc.S, static_cast<int>(100 + i));
    VoxelStreamOptions opt;
    opt.stall = rng.chance(0.5) ? 0 : static_cast<double>(rng.range(1, 60)) / 100.0;
    opt.max_gap = static_cast<int>(rng.range(1, 5));
    opt.junk = rng.chance(0.5);
    check_ring<Vcube4_interp_ring_p1>(kRingP1, {&f}, opt, 200 + i, &samples);
    check_ring<Vcube4_interp_ring_p2>(kRingP2, {&f}, opt, 300 + i, &samples);
    check_ring<Vcube4_interp_ring>(kRingP4, {&f}, opt, 400 + i, &samples);
    check_ring<Vcube4_interp_ring_p5>(kRingP5, {&f}, opt, 500 + i, &samples);
    if (::testing::Test::HasFailure()) return;
  }
  std::printf("  %ld random scenes, each through p = 1, 2, 4, 5: %llu golden samples matched\n", n,
              static_cast<unsigned long long>(samples));
}

// Voxel tags (bela §III): every view, S = 1, 2, 3, with and without stalls
// and junk, through the ring with 4-bit tags; each sample's tag is golden's
// (its nearest voxel's, the SampleProbe's tagged()). Neighbouring voxels'
// tags differ (value bands of a noise volume), so a wrong corner shows.
TEST(RtlInterpRing, VoxelTagsTakeTheNearestVoxels) {
  Timer t("voxel tags");
  uint64_t samples = 0;
  for (size_t v = 0; v < kViews.size(); ++v)
    for (int S : {1, 2, 3}) {
      const SampleFrame& f = frame(kViews[v].name, kSizes[(v + S) % kSizes.size()], kViews[v].dir, kViews[v].up, S,
                                   static_cast<int>(60 + v), kVoxelTagBits);
      // The labelling gives the samples several tags (else the test proves little).
      std::set<uint32_t> seen(f.vtags.begin(), f.vtags.end());
      EXPECT_GE(seen.size(), 3u) << f.name << ": the samples' tags hardly differ";
      for (bool stalls : {false, true}) {
        VoxelStreamOptions opt;
        opt.stall = stalls ? 0.3 : 0;
        opt.junk = stalls;
        opt.vtag_bits = kVoxelTagBits;
        check_ring<Vcube4_interp_ring_t4>(kRingT4, {&f}, opt, 700 + 10 * v + S + (stalls ? 5 : 0), &samples);
        if (::testing::Test::HasFailure()) return;
      }
    }
  std::printf("  %llu golden samples and tags matched\n", static_cast<unsigned long long>(samples));
}

// A larger volume through the default ring (p = 4, 256^3 storage), every
// supersampling factor up to VolumePro's 8 for one view.
TEST(RtlInterpRing, LargerVolumeP4) {
  Timer t("larger volume, p=4");
  for (int S : {1, 4, 8}) {
    const SampleFrame& f = frame("oblique", {37, 30, 14}, {0.55, 0.4, -1}, {0, 1, 0}, S, 41);
    VoxelStreamOptions opt;
    opt.stall = 0.1;
    check_ring<Vcube4_interp_ring>(kRingP4, {&f}, opt, 90 + S);
  }
}

}  // namespace
