// A VerilatedContext that lives for one scope. Verilator 5.006's context
// makes itself the thread's (and the last) context when it is constructed and
// leaves that pointer behind when it is destroyed, so a model constructed
// later in the process without a context of its own finds a deleted one: a
// fatal error ("bad/deleted VerilatedContext pointer"), which in 5.006 then
// deadlocks inside vl_fatal's own mutex. This one hands the thread back the
// context it had before. Use it for every context that is not the process's
// last word (the system's per-frame context, tests' private contexts).
#pragma once
#include <verilated.h>

#include <cstdint>

namespace cube4::rtl {

class ScopedVerilatedContext {
 public:
  ScopedVerilatedContext() : before_(Verilated::threadContextp()) {}
  ~ScopedVerilatedContext() { Verilated::threadContextp(before_); }
  ScopedVerilatedContext(const ScopedVerilatedContext&) = delete;
  ScopedVerilatedContext& operator=(const ScopedVerilatedContext&) = delete;

  // A context for one simulated run: Verilator's random reset from `seed`
  // (every register and memory the RTL does not reset starts from values
  // drawn from it), tracing allowed when asked, the units' assertions
  // evaluated or not. A failed assertion is reported by the unit that
  // raised it (RtlModel: RtlAssertionError), not by Verilator's abort().
  ScopedVerilatedContext(uint32_t seed, bool trace, bool assertions) : ScopedVerilatedContext() {
    if (trace) ctx_.traceEverOn(true);
    ctx_.randReset(2);
    ctx_.randSeed(static_cast<int>(seed & 0x7FFFFFFF));
    ctx_.fatalOnError(false);
    ctx_.assertOn(assertions);
  }

  VerilatedContext& operator*() { return ctx_; }
  VerilatedContext* operator->() { return &ctx_; }
  VerilatedContext* get() { return &ctx_; }

 private:
  VerilatedContext* before_;  // constructed first: the thread's context before ctx_
  VerilatedContext ctx_;
};

}  // namespace cube4::rtl
