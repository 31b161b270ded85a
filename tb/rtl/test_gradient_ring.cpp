// RTL tests of the gradient unit with its sample storage and near-neighbour
// links: cube4_gradient_ring (p = 1, 2, 4, 5 pipelines) against the golden
// renderer.
//
// Two ways in:
//   - chain: the permuted volume streamed into a verilated
//     cube4_interp_ring (docs/rtl-interp.md order: frames and passes back
//     to back, and after a frame that ends a stream its zero pass and a
//     flush beam), whose outputs drive the gradient ring wire for wire:
//     voxels -> samples -> gradients, proving the two rings fit;
//   - direct: the golden samples (from a SampleProbe) streamed straight into
//     the gradient ring, with random gaps, and exactly the B idle cycles
//     after each zero slice that the ring's zero beam needs (the chain
//     always leaves exactly B).
// Every gradient (and the sample, position, flags and tag beside it) of
// every pipeline is compared with golden render_fixed()'s (regs.gradient
// forced on; the probe gives every sample's value and gradient), in the
// exact cycle the model of docs/rtl-gradient.md predicts. A failure prints
// the first mismatch: cycle, pipeline, frame, x, y, slice, expected, got.
// Nothing here re-implements the gradient.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "Vcube4_gradient_ring.h"
#include "Vcube4_gradient_ring_p1.h"
#include "Vcube4_gradient_ring_p2.h"
#include "Vcube4_gradient_ring_p5.h"
#include "Vcube4_gradient_ring_t4.h"
#include "Vcube4_gradient_ring_z1.h"
#include "Vcube4_gradient_ring_z4.h"
#include "Vcube4_interp_ring_g1.h"
#include "Vcube4_interp_ring_g2.h"
#include "Vcube4_interp_ring_g4.h"
#include "Vcube4_interp_ring_g5.h"
#include "Vcube4_interp_ring_gt4.h"
#include "Vcube4_interp_ring_gz1.h"
#include "Vcube4_interp_ring_gz4.h"
#include "golden/pipeline.hpp"
#include "systemc/rtl/gradient_tag.hpp"
#include "systemc/rtl/unit_streams.hpp"
#include "tb/rtl/ring_bench.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace sysc = cube4::sysc;
using namespace cube4::rtl;  // the shared bench: rtl_check.hpp, ring_bench.hpp

// Ring defaults (cube4_gradient_ring, cube4_interp_ring).
constexpr int kVoxelBits = 12;
constexpr int kWeightBits = 8;
constexpr int kGradientBits = 8;
constexpr int kUserTagBits = 8;
constexpr int kTagBits = CUBE4_GRADIENT_TAG_BITS;  // rtl/groups/gradient.cmake
static_assert(kTagBits == gradient_tag_bits(kWeightBits, kUserTagBits), "gradient.cmake's tag width differs from the ring's");
static_assert(kTagBits <= 64, "the test packs a tag into 64 bits");
// Gradient ring: a step fires with the next step (or one cycle later if it
// ends a beam), then cube4_gradient's 3 cycles.
constexpr int kGradientStages = 3;

// Ring parameters, as in rtl/groups/gradient.cmake: the rings with 4-bit
// voxel tags (bela §III) have p = 4, MaxDim = 16.
constexpr int kVoxelTagBits = 4;
constexpr RingParams kRingT4{4, 16};

// ===========================================================================
// Golden frames: every sample and its gradient (regs.gradient forced on).

const SampleFrame& frame(const std::string& name, const std::array<int, 3>& size, const std::array<double, 3>& dir,
                         const std::array<double, 3>& up, int S, int seed, int vtag_bits = 0, bool voxel_z = false) {
  const SampleFrame& f = sample_frame(name, size, dir, up, S, seed, /*gradient=*/true, vtag_bits, voxel_z);
  EXPECT_EQ(f.regs.p.voxel_bits, kVoxelBits);
  EXPECT_EQ(f.regs.p.weight_bits, kWeightBits);
  EXPECT_EQ(f.regs.p.gradient_bits, kGradientBits);
  return f;
}

// Frame fi's plan: the system's stream formation, with the ring's user tag
// (61 apart from frame to frame).
sysc::FramePlan plan_of(const SampleFrame& f, int p, size_t fi) { return sysc::FramePlan(f.regs, p, kUserTagBits, 61 * fi); }

// VolumePro's z gradient: the interpolated voxel z difference of sample
// (x, y) of slice k, from golden's functions on the frame's voxels (zero
// outside the volume, as the stream reads them).
bool voxel_z(const SampleFrame& f) { return f.regs.gradient && f.regs.z_gradient == g::ZGradient::VoxelDifferences; }
int32_t expected_zdiff(const SampleFrame& f, int k, int y, int x) {
  const g::SliceControl c = g::slice_control(f.regs, k);
  std::array<int32_t, 8> d{};
  for (int i = 0; i < 8; ++i) {
    const int vx = x + (i & 1), vy = y + (i >> 1 & 1), z = c.z_voxel + (i >> 2);
    d[static_cast<size_t>(i)] = g::voxel_z_difference(f.pv->at(vx, vy, z + 1), f.pv->at(vx, vy, z - 1));
  }
  return static_cast<int32_t>(g::interpolated_z_difference(d, c.wx, c.wy, c.wz, kWeightBits));
}

