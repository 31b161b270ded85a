// RTL equivalence tests of the perspective interpolation ring,
// cube4_interp_persp_ring, against golden perspective_sample()
// (golden/perspective.hpp): random volumes and cameras (random registers as
// the host makes them, and the cameras of random perspective scenes),
// streamed as the system streams a frame (pass after pass, three flush
// beams at the end; sometimes two frames back to back), with random idle cycles.
// Every ray of every slice must leave exactly once, with golden's sample,
// on the lane and in the cycle the dataflow says: the stream position two
// columns after its home in the beam two after its home row, 4 cycles
// after that step (docs/rtl-interp-persp.md). With VolumePro's z gradient
// (HasZDiff) each frame starts with a priming pass, the stream reads a
// voxel slice ahead, and every sample's z difference is checked against
// golden perspective_z_difference() too.
//
// CUBE4_RTL_VECTORS overrides the sample count per ring (default 300,000).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "Vcube4_interp_persp_ring.h"
#include "Vcube4_interp_persp_ring_p1.h"
#include "Vcube4_interp_persp_ring_p5.h"
#include "Vcube4_interp_persp_ring_p8.h"
#include "Vcube4_interp_persp_ring_m128.h"
#include "Vcube4_interp_persp_ring_t4.h"
#include "Vcube4_interp_persp_ring_zdiff.h"
#include "Vcube4_interp_persp_ring_zdiff_p5.h"
#include "golden/errors.hpp"
#include "golden/host_driver.hpp"
#include "golden/perspective.hpp"
#include "golden/permuted_volume.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/scene_io.hpp"
#include "golden/units/gradient.hpp"
#include "golden/volume_io.hpp"
#include "tb/rtl/persp_registers.hpp"
#include "tb/rtl/rtl_check.hpp"
#include "tb/rtl/voxel_grid.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;

constexpr int kV = 12, kF = 20, kPos = 48, kRay = 16, kTag = 8;
constexpr int kMaxDim = 24;  // rtl/groups/interp_persp.cmake

uint64_t word(int64_t v, int bits) { return static_cast<uint64_t>(v) & ((uint64_t{1} << bits) - 1); }

using Volume = rtl::VoxelGrid;

struct Want {
  uint32_t sample = 0, vtag = 0;
  int32_t zdiff = 0;
  int lane = 0;
  uint64_t cycle = 0;
  bool seen = false;
};

