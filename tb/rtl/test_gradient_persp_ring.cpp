// RTL equivalence tests of the perspective gradient ring,
// cube4_gradient_persp_ring, against golden perspective_gradient()
// (golden/perspective.hpp) at the schedule golden gradient_cell() gives:
// random cameras (random registers as the host makes them, and the cameras
// of random perspective scenes), streamed as the system streams frames
// (pass after pass, one or two frames back to back, the zero pass and six
// flush beams at the end) with random idle cycles, each sample arriving on
// the lane and in the step that the interpolation ring forms it
// (formed_cell()). The samples are random (the ring never looks at how
// they were made): smooth fields, where the gradients are small and
// rounding matters, and noise, where they saturate. Every ray of every
// slice must leave exactly once, with golden's gradient, its own sample,
// voxel tag, ray and pass tag, on the lane and in the cycle the schedule
// says: gradient_forming_position()'s step, 3 cycles after it
// (docs/rtl-gradient-persp.md). The HasVoxelZ variant (VolumePro's z
// gradient) takes each sample's filtered voxel z difference beside it
// (random, signed) and must give golden perspective_gradient_voxel_z().
//
// CUBE4_RTL_VECTORS overrides the gradient count per ring (default 1,000,000).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "Vcube4_gradient_persp_ring.h"
#include "Vcube4_gradient_persp_ring_p1.h"
#include "Vcube4_gradient_persp_ring_p5.h"
#include "Vcube4_gradient_persp_ring_p8.h"
#include "Vcube4_gradient_persp_ring_t4.h"
#include "Vcube4_gradient_persp_ring_vz.h"
#include "Vcube4_gradient_persp_ring_vz_p5.h"
#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "tb/rtl/persp_registers.hpp"
#include "tb/rtl/persp_ring_stream.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;

constexpr int kV = 12, kF = 20, kPos = 48, kRay = 16, kTag = 8, kG = 8;
constexpr int kMaxDim = 24;  // rtl/groups/gradient_persp.cmake

uint64_t word(int64_t v, int bits) { return static_cast<uint64_t>(v) & ((uint64_t{1} << bits) - 1); }

// The samples of one frame's slices, by ray, with their voxel tags.
class FrameSamples {
 public:
  FrameSamples(const std::vector<g::PerspectiveSlice>& slices, rtl::Random& rng, int vtag_bits) : slices_(slices) {
    // Smooth: a plane plus a little noise (small gradients, rounding);
    // noisy: edgy random values (saturation).
    const bool smooth = rng.chance(0.5);
    const int64_t a = rng.range(-40, 40), b = rng.range(-40, 40), c = rng.range(-60, 60), base = rng.range(0, 4095);
    for (const g::PerspectiveSlice& s : slices) {
      std::vector<uint32_t>& value = values_.emplace_back();
      std::vector<uint32_t>& tag = tags_.emplace_back();
      std::vector<int32_t>& zdiff = zdiffs_.emplace_back();
      for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
        for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
          const int64_t x = smooth ? base + a * u + b * v + c * s.k + rng.range(-3, 3)
                                   : rng.edgy((1 << kV) - 1, 0.2);
          value.push_back(static_cast<uint32_t>(std::clamp<int64_t>(x, 0, (1 << kV) - 1)));
          tag.push_back(vtag_bits > 0 ? static_cast<uint32_t>(rng.bits(vtag_bits)) : 0u);
          // A filtered voxel z difference: signed V + 1 bits, extremes often.
          const int64_t vmax = (1 << kV) - 1;
          zdiff.push_back(static_cast<int32_t>(smooth ? std::clamp<int64_t>(c * 8 + rng.range(-20, 20), -vmax, vmax)
                                                      : rng.edgy(2 * vmax, 0.2) - vmax));
        }
    }
  }
  // 0 for rays that miss the slice, or slices the frame does not have.
  uint32_t sample(int k, int64_t u, int64_t v) const { return at(values_, k, u, v); }
  uint32_t vtag(int k, int64_t u, int64_t v) const { return at(tags_, k, u, v); }
  int32_t zdiff(int k, int64_t u, int64_t v) const { return at(zdiffs_, k, u, v); }

 private:
  template <class T>
  T at(const std::vector<std::vector<T>>& t, int k, int64_t u, int64_t v) const {
    if (k < 0 || k >= static_cast<int>(slices_.size())) return 0;
    const g::PerspectiveSlice& s = slices_[static_cast<size_t>(k)];
    if (!g::samples(s, u, v)) return 0;
    const int64_t w = s.rays_x.hi - s.rays_x.lo;
    return t[static_cast<size_t>(k)][static_cast<size_t>((v - s.rays_y.lo) * w + (u - s.rays_x.lo))];
  }
  const std::vector<g::PerspectiveSlice>& slices_;
  std::vector<std::vector<uint32_t>> values_, tags_;
  std::vector<std::vector<int32_t>> zdiffs_;
};