// The gradient ring's tag for input slice k: the plan's, except that the
// zero slice (k = K), whose slice control the ring must not use, carries
// random realign fields and supersampling factor.
uint64_t slice_tag(const sysc::FramePlan& plan, int k, Random& rng) {
  if (k == plan.K) {
    const uint64_t realign = rng.bits(4 * (kWeightBits + 1));
    const uint64_t supersampling = rng.bits(kSupersamplingBits);
    return gradient_tag(nullptr, realign, supersampling, false, plan.user_tag(k), kWeightBits, kUserTagBits);
  }
  for (const g::Realign& r : {plan.slices[k].behind_x, plan.slices[k].behind_y, plan.slices[k].ahead_x,
                              plan.slices[k].ahead_y}) {
    EXPECT_TRUE(r.base == 0 || r.base == -1);
    EXPECT_LT(r.weight, 1u << kWeightBits);
  }
  return plan.pass_tag(k);
}

// ===========================================================================
// Streams.

// A sample entering the gradient ring (one partial beam, every pipeline).
struct SampleIn {
  uint64_t cycle;
  int frame, k, y, j;  // k: input slice 0 .. K (K = the zero slice)
  bool beam_start, beam_end, slice_start, slice_end;
  uint64_t tag;
  std::vector<uint32_t> sample;  // direct mode: one per pipeline
  std::vector<uint32_t> vtag;    // direct mode: the samples' voxel tags
  std::vector<int32_t> zdiff;    // direct mode: the samples' z differences (VolumePro's z gradient)
};

// A gradient every pipeline must emit in `cycle` (pipeline q: x = j*p + q).
struct Expect {
  uint64_t cycle;
  int frame, k, y, j;  // k: sample slice of the gradient
  bool beam_start, beam_end, slice_start, slice_end;
};

struct StreamOptions {
  bool chain = true;     // through the interpolation ring, else golden samples directly
  double stall = 0;      // probability of idle cycles before a partial beam (and after a slice)
  int max_gap = 3;       // 1 .. max_gap idle cycles each time
  bool junk = false;     // junk values wherever the rings must ignore them
  int vtag_bits = 0;     // the rings' VoxelTagBits: voxel words {tag, value}, tags checked
};

struct Stream {
  std::vector<sysc::VoxelBeat> beats;  // chain: the interpolation ring's input, one per cycle
  std::vector<SampleIn> in;      // the gradient ring's input samples, by cycle
  std::vector<Expect> expects;   // the gradient ring's outputs, by cycle
  uint64_t voxel_valid = 0, expected_voxel_valid = 0;
  uint64_t sample_valid = 0, expected_sample_valid = 0, zero_steps = 0;
  uint64_t last_voxel = 0, last_sample = 0, last_output = 0, end = 0;
  int last_B = 1;
  std::vector<sysc::FramePlan> plans;  // per frame
  std::string error;  // the stream breaks the ring's preconditions
};

