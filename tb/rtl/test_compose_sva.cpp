// The compositing node's assertions (rtl/assert/cube4_compose_node_sva.sv),
// each driven into its violation: it must fire, in the cycle of the
// violation, with the values at fault in its message; the same stream
// without the fault must not. The over-mode α sum never passes 1.0 in the
// node, so that invariant's checker is driven alone. The node and
// compositor tests (test_compose.cpp, test_rtl_composite) run both
// assertions on correct streams, where either would abort.
#include <gtest/gtest.h>

#include <cstdint>

#include "Vcube4_compose_node.h"
#include "Vcube4_compose_node_l1.h"
#include "Vcube4_compose_node_sva.h"
#include "tb/rtl/rtl_check.hpp"
#include "tb/rtl/sva_check.hpp"

namespace {

using namespace cube4::rtl;

// A pixel enters in cycle 1, the mode changes in cycle 2: inside the node
// at Latency 2 (default), already out at Latency 1.
template <class M>
void change_mode_behind_a_pixel(SvaBench<M>& b) {
  b->blend_mode_i = 0;
  b->valid_i = 0;
  reset(*b);
  for (int cycle = 1; cycle <= 4; ++cycle) {
    b->valid_i = cycle == 1;
    b->blend_mode_i = cycle >= 2 ? 1 : 0;
    settle(*b);
    rise(*b);
  }
}

TEST(RtlComposeSva, ModeStable) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  SvaBench<Vcube4_compose_node> l2;
  change_mode_behind_a_pixel(l2);
  expect_fired(l2, "a_mode_stable", {"cycle 2:", "blend mode 0 -> 1 with a pixel inside the node"});
  SvaBench<Vcube4_compose_node_l1> l1;
  change_mode_behind_a_pixel(l1);
  expect_quiet(l1);
}

// The checker alone (Latency 2): a pixel with front α 1000 leaves with α
// `alpha` in mode `mode`.
TEST(RtlComposeSva, AlphaNoWrap) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  struct Case {
    int mode, alpha;
    bool fires;
  };
  for (const Case c : {Case{0, 1000, false}, Case{0, 999, true}, Case{3, 999, true}, Case{1, 999, false},
                       Case{2, 999, false}}) {
    SvaBench<Vcube4_compose_node_sva> b;
    b->valid_i = 0;
    b->valid_o = 0;
    reset(*b);
    for (int cycle = 1; cycle <= 4; ++cycle) {
      b->valid_i = cycle == 1;
      b->blend_mode_i = static_cast<uint32_t>(c.mode);
      b->front_alpha_i = cycle == 1 ? 1000 : 0;
      b->valid_o = cycle == 3;
      b->alpha_o = cycle == 3 ? static_cast<uint32_t>(c.alpha) : 0;
      settle(*b);
      rise(*b);
    }
    if (c.fires)
      expect_fired(b, "a_alpha_no_wrap", {"cycle 3:", "over mode composed alpha 999 below the front pixel's 1000"});
    else
      expect_quiet(b);
  }
}

}  // namespace
