// A verilated model as a clocked unit: construction, reset, the clock edge
// and optional FST tracing over a cycle window. Cycle convention (as in the
// unit tests, tb/rtl/rtl_check.hpp): inputs are driven, the clock goes low
// and the model is evaluated (the outputs of this cycle are visible), the
// outputs are read, then the clock rises (the edge that ends the cycle).
// The assertions (rtl/assert/) act on clock edges: an edge after which the
// context records an error throws RtlAssertionError (the context must not
// be fatalOnError, or Verilator aborts first; the system's is not).
//
// A model whose outputs are all registered (Outputs::Registered) shows the
// same outputs after the previous rising edge as after this cycle's
// settling, so without a trace its clock-low evaluation does nothing a
// reader can see; but Verilator's eval() runs the model's whole
// input-combinational region every time and finds a rising edge only
// against the clock of the eval() before. Such a model is therefore
// evaluated once a cycle: rise() tells the model the clock was low (its
// previous-clock register, an internal of the verilated code checked
// against Verilator 5.006's) and evaluates the edge. About a tenth of an
// RTL frame's time was these clock-low evaluations (docs/performance.md,
// "One evaluation a cycle"). Other Verilator versions, traced models and
// models with combinational outputs keep both evaluations.
#pragma once
// verilated.h calls sc_time_stamp() unqualified once SystemC is included.
#include <systemc>
using sc_core::sc_time_stamp;
#include <verilated.h>
#include <verilated_fst_c.h>

#include <cstdint>
#include <memory>
#include <string>

#include "systemc/core/trace_window.hpp"
#include "systemc/rtl/rtl_assertion.hpp"
#include "systemc/rtl/vl_bits.hpp"

namespace cube4::sysc {

// Whether any output of a unit's RTL depends on its inputs within the
// cycle (then they are read after the clock-low evaluation), or every
// output comes from registers.
enum class Outputs { Combinational, Registered };

#if VERILATOR_VERSION_INTEGER == 5006000
inline constexpr bool kVerilatorClockLowSkippable = true;
#else
inline constexpr bool kVerilatorClockLowSkippable = false;
#endif

template <class M>
class RtlModel {
 public:
  RtlModel(VerilatedContext& ctx, const std::string& name, const TraceWindow& trace, const std::string& trace_suffix,
           Outputs outputs = Outputs::Combinational)
      : ctx_(ctx), name_(name), m_(std::make_unique<M>(&ctx, name.c_str())), window_(trace) {
    if (!trace.file.empty()) {
      fst_ = std::make_unique<VerilatedFstC>();
      m_->trace(fst_.get(), 99);
      fst_->open(trace_file_name(trace.file, trace_suffix).c_str());
    }
    skip_low_ = kVerilatorClockLowSkippable && outputs == Outputs::Registered && !fst_;
    m_->rst_ni = 0;
    for (int i = 0; i < 2; ++i) setup_edge();
    m_->rst_ni = 1;
    restart_cycles();
  }
  ~RtlModel() {
    if (fst_) fst_->close();
  }
  RtlModel(const RtlModel&) = delete;
  RtlModel& operator=(const RtlModel&) = delete;

  M& operator*() { return *m_; }
  M* operator->() { return m_.get(); }

  void settle() {
    if (skip_low_) return;
    m_->clk_i = 0;
    m_->eval();
    dump(2 * cycle_);
  }
  void rise() {
    if (skip_low_) clock_was_low();
    m_->clk_i = 1;
    m_->eval();
    dump(2 * cycle_ + 1);
    check_assertions(cycle_);
    ++cycle_;
  }
  void edge() { settle(); rise(); }
  // A clock before the frame (reset, setup, a table load), not traced: the
  // trace holds the frame's cycles under the system's numbers, and FST
  // times must only grow (Verilator warns "previous dump" for each that
  // does not, and the frame after a long table load would be lost).
  void setup_edge() {
    m_->clk_i = 0;
    m_->eval();
    m_->clk_i = 1;
    m_->eval();
    check_assertions(0);
  }
  // The system's cycle numbers: the frame's first clock is cycle 1 (after
  // reset, or after a table load through the write ports).
  void restart_cycles() { cycle_ = 1; }

  // trace.fst + "interp" -> trace.interp.fst: one file per verilated unit.
  static std::string trace_file_name(const std::string& file, const std::string& suffix) {
    const auto dot = file.rfind(".fst");
    const std::string stem = dot == std::string::npos ? file : file.substr(0, dot);
    return stem + "." + suffix + ".fst";
  }

 private:
  // What the clock-low eval() would have left for the edge detection of
  // the next (Verilator 5.006: the act region's trigger compares clk_i with
  // the clock it saw last).
  void clock_was_low() {
    m_->clk_i = 0;
    if constexpr (kVerilatorClockLowSkippable) m_->rootp->__Vtrigrprev__TOP__clk_i = 0;
  }
  void check_assertions(uint64_t cycle) const {
    if (ctx_.gotError()) throw RtlAssertionError(name_, cycle);
  }
  void dump(uint64_t t) {
    if (fst_ && cycle_ >= window_.first && cycle_ <= window_.last) fst_->dump(t);
  }
  VerilatedContext& ctx_;
  std::string name_;
  std::unique_ptr<M> m_;
  std::unique_ptr<VerilatedFstC> fst_;
  TraceWindow window_;
  bool skip_low_ = false;
  uint64_t cycle_ = 0;
};

}  // namespace cube4::sysc
