// Shared helpers of the RTL unit tests: clocking a verilated unit, bit
// access to ports of any width, random stimulus, and a scoreboard that
// compares every output with the golden result of the input that entered
// `latency` cycles earlier and reports the first mismatch with its cycle,
// the unit, all inputs, the expected and the received outputs.
//
// Cycle convention (every test): in cycle c the testbench drives the
// inputs, calls settle() (clock low, evaluate: outputs of cycle c are now
// visible), reads the outputs, then calls rise() (the clock edge that ends
// cycle c). A unit of latency L shows in cycle c the result of the input
// driven in cycle c - L.
#pragma once
#include <verilated.h>

#include "systemc/rtl/vl_bits.hpp"
#include "systemc/rtl/vl_coverage.hpp"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace cube4::rtl {

// ---------------------------------------------------------------------------
// Named values, for reports.
struct Field {
  std::string name;
  int64_t value;
};
using Fields = std::vector<Field>;

inline std::string format(const Fields& f) {
  std::ostringstream s;
  for (size_t i = 0; i < f.size(); ++i) s << (i ? " " : "") << f[i].name << '=' << f[i].value;
  return s.str();
}

// ---------------------------------------------------------------------------
// Clocking (see the cycle convention above).
template <class M> inline void settle(M& m) { m.clk_i = 0; m.eval(); }
template <class M> inline void rise(M& m) { m.clk_i = 1; m.eval(); }
// Asynchronous reset for `cycles` clocks, released with the clock low.
template <class M> inline void reset(M& m, int cycles = 3) {
  m.rst_ni = 0;
  for (int i = 0; i < cycles; ++i) { settle(m); rise(m); }
  m.clk_i = 0;
  m.rst_ni = 1;
  m.eval();
}

// ---------------------------------------------------------------------------
// Stimulus. The seed is CUBE4_SEED (as for Verilator's X randomisation) or a
// fixed default; CUBE4_RTL_VECTORS overrides the random vector count.
inline uint64_t test_seed() {
  const char* env = std::getenv("CUBE4_SEED");
  return env ? std::strtoull(env, nullptr, 10) : 20261124u;
}
inline long vector_count(long default_count) {
  const char* env = std::getenv("CUBE4_RTL_VECTORS");
  return env ? std::atol(env) : default_count;
}

class Random {
 public:
  explicit Random(uint64_t salt) : g_(test_seed() * 0x9E3779B97F4A7C15ull + salt) {}
  uint64_t bits(int n) { return n >= 64 ? g_() : g_() & ((uint64_t{1} << n) - 1); }
  // Uniform in [lo, hi].
  int64_t range(int64_t lo, int64_t hi) {
    return lo + static_cast<int64_t>(g_() % static_cast<uint64_t>(hi - lo + 1));
  }
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(g_) < p; }
  // Uniform in [0, max], but the end points (and their neighbours) with
  // probability `edge`: limits are where rounding and saturation live.
  int64_t edgy(int64_t max, double edge = 0.1) {
    if (chance(edge)) {
      const int64_t c[] = {0, 1, max - 1, max};
      const int64_t v = c[g_() % 4];
      return v < 0 ? 0 : (v > max ? max : v);
    }
    return range(0, max);
  }

 private:
  std::mt19937_64 g_;
};

// ---------------------------------------------------------------------------
// Scoreboard of a valid-only pipeline. In and Out provide `Fields fields()
// const`; Out provides operator==. Per cycle: expect() for an input driven
// with valid_i high, observe() with the unit's valid_o and outputs.
template <class In, class Out>
class Scoreboard {
 public:
  Scoreboard(std::string unit, int latency) : unit_(std::move(unit)), latency_(latency) {}

  void expect(uint64_t cycle, const In& in, const Out& out) { queue_.push_back({cycle, in, out}); }

  void observe(uint64_t cycle, bool valid, const Out& got) {
    const bool due = !queue_.empty() && cycle - queue_.front().cycle == static_cast<uint64_t>(latency_);
    if (!valid) {
      if (due) fail(cycle, queue_.front(), nullptr, "valid_o low, a result was due");
      if (due) queue_.pop_front();
      return;
    }
    if (!due) {
      ++mismatches_;
      if (report_.empty()) {
        std::ostringstream s;
        s << unit_ << ": valid_o high at cycle " << cycle << " with no input due (latency "
          << latency_ << "); got: " << format(got.fields());
        report_ = s.str();
      }
      return;
    }
    ++checked_;
    if (!(got == queue_.front().expected)) fail(cycle, queue_.front(), &got, "output differs");
    queue_.pop_front();
  }

  // Call after the last cycle: every input must have produced its result.
  void finish() {
    if (!queue_.empty()) {
      ++mismatches_;
      if (report_.empty()) {
        std::ostringstream s;
        s << unit_ << ": " << queue_.size() << " inputs never produced a result; first entered at cycle "
          << queue_.front().cycle << ": " << format(queue_.front().in.fields());
        report_ = s.str();
      }
      queue_.clear();
    }
  }

