// Where and when the RTL units trace. Kept apart from systemc/rtl/rtl_model.hpp
// so the system's interface does not need Verilator's headers (CUBE4_RTL=OFF).
#pragma once
#include <cstdint>
#include <string>

namespace cube4::sysc {

// file empty: no tracing.
struct TraceWindow {
  std::string file;
  uint64_t first = 0, last = UINT64_MAX;  // cycles, inclusive
};

}  // namespace cube4::sysc
