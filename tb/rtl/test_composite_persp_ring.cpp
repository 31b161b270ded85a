// RTL equivalence tests of the perspective compositing ring,
// cube4_composite_persp_ring, against golden: every ray's samples,
// cropped and blended in slice order (golden perspective_crop_and_cut()
// and blend()), starting empty where the ray enters; its accumulator and
// pixel (golden pixel_of()) leave once a frame, when it blends its last
// sample, on the pipeline and in the cycle the plan gives
// (golden composite_position(): its gradient's position + Reach, 7 cycles
// after that step; docs/perspective.md, "The plan for the compositing
// ring"). Random cameras (random registers as the host makes them, and the
// cameras of random perspective scenes) whose rays move at most Reach,
// streamed as the system streams frames (one or two back to back, the zero
// pass and six flush beams) with random idle cycles; random shaded samples
// arriving where the gradient ring forms them; front-to-back, MIP and
// MinIP blends, with and without cropping. With polygons (Cube-5 in
// perspective, the p = 4 ring built with HasPolygons): random front, back
// and slab pixels (blank ones often) and ray depths around the slices, a
// ray starting from its front pixel, the Z test and the slab pixel after
// each sample (golden double_composite()), the pixel over the back pixel
// (leave_with_polygons()); the p = 1 and 5 rings are built without
// polygon hardware.
//
// CUBE4_RTL_VECTORS overrides the sample count per ring (default 1,000,000).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "Vcube4_composite_persp_ring.h"
#include "Vcube4_composite_persp_ring_p1.h"
#include "Vcube4_composite_persp_ring_p5.h"
#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/units/composite_polygon.hpp"
#include "systemc/rtl/unit_registers.hpp"
#include "tb/rtl/persp_registers.hpp"
#include "tb/rtl/persp_ring_stream.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;

constexpr int kV = 12, kF = 20, kDda = 48, kRay = 16, kTag = 8, kA = 16, kG = 8, kPos = 16;
constexpr int kMaxDim = 24, kReach = 3;  // rtl/groups/composite_persp.cmake

struct Expect {
  int pass = 0;
  int64_t u = 0, v = 0;
  g::RayAcc acc;
  g::Pixel pixel;
  bool seen = false;
};

// A random premultiplied pixel, blank a third of the time.
g::Pixel random_pixel(rtl::Random& rng) {
  if (rng.chance(0.33)) return {};
  const auto a = static_cast<uint16_t>(rng.edgy((1 << kA) - 1));
  auto channel = [&] { return static_cast<uint16_t>(a == 0 ? 0 : rng.range(0, a)); };
  const uint16_t r = channel(), gr = channel(), b = channel();
  return {r, gr, b, a};
}

// A ray's polygon data: its depth and front and back pixels.
struct RayPolygons {
  uint32_t z = g::kZNone;
  g::Pixel front, back;
};