Stream make_stream(const std::vector<const SampleFrame*>& frames, int p, const StreamOptions& opt, Random& rng) {
  Stream s;
  std::vector<sysc::FramePlan>& plans = s.plans;
  for (size_t fi = 0; fi < frames.size(); ++fi) plans.push_back(plan_of(*frames[fi], p, fi));
  if (opt.chain) {
    VoxelStreamOptions vo;
    vo.stall = opt.stall;
    vo.max_gap = opt.max_gap;
    vo.junk = opt.junk;
    vo.vtag_bits = opt.vtag_bits;
    VoxelStream v = voxel_stream(
        frames, plans, [&](int fi, int pass) { return slice_tag(plans[static_cast<size_t>(fi)], pass, rng); },
        kVoxelBits, kTagBits, vo, rng);
    s.voxel_valid = v.valid;
    for (size_t fi = 0; fi < frames.size(); ++fi) {
      const sysc::FramePlan& pl = plans[fi];
      const uint64_t beam = static_cast<uint64_t>(pl.B), slice = static_cast<uint64_t>(pl.ny) * beam;
      // K passes; a frame that ends a stream adds its zero pass and a flush beam.
      s.expected_voxel_valid += slice * static_cast<uint64_t>(pl.K) + (ends_stream(plans, fi) ? slice + beam : 0) +
                                (pl.zdiff ? slice : 0);  // the priming pass
    }
    s.last_voxel = v.last_input;
    s.beats = std::move(v.beats);
    for (const PassSample& e : v.samples)
      s.in.push_back({e.cycle, e.frame, e.k, e.y, e.j, e.f.beam_start, e.f.beam_end, e.f.slice_start, e.f.slice_end,
                      e.tag, {}, {}, {}});
  } else {
    uint64_t cycle = 0;
    for (size_t fi = 0; fi < frames.size(); ++fi) {
      const SampleFrame& f = *frames[fi];
      const int B = (f.nx + p - 1) / p;
      const int slices = ends_stream(plans, fi) ? f.K + 1 : f.K;  // the zero slice ends a stream
      for (int k = 0; k < slices; ++k) {
        const uint64_t tag = slice_tag(plans[fi], k, rng);
        for (int y = 0; y < f.ny; ++y)
          for (int j = 0; j < B; ++j) {
            if (opt.stall > 0 && rng.chance(opt.stall)) cycle += rng.range(1, opt.max_gap);
            SampleIn e{cycle++, static_cast<int>(fi), k, y, j, j == 0, j == B - 1, y == 0, y == f.ny - 1, tag, {}, {}, {}};
            for (int q = 0; q < p; ++q) {
              const int x = j * p + q;
              uint32_t v = 0;  // padding columns: zero (as the interpolation ring makes them)
              uint32_t t = 0;
              if (k < f.K && x < f.nx) {
                v = f.samples[f.index(k, y, x)];
                t = f.vtags[f.index(k, y, x)];
              }
              if (k == f.K && opt.junk) {
                v = static_cast<uint32_t>(rng.bits(kVoxelBits));
                if (opt.vtag_bits > 0) t = static_cast<uint32_t>(rng.bits(opt.vtag_bits));
              }
              int32_t zd = 0;
              if (voxel_z(f) && k < f.K && x < f.nx) zd = expected_zdiff(f, k, y, x);
              if (voxel_z(f) && k == f.K && opt.junk) zd = static_cast<int32_t>(rng.bits(kVoxelBits + 1));
              e.sample.push_back(v);
              e.vtag.push_back(t);
              e.zdiff.push_back(zd);
            }
            s.in.push_back(std::move(e));
          }
        // After the zero slice, the zero beam's B cycles, and sometimes more.
        if (k == f.K) cycle += B;
        if (opt.stall > 0 && rng.chance(opt.stall)) cycle += rng.range(1, opt.max_gap);
      }
    }
  }
  for (size_t fi = 0; fi < frames.size(); ++fi) {
    const SampleFrame* f = frames[fi];
    s.expected_sample_valid += static_cast<uint64_t>(f->ny) * ((f->nx + p - 1) / p) *
                               static_cast<uint64_t>(f->K + (ends_stream(plans, fi) ? 1 : 0));
  }
  s.sample_valid = s.in.size();
  s.last_sample = s.in.back().cycle;

  // The gradient ring's steps: every input sample, and after the zero
  // slice's last one the B steps of the zero beam (beam ny), one per cycle.
  struct Step {
    uint64_t cycle;
    int frame, k, y, j;
    bool beam_end, zero_beam;
  };
  std::vector<Step> steps;
  for (size_t i = 0; i < s.in.size(); ++i) {
    const SampleIn& e = s.in[i];
    if (!steps.empty() && e.cycle <= steps.back().cycle && s.error.empty()) {
      std::ostringstream o;
      o << "input sample at cycle " << e.cycle << " (frame " << e.frame << ", slice " << e.k << ", y " << e.y
        << ", j " << e.j << ") falls into the zero beam of the slice before (ends at cycle " << steps.back().cycle
        << ")";
      s.error = o.str();
    }
    steps.push_back({e.cycle, e.frame, e.k, e.y, e.j, e.beam_end, false});
    const SampleFrame& f = *frames[e.frame];
    if (e.slice_end && e.beam_end && e.k == f.K) {
      const int B = (f.nx + p - 1) / p;
      for (int j = 0; j < B; ++j) steps.push_back({e.cycle + 1 + j, e.frame, e.k, f.ny, j, j == B - 1, true});
      s.zero_steps += B;
      s.last_B = B;
    }
  }
  // Which gradients each step gives (docs/rtl-gradient.md): a step of beam
  // y >= 1 of input slice t, those of beam y-1 of the slice before t (its
  // output slice: t-1, or the previous frame's last slice when t starts a
  // frame streamed right after it); a step of beam 0 those of the last beam
  // of the output slice of the slice before (if it had one), with zeros
  // below; the zero beam's steps those of the zero slice's output slice's
  // last beam. Each fires with the next step (or a cycle later at a beam's
  // end) and appears kGradientStages cycles after that.
  struct SliceId {
    int frame = -1, k = 0;
  };
  SliceId prev_in;       // the previous input slice, frame -1: none since reset or a zero slice
  SliceId out, open;     // the current input slice's output slice; the slice whose last beam is due
  for (size_t i = 0; i < steps.size(); ++i) {
    const Step& st = steps[i];
    const SampleFrame& f = *frames[st.frame];
    const int B = (f.nx + p - 1) / p;
    if (!st.zero_beam && st.y == 0 && st.j == 0) out = prev_in;  // a new input slice
    SliceId g;  // the gradients' slice, frame -1: none
    int row = 0;
    if (st.zero_beam) {
      g = out;
      row = f.ny - 1;
    } else if (st.y == 0) {
      g = open;
      row = g.frame >= 0 ? frames[g.frame]->ny - 1 : 0;
    } else {
      g = out;
      row = st.y - 1;
    }
    if (g.frame >= 0) {
      const uint64_t fire = st.beam_end ? st.cycle + 1 : steps[i + 1].cycle;
      const int gny = frames[g.frame]->ny;
      s.expects.push_back({fire + kGradientStages, g.frame, g.k, row, st.j, st.j == 0, st.j == B - 1, row == 0,
                           row == gny - 1});
    }
    if (!st.zero_beam && st.y == 0 && st.beam_end) open = SliceId{};
    if (!st.zero_beam && st.y == f.ny - 1 && st.beam_end) {  // the input slice's last step
      if (st.k == f.K) {
        prev_in = SliceId{};  // the zero slice: its own zero beam ends the stream
      } else {
        open = out;
        prev_in = {st.frame, st.k};
      }
    }
  }
  s.last_output = s.expects.back().cycle;
  s.end = s.last_output + 8;
  return s;
}

// ===========================================================================
// Running a ring.

struct RunResult {
  bool ok = true;
  std::string report;
  uint64_t checked = 0, gradients_checked = 0, last_output = 0;
  uint64_t voxel_valid = 0, sample_valid = 0;
};

