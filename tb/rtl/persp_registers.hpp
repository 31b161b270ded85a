// Random perspective frame registers for the RTL tests of the weight
// generator and the rings (test_persp_*.cpp, test_interp_persp_ring.cpp,
// test_gradient_persp_*.cpp): as the host makes them, spacing from 1 at the
// first slice to at most 3 at the last, rays meeting at an eye anywhere in
// x and y, volumes up to 1023 x 1023 x 300; or the camera of a random
// perspective scene.
#pragma once
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "golden/errors.hpp"
#include "golden/host_driver.hpp"
#include "golden/perspective.hpp"
#include "golden/registers.hpp"
#include "golden/scene_io.hpp"
#include "golden/units/dda_perspective.hpp"
#include "golden/volume_io.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace cube4::rtl {

// `min_dim` and `max_dim` bound the volume (the rings' tests take small ones).
inline golden::Registers random_perspective_registers(Random& rng, int frac_bits,
                                                      std::array<int, 3> max_dim = {1023, 1023, 300},
                                                      std::array<int, 3> min_dim = {1, 1, 1}, int max_s = 4) {
  golden::Registers r;
  r.perspective = true;
  r.p.dda_frac_bits = frac_bits;
  const int64_t one = int64_t{1} << frac_bits;
  for (size_t i = 0; i < 3; ++i) r.dim[i] = static_cast<int>(rng.range(min_dim[i], max_dim[i]));
  r.supersampling = static_cast<int>(rng.range(1, max_s));
  const int K = r.sample_slices();
  r.scale_start = one;
  r.scale_step = rng.range(0, K > 1 ? 2 * one / (K - 1) : 2 * one);
  const int64_t ex = rng.range(-2000, 3000), ey = rng.range(-2000, 3000);
  r.x_start = rng.range(0, one - 1);
  r.y_start = rng.range(0, one - 1);
  // x_step = (ray_offset - eye) * scale_step, give or take the host's rounding.
  r.x_step = (r.x_start - ex * one) / one * r.scale_step + rng.range(-1000, 1000);
  r.y_step = (r.y_start - ey * one) / one * r.scale_step + rng.range(-1000, 1000);
  return r;
}

// A perspective camera from a random scene (S 1 to 3, field of view 10 to
// 89 degrees, any rotation) over a sphere of these sizes, as the host
// programs it.
inline golden::Registers scene_registers(Random& rng, std::array<int, 3> size) {
  for (;;) {
    const std::string json =
        R"({"volume": {"synthetic": "sphere", "size": [)" + std::to_string(size[0]) + "," + std::to_string(size[1]) +
        "," + std::to_string(size[2]) + R"(]}, "supersampling": )" + std::to_string(rng.range(1, 3)) +
        R"(, "view": {"projection": "perspective", "fov": )" + std::to_string(rng.range(10, 89)) +
        R"(, "rotate": [)" + std::to_string(rng.range(-180, 179)) + "," + std::to_string(rng.range(-180, 179)) + "," +
        std::to_string(rng.range(-180, 179)) + "]}}";
    try {
      const golden::Scene s = golden::parse_scene(json, "ring.json");
      const golden::Volume vol = golden::load_volume(s.volume, s.precision.voxel_bits, ".");
      return golden::program_host(s, vol).regs;
    } catch (const golden::InputError&) {
      // A camera too close for the volume's depth: another one.
    }
  }
}

// A ring test's frame: half the time a random scene's camera over a sphere
// of max(min_xy) .. max_dim voxels a side, half the time random registers
// (x and y of min_xy .. max_dim, up to 24 deep, S up to 3). Scenes permute
// their axes: the caller checks the permuted sizes.
inline golden::Registers ring_registers(Random& rng, int frac_bits, std::array<int, 2> min_xy, int max_dim) {
  if (rng.chance(0.5)) {
    std::array<int, 3> size{};
    for (int& d : size) d = static_cast<int>(rng.range(std::max(min_xy[0], min_xy[1]), max_dim));
    return scene_registers(rng, size);
  }
  return random_perspective_registers(rng, frac_bits, {max_dim, max_dim, 24}, {min_xy[0], min_xy[1], 1}, 3);
}

// The rays of a frame that leave the volume through each side face (x low,
// x high, y low, y high) between two slices: the perspective rings'
// directed cases, which their tests count over their random frames.
inline std::array<long, 4> rays_leaving(const golden::Registers& r) {
  std::array<long, 4> out{};
  for (int k = 0; k + 1 < r.sample_slices(); ++k)
    for (int axis = 0; axis < 2; ++axis) {
      const golden::RayRange here = r.rays_in_slice(axis, k), next = r.rays_in_slice(axis, k + 1);
      if (here.empty()) continue;
      out[static_cast<size_t>(2 * axis)] += std::max<int64_t>(0, std::min(next.lo, here.hi) - here.lo);
      out[static_cast<size_t>(2 * axis + 1)] += std::max<int64_t>(0, here.hi - std::max(next.hi, here.lo));
    }
  return out;
}