struct Expect {
  int pass = 0;  // in the stream: the pass tag
  int64_t u = 0, v = 0;
  g::Gradient grad;
  uint32_t sample = 0, vtag = 0;
  bool seen = false;
};

// Streams `frames` frames of registers r through ring m with random samples,
// checking every gradient. Returns the gradients checked. `voxel_z`: the
// ring has HasVoxelZ (z from each sample's z difference).
template <class M>
long stream_frames(M& m, int p, const g::Registers& r, int frames, int vtag_bits, rtl::Random& rng, rtl::Checker& c,
                   uint64_t& cycle, bool voxel_z = false) {
  const int K = r.sample_slices(), nx = r.dim[0], ny = r.dim[1];
  const int B = (nx + p - 1) / p;
  const int64_t row = int64_t{B} * p;
  const int passes = frames * K;  // then the zero pass
  std::vector<g::PerspectiveSlice> slices;
  for (int k = 0; k < K; ++k) slices.push_back(g::perspective_slice(r, k));
  std::vector<FrameSamples> samples;
  for (int f = 0; f < frames; ++f) samples.emplace_back(slices, rng, vtag_bits);

  // Golden: every ray's gradient, by the step and lane that form it.
  std::map<int64_t, std::map<int, Expect>> want;
  for (int f = 0; f < frames; ++f)
    for (int k = 0; k < K; ++k) {
      const g::PerspectiveSlice& s = slices[static_cast<size_t>(k)];
      const FrameSamples& fs = samples[static_cast<size_t>(f)];
      auto from = [&](int slice) { return [&fs, slice](int64_t u, int64_t v) { return fs.sample(slice, u, v); }; };
      for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
        for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
          const int64_t X = g::home_cell(g::ray_position(s.ray0_x, s.spacing, u), kF);
          const int64_t Y = g::home_cell(g::ray_position(s.ray0_y, s.spacing, v), kF);
          const int64_t pos = g::gradient_forming_position(int64_t{f} * K + k, X, Y, row, ny);
          Expect& e = want[pos / p][static_cast<int>(pos % p)];
          const g::Gradient grad =
              voxel_z ? g::perspective_gradient_voxel_z(r, s, u, v, from(k), fs.zdiff(k, u, v))
                      : g::perspective_gradient(r, s, u, v, from(k), from(k - 1), from(k + 1));
          e = {f * K + k, u, v, grad, fs.sample(k, u, v), fs.vtag(k, u, v), false};
        }
    }

  long checked = 0;
  rtl::DueLanes<Expect> due(want, 3);
  auto observe = [&] {
    const int64_t step = due.take(cycle);
    for (int lane = 0; lane < p; ++lane) {
      const bool valid = rtl::get_bits(m.valid_o, lane, 1) != 0;
      Expect* e = due.lane(lane);
      const rtl::Fields where{{"step", step}, {"lane", lane}, {"nx", nx}, {"ny", ny}, {"nz", r.dim[2]},
                              {"S", r.supersampling}, {"frames", frames}};
      if (valid != (e != nullptr)) {
        c.check(cycle, where, {{"valid", e != nullptr}}, {{"valid", valid}});
        continue;
      }
      if (!e) continue;
      e->seen = true;
      auto bits = [&](const auto& port, int width) { return rtl::get_bits(port, lane * width, width); };
      c.check(cycle, where,
              {{"pass", e->pass}, {"u", e->u}, {"v", e->v}, {"gx", e->grad.x}, {"gy", e->grad.y}, {"gz", e->grad.z},
               {"sample", e->sample}, {"vtag", e->vtag}},
              {{"pass", static_cast<int64_t>(bits(m.tag_o, kTag))},
               {"u", rtl::sign_extend(bits(m.ray_u_o, kRay), kRay)},
               {"v", rtl::sign_extend(bits(m.ray_v_o, kRay), kRay)},
               {"gx", rtl::sign_extend(bits(m.gx_o, kG), kG)},
               {"gy", rtl::sign_extend(bits(m.gy_o, kG), kG)},
               {"gz", rtl::sign_extend(bits(m.gz_o, kG), kG)},
               {"sample", static_cast<int64_t>(bits(m.sample_o, kV))},
               {"vtag", vtag_bits > 0 ? static_cast<int64_t>(bits(m.vtag_o, vtag_bits)) : 0}});
      ++checked;
    }
  };
  auto clock = [&] {
    rtl::settle(m);
    rtl::rise(m);
    ++cycle;
    rtl::settle(m);
    observe();
  };
  // A pass's constants at its first step, random words elsewhere: the
  // common ones and the realignment DDAs and lateral reciprocal.
  auto drive_constants = [&](const g::PerspectiveSlice* s, int pass, bool zero) {
    rtl::drive_persp_pass_constants(m, s, pass, zero, K, rng, kTag);
    auto pos = [&](int64_t v) { return word(s ? v : static_cast<int64_t>(rng.bits(kPos)), kPos); };
    const g::PerspectiveSlice none;
    const g::PerspectiveSlice& q = s ? *s : none;
    m.behind_start_x_i = pos(q.behind_x.start);
    m.behind_start_y_i = pos(q.behind_y.start);
    m.behind_step_i = pos(q.behind_x.step);
    m.ahead_start_x_i = pos(q.ahead_x.start);
    m.ahead_start_y_i = pos(q.ahead_y.start);
    m.ahead_step_i = pos(q.ahead_x.step);
    m.lateral_recip_i = static_cast<uint32_t>(s ? q.lateral_reciprocal : static_cast<int64_t>(rng.bits(kV + 3)));
  };
  m.supersampling_i = static_cast<uint8_t>(r.supersampling);

  rtl::stream_persp_passes(
      m, slices, passes, ny, B, p, rng,
      [&](const rtl::PerspStep& st) {
        drive_constants(st.slice, st.pass, st.zero);
        uint32_t valid = 0;
        for (int lane = 0; lane < p; ++lane) {
          const g::FormedCell fc = g::formed_cell(st.step * p + lane, row, nx, ny);
          uint32_t value = static_cast<uint32_t>(rng.bits(kV)),
                   tag = static_cast<uint32_t>(rng.bits(vtag_bits ? vtag_bits : 1));
          uint64_t zdiff = rng.bits(kV + 1);
          if (const rtl::HomedRay h = rtl::ray_homed_at(slices, fc, passes, kF, r.p.weight_bits); h.valid) {
            const FrameSamples& fs = samples[static_cast<size_t>(fc.pass / K)];
            valid |= 1u << lane;
            value = fs.sample(h.k, h.u, h.v);
            tag = fs.vtag(h.k, h.u, h.v);
            zdiff = word(fs.zdiff(h.k, h.u, h.v), kV + 1);
          }
          rtl::put_bits(m.zdiff_i, lane * (kV + 1), kV + 1, zdiff);  // ignored without HasVoxelZ
          rtl::put_bits(m.sample_i, lane * kV, kV, value);
          const int tb = vtag_bits > 0 ? vtag_bits : 1;
          rtl::put_bits(m.vtag_i, lane * tb, tb, tag);
        }
        m.sample_valid_i = valid;
        due.driven(cycle, st.step);
      },
      clock, [&] { return c.ok(); });
  m.valid_i = 0;
  for (int i = 0; i < 4; ++i) clock();
  due.check_every_ray_left(c, cycle);
  return checked;
}

