// A failed assertion of a verilated unit (rtl/assert/, docs/verification.md,
// "Assertions"), as an exception: the system stops the frame, and cube4
// render exits with kExitRtlAssertion. Verilator has printed the
// assertion's own message on stdout just before (its instance and label,
// the cycle and the values at fault); this names the unit and the cycle in
// the system's numbering. Free of Verilator's headers, so that code without
// the RTL can catch it.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>

namespace cube4::sysc {

// cube4 render's exit code when an RTL assertion failed (README, docs/verification.md).
constexpr int kExitRtlAssertion = 4;

class RtlAssertionError : public std::runtime_error {
 public:
  RtlAssertionError(const std::string& unit, uint64_t cycle)
      : std::runtime_error("an assertion of the " + unit + " unit (RTL) failed in cycle " + std::to_string(cycle) +
                           " (its message, with the values at fault, is the %Error line before this one)"),
        unit_(unit),
        cycle_(cycle) {}
  const std::string& unit() const { return unit_; }
  uint64_t cycle() const { return cycle_; }

 private:
  std::string unit_;
  uint64_t cycle_;
};

}  // namespace cube4::sysc