// Streams `frames` frames of registers r through ring m, checking every
// ray that leaves. Returns the samples blended.
template <class M>
long stream_frames(M& m, int p, const g::Registers& r, int frames, bool polygons, rtl::Random& rng, rtl::Checker& c,
                   uint64_t& cycle) {
  const int K = r.sample_slices(), nx = r.dim[0], ny = r.dim[1];
  const int B = (nx + p - 1) / p;
  const int64_t row = int64_t{B} * p;
  const int passes = frames * K;
  std::vector<g::PerspectiveSlice> slices;
  for (int k = 0; k < K; ++k) slices.push_back(g::perspective_slice(r, k));

  // Random shaded samples of every ray of every slice of every frame.
  std::map<std::tuple<int, int64_t, int64_t>, g::ShadedSample> samples;  // (pass, u, v)
  for (int f = 0; f < frames; ++f)
    for (int k = 0; k < K; ++k) {
      const g::PerspectiveSlice& s = slices[static_cast<size_t>(k)];
      for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
        for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
          g::ShadedSample x;
          x.rgb = {static_cast<uint32_t>(rng.edgy((1 << kA) - 1)), static_cast<uint32_t>(rng.edgy((1 << kA) - 1)),
                   static_cast<uint32_t>(rng.edgy((1 << kA) - 1))};
          x.alpha = static_cast<uint32_t>(rng.chance(0.3) ? 0 : rng.edgy((1 << kA) - 1));
          x.value = static_cast<uint32_t>(rng.bits(kV));
          samples[{f * K + k, u, v}] = x;
        }
    }
  // Polygons: each ray's data per frame (depths from before the first
  // slice to past the last, or none), each sample's slab pixel.
  std::map<std::tuple<int, int64_t, int64_t>, RayPolygons> ray_polygons;  // (frame, u, v)
  std::map<std::tuple<int, int64_t, int64_t>, g::Pixel> slab;            // (pass, u, v)
  if (polygons)
    for (int f = 0; f < frames; ++f)
      for (int k = 0; k < K; ++k) {
        const g::PerspectiveSlice& s = slices[static_cast<size_t>(k)];
        for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
          for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
            slab[{f * K + k, u, v}] = random_pixel(rng);
            if (ray_polygons.count({f, u, v})) continue;
            RayPolygons& rp = ray_polygons[{f, u, v}];
            if (!rng.chance(0.2)) rp.z = static_cast<uint32_t>(rng.range(0, int64_t{K + 1} << g::kZFracBits));
            rp.front = random_pixel(rng);
            rp.back = random_pixel(rng);
          }
      }
  // Golden: each ray's accumulator over its run of slices, leaving at its
  // last, by the step and lane that blend that sample.
  std::map<int64_t, std::map<int, Expect>> want;
  long blended = 0;
  for (int f = 0; f < frames; ++f) {
    std::map<std::pair<int64_t, int64_t>, g::RayAcc> rays;
    for (int k = 0; k < K; ++k) {
      const g::PerspectiveSlice& s = slices[static_cast<size_t>(k)];
      for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
        for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
          const g::ShadedSample x = g::perspective_crop_and_cut(r, s, u, v, samples.at({f * K + k, u, v}));
          const RayPolygons* rp = polygons ? &ray_polygons.at({f, u, v}) : nullptr;
          const auto [it, entered] = rays.try_emplace({u, v}, rp ? g::pixel_to_acc(rp->front, r.p) : g::RayAcc{});
          g::RayAcc& acc = it->second;
          (void)entered;
          acc = rp ? g::double_composite(acc, x, g::sample_before_z(k, rp->z), slab.at({f * K + k, u, v}), r.p)
                   : g::blend(r.blend, acc, x, r.p);
          ++blended;
          if (k + 1 < K && g::samples(slices[static_cast<size_t>(k + 1)], u, v)) continue;
          const int64_t X = g::ray_home(g::axis_slice(s, 0), u, kF), Y = g::ray_home(g::axis_slice(s, 1), v, kF);
          const int64_t pos = g::composite_position(int64_t{f} * K + k, X, Y, row, ny, kReach);
          const g::Pixel px = rp ? g::leave_with_polygons(acc, rp->back, r.p) : g::pixel_of(acc, r.p);
          want[pos / p][static_cast<int>(pos % p)] = {f * K + k, u, v, acc, px, false};
        }
    }
  }

  rtl::DueLanes<Expect> due(want, 7);
  auto observe = [&] {
    const int64_t step = due.take(cycle);
    for (int lane = 0; lane < p; ++lane) {
      const bool valid = rtl::get_bits(m.pixel_valid_o, lane, 1) != 0;
      Expect* e = due.lane(lane);
      const rtl::Fields where{{"step", step}, {"lane", lane}, {"nx", nx}, {"ny", ny}, {"nz", r.dim[2]},
                              {"S", r.supersampling}, {"frames", frames}, {"blend", static_cast<int>(r.blend)},
                              {"polygons", polygons}};
      if (valid != (e != nullptr)) {
        c.check(cycle, where, {{"leaves", e != nullptr}}, {{"leaves", valid}});
        continue;
      }
      if (!e) continue;
      e->seen = true;
      auto bits = [&](const auto& port, int width) { return static_cast<int64_t>(rtl::get_bits(port, lane * width, width)); };
      const g::Pixel px = e->pixel;
      c.check(cycle, where,
              {{"pass", e->pass}, {"u", e->u}, {"v", e->v}, {"r", e->acc.r}, {"g", e->acc.g}, {"b", e->acc.b},
               {"a", e->acc.a}, {"value", e->acc.value}, {"selected", e->acc.valid}, {"pixel r", px.r},
               {"pixel g", px.g}, {"pixel b", px.b}, {"pixel a", px.a}},
              {{"pass", bits(m.tag_o, kTag)}, {"u", rtl::sign_extend(rtl::get_bits(m.ray_u_o, lane * kRay, kRay), kRay)},
               {"v", rtl::sign_extend(rtl::get_bits(m.ray_v_o, lane * kRay, kRay), kRay)},
               {"r", bits(m.acc_red_o, kA + kG)}, {"g", bits(m.acc_green_o, kA + kG)},
               {"b", bits(m.acc_blue_o, kA + kG)}, {"a", bits(m.acc_alpha_o, kA + kG)},
               {"value", bits(m.acc_value_o, kV)}, {"selected", bits(m.acc_selected_o, 1)},
               {"pixel r", bits(m.pixel_red_o, kA)}, {"pixel g", bits(m.pixel_green_o, kA)},
               {"pixel b", bits(m.pixel_blue_o, kA)}, {"pixel a", bits(m.pixel_alpha_o, kA)}});
    }
  };
  auto clock = [&] {
    rtl::settle(m);
    rtl::rise(m);
    ++cycle;
    rtl::settle(m);
    observe();
  };
  // The frame registers (cut plane and block window off).
  rtl::drive_composite_registers(m, r);
  // A pass's constants at its first step, random words elsewhere: the
  // common ones and the voxel slice and z weight.
  auto drive_constants = [&](const g::PerspectiveSlice* s, int pass, bool zero) {
    rtl::drive_persp_pass_constants(m, s, pass, zero, K, rng, kTag);
    m.z_voxel_i = static_cast<uint16_t>(s ? s->z_voxel : static_cast<int>(rng.bits(kPos)));
    m.wz_i = static_cast<uint8_t>(s ? s->wz : rng.bits(8));
    m.slice_k_i = static_cast<uint16_t>(s ? s->k : static_cast<int>(rng.bits(16)));
  };
  m.poly_enabled_i = polygons;

  rtl::stream_persp_passes(
      m, slices, passes, ny, B, p, rng,
      [&](const rtl::PerspStep& st) {
        drive_constants(st.slice, st.pass, st.zero);
        uint32_t valid = 0;
        for (int lane = 0; lane < p; ++lane) {
          g::ShadedSample x;
          x.rgb = {static_cast<uint32_t>(rng.bits(kA)), static_cast<uint32_t>(rng.bits(kA)),
                   static_cast<uint32_t>(rng.bits(kA))};
          x.alpha = static_cast<uint32_t>(rng.bits(kA));
          x.value = static_cast<uint32_t>(rng.bits(kV));
          const g::FormedCell fc = g::gradient_cell(st.step * p + lane, row, nx, ny);
          RayPolygons rp{static_cast<uint32_t>(rng.bits(g::kZBits)), random_pixel(rng), random_pixel(rng)};
          g::Pixel behind = random_pixel(rng);
          if (const rtl::HomedRay h = rtl::ray_homed_at(slices, fc, passes, kF, r.p.weight_bits); h.valid) {
            valid |= 1u << lane;
            x = samples.at({static_cast<int>(fc.pass), h.u, h.v});
            if (polygons) {
              rp = ray_polygons.at({static_cast<int>(fc.pass) / K, h.u, h.v});
              behind = slab.at({static_cast<int>(fc.pass), h.u, h.v});
            }
          }
          rtl::put_bits(m.ray_z_i, lane * g::kZBits, g::kZBits, rp.z);
          const std::array<std::pair<const g::Pixel*, std::array<decltype(&m.slab_red_i), 4>>, 3> ports{{
              {&rp.front, {&m.ray_front_red_i, &m.ray_front_green_i, &m.ray_front_blue_i, &m.ray_front_alpha_i}},
              {&rp.back, {&m.ray_back_red_i, &m.ray_back_green_i, &m.ray_back_blue_i, &m.ray_back_alpha_i}},
              {&behind, {&m.slab_red_i, &m.slab_green_i, &m.slab_blue_i, &m.slab_alpha_i}},
          }};
          for (const auto& [px, chans] : ports) {
            rtl::put_bits(*chans[0], lane * kA, kA, px->r);
            rtl::put_bits(*chans[1], lane * kA, kA, px->g);
            rtl::put_bits(*chans[2], lane * kA, kA, px->b);
            rtl::put_bits(*chans[3], lane * kA, kA, px->a);
          }
          rtl::put_bits(m.red_i, lane * kA, kA, x.rgb[0]);
          rtl::put_bits(m.green_i, lane * kA, kA, x.rgb[1]);
          rtl::put_bits(m.blue_i, lane * kA, kA, x.rgb[2]);
          rtl::put_bits(m.alpha_i, lane * kA, kA, x.alpha);
          rtl::put_bits(m.value_i, lane * kV, kV, x.value);
        }
        m.sample_valid_i = valid;
        due.driven(cycle, st.step);
      },
      clock, [&] { return c.ok(); });
  m.valid_i = 0;
  for (int i = 0; i < 12; ++i) clock();
  due.check_every_ray_left(c, cycle);
  return blended;
}

