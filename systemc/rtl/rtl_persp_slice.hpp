// The perspective weight generator's per-slice part at RTL
// (cube4_persp_slice, docs/rtl-persp.md): the constants of every sample
// slice of a perspective frame, read from the verilated unit slice by slice
// before the frame starts. Golden perspective_slice() is its specification
// and its TLM model (FramePlan without perspective slices). The unit
// computes what depends on the rays; the slice's voxel slices and z weight
// are the z DDA's, shared with parallel projection (golden z_voxel_slice(),
// z_weight()), and come from the golden slice.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "golden/perspective.hpp"
#include "systemc/core/trace_window.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/rtl/rtl_model.hpp"

namespace cube4::sysc {

// The verilated unit's position width (its PosBits default,
// rtl/cube4_persp_slice.sv); its FracBits is the build's dda_frac_bits.
constexpr int kRtlPerspPosBits = 48;

template <class M>
std::vector<golden::PerspectiveSlice> run_rtl_persp_slices(const golden::Registers& r, VerilatedContext& ctx) {
  require_rtl_widths(r.p, "the RTL perspective weight generator");
  const int64_t limit = int64_t{1} << (kRtlPerspPosBits - 1);
  for (const auto& [value, name] : {std::tuple{r.scale_start, "SCALE_START"}, std::tuple{r.scale_step, "SCALE_STEP"},
                                    std::tuple{r.x_start, "X_START"}, std::tuple{r.x_step, "X_STEP"},
                                    std::tuple{r.y_start, "Y_START"}, std::tuple{r.y_step, "Y_STEP"}})
    if (value < -limit || value >= limit)
      throw std::invalid_argument(std::string("view: the perspective register ") + name + " (" +
                                  std::to_string(value) + ") needs more than the RTL weight generator's " +
                                  std::to_string(kRtlPerspPosBits) + " bits; run with --model tlm");
  RtlModel<M> m(ctx, "persp_slice", TraceWindow{}, "persp_slice");
  const uint64_t mask = (uint64_t{1} << kRtlPerspPosBits) - 1;
  m->scale_start_i = static_cast<uint64_t>(r.scale_start) & mask;
  m->scale_step_i = static_cast<uint64_t>(r.scale_step) & mask;
  m->x_start_i = static_cast<uint64_t>(r.x_start) & mask;
  m->x_step_i = static_cast<uint64_t>(r.x_step) & mask;
  m->y_start_i = static_cast<uint64_t>(r.y_start) & mask;
  m->y_step_i = static_cast<uint64_t>(r.y_step) & mask;
  m->dim_x_i = static_cast<uint32_t>(r.dim[0]);
  m->dim_y_i = static_cast<uint32_t>(r.dim[1]);
  const int K = r.sample_slices();
  m->last_slice_i = static_cast<uint32_t>(K - 1);
  auto get = [](uint64_t v) {
    return static_cast<int64_t>(v << (64 - kRtlPerspPosBits)) >> (64 - kRtlPerspPosBits);
  };
  // The unit's documented latency, with room: a unit that never finishes
  // is an error, not a hang.
  const int max_cycles = 4 * (1 + 12 * (kRtlPerspPosBits + r.p.dda_frac_bits + 2));
  std::vector<golden::PerspectiveSlice> out;
  out.reserve(static_cast<size_t>(K));
  for (int k = 0; k < K; ++k) {
    m->k_i = static_cast<uint32_t>(k);
    m->start_i = 1;
    m.setup_edge();
    m->start_i = 0;
    int cycles = 1;
    for (; !m->done_o; ++cycles) {
      if (cycles > max_cycles)
        throw std::logic_error("cube4_persp_slice: slice " + std::to_string(k) + " not done after " +
                               std::to_string(max_cycles) + " cycles");
      m.setup_edge();
    }
    golden::PerspectiveSlice s = golden::perspective_slice(r, k);  // k, z_voxel, wz
    s.spacing = get(m->spacing_o);
    s.ray0_x = get(m->ray0_x_o);
    s.ray0_y = get(m->ray0_y_o);
    s.rays_x = {get(m->rays_x_lo_o), get(m->rays_x_hi_o)};
    s.rays_y = {get(m->rays_y_lo_o), get(m->rays_y_hi_o)};
    s.box_reciprocal = static_cast<uint64_t>(get(m->box_recip_o));
    s.lateral_reciprocal = get(m->lateral_recip_o);
    s.behind_x = {get(m->behind_start_x_o), get(m->behind_step_o)};
    s.behind_y = {get(m->behind_start_y_o), get(m->behind_step_o)};
    s.ahead_x = {get(m->ahead_start_x_o), get(m->ahead_step_o)};
    s.ahead_y = {get(m->ahead_start_y_o), get(m->ahead_step_o)};
    out.push_back(s);
    m.setup_edge();  // the done cycle
  }
  return out;
}

}  // namespace cube4::sysc
