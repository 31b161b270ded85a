// Coverage of verilated models (docs/verification.md, "Coverage"): in a
// build with CUBE4_RTL_COVERAGE=ON every model is verilated with
// --coverage (lines, toggles, the checkers' cover properties) and its
// counts are written as a Verilator coverage file into
// $CUBE4_COVERAGE_DIR (default: the working folder), one file per write,
// which scripts/coverage.sh merges.
//
// Verilator's coverage database holds pointers into each model's symbol
// table, so it must be written while the models live: a context's
// coverage is written by write_coverage() before its models are
// destroyed, and a unit-test model made by make_dut() has a context of its
// own, written when the model is. In other builds both cost nothing.
#pragma once
#include <verilated.h>
#if CUBE4_RTL_COVERAGE
#include <verilated_cov.h>
#include <unistd.h>
#endif

#include <atomic>
#include <cstdlib>
#include <memory>
#include <string>

namespace cube4::rtl {

inline void write_coverage(VerilatedContext& ctx) {
#if CUBE4_RTL_COVERAGE
  static std::atomic<int> count{0};
  const char* dir = std::getenv("CUBE4_COVERAGE_DIR");
  const std::string file = std::string(dir && *dir ? dir : ".") + "/coverage-" + std::to_string(::getpid()) + "-" +
                           std::to_string(count++) + ".dat";
  ctx.coveragep()->write(file.c_str());
#else
  (void)ctx;
#endif
}

// A unit under test, as std::make_unique<M>() makes it on the thread's
// context; in a coverage build on a context of its own with the thread
// context's random-reset settings, whose coverage is written when the
// unit is destroyed.
template <class M>
class Dut {
 public:
  Dut() {
#if CUBE4_RTL_COVERAGE
    VerilatedContext* thread = Verilated::threadContextp();
    ctx_ = std::make_unique<VerilatedContext>();
    ctx_->randReset(thread->randReset());
    ctx_->randSeed(thread->randSeed());
    m_ = std::make_unique<M>(ctx_.get(), "TOP");
    // A new context, and a model's symbol table, make their context the
    // thread's: hand the thread its own back, which outlives this one.
    Verilated::threadContextp(thread);
#else
    m_ = std::make_unique<M>();
#endif
  }
  ~Dut() {
#if CUBE4_RTL_COVERAGE
    write_coverage(*ctx_);
#endif
  }
  Dut(const Dut&) = delete;
  Dut& operator=(const Dut&) = delete;
  M& operator*() const { return *m_; }
  M* operator->() const { return m_.get(); }
  M* get() const { return m_.get(); }

 private:
#if CUBE4_RTL_COVERAGE
  std::unique_ptr<VerilatedContext> ctx_;  // declared first: outlives the model
#endif
  std::unique_ptr<M> m_;
};

// `auto m = make_dut<M>();` then `*m`, `m->`, as with std::make_unique.
template <class M>
Dut<M> make_dut() {
  return Dut<M>();
}

}  // namespace cube4::rtl
