// The address generator's assertions (rtl/assert/cube4_addr_sva.sv), each
// driven into its violation: it must fire, in the cycle of the violation,
// with the values at fault in its message; the same input without the
// fault must not. No traversal makes the unit hand a pipeline the wrong
// module, so that checker is driven alone. The unit's tests (test_addr.cpp)
// run both assertions on every traversal, where either would abort.
#include <gtest/gtest.h>

#include <cstdint>

#include "Vcube4_addr.h"
#include "Vcube4_addr_sva.h"
#include "tb/rtl/rtl_check.hpp"
#include "tb/rtl/sva_check.hpp"

namespace {

using namespace cube4::rtl;

constexpr int kDimBits = 10;  // cube4_addr's default

uint32_t perm_bits(int p0, int p1, int p2) { return static_cast<uint32_t>(p0 | p1 << 2 | p2 << 4); }
uint32_t dim_bits(int nx, int ny, int nz) {
  return static_cast<uint32_t>(nx | ny << kDimBits | static_cast<uint32_t>(nz) << 2 * kDimBits);
}

TEST(RtlAddrSva, StartConfig) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  struct Case {
    uint32_t perm, dim;
    const char* message;
  };
  for (const Case c : {Case{perm_bits(2, 0, 1), dim_bits(5, 6, 7), ""},
                       Case{perm_bits(0, 0, 2), dim_bits(5, 6, 7), "start with perm 0 0 2"},
                       Case{perm_bits(0, 3, 1), dim_bits(5, 6, 7), "start with perm 0 3 1"},
                       Case{perm_bits(0, 1, 2), dim_bits(5, 6, 0), "dims 5 x 6 x 0"}}) {
    SvaBench<Vcube4_addr> b;
    b->start_i = 0;
    b->advance_i = 0;
    reset(*b);
    b->perm_i = 0x3F;  // cycle 1: no start, any registers
    b->dim_i = 0;
    settle(*b);
    rise(*b);
    b->start_i = 1;  // cycle 2
    b->perm_i = c.perm;
    b->flip_i = 0;
    b->dim_i = c.dim;
    settle(*b);
    rise(*b);
    if (*c.message)
      expect_fired(b, "a_start_config", {"cycle 2:", c.message});
    else
      expect_quiet(b);
  }
}

// The checker alone (p = 4), a partial beam of beam 1, slice 2 of a 5 x 6 x 7
// volume in object order: pipeline k's voxel (4j + k, 1, 2) is in module
// (3 + k) mod 4; with the beam axis backwards, (4 - k) + 1 + 2 = (3 - k) mod 4.
TEST(RtlAddrSva, OneAccessPerModule) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  struct Case {
    int flip, rotation, reverse;
    const char* message;
  };
  for (const Case c : {Case{0, 3, 0, ""}, Case{1, 3, 1, ""},
                       Case{0, 2, 0, "de-skew rotation 2 reverse 0, but pipeline k's voxel is in module (3 + k) mod 4"},
                       Case{1, 3, 0, "de-skew rotation 3 reverse 0, but pipeline k's voxel is in module (3 - k) mod 4"}}) {
    SvaBench<Vcube4_addr_sva> b;
    b->start_i = 0;
    b->valid_o = 0;
    reset(*b);
    b->perm_q = perm_bits(0, 1, 2);
    b->flip_q = static_cast<uint32_t>(c.flip);
    b->n_q = dim_bits(5, 6, 7);
    b->valid_o = 1;  // cycle 1
    b->beam_o = 1;
    b->y_o = 1;
    b->z_o = 2;
    b->rotation_o = static_cast<uint32_t>(c.rotation);
    b->reverse_o = c.reverse;
    settle(*b);
    rise(*b);
    if (*c.message)
      expect_fired(b, "a_one_access_per_module", {"cycle 1:", "partial beam 1, beam 1, slice 2", c.message});
    else
      expect_quiet(b);
  }
}

}  // namespace