// vtag_bits: the rings' VoxelTagBits (0: the one-bit tag lanes stay 0).
template <class G, class I>
RunResult run(G& m, I* interp, int p, const RingParams& rp, const std::vector<const SampleFrame*>& frames,
              const Stream& s, Random& rng, int vtag_bits) {
  RunResult r;
  const int lane = vtag_bits > 0 ? vtag_bits : 1;
  cube4::rtl::reset(m);
  if (interp) cube4::rtl::reset(*interp);
  const int D = rp.dim_bits();
  auto fail = [&](uint64_t cycle, int pipe, const Expect* e, const std::string& what, const std::string& detail) {
    if (!r.ok) return;
    r.ok = false;
    r.report = mismatch_report(cycle, pipe, p, frames, e, "gradient of", what, detail);
  };
  size_t ii = 0, ei = 0;
  for (uint64_t cycle = 0; cycle < s.end; ++cycle) {
    const SampleIn* in = ii < s.in.size() && s.in[ii].cycle == cycle ? &s.in[ii] : nullptr;
    if (interp) {
      const sysc::VoxelBeat b =
          cycle < s.beats.size() ? s.beats[cycle] : junk_voxel_beat(rng, p, kVoxelBits + vtag_bits, kTagBits);
      I& v = *interp;
      drive_interp_stream(v, b, p, kVoxelBits + vtag_bits, kTagBits);
      if (b.valid) ++r.voxel_valid;
      cube4::rtl::settle(v);
      // The interpolation ring's outputs drive the gradient ring as they are.
      m.valid_i = v.valid_o;
      m.beam_start_i = v.beam_start_o;
      m.beam_end_i = v.beam_end_o;
      m.slice_start_i = v.slice_start_o;
      m.slice_end_i = v.slice_end_o;
      m.sample_i = v.sample_o;
      m.tag_i = v.tag_o;
      m.vtag_i = v.vtag_o;
      m.zdiff_i = v.zdiff_o;
      // Its timing and samples, as docs/rtl-interp.md promises (checked here
      // only to tell an interpolation fault from a gradient one).
      for (int q = 0; q < p; ++q) {
        const bool valid = get_bits(v.valid_o, q, 1);
        if (valid != (in != nullptr)) {
          fail(cycle, q, nullptr, "interpolation ring valid_o differs from its documented timing", "");
          continue;
        }
        if (!in) continue;
        const SampleFrame& f = *frames[in->frame];
        const int x = in->j * p + q;
        if (in->k < f.K && x < f.nx) {
          const uint32_t exp = f.samples[f.index(in->k, in->y, x)];
          const uint32_t got = static_cast<uint32_t>(get_bits(v.sample_o, q * kVoxelBits, kVoxelBits));
          if (exp != got)
            fail(cycle, q, nullptr, "interpolation ring sample differs",
                 "x=" + std::to_string(x) + " y=" + std::to_string(in->y) + " k=" + std::to_string(in->k) +
                     " expected " + std::to_string(exp) + " got " + std::to_string(got));
          if (voxel_z(f)) {
            const int32_t zexp = expected_zdiff(f, in->k, in->y, x);
            const auto zgot = static_cast<int32_t>(
                cube4::rtl::sign_extend(get_bits(v.zdiff_o, q * (kVoxelBits + 1), kVoxelBits + 1), kVoxelBits + 1));
            if (zexp != zgot)
              fail(cycle, q, nullptr, "interpolation ring z difference differs",
                   "x=" + std::to_string(x) + " y=" + std::to_string(in->y) + " k=" + std::to_string(in->k) +
                       " expected " + std::to_string(zexp) + " got " + std::to_string(zgot));
          }
        }
      }
    } else {
      // Direct: junk on every input while valid_i is low.
      const bool v = in != nullptr;
      for (int q = 0; q < p; ++q) {
        put_bits(m.valid_i, q, 1, v);
        put_bits(m.beam_start_i, q, 1, v ? in->beam_start : rng.chance(0.5));
        put_bits(m.beam_end_i, q, 1, v ? in->beam_end : rng.chance(0.5));
        put_bits(m.slice_start_i, q, 1, v ? in->slice_start : rng.chance(0.5));
        put_bits(m.slice_end_i, q, 1, v ? in->slice_end : rng.chance(0.5));
        put_bits(m.sample_i, q * kVoxelBits, kVoxelBits, v ? in->sample[q] : rng.bits(kVoxelBits));
        put_bits(m.tag_i, q * kTagBits, kTagBits, v ? in->tag : rng.bits(kTagBits));
        if (vtag_bits > 0) put_bits(m.vtag_i, q * lane, lane, v ? in->vtag[q] : rng.bits(lane));
        put_bits(m.zdiff_i, q * (kVoxelBits + 1), kVoxelBits + 1,
                 v ? static_cast<uint64_t>(in->zdiff[q]) & ((uint64_t{1} << (kVoxelBits + 1)) - 1)
                   : rng.bits(kVoxelBits + 1));
      }
    }
    if (in) {
      ++r.sample_valid;
      ++ii;
    }
    cube4::rtl::settle(m);

    const Expect* e = ei < s.expects.size() && s.expects[ei].cycle == cycle ? &s.expects[ei] : nullptr;
    for (int q = 0; q < p; ++q) {
      if (!output_due(get_bits(m.valid_o, q, 1), e, cycle, q, "gradient", fail)) continue;
      const SampleFrame& f = *frames[e->frame];
      const int x = e->j * p + q;
      const bool real = x < f.nx;  // else a padding column: sample 0, gradient not defined
      const size_t i = real ? f.index(e->k, e->y, x) : 0;
      const uint32_t exp_sample = real ? f.samples[i] : 0;
      const g::Gradient exp_g = real ? f.gradients[i] : g::Gradient{};
      const uint64_t exp_tag = s.plans[static_cast<size_t>(e->frame)].user_tag(e->k);
      const uint32_t sample = static_cast<uint32_t>(get_bits(m.sample_o, q * kVoxelBits, kVoxelBits));
      const g::Gradient got_g{
          static_cast<int32_t>(cube4::rtl::sign_extend(get_bits(m.gx_o, q * kGradientBits, kGradientBits), kGradientBits)),
          static_cast<int32_t>(cube4::rtl::sign_extend(get_bits(m.gy_o, q * kGradientBits, kGradientBits), kGradientBits)),
          static_cast<int32_t>(cube4::rtl::sign_extend(get_bits(m.gz_o, q * kGradientBits, kGradientBits), kGradientBits))};
      const int gx = static_cast<int>(get_bits(m.x_o, q * D, D)), gy = static_cast<int>(get_bits(m.y_o, q * D, D));
      const uint64_t tag = get_bits(m.tag_o, q * kUserTagBits, kUserTagBits);
      // The centre's voxel tag (padding columns: 0, as their samples).
      const uint32_t exp_vtag = real ? f.vtags[i] : 0;
      const auto vtag = static_cast<uint32_t>(get_bits(m.vtag_o, q * lane, lane));
      const bool bs = get_bits(m.beam_start_o, q, 1), be = get_bits(m.beam_end_o, q, 1);
      const bool ss = get_bits(m.slice_start_o, q, 1), se = get_bits(m.slice_end_o, q, 1);
      const bool same = sample == exp_sample && (!real || got_g == exp_g) && gx == x && gy == e->y &&
                        tag == exp_tag && bs == e->beam_start && be == e->beam_end && ss == e->slice_start &&
                        se == e->slice_end && vtag == exp_vtag;
      if (!same) {
        std::ostringstream d;
        d << "expected: g=(" << exp_g.x << "," << exp_g.y << "," << exp_g.z << ")" << (real ? "" : " (padding: any)")
          << " sample=" << exp_sample << " vtag=" << exp_vtag << " x=" << x << " y=" << e->y << " tag=" << exp_tag
          << " flags bs/be/ss/se=" << e->beam_start << e->beam_end << e->slice_start << e->slice_end
          << "\n  got:      g=(" << got_g.x << "," << got_g.y << "," << got_g.z << ") sample=" << sample
          << " vtag=" << vtag << " x=" << gx << " y=" << gy << " tag=" << tag << " flags bs/be/ss/se=" << bs << be << ss << se;
        fail(cycle, q, e, "output differs", d.str());
      } else {
        ++r.checked;
        if (real) ++r.gradients_checked;
      }
      if (real) r.last_output = cycle;
    }
    if (e) ++ei;
    if (interp) cube4::rtl::rise(*interp);
    cube4::rtl::rise(m);
  }
  if (ei != s.expects.size())
    fail(s.end, 0, &s.expects[ei], std::to_string(s.expects.size() - ei) + " gradients never appeared", "");
  return r;
}