template <class M>
void test_ring(int p, uint64_t salt, bool has_polygons) {
  rtl::Random rng(salt);
  const auto dut = rtl::make_dut<M>();
  M& m = *dut;
  rtl::reset(m);
  const std::string name = "cube4_composite_persp_ring p=" + std::to_string(p);
  rtl::Checker c(name);
  const long n = rtl::vector_count(1000000);
  rtl::Timer t(name + ": " + std::to_string(n) + " samples");
  uint64_t cycle = 0;
  long blended = 0, before = 0, polygon_samples = 0;
  int streams = 0;
  std::array<long, 4> faces{};
  while (blended < n && c.ok()) {
    g::Registers r = rtl::ring_registers(rng, kF, {11, 7}, kMaxDim);
    // The ring's preconditions: ny >= 6, a beam of at least 8 + Reach
    // positions, moves within the reach.
    const int64_t row = static_cast<int64_t>((r.dim[0] + p - 1) / p) * p;
    if (r.dim[1] < 6 || row < 8 + kReach || r.dim[0] > kMaxDim || r.dim[1] > kMaxDim) continue;
    if (g::largest_home_move(g::perspective_reach(r)) > kReach) continue;
    const int frames = rng.chance(0.3) ? 2 : 1;
    if (frames * r.sample_slices() + 1 > (1 << kTag) - 1) continue;
    // A ring with polygons blends front to back more often (polygons need it).
    const int mode = has_polygons && rng.chance(0.4) ? 0 : static_cast<int>(rng.range(0, 3));
    r.blend = mode == 1 ? g::BlendMode::Mip : mode == 2 ? g::BlendMode::MinIp : g::BlendMode::Composite;
    r.crop_enabled = rng.chance(0.3);
    for (auto& slab : r.crop.slab) {
      slab[0] = static_cast<int32_t>(rng.range(0, 12));
      slab[1] = static_cast<int32_t>(rng.range(slab[0], 24));
    }
    r.crop.mask = static_cast<uint8_t>(rng.bits(8));
    // Polygons in most front-to-back frames of a ring that has them
    // (golden refuses them with MIP and MinIP).
    const bool polygons = has_polygons && r.blend == g::BlendMode::Composite && rng.chance(0.8);
    blended += stream_frames(m, p, r, frames, polygons, rng, c, cycle);
    polygon_samples += polygons ? blended - before : 0;
    before = blended;
    const std::array<long, 4> leaving = rtl::rays_leaving(r);
    for (size_t f = 0; f < 4; ++f) faces[f] += leaving[f];
    ++streams;
  }
  EXPECT_TRUE(c.ok()) << c.report();
  // Rays left the volume through every side face in these streams (their
  // pixels written before the frame's last slice).
  for (size_t f = 0; f < 4; ++f) EXPECT_GT(faces[f], 0) << "no ray left through side face " << f;
  if (has_polygons) EXPECT_GT(polygon_samples, n / 10);
  std::printf("  [%s: %d streams; rays leaving through x-, x+, y-, y+: %ld %ld %ld %ld; %ld samples with polygons]\n",
              name.c_str(), streams, faces[0], faces[1], faces[2], faces[3], polygon_samples);
}

