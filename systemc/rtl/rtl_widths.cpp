// The refusal of a frame whose widths the verilated RTL was not built
// with, in both builds (with and without RTL).
#include <stdexcept>
#include <string>

#include "systemc/rtl/rtl_factory.hpp"

namespace cube4::sysc {

void require_rtl_widths(const golden::Precision& p, const std::string& what) {
  golden::Precision asked = p;
  asked.tag_bits = 0;
  const golden::Precision built = rtl_precision();
  const golden::PrecisionField* f = golden::first_difference(asked, built, true);
  if (!f) return;
  throw std::invalid_argument(std::string("precision: ") + f->key + " = " + std::to_string(p.*f->member) + ", but " +
                              what + " is verilated with " + f->key + " = " + std::to_string(built.*f->member) +
                              " (CMake CUBE4_SYSTEM_WIDTHS, docs/system.md \"RTL at other widths\"); run these "
                              "widths with --model tlm, or build the RTL with them: scripts/build_widths.sh " +
                              f->rtl_parameter + "=" + std::to_string(p.*f->member) + " ...");
}

}  // namespace cube4::sysc