  bool ok() const { return mismatches_ == 0; }
  uint64_t checked() const { return checked_; }
  uint64_t mismatches() const { return mismatches_; }
  std::string report() const {
    if (ok()) return unit_ + ": " + std::to_string(checked_) + " results equal";
    return report_ + "\n  (" + std::to_string(mismatches_) + " mismatches, " + std::to_string(checked_) +
           " results checked)";
  }

 private:
  struct Entry {
    uint64_t cycle;
    In in;
    Out expected;
  };

  void fail(uint64_t cycle, const Entry& e, const Out* got, const char* what) {
    ++mismatches_;
    if (!report_.empty()) return;
    std::ostringstream s;
    s << unit_ << ": first mismatch at cycle " << cycle << " (" << what << "; input driven in cycle "
      << e.cycle << ", latency " << latency_ << ")\n"
      << "  inputs:   " << format(e.in.fields()) << "\n"
      << "  expected: " << format(e.expected.fields()) << "\n"
      << "  got:      " << (got ? format(got->fields()) : std::string("(no valid_o)"));
    report_ = s.str();
  }

  std::string unit_;
  int latency_;
  std::deque<Entry> queue_;
  uint64_t checked_ = 0, mismatches_ = 0;
  std::string report_;
};

// One-shot comparison for combinational units and ad-hoc checks: records the
// first mismatch in the same format.
class Checker {
 public:
  explicit Checker(std::string unit) : unit_(std::move(unit)) {}
  void check(uint64_t cycle, const Fields& in, const Fields& expected, const Fields& got) {
    ++checked_;
    bool same = expected.size() == got.size();
    for (size_t i = 0; same && i < expected.size(); ++i) same = expected[i].value == got[i].value;
    if (same) return;
    ++mismatches_;
    if (!report_.empty()) return;
    std::ostringstream s;
    s << unit_ << ": first mismatch at cycle " << cycle << "\n"
      << "  inputs:   " << format(in) << "\n"
      << "  expected: " << format(expected) << "\n"
      << "  got:      " << format(got);
    report_ = s.str();
  }
  // As check(), but the fields are built (by calling the three functions)
  // only on a mismatch: for the hot loop of a million vectors.
  template <class InFn, class ExpFn, class GotFn>
  void check_lazy(uint64_t cycle, bool equal, InFn in, ExpFn expected, GotFn got) {
    if (equal) {
      ++checked_;
      return;
    }
    check(cycle, in(), expected(), got());
  }
  // A failed property (not a value comparison), e.g. a module accessed twice.
  void fail(uint64_t cycle, const Fields& in, const std::string& what) {
    ++mismatches_;
    if (!report_.empty()) return;
    report_ = unit_ + ": at cycle " + std::to_string(cycle) + ": " + what + "\n  inputs:   " + format(in);
  }
  bool ok() const { return mismatches_ == 0; }
  uint64_t checked() const { return checked_; }
  std::string report() const {
    if (ok()) return unit_ + ": " + std::to_string(checked_) + " results equal";
    return report_ + "\n  (" + std::to_string(mismatches_) + " mismatches, " + std::to_string(checked_) +
           " results checked)";
  }

 private:
  std::string unit_;
  uint64_t checked_ = 0, mismatches_ = 0;
  std::string report_;
};

// ---------------------------------------------------------------------------
// Prints how long a stage of a test took (the million-vector runs and the
// rings' tests are the longest).
struct Timer {
  std::string what;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  explicit Timer(std::string w) : what(std::move(w)) {}
  ~Timer() {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("  [%s: %.2f s]\n", what.c_str(), s);
  }
};

// Probability of valid_i in the datapath tests' stream with random gaps.
constexpr double kGapValid = 0.6;

// Drives a valid-only pipeline: `count` input sets from gen(i), each in a
// cycle with valid_i high (probability valid_prob, junk inputs otherwise),
// then drains. Returns the number of cycles run.
template <class M, class In, class Out, class Gen, class Drive, class Golden, class Read>
uint64_t run_stream(M& m, Scoreboard<In, Out>& sb, long count, double valid_prob, Random& rng, Gen gen,
                Drive drive, Golden golden, Read read, int latency) {
  reset(m);
  uint64_t cycle = 0;
  long sent = 0;
  uint64_t drain = 0;
  while (sent < count || drain <= static_cast<uint64_t>(latency)) {
    const bool v = sent < count && (valid_prob >= 1.0 || rng.chance(valid_prob));
    const In in = v ? gen(sent) : gen(-1);
    drive(m, in);
    m.valid_i = v;
    if (v) sb.expect(cycle, in, golden(in));
    settle(m);
    sb.observe(cycle, m.valid_o, read(m));
    rise(m);
    if (v) ++sent;
    if (sent >= count) ++drain;
    ++cycle;
  }
  sb.finish();
  return cycle;
}

}  // namespace cube4::rtl