// The directed cases (tb/rtl/persp_registers.hpp): box extents exactly 1,
// 2 and 3, rays leaving through each side face, spreading rays; one frame
// each and two back to back, with polygons at p = 4.
template <class M>
void test_directed(int p, bool has_polygons) {
  rtl::Random rng(9);
  const auto dut = rtl::make_dut<M>();
  rtl::reset(*dut);
  rtl::Checker c("cube4_composite_persp_ring p=" + std::to_string(p) + " (directed)");
  uint64_t cycle = 0;
  for (const rtl::DirectedCase& d : rtl::directed_cases(kF))
    ASSERT_LE(g::largest_home_move(g::perspective_reach(d.r)), kReach) << d.name;
  EXPECT_EQ(rtl::stream_directed_cases(kF, c,
                                       [&](const rtl::DirectedCase& d, int frames) {
                                         return stream_frames(*dut, p, d.r, frames, has_polygons && frames == 2, rng, c,
                                                              cycle);
                                       }),
            "");
}

TEST(RtlCompositePerspRing, DirectedCasesAtP4) { test_directed<Vcube4_composite_persp_ring>(4, true); }
TEST(RtlCompositePerspRing, DirectedCasesAtP5) { test_directed<Vcube4_composite_persp_ring_p5>(5, false); }

TEST(RtlCompositePerspRing, EveryRayLeavesOnceWithGoldensAccumulatorWhereThePlanSaysAtP4WithPolygons) {
  test_ring<Vcube4_composite_persp_ring>(4, 91, true);
}
TEST(RtlCompositePerspRing, EveryRayLeavesOnceWithGoldensAccumulatorWhereThePlanSaysAtP1) {
  test_ring<Vcube4_composite_persp_ring_p1>(1, 92, false);
}
TEST(RtlCompositePerspRing, EveryRayLeavesOnceWithGoldensAccumulatorWhereThePlanSaysAtP5) {
  test_ring<Vcube4_composite_persp_ring_p5>(5, 93, false);
}

}  // namespace