// Streams `frames` frames of registers r over the volume (values, and the
// tags in the words' upper bits) through ring m, checking every sample
// against golden: its value, tag, lane and cycle, each ray once. Returns
// the samples checked. `zdiff`: the ring has HasZDiff (VolumePro's z
// gradient: a priming pass per frame, the stream a slice ahead).
template <class M>
long stream_frames(M& m, int p, const g::Registers& r, const Volume& vol, const Volume& tags, int frames, int vtag_bits,
                   rtl::Random& rng, rtl::Checker& c, uint64_t& cycle, bool zdiff = false) {
  const int K = r.sample_slices();
  const int primed = zdiff ? 1 : 0;  // each frame's priming pass
  long samples = 0;
  const int B = (vol.nx + p - 1) / p;
  const int64_t Bp = int64_t{B} * p;

  std::vector<g::PerspectiveSlice> slices;
  for (int k = 0; k < K; ++k) slices.push_back(g::perspective_slice(r, k));
  // Golden: every ray of every slice of every frame, by (tag, u, v); its
  // lane and the index of the step that forms it.
  std::map<std::tuple<int, int64_t, int64_t>, Want> want;
  std::vector<std::pair<std::tuple<int, int64_t, int64_t>, int64_t>> forming;  // key, step index
  for (int f = 0; f < frames; ++f)
    for (int k = 0; k < K; ++k) {
      const g::PerspectiveSlice& s = slices[static_cast<size_t>(k)];
      auto voxel = [&](int x, int y, int dz) { return vol.at(x, y, s.z_voxel + dz); };
      auto difference = [&](int x, int y, int dz) {
        const int z = s.z_voxel + dz;
        return g::voxel_z_difference(vol.at(x, y, z + 1), vol.at(x, y, z - 1));
      };
      for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
        for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
          const int64_t hx = g::home_cell(g::ray_position(s.ray0_x, s.spacing, u), kF);
          const int64_t hy = g::home_cell(g::ray_position(s.ray0_y, s.spacing, v), kF);
          const int64_t pos = g::forming_position(int64_t{f} * (K + primed) + primed + k, hx, hy, Bp, vol.ny);
          const auto key = std::make_tuple(f * K + k, u, v);
          const g::TagVoxel t = g::perspective_tag_voxel(r, s, u, v);
          const uint32_t vtag = tags.at(t.x, t.y, s.z_voxel + t.dz);
          const int32_t zd = zdiff ? g::perspective_z_difference(r, s, u, v, difference) : 0;
          want[key] = {g::perspective_sample(r, s, u, v, voxel), vtag, zd, static_cast<int>(pos % p), 0, false};
          forming.push_back({key, pos / p});
        }
    }

  // The stream, recording each step's cycle.
  std::vector<uint64_t> step_cycle;
  auto observe = [&] {
    for (int lane = 0; lane < p; ++lane) {
      if (!rtl::get_bits(m.valid_o, lane, 1)) continue;
      const int tag = static_cast<int>(rtl::get_bits(m.tag_o, lane * kTag, kTag));
      const int64_t u = rtl::sign_extend(rtl::get_bits(m.ray_u_o, lane * kRay, kRay), kRay);
      const int64_t v = rtl::sign_extend(rtl::get_bits(m.ray_v_o, lane * kRay, kRay), kRay);
      const int64_t got = static_cast<int64_t>(rtl::get_bits(m.sample_o, lane * kV, kV));
      const auto it = want.find(std::make_tuple(tag, u, v));
      const rtl::Fields where{{"frame pass", tag}, {"u", u}, {"v", v}, {"lane", lane}, {"nx", vol.nx},
                              {"ny", vol.ny}, {"nz", vol.nz}, {"S", r.supersampling}};
      if (it == want.end() || it->second.seen) {
        c.check(cycle, where, {{"expected", 0}}, {{"sample out", 1}});
        continue;
      }
      it->second.seen = true;
      const int64_t got_vtag =
          vtag_bits > 0 ? static_cast<int64_t>(rtl::get_bits(m.vtag_o, lane * vtag_bits, vtag_bits)) : 0;
      const int64_t got_zdiff = rtl::sign_extend(rtl::get_bits(m.zdiff_o, lane * (kV + 1), kV + 1), kV + 1);
      c.check(cycle, where,
              {{"sample", it->second.sample}, {"vtag", it->second.vtag}, {"z difference", it->second.zdiff},
               {"lane", it->second.lane}, {"cycle", static_cast<int64_t>(it->second.cycle)}},
              {{"sample", got}, {"vtag", got_vtag}, {"z difference", got_zdiff}, {"lane", lane},
               {"cycle", static_cast<int64_t>(cycle)}});
      ++samples;
    }
  };
  auto clock = [&] {
    rtl::settle(m);
    rtl::rise(m);
    ++cycle;
    rtl::settle(m);
    observe();
  };
  // The forming steps' cycles are known once the step is driven; the
  // check of a sample needs them before it leaves (4 cycles later).
  size_t next_forming = 0;
  auto note_cycles = [&] {
    while (next_forming < forming.size() &&
           static_cast<size_t>(forming[next_forming].second) < step_cycle.size()) {
      want[forming[next_forming].first].cycle = step_cycle[static_cast<size_t>(forming[next_forming].second)] + 4;
      ++next_forming;
    }
  };
  std::sort(forming.begin(), forming.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  // The stream's passes (with zdiff each frame's priming pass first), then
  // the flush beams.
  const int per_frame = K + primed, passes = frames * per_frame;
  for (int pass = 0; pass <= passes && c.ok(); ++pass) {
    const bool flush = pass == passes;
    const bool prime = !flush && pass % per_frame < primed;
    const int k = flush || prime ? 0 : pass % per_frame - primed;
    const int frame_pass = pass / per_frame * K + k;  // the samples' tag
    const g::PerspectiveSlice& s = slices[static_cast<size_t>(k)];
    const int z_in = prime ? 0 : (s.wz == 0 ? s.z_voxel : s.z_voxel + 1) + primed;
    for (int b = 0; b < (flush ? 3 : vol.ny) && c.ok(); ++b)
      for (int j = 0; j < B && c.ok(); ++j) {
        while (rng.chance(0.15)) {
          m.valid_i = 0;
          clock();
        }
        m.valid_i = 1;
        m.beam_start_i = j == 0;
        m.beam_end_i = j == B - 1;
        m.slice_start_i = !flush && b == 0;
        m.slice_end_i = !flush && b == vol.ny - 1;
        m.flush_i = flush;
        m.prime_i = prime;
        const int word_bits = kV + vtag_bits;
        for (int lane = 0; lane < p; ++lane) {
          const int x = j * p + lane;
          rtl::put_bits(m.voxels_i, lane * word_bits, word_bits,
                        flush ? rng.bits(word_bits) : vol.at(x, b, z_in) | tags.at(x, b, z_in) << kV);
        }
        m.wz_i = static_cast<uint16_t>(flush ? rng.bits(9) : prime ? 0 : s.wz);
        m.tag_i = static_cast<uint8_t>(flush || prime ? rng.bits(kTag) : frame_pass);
        m.spacing_i = word(flush ? static_cast<int64_t>(rng.bits(kPos)) : s.spacing, kPos);
        m.ray0_x_i = word(flush ? static_cast<int64_t>(rng.bits(kPos)) : s.ray0_x, kPos);
        m.ray0_y_i = word(s.ray0_y, kPos);
        // The priming pass has no rays (the system gives it the zero pass's constants).
        m.rays_x_lo_i = static_cast<uint16_t>(prime ? 0 : word(s.rays_x.lo, kRay));
        m.rays_x_hi_i = static_cast<uint16_t>(prime ? 0 : word(s.rays_x.hi, kRay));
        m.rays_y_lo_i = static_cast<uint16_t>(prime ? 0 : word(s.rays_y.lo, kRay));
        m.rays_y_hi_i = static_cast<uint16_t>(prime ? 0 : word(s.rays_y.hi, kRay));
        m.recip_i = static_cast<uint32_t>(flush ? rng.bits(kV + 6) : s.box_reciprocal);
        step_cycle.push_back(cycle);  // the cycle it is driven in
        note_cycles();
        clock();
      }
  }
  m.valid_i = 0;
  for (int i = 0; i < 6; ++i) clock();
  for (const auto& [key, w] : want)
    if (!w.seen && c.ok()) {
      const g::PerspectiveSlice& s = slices[static_cast<size_t>(std::get<0>(key) % K)];
      c.check(cycle,
              {{"frame pass", std::get<0>(key)}, {"passes", frames * K}, {"u", std::get<1>(key)},
               {"v", std::get<2>(key)}, {"nx", vol.nx}, {"ny", vol.ny}, {"p", p},
               {"home x", g::home_cell(g::ray_position(s.ray0_x, s.spacing, std::get<1>(key)), kF)},
               {"home y", g::home_cell(g::ray_position(s.ray0_y, s.spacing, std::get<2>(key)), kF)},
               {"due in cycle", static_cast<int64_t>(w.cycle)}},
              {{"left", 1}}, {{"left", 0}});
    }
  return samples;
}

