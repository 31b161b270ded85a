// The shader's assertion (rtl/assert/cube4_shade_sva.sv) driven into its
// violation: a coefficient changed, or a table written, while a sample is
// inside; it must fire in that cycle with what changed in its message, and
// not once the sample has left. The shader tests (test_shade.cpp) load
// tables and change modes after draining, as the rule asks, with it on.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "Vcube4_shade.h"
#include "tb/rtl/rtl_check.hpp"
#include "tb/rtl/sva_check.hpp"

namespace {

using namespace cube4::rtl;

constexpr int kLatency = 17;  // cube4_shade's at the default widths

TEST(RtlShadeSva, FrameRegistersStable) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  struct Case {
    int cycle;
    bool table_write;
    const char* message;
  };
  for (const Case c : {Case{kLatency + 1, false, ""}, Case{kLatency + 1, true, ""},
                       Case{kLatency, false, "modes, coefficients or eye changed 1, table writes (class, GmLUT, diffuse, specular) 0000"},
                       Case{2, true, "modes, coefficients or eye changed 0, table writes (class, GmLUT, diffuse, specular) 1000"}}) {
    SvaBench<Vcube4_shade> b;
    b->valid_i = 0;
    b->ke_i = 256;
    b->class_we_i = b->gmlut_we_i = b->dmap_we_i = b->smap_we_i = 0;
    reset(*b);
    for (int cycle = 1; cycle <= kLatency + 3; ++cycle) {
      b->valid_i = cycle == 1;  // the one sample: inside until cycle kLatency
      if (c.table_write)
        b->class_we_i = cycle == c.cycle;
      else if (cycle == c.cycle)
        b->ke_i = 128;
      settle(*b);
      rise(*b);
    }
    if (*c.message)
      expect_fired(b, "a_frame_registers_stable", {"cycle " + std::to_string(c.cycle) + ":", c.message});
    else
      expect_quiet(b);
  }
}

}  // namespace
