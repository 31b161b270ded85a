// The weight generator of parallel projection at RTL (cube4_dda): a frame's
// slice controls, read from the verilated unit as it steps from slice 0 to
// slice K (the one past the last, whose control the stream tag and the
// compositor read too). Golden slice_control() is its specification and
// its TLM model (FramePlan without slice controls).
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "golden/pipeline.hpp"
#include "systemc/core/trace_window.hpp"
#include "systemc/rtl/dda_control.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/rtl/rtl_model.hpp"

namespace cube4::sysc {

// The verilated unit's position width (its parameter default,
// rtl/cube4_dda.sv); its FracBits is the build's dda_frac_bits.
constexpr int kRtlDdaPosBits = 48;

template <class M>
std::vector<golden::SliceControl> run_rtl_dda(const golden::Registers& r, VerilatedContext& ctx) {
  require_rtl_widths(r.p, "the RTL weight generator");
  const int K = r.sample_slices();
  // Every position the accumulators hold (slices -1 .. K + 1) must fit.
  const int64_t limit = int64_t{1} << (kRtlDdaPosBits - 1);
  for (const auto& [start, step, axis] : {std::tuple{r.x_start, r.x_step, "x"}, std::tuple{r.y_start, r.y_step, "y"}})
    for (int k : {-1, K + 1}) {
      const int64_t pos = golden::dda_position(start, step, k);
      if (pos < -limit || pos >= limit)
        throw std::invalid_argument(std::string("view: the ") + axis + " ray offset of slice " + std::to_string(k) +
                                    " needs more than the RTL weight generator's " +
                                    std::to_string(kRtlDdaPosBits) + "-bit DDA; run with --model tlm");
    }
  RtlModel<M> m(ctx, "dda", TraceWindow{}, "dda");
  const uint64_t mask = (uint64_t{1} << kRtlDdaPosBits) - 1;
  m->x_start_i = static_cast<uint64_t>(r.x_start) & mask;
  m->x_step_i = static_cast<uint64_t>(r.x_step) & mask;
  m->y_start_i = static_cast<uint64_t>(r.y_start) & mask;
  m->y_step_i = static_cast<uint64_t>(r.y_step) & mask;
  m->supersampling_i = static_cast<uint32_t>(r.supersampling);
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

}  // namespace cube4::sysc