// vtag_bits: the model's VoxelTagBits (0: none); zdiff: its HasZDiff.
template <class M>
void test_ring(int p, uint64_t salt, int vtag_bits = 0, bool zdiff = false) {
  rtl::Random rng(salt);
  const auto dut = rtl::make_dut<M>();
  M& m = *dut;
  rtl::reset(m);
  const std::string name = "cube4_interp_persp_ring p=" + std::to_string(p) + (zdiff ? " (HasZDiff)" : "");
  rtl::Checker c(name);
  const long n = rtl::vector_count(300000);
  rtl::Timer t(name + ": " + std::to_string(n) + " samples");
  uint64_t cycle = 0;
  long samples = 0;
  int frames_run = 0;
  std::array<long, 4> faces{};
  while (samples < n && c.ok()) {
    const g::Registers r = rtl::ring_registers(rng, kF, {1, 2}, kMaxDim);
    if (r.dim[1] < 2 || r.dim[0] > kMaxDim || r.dim[1] > kMaxDim) continue;
    const int K = r.sample_slices();
    const int frames = rng.chance(0.3) ? 2 : 1;
    if (frames * K > 255 || (zdiff && r.dim[1] < 2)) continue;
    Volume vol;
    vol.resize(r.dim[0], r.dim[1], r.dim[2]);
    for (uint32_t& x : vol.v) x = static_cast<uint32_t>(rng.edgy((1 << kV) - 1, 0.1));
    Volume tags;  // the voxels' tags, the memory words' upper bits
    tags.resize(r.dim[0], r.dim[1], r.dim[2]);
    if (vtag_bits > 0)
      for (uint32_t& x : tags.v) x = static_cast<uint32_t>(rng.bits(vtag_bits));
    samples += stream_frames(m, p, r, vol, tags, frames, vtag_bits, rng, c, cycle, zdiff);
    const std::array<long, 4> leaving = rtl::rays_leaving(r);
    for (size_t f = 0; f < 4; ++f) faces[f] += leaving[f];
    ++frames_run;
  }
  EXPECT_TRUE(c.ok()) << c.report();
  // Rays left the volume through every side face in these streams.
  for (size_t f = 0; f < 4; ++f) EXPECT_GT(faces[f], 0) << "no ray left through side face " << f;
  std::printf("  %d streams, %ld samples; rays leaving through x-, x+, y-, y+: %ld %ld %ld %ld\n", frames_run, samples,
              faces[0], faces[1], faces[2], faces[3]);
}

