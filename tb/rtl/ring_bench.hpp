// What the three ring testbenches (test_interp.cpp, test_gradient_ring.cpp,
// test_composite_ring.cpp) share: the ring sizes the CMake groups verilate,
// the check that a frame fits a ring, the first-mismatch report, a stage
// timer, the views every ring is run through and the view's JSON.
#pragma once
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

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

}  // namespace cube4::rtl