// Streams the frames back to back through ring G (chain: behind ring I) and
// checks everything.
template <class G, class I>
void check_ring(const RingParams& rp, const std::vector<const SampleFrame*>& frames, const StreamOptions& opt,
                uint64_t salt, uint64_t* gradients_checked = nullptr) {
  std::string what;
  ASSERT_TRUE(frames_fit(rp, frames, what));
  for (const SampleFrame* f : frames) ASSERT_LE(f->S, (1 << kSupersamplingBits) - 1) << f->name;
  SCOPED_TRACE("p=" + std::to_string(rp.p) + (opt.chain ? ", chain" : ", direct") +
               (opt.stall > 0 ? ", stalls" : ", no stalls") + (opt.junk ? ", junk" : "") + ": " + what);
  Random rng(salt);
  const Stream s = make_stream(frames, rp.p, opt, rng);
  ASSERT_TRUE(s.error.empty()) << s.error;
  auto m = std::make_unique<G>();
  std::unique_ptr<I> interp = opt.chain ? std::make_unique<I>() : nullptr;
  const RunResult r = run(*m, interp.get(), rp.p, rp, frames, s, rng, opt.vtag_bits);
  m->final();
  if (interp) interp->final();
  EXPECT_TRUE(r.ok) << r.report;
  if (!r.ok) return;
  // Every sample of every frame has its gradient, once per pipeline column;
  // the columns x < nx equal golden.
  uint64_t expected = 0, golden = 0;
  for (const SampleFrame* f : frames) {
    expected += static_cast<uint64_t>(f->K) * f->ny * ((f->nx + rp.p - 1) / rp.p) * rp.p;
    golden += f->samples.size();
  }
  EXPECT_EQ(r.checked, expected);
  EXPECT_EQ(r.gradients_checked, golden);
  // Cycle counts: ny * B * K input samples per frame, and ny * B more for
  // the zero slice of a frame that ends a stream (chain: the same in voxel
  // cycles, and a flush beam after the zero pass), B zero-beam steps after
  // each zero slice, and the last gradient B + 4 cycles after the last
  // sample (chain: B + 8 after the last voxel).
  EXPECT_EQ(r.sample_valid, s.expected_sample_valid);
  EXPECT_EQ(s.sample_valid, s.expected_sample_valid);
  if (opt.chain) {
    EXPECT_EQ(r.voxel_valid, s.expected_voxel_valid);
    EXPECT_EQ(r.last_output, s.last_voxel + s.last_B + kInterpLatency + 1 + kGradientStages);
  }
  EXPECT_EQ(r.last_output, s.last_sample + s.last_B + 1 + kGradientStages);
  uint64_t zero_steps = 0;
  for (size_t fi = 0; fi < frames.size(); ++fi)
    if (ends_stream(s.plans, fi)) zero_steps += static_cast<uint64_t>((frames[fi]->nx + rp.p - 1) / rp.p);
  EXPECT_EQ(s.zero_steps, zero_steps);
  if (gradients_checked) *gradients_checked += golden;
}