// The directed cases (tb/rtl/persp_registers.hpp): box extents exactly 1,
// 2 and 3, rays leaving through each side face, spreading rays; one frame
// each and two back to back.
template <class M>
void test_directed(int p, bool zdiff = false) {
  rtl::Random rng(7);
  const auto dut = rtl::make_dut<M>();
  rtl::reset(*dut);
  rtl::Checker c("cube4_interp_persp_ring p=" + std::to_string(p) + " (directed)");
  uint64_t cycle = 0;
  EXPECT_EQ(rtl::stream_directed_cases(kF, c,
                                       [&](const rtl::DirectedCase& d, int frames) {
                                         Volume vol, tags;
                                         vol.resize(d.r.dim[0], d.r.dim[1], d.r.dim[2]);
                                         tags.resize(d.r.dim[0], d.r.dim[1], d.r.dim[2]);
                                         for (uint32_t& x : vol.v)
                                           x = static_cast<uint32_t>(rng.edgy((1 << kV) - 1, 0.1));
                                         return stream_frames(*dut, p, d.r, vol, tags, frames, 0, rng, c, cycle,
                                                              zdiff);
                                       }),
            "");
}

TEST(RtlInterpPerspRing, DirectedCasesAtP4) { test_directed<Vcube4_interp_persp_ring>(4); }
TEST(RtlInterpPerspRing, DirectedCasesAtP5) { test_directed<Vcube4_interp_persp_ring_p5>(5); }