// The constants cube4_persp_slice divides out of a perspective slice, as
// checker fields: what test_persp_slice.cpp and test_dda.cpp compare.
inline Fields divided_fields(const golden::PerspectiveSlice& s) {
  return {{"rays_x_lo", s.rays_x.lo},
          {"rays_x_hi", s.rays_x.hi},
          {"rays_y_lo", s.rays_y.lo},
          {"rays_y_hi", s.rays_y.hi},
          {"box_recip", static_cast<int64_t>(s.box_reciprocal)},
          {"lateral_recip", s.lateral_reciprocal},
          {"behind_start_x", s.behind_x.start},
          {"behind_start_y", s.behind_y.start},
          {"behind_step_x", s.behind_x.step},
          {"behind_step_y", s.behind_y.step},
          {"ahead_start_x", s.ahead_x.start},
          {"ahead_start_y", s.ahead_y.start},
          {"ahead_step_x", s.ahead_x.step},
          {"ahead_step_y", s.ahead_y.step}};
}

// The rings' directed cases (issue 13): rays a constant 1, 2 or 3 voxels
// apart (box extents exactly 1, 2 and 3: SCALE_STEP zero), standing still
// or drifting half a voxel a slice out through each side face, and rays
// spreading from 1 to 3 voxels apart from a centred eye, out through all
// four; each frame has its first and last slice. A 20 x 20 volume (every
// ring's MaxDim-24 test build takes it) of `nz` slices.
struct DirectedCase {
  std::string name;
  golden::Registers r;
  int face = -1;  // the side face rays must leave through (rays_leaving()'s index), 4 all, or -1 none
};
inline std::vector<DirectedCase> directed_cases(int frac_bits, int nz = 8) {
  const int64_t one = int64_t{1} << frac_bits, half = one / 2;
  std::vector<DirectedCase> out;
  auto base = [&](int64_t spacing, int slices) {
    golden::Registers r;
    r.perspective = true;
    r.p.dda_frac_bits = frac_bits;
    r.dim = {20, 20, slices};
    r.supersampling = 1;
    r.scale_start = spacing;
    r.scale_step = 0;
    r.x_start = one / 4;
    r.y_start = one / 8;
    return r;
  };
  const char* faces[] = {"x-", "x+", "y-", "y+"};
  for (int e = 1; e <= 3; ++e) {
    const std::string extent = "extent " + std::to_string(e);
    out.push_back({extent + ", rays standing", base(e * one, nz), -1});
    for (int f = 0; f < 4; ++f) {
      golden::Registers r = base(e * one, nz);
      (f < 2 ? r.x_step : r.y_step) = f % 2 == 0 ? -half : half;
      out.push_back({extent + ", rays leaving through " + faces[f], r, f});
    }
  }
  // Spreading from an eye over the volume's centre: m from 1 to 3.
  const int deep = 3 * nz;
  golden::Registers r = base(one, deep);
  r.scale_step = 2 * one / (deep - 1);
  r.x_step = r.y_step = -10 * r.scale_step;  // c_k = c_0 - 10 (m_k - 1): ray 10 stays put
  out.push_back({"rays spreading 1 to 3 apart", r, 4});
  return out;
}

// What a directed case promises, checked on golden's slices: the box
// extent of every slice (exactly the spacing for the constant ones), and
// rays leaving through its face (all four for 4, none for -1). Empty when
// it holds, else what does not.
inline std::string directed_case_broken(const DirectedCase& d) {
  const golden::Registers& r = d.r;
  const int F = r.p.dda_frac_bits, W = r.p.weight_bits;
  if (r.scale_step == 0)
    for (int k = 0; k < r.sample_slices(); ++k)
      if (golden::box_extent(r.ray_spacing(k), F, W) != (r.scale_start >> F) << W)
        return d.name + ": slice " + std::to_string(k) + "'s box extent is not the spacing";
  const std::array<long, 4> leaving = rays_leaving(r);
  for (int f = 0; f < 4; ++f) {
    const bool want = d.face == 4 || d.face == f;
    if ((leaving[static_cast<size_t>(f)] > 0) != want)
      return d.name + ": " + std::to_string(leaving[static_cast<size_t>(f)]) + " rays leave through side face " +
             std::to_string(f);
  }
  return {};
}

// Streams every directed case through a ring's testbench, one frame and
// two back to back: `stream(case, frames)` returns the results it checked
// with `checker`. Stops at the first case whose premise fails, that
// streams nothing, or that the checker faults. Returns what went wrong
// (empty: every case ran and matched).
template <class Checker, class Stream>
std::string stream_directed_cases(int frac_bits, const Checker& checker, Stream&& stream) {
  for (const DirectedCase& d : directed_cases(frac_bits)) {
    if (std::string broken = directed_case_broken(d); !broken.empty()) return broken;
    for (int frames : {1, 2})
      if (stream(d, frames) <= 0) return d.name + ": nothing streamed in " + std::to_string(frames) + " frame(s)";
    if (!checker.ok()) return d.name + ": " + checker.report();
  }
  return {};
}

}  // namespace cube4::rtl