// Every view, S = 1, 2, 3: chained without stalls, chained with stalls and
// junk, direct with random gaps and junk.
template <class G, class I>
void ring_matrix(const RingParams& rp) {
  Timer t("p=" + std::to_string(rp.p) + " matrix");
  uint64_t gradients = 0, saturated = 0;
  int runs = 0;
  // Coverage: each realign field (behind x/y, ahead x/y) with base 0 and -1.
  std::array<std::array<int, 2>, 4> bases{};
  for (size_t v = 0; v < kViews.size(); ++v)
    for (int S : {1, 2, 3}) {
      const SampleFrame& f = frame(kViews[v].name, kSizes[(v + S) % kSizes.size()], kViews[v].dir, kViews[v].up, S,
                             static_cast<int>(3 + v));
      for (int k = 0; k < f.K; ++k) {
        const g::SliceControl c = g::slice_control(f.regs, k);
        const g::Realign r[4] = {c.behind_x, c.behind_y, c.ahead_x, c.ahead_y};
        for (int i = 0; i < 4; ++i) ++bases[i][r[i].base < 0];
      }
      for (const g::Gradient& gr : f.gradients)
        for (int comp : {gr.x, gr.y, gr.z}) saturated += std::abs(comp) == (1 << (kGradientBits - 1)) - 1;
      for (int mode = 0; mode < 3; ++mode) {
        StreamOptions opt;
        opt.chain = mode < 2;
        opt.stall = mode == 0 ? 0 : 0.3;
        opt.junk = mode > 0;
        check_ring<G, I>(rp, {&f}, opt, 1000 * rp.p + 10 * v + S + 100 * mode, &gradients);
        ++runs;
        if (::testing::Test::HasFailure()) return;
      }
    }
  for (int i = 0; i < 4; ++i) {
    EXPECT_GT(bases[i][0], 0) << "realign field " << i << " never has base 0";
    EXPECT_GT(bases[i][1], 0) << "realign field " << i << " never has base -1";
  }
  std::printf("  p=%d: %d runs, %llu golden gradients matched in all (slices with base -1: behind x %d y %d, "
              "ahead x %d y %d; saturated components %llu)\n",
              rp.p, runs, static_cast<unsigned long long>(gradients), bases[0][1], bases[1][1], bases[2][1],
              bases[3][1], static_cast<unsigned long long>(saturated));
}

// Voxel tags (bela §III): every view, S = 1, 2, 3, chained (voxel words
// {tag, value} -> samples and their tags -> gradients and the centre's tag)
// without and with stalls and junk, and direct; the rings with 4-bit tags.
// Every centre's tag is golden's (the SampleProbe's tagged()).
TEST(RtlGradientRing, VoxelTagsTravelWithTheCentreSample) {
  Timer t("voxel tags");
  uint64_t gradients = 0;
  for (size_t v = 0; v < kViews.size(); ++v)
    for (int S : {1, 2, 3}) {
      const SampleFrame& f = frame(kViews[v].name, kSizes[(v + S) % kSizes.size()], kViews[v].dir, kViews[v].up, S,
                                   static_cast<int>(60 + v), kVoxelTagBits);
      // The labelling gives the samples several tags (else the test proves little).
      std::set<uint32_t> seen(f.vtags.begin(), f.vtags.end());
      EXPECT_GE(seen.size(), 3u) << f.name << ": the samples' tags hardly differ";
      for (int mode = 0; mode < 3; ++mode) {
        StreamOptions opt;
        opt.chain = mode < 2;
        opt.stall = mode == 0 ? 0 : 0.3;
        opt.junk = mode > 0;
        opt.vtag_bits = kVoxelTagBits;
        check_ring<Vcube4_gradient_ring_t4, Vcube4_interp_ring_gt4>(kRingT4, {&f}, opt, 7000 + 10 * v + S + 100 * mode,
                                                                     &gradients);
        if (::testing::Test::HasFailure()) return;
      }
    }
  std::printf("  %llu golden gradients and centre tags matched\n", static_cast<unsigned long long>(gradients));
}

// VolumePro's z gradient (z_gradient voxel_differences): the rings with
// HasZDiff and HasVoxelZ, every view, S = 1, 2, 3, chained (the stream read
// one slice ahead after its priming pass -> samples and their interpolated
// z differences -> gradients with gz from them) without and with stalls
// and junk, and direct, at p = 4 (padding columns) and p = 1. Every sample
// and z difference of the interpolation ring and every gradient is
// golden's; then frames back to back (each primed anew, some without a
// zero pass between them).
constexpr RingParams kRingZ4{4, 16}, kRingZ1{1, 24};  // rtl/groups/gradient.cmake