TEST(RtlInterpPerspRing, EveryRayLeavesOnceWithGoldensSampleWhereTheDataflowSaysAtP4) {
  test_ring<Vcube4_interp_persp_ring>(4, 91);
}
TEST(RtlInterpPerspRing, EveryRayLeavesOnceWithGoldensSampleWhereTheDataflowSaysAtP1) {
  test_ring<Vcube4_interp_persp_ring_p1>(1, 92);
}
TEST(RtlInterpPerspRing, EveryRayLeavesOnceWithGoldensSampleWhereTheDataflowSaysAtP5) {
  test_ring<Vcube4_interp_persp_ring_p5>(5, 93);
}
TEST(RtlInterpPerspRing, EveryRayLeavesOnceWithGoldensSampleWhereTheDataflowSaysAtP8) {
  test_ring<Vcube4_interp_persp_ring_p8>(8, 94);
}
// VolumePro's z gradient (HasZDiff): every sample's filtered voxel z
// difference too, the stream primed each frame and a slice ahead.
TEST(RtlInterpPerspRing, EveryRayLeavesOnceWithGoldensSampleAndZDifferenceAtP4WithHasZDiff) {
  test_ring<Vcube4_interp_persp_ring_zdiff>(4, 97, 0, true);
}
TEST(RtlInterpPerspRing, EveryRayLeavesOnceWithGoldensSampleAndZDifferenceAtP5WithHasZDiff) {
  test_ring<Vcube4_interp_persp_ring_zdiff_p5>(5, 98, 0, true);
}
TEST(RtlInterpPerspRing, DirectedCasesAtP4WithHasZDiff) { test_directed<Vcube4_interp_persp_ring_zdiff>(4, true); }
// With 4-bit voxel tags (bela §III): each sample's tag is its nearest voxel's.
TEST(RtlInterpPerspRing, EveryRayLeavesOnceWithGoldensSampleAndTagAtP4WithVoxelTags) {
  test_ring<Vcube4_interp_persp_ring_t4>(4, 95, 4);
}

// The MRI head (VolPack's brainsmall, 128 x 128 x 84) in perspective, a
// ring as large as the volume (MaxDim 128, p = 4): real data, a whole
// frame, every sample and cycle checked as above.
TEST(RtlInterpPerspRing, BrainsmallInPerspectiveAtP4) {
  if (!std::filesystem::exists(CUBE4_BRAINSMALL)) GTEST_SKIP() << "brainsmall.den not installed (libvolpack1-dev)";
  const g::Scene s = g::parse_scene(R"({"volume": {"file": ")" CUBE4_BRAINSMALL R"("},
      "view": {"projection": "perspective", "fov": 40, "rotate": [20, 30, 0]}})", "brainsmall.json");
  const g::Volume head = g::load_volume(s.volume, s.precision.voxel_bits, ".");
  const g::Registers r = g::program_host(s, head).regs;
  ASSERT_TRUE(r.perspective);
  Volume vol, tags;
  vol.resize(r.dim[0], r.dim[1], r.dim[2]);
  tags.resize(r.dim[0], r.dim[1], r.dim[2]);
  const g::PermutedVolume pv(head, r.perm, r.flip);
  for (int z = 0; z < vol.nz; ++z)
    for (int y = 0; y < vol.ny; ++y) pv.load_beam(y, z, &vol.v[(static_cast<size_t>(z) * vol.ny + y) * vol.nx]);
  rtl::Random rng(96);
  const auto dut = rtl::make_dut<Vcube4_interp_persp_ring_m128>();
  rtl::reset(*dut);
  rtl::Checker c("cube4_interp_persp_ring brainsmall");
  rtl::Timer t("cube4_interp_persp_ring: brainsmall in perspective");
  uint64_t cycle = 0;
  const long samples = stream_frames(*dut, 4, r, vol, tags, 1, 0, rng, c, cycle);
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_GT(samples, 100000);
  std::printf("  %ld samples in %llu cycles\n", samples, static_cast<unsigned long long>(cycle));
}

}  // namespace