// vtag_bits: the model's VoxelTagBits (0: none); voxel_z: its HasVoxelZ.
template <class M>
void test_ring(int p, uint64_t salt, int vtag_bits = 0, bool voxel_z = false) {
  rtl::Random rng(salt);
  const auto dut = rtl::make_dut<M>();
  M& m = *dut;
  rtl::reset(m);
  const std::string name =
      "cube4_gradient_persp_ring p=" + std::to_string(p) + (vtag_bits ? " tags" : "") + (voxel_z ? " HasVoxelZ" : "");
  rtl::Checker c(name);
  const long n = rtl::vector_count(1000000);
  rtl::Timer t(name + ": " + std::to_string(n) + " gradients");
  uint64_t cycle = 0;
  long gradients = 0;
  int frames_run = 0;
  std::array<long, 4> faces{};
  while (gradients < n && c.ok()) {
    const g::Registers r = rtl::ring_registers(rng, kF, {7, 7}, kMaxDim);
    // The ring's preconditions: ny >= 6, a beam of at least seven positions.
    if (r.dim[1] < 6 || r.dim[0] < 7 || r.dim[0] > kMaxDim || r.dim[1] > kMaxDim) continue;
    const int frames = rng.chance(0.3) ? 2 : 1;
    if (frames * r.sample_slices() + 1 > (1 << kTag) - 1) continue;
    gradients += stream_frames(m, p, r, frames, vtag_bits, rng, c, cycle, voxel_z);
    const std::array<long, 4> leaving = rtl::rays_leaving(r);
    for (size_t f = 0; f < 4; ++f) faces[f] += leaving[f];
    ++frames_run;
  }
  EXPECT_TRUE(c.ok()) << c.report();
  // Rays left the volume through every side face in these streams (their
  // neighbours and realigned points miss the slices beyond).
  for (size_t f = 0; f < 4; ++f) EXPECT_GT(faces[f], 0) << "no ray left through side face " << f;
  std::printf("  [%s: %d streams; rays leaving through x-, x+, y-, y+: %ld %ld %ld %ld]\n", name.c_str(),
              frames_run, faces[0], faces[1], faces[2], faces[3]);
}