template <class G, class I>
uint64_t voxel_z_matrix(const RingParams& rp, int salt) {
  uint64_t gradients = 0;
  for (size_t v = 0; v < kViews.size(); ++v)
    for (int S : {1, 2, 3}) {
      const SampleFrame& f = frame(kViews[v].name, kSizes[(v + S) % kSizes.size()], kViews[v].dir, kViews[v].up, S,
                                   static_cast<int>(80 + v), 0, /*voxel_z=*/true);
      EXPECT_TRUE(voxel_z(f));
      for (int mode = 0; mode < 3; ++mode) {
        StreamOptions opt;
        opt.chain = mode < 2;
        opt.stall = mode == 0 ? 0 : 0.3;
        opt.junk = mode > 0;
        check_ring<G, I>(rp, {&f}, opt, salt + 10 * v + S + 100 * mode, &gradients);
        if (::testing::Test::HasFailure()) return gradients;
      }
    }
  return gradients;
}

TEST(RtlGradientRing, VoxelZDifferencesMatchGolden) {
  Timer t("VolumePro's z gradient");
  const uint64_t g4 = voxel_z_matrix<Vcube4_gradient_ring_z4, Vcube4_interp_ring_gz4>(kRingZ4, 9000);
  if (::testing::Test::HasFailure()) return;
  const uint64_t g1 = voxel_z_matrix<Vcube4_gradient_ring_z1, Vcube4_interp_ring_gz1>(kRingZ1, 9500);
  if (::testing::Test::HasFailure()) return;
  // The z differences must change the gradients (else the test proves little).
  const SampleFrame& abc = frame("oblique", {7, 11, 10}, {0.7, -0.6, 1}, {0, 1, 0}, 2, 95);
  const SampleFrame& vz = frame("oblique", {7, 11, 10}, {0.7, -0.6, 1}, {0, 1, 0}, 2, 95, 0, true);
  size_t differ = 0;
  for (size_t i = 0; i < abc.gradients.size(); ++i) differ += abc.gradients[i].z != vz.gradients[i].z;
  EXPECT_GT(differ, abc.gradients.size() / 4) << "the two z gradients hardly differ";
  const std::vector<const SampleFrame*> frames = {
      &frame("+z tilted", {9, 7, 6}, {0.35, -0.3, 1}, {0, 1, 0}, 2, 97, 0, true),
      &frame("+z tilted again", {9, 7, 6}, {-0.2, 0.25, 1}, {0, 1, 0}, 1, 98, 0, true),
      &frame("-y tilted", {12, 5, 8}, {-0.4, -1, -0.3}, {0, 0, 1}, 3, 99, 0, true)};
  for (int mode = 0; mode < 2; ++mode) {
    StreamOptions opt;
    opt.stall = mode ? 0.3 : 0;
    opt.junk = mode > 0;
    check_ring<Vcube4_gradient_ring_z4, Vcube4_interp_ring_gz4>(kRingZ4, frames, opt, 9900 + mode);
    check_ring<Vcube4_gradient_ring_z1, Vcube4_interp_ring_gz1>(kRingZ1, frames, opt, 9910 + mode);
  }
  std::printf("  %llu golden gradients (and their samples' z differences) matched; gz differs from the "
              "12-neighbourhood's in %zu of %zu samples of one view\n",
              static_cast<unsigned long long>(g4 + g1), differ, abc.gradients.size());
}

TEST(RtlGradientRing, P1MatchesGoldenGradients) {
  ring_matrix<Vcube4_gradient_ring_p1, Vcube4_interp_ring_g1>(kRingP1);
}
TEST(RtlGradientRing, P2MatchesGoldenGradients) {
  ring_matrix<Vcube4_gradient_ring_p2, Vcube4_interp_ring_g2>(kRingP2);
}
TEST(RtlGradientRing, P4MatchesGoldenGradients) {
  ring_matrix<Vcube4_gradient_ring, Vcube4_interp_ring_g4>(kRingP4);
}
TEST(RtlGradientRing, P5MatchesGoldenGradients) {
  ring_matrix<Vcube4_gradient_ring_p5, Vcube4_interp_ring_g5>(kRingP5);
}

// Frames back to back without a reset (different sizes, permutations and
// S: the first slice of each frame re-primes the storage), chained and
// direct, with and without stalls, every p.
TEST(RtlGradientRing, BackToBackFrames) {
  Timer t("back-to-back frames");
  const std::vector<const SampleFrame*> frames = back_to_back_frames(/*gradient=*/true);
  // Some frames follow one of their shape: a frame's first slice then
  // finishes the previous frame's last (no zero slice between them).
  for (int p : {1, 2, 4, 5}) {
    std::vector<sysc::FramePlan> plans;
    for (size_t fi = 0; fi < frames.size(); ++fi) plans.push_back(plan_of(*frames[fi], p, fi));
    int joined = 0;
    for (size_t fi = 0; fi < frames.size(); ++fi) joined += !ends_stream(plans, fi);
    EXPECT_EQ(joined, 2) << "p=" << p;
  }
  for (int mode = 0; mode < 4; ++mode) {
    StreamOptions opt;
    opt.chain = mode < 2;
    opt.stall = mode % 2 ? 0.25 : 0;
    opt.junk = mode % 2;
    check_ring<Vcube4_gradient_ring_p1, Vcube4_interp_ring_g1>(kRingP1, frames, opt, 71 + 10 * mode);
    check_ring<Vcube4_gradient_ring_p2, Vcube4_interp_ring_g2>(kRingP2, frames, opt, 72 + 10 * mode);
    check_ring<Vcube4_gradient_ring, Vcube4_interp_ring_g4>(kRingP4, frames, opt, 74 + 10 * mode);
    check_ring<Vcube4_gradient_ring_p5, Vcube4_interp_ring_g5>(kRingP5, frames, opt, 75 + 10 * mode);
  }
}

