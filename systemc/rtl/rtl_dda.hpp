// The weight generator at RTL (cube4_dda, both projections): a frame's
// slice controls (parallel projection) or perspective slice constants,
// read from the verilated unit as it steps through the frame's slices.
// Golden slice_control() and perspective_slice() are its specification
// and its TLM model (FramePlan without slice controls or perspective
// slices).
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "golden/perspective.hpp"
#include "golden/pipeline.hpp"
#include "systemc/core/trace_window.hpp"
#include "systemc/rtl/dda_control.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/rtl/rtl_model.hpp"

namespace cube4::sysc {

// The verilated unit's position width (its parameter default,
// rtl/cube4_dda.sv); its FracBits is the build's dda_frac_bits.
constexpr int kRtlDdaPosBits = 48;

// Loads the frame's registers into the unit, after checking that every
// position its walks hold (slices -1 .. K + 1 of each DDA) fits.
template <class M>
void load_rtl_dda(M& m, const golden::Registers& r) {
  const int K = r.sample_slices();
  const int64_t limit = int64_t{1} << (kRtlDdaPosBits - 1);
  using Dda = std::tuple<int64_t, int64_t, const char*>;
  std::vector<Dda> ddas{{r.x_start, r.x_step, "X_START/X_STEP"}, {r.y_start, r.y_step, "Y_START/Y_STEP"}};
  if (r.perspective) ddas.emplace_back(r.scale_start, r.scale_step, "SCALE_START/SCALE_STEP");
  for (const auto& [start, step, regs] : ddas)
    for (int k : {-1, K + 1}) {
      const __int128 pos = __int128{start} + __int128{step} * k;
      if (pos < -limit || pos >= limit)
        throw std::invalid_argument(std::string("view: the DDA of ") + regs + " reaches " +
                                    std::to_string(static_cast<double>(pos)) + " at slice " + std::to_string(k) +
                                    ", more than the RTL weight generator's " + std::to_string(kRtlDdaPosBits) +
                                    "-bit positions hold; run with --model tlm");
    }
  const uint64_t mask = (uint64_t{1} << kRtlDdaPosBits) - 1;
  m->x_start_i = static_cast<uint64_t>(r.x_start) & mask;
  m->x_step_i = static_cast<uint64_t>(r.x_step) & mask;
  m->y_start_i = static_cast<uint64_t>(r.y_start) & mask;
  m->y_step_i = static_cast<uint64_t>(r.y_step) & mask;
  m->supersampling_i = static_cast<uint32_t>(r.supersampling);
  m->perspective_i = r.perspective;
  m->scale_start_i = static_cast<uint64_t>(r.scale_start) & mask;
  m->scale_step_i = static_cast<uint64_t>(r.scale_step) & mask;
  m->dim_x_i = static_cast<uint32_t>(r.dim[0]);
  m->dim_y_i = static_cast<uint32_t>(r.dim[1]);
  m->last_slice_i = static_cast<uint32_t>(K - 1);
}

// Parallel projection: the control of slices 0 .. K (the one past the
// last, whose control the stream tag and the compositor read too).
template <class M>
std::vector<golden::SliceControl> run_rtl_dda(const golden::Registers& r, VerilatedContext& ctx) {
  require_rtl_widths(r.p, "the RTL weight generator");
  RtlModel<M> m(ctx, "dda", TraceWindow{}, "dda");
  load_rtl_dda(m, r);
  const int K = r.sample_slices();
  std::vector<golden::SliceControl> out;
  out.reserve(static_cast<size_t>(K) + 1);
  m->start_i = 1;
  for (int k = 0; k <= K; ++k) {
    m->advance_i = k > 0;
    m.setup_edge();
    m->start_i = 0;
    out.push_back(rtl::read_dda_control(*m, kRtlDdaPosBits - r.p.dda_frac_bits));
  }
  return out;
}

// Perspective projection: the constants of slices 0 .. K - 1, each read
// when the unit's divisions are done (ready_o).
template <class M>
std::vector<golden::PerspectiveSlice> run_rtl_dda_perspective(const golden::Registers& r, VerilatedContext& ctx) {
  require_rtl_widths(r.p, "the RTL weight generator");
  RtlModel<M> m(ctx, "dda", TraceWindow{}, "dda");
  load_rtl_dda(m, r);
  const int K = r.sample_slices();
  // The divisions' documented latency, with room: a unit that never
  // finishes is an error, not a hang.
  const int max_cycles = 4 * (1 + 12 * (kRtlDdaPosBits + r.p.dda_frac_bits + 2));
  std::vector<golden::PerspectiveSlice> out;
  out.reserve(static_cast<size_t>(K));
  m->start_i = 1;
  for (int k = 0; k < K; ++k) {
    m->advance_i = k > 0;
    m.setup_edge();
    m->start_i = 0;
    m->advance_i = 0;
    for (int cycles = 1; !m->ready_o; ++cycles) {
      if (cycles > max_cycles)
        throw std::logic_error("cube4_dda: perspective slice " + std::to_string(k) + " not ready after " +
                               std::to_string(max_cycles) + " cycles");
      m.setup_edge();
    }
    out.push_back(rtl::read_perspective_slice(*m, kRtlDdaPosBits));
  }
  return out;
}

}  // namespace cube4::sysc