// The directed cases (tb/rtl/persp_registers.hpp): box extents exactly 1,
// 2 and 3, rays leaving through each side face, spreading rays; one frame
// each and two back to back.
template <class M>
void test_directed(int p, bool voxel_z = false) {
  rtl::Random rng(8);
  const auto dut = rtl::make_dut<M>();
  rtl::reset(*dut);
  rtl::Checker c("cube4_gradient_persp_ring p=" + std::to_string(p) + " (directed)");
  uint64_t cycle = 0;
  EXPECT_EQ(rtl::stream_directed_cases(
                kF, c,
                [&](const rtl::DirectedCase& d, int frames) {
                  return stream_frames(*dut, p, d.r, frames, 0, rng, c, cycle, voxel_z);
                }),
            "");
}

TEST(RtlGradientPerspRing, DirectedCasesAtP4) { test_directed<Vcube4_gradient_persp_ring>(4); }
TEST(RtlGradientPerspRing, DirectedCasesAtP5) { test_directed<Vcube4_gradient_persp_ring_p5>(5); }

TEST(RtlGradientPerspRing, EveryRaysGradientLeavesOnceAsGoldensWhereTheScheduleSaysAtP4) {
  test_ring<Vcube4_gradient_persp_ring>(4, 81);
}
TEST(RtlGradientPerspRing, EveryRaysGradientLeavesOnceAsGoldensWhereTheScheduleSaysAtP1) {
  test_ring<Vcube4_gradient_persp_ring_p1>(1, 82);
}
TEST(RtlGradientPerspRing, EveryRaysGradientLeavesOnceAsGoldensWhereTheScheduleSaysAtP5) {
  test_ring<Vcube4_gradient_persp_ring_p5>(5, 83);
}
TEST(RtlGradientPerspRing, EveryRaysGradientLeavesOnceAsGoldensWhereTheScheduleSaysAtP8) {
  test_ring<Vcube4_gradient_persp_ring_p8>(8, 84);
}
// VolumePro's z gradient (HasVoxelZ): z from each ray's own z difference.
TEST(RtlGradientPerspRing, EveryRaysGradientLeavesOnceAsGoldensWithVoxelZAtP4) {
  test_ring<Vcube4_gradient_persp_ring_vz>(4, 86, 0, true);
}
TEST(RtlGradientPerspRing, EveryRaysGradientLeavesOnceAsGoldensWithVoxelZAtP5) {
  test_ring<Vcube4_gradient_persp_ring_vz_p5>(5, 87, 0, true);
}
TEST(RtlGradientPerspRing, DirectedCasesAtP4WithVoxelZ) { test_directed<Vcube4_gradient_persp_ring_vz>(4, true); }
TEST(RtlGradientPerspRing, VoxelTagsLeaveWithTheirRaysGradients) {
  test_ring<Vcube4_gradient_persp_ring_t4>(4, 85, 4);
}

}  // namespace