// Slices that fill the slice delay to its last entry (ny * ceil(nx/p) =
// SliceDepth) and beams that fill the beam delay (ceil(nx/p) = BeamDepth);
// tiny volumes (one beam, one partial beam, one slice).
TEST(RtlGradientRing, FullStorageAndTinyVolumes) {
  Timer t("full storage, tiny volumes");
  const FullStorageFrames full = full_storage_frames(/*gradient=*/true);
  ASSERT_FALSE(::testing::Test::HasFailure());
  const SampleFrame &f2 = *full.p2, &f5 = *full.p5, &f1 = *full.p1;
  for (int mode = 0; mode < 3; ++mode) {
    StreamOptions opt;
    opt.chain = mode < 2;
    opt.stall = mode ? 0.3 : 0;
    opt.junk = mode > 0;
    check_ring<Vcube4_gradient_ring_p2, Vcube4_interp_ring_g2>(kRingP2, {&f2}, opt, 81 + 10 * mode);
    check_ring<Vcube4_gradient_ring_p5, Vcube4_interp_ring_g5>(kRingP5, {&f5}, opt, 85 + 10 * mode);
    check_ring<Vcube4_gradient_ring_p1, Vcube4_interp_ring_g1>(kRingP1, {&f1}, opt, 82 + 10 * mode);
  }
  const std::vector<std::array<int, 3>> tiny = {{1, 1, 1}, {1, 3, 2}, {4, 1, 3}, {2, 2, 1}, {5, 1, 1}};
  for (size_t i = 0; i < tiny.size(); ++i)
    for (int S : {1, 2}) {
      const SampleFrame& f = frame("tiny +z tilted", tiny[i], {0.3, -0.4, 1}, {0, 1, 0}, S, static_cast<int>(40 + i));
      for (bool chain : {true, false}) {
        StreamOptions opt;
        opt.chain = chain;
        opt.stall = 0.2;
        opt.junk = true;
        check_ring<Vcube4_gradient_ring_p1, Vcube4_interp_ring_g1>(kRingP1, {&f}, opt, 600 + i);
        check_ring<Vcube4_gradient_ring_p2, Vcube4_interp_ring_g2>(kRingP2, {&f}, opt, 610 + i);
        check_ring<Vcube4_gradient_ring, Vcube4_interp_ring_g4>(kRingP4, {&f}, opt, 620 + i);
        check_ring<Vcube4_gradient_ring_p5, Vcube4_interp_ring_g5>(kRingP5, {&f}, opt, 630 + i);
      }
    }
}

// Random scenes: direction, volume size, S up to VolumePro's 8, gap rate
// and length; every ring, chained and direct.
TEST(RtlGradientRing, RandomScenes) {
  Timer t("random scenes");
  Random rng(0x6AD1E);
  const long n = cube4::rtl::vector_count(1000000) >= 1000000 ? 120 : 4;
  uint64_t gradients = 0;
  for (long i = 0; i < n; ++i) {
    const RandomScene sc = random_scene(rng);
    const SampleFrame& f = frame("random " + std::to_string(i), sc.size, sc.dir, sc.up, sc.S, static_cast<int>(100 + i));
    StreamOptions opt;
    opt.chain = rng.chance(0.5);
    opt.stall = rng.chance(0.5) ? 0 : static_cast<double>(rng.range(1, 60)) / 100.0;
    opt.max_gap = static_cast<int>(rng.range(1, 5));
    opt.junk = rng.chance(0.5);
    check_ring<Vcube4_gradient_ring_p1, Vcube4_interp_ring_g1>(kRingP1, {&f}, opt, 200 + i, &gradients);
    check_ring<Vcube4_gradient_ring_p2, Vcube4_interp_ring_g2>(kRingP2, {&f}, opt, 300 + i, &gradients);
    check_ring<Vcube4_gradient_ring, Vcube4_interp_ring_g4>(kRingP4, {&f}, opt, 400 + i, &gradients);
    check_ring<Vcube4_gradient_ring_p5, Vcube4_interp_ring_g5>(kRingP5, {&f}, opt, 500 + i, &gradients);
    if (::testing::Test::HasFailure()) return;
  }
  std::printf("  %ld random scenes, each through p = 1, 2, 4, 5: %llu golden gradients matched\n", n,
              static_cast<unsigned long long>(gradients));
}

// A larger volume through the default chain (p = 4, 256^3 storage).
TEST(RtlGradientRing, LargerVolumeP4) {
  Timer t("larger volume, p=4");
  for (int S : {1, 4}) {
    const SampleFrame& f = frame("oblique", {37, 30, 14}, {0.55, 0.4, -1}, {0, 1, 0}, S, 41);
    StreamOptions opt;
    opt.stall = 0.1;
    check_ring<Vcube4_gradient_ring, Vcube4_interp_ring_g4>(kRingP4, {&f}, opt, 90 + S);
  }
}

}  // namespace
