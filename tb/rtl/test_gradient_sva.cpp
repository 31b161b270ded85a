// The gradient ring's assertions (rtl/assert/cube4_gradient_unit_sva.sv,
// cube4_gradient_ring_sva.sv, cube4_gradient_sva.sv), each driven into its
// violation: it must fire, in the cycle of the violation, with the values
// at fault in its message. The ring tests (test_gradient_ring.cpp) run the
// same assertions on correct streams, where any of them would abort.
#include <gtest/gtest.h>

#include <cstdint>

#include "Vcube4_gradient.h"
#include "Vcube4_gradient_ring_p2.h"
#include "Vcube4_gradient_ring_p5.h"
#include "systemc/rtl/vl_bits.hpp"
#include "tb/rtl/rtl_check.hpp"
#include "tb/rtl/sva_check.hpp"

namespace {

using namespace cube4::rtl;

constexpr int kVoxelBits = 12;
constexpr int kTagBits = CUBE4_GRADIENT_TAG_BITS;  // rtl/groups/gradient.cmake

// The tag of a plain slice: realign weights 0, S = 1, not a zero slice
// (docs/rtl-gradient.md, "Tag"; R = WeightBits + 1 = 9 bits a field), and
// the zero slice's bit above S's four.
constexpr uint64_t kSupersamplingOne = uint64_t{1} << (4 * 9);
constexpr uint64_t kZeroSlice = uint64_t{1} << (4 * 9 + 4);

// One input cycle of a gradient ring of p pipelines in lock step (the
// samples do not matter here).
template <class M>
void drive(M& m, int p, bool valid, bool bs, bool be, bool ss, bool se, uint64_t tag = kSupersamplingOne) {
  const uint32_t all = (1u << p) - 1;
  m.valid_i = valid ? all : 0;
  m.beam_start_i = bs ? all : 0;
  m.beam_end_i = be ? all : 0;
  m.slice_start_i = ss ? all : 0;
  m.slice_end_i = se ? all : 0;
  for (int k = 0; k < p; ++k) {
    put_bits(m.sample_i, k * kVoxelBits, kVoxelBits, 100 + k);
    put_bits(m.tag_i, k * kTagBits, kTagBits, tag);
  }
  settle(m);
  rise(m);
}

// One slice of `beams` beams of `b` partial beams, back to back (the
// zero slice if `zero`).
template <class M>
void slice(M& m, int p, int beams, int b, bool zero = false) {
  for (int y = 0; y < beams; ++y)
    for (int j = 0; j < b; ++j)
      drive(m, p, true, j == 0, j == b - 1, y == 0, y == beams - 1, kSupersamplingOne | (zero ? kZeroSlice : 0));
}

// A sample inside the unit's zero beam (B = 3 cycles after the zero
// slice); slices before it follow back to back.
TEST(RtlGradientSva, ZeroBeamIdle) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  for (const bool violate : {false, true}) {
    SvaBench<Vcube4_gradient_ring_p2> b;
    reset(*b);
    slice(*b, 2, 2, 3);                         // cycles 1 .. 6
    slice(*b, 2, 2, 3, true);                   // cycles 7 .. 12: the zero slice
    drive(*b, 2, false, 0, 0, 0, 0);            // cycle 13: zero-beam step 1 of 3
    drive(*b, 2, violate, 1, 0, 1, 0);          // cycle 14: step 2, a sample if `violate`
    drive(*b, 2, false, 0, 0, 0, 0);            // cycle 15: step 3
    slice(*b, 2, 2, 3);                         // the next stream, in time
    if (violate)
      expect_fired(b, "a_zero_beam_idle", {"cycle 14:", "(2 of its steps left)"});
    else
      expect_quiet(b);
  }
}

// A beam of 9 partial beams into a ring whose beam delay holds 8 (p = 2, MaxDim 16).
TEST(RtlGradientSva, BeamFits) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  for (const int partial_beams : {8, 9}) {
    SvaBench<Vcube4_gradient_ring_p2> b;
    reset(*b);
    slice(*b, 2, 2, partial_beams);
    if (partial_beams > 8)
      expect_fired(b, "a_beam_fits", {"cycle 9:", "partial beam 8 of beam 0, but the beam delay holds 8"});
    else
      expect_quiet(b);
  }
}

// A slice of 13 beams of 3 partial beams (39 samples) into a ring whose
// slice delay holds 36 (p = 5, MaxDim 12).
TEST(RtlGradientSva, SliceFits) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  for (const int beams : {12, 13}) {
    SvaBench<Vcube4_gradient_ring_p5> b;
    reset(*b);
    slice(*b, 5, beams, 3);
    if (beams > 12)
      expect_fired(b, "a_slice_fits", {"cycle 37:", "sample 36 of a slice, but the slice delay holds 36"});
    else
      expect_quiet(b);
  }
}

// Pipeline 0 valid, pipeline 1 not.
TEST(RtlGradientSva, LockStep) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  SvaBench<Vcube4_gradient_ring_p2> b;
  reset(*b);
  drive(*b, 2, true, 1, 0, 1, 0);
  b->valid_i = 1;
  settle(*b);
  rise(*b);
  expect_fired(b, "a_lock_step", {"cycle 2:", "valid_i 01"});
}

// The datapath alone: a realign weight above 2^WeightBits, then S = 0.
TEST(RtlGradientSva, ControlInRange) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  struct Case {
    int weight, supersampling;
    const char* message;
  };
  for (const Case c : {Case{256, 1, ""}, Case{257, 1, "ahead (0, 257) must lie in [0, 256], supersampling 1"},
                       Case{0, 0, "supersampling 0 in [1, 15]"}}) {
    SvaBench<Vcube4_gradient> b;
    reset(*b);
    b->valid_i = 0;  // cycle 1: junk, not valid
    b->ahead_wy_i = 511;
    b->supersampling_i = 0;
    settle(*b);
    rise(*b);
    b->valid_i = 1;  // cycle 2
    b->behind_wx_i = b->behind_wy_i = b->ahead_wx_i = 0;
    b->ahead_wy_i = static_cast<uint32_t>(c.weight);
    b->supersampling_i = static_cast<uint32_t>(c.supersampling);
    settle(*b);
    rise(*b);
    if (*c.message)
      expect_fired(b, "a_control_in_range", {"cycle 2:", c.message});
    else
      expect_quiet(b);
  }
}

}  // namespace
