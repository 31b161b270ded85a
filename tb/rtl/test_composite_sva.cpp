// The compositing ring's assertions (rtl/assert/cube4_composite_unit_sva.sv,
// cube4_composite_sva.sv), each driven into its violation: it must fire, in
// the cycle of the violation, with the values at fault in its message; the
// same stream without the fault must not. The ray-store order is an
// invariant of the unit, which no stream breaks: its checker is driven
// alone. The ring and datapath tests (test_composite_ring.cpp,
// test_composite.cpp) run every assertion on correct streams, where any of
// them would abort.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>

#include "Vcube4_composite.h"
#include "Vcube4_composite_ring_p2.h"
#include "Vcube4_composite_ring_p5.h"
#include "Vcube4_composite_unit_sva.h"
#include "tb/rtl/rtl_check.hpp"
#include "tb/rtl/sva_check.hpp"

namespace {

using namespace cube4::rtl;

using P2 = Vcube4_composite_ring_p2;  // MaxDim 16: ray beam delay 8, ray slice store 128 entries
using P5 = Vcube4_composite_ring_p5;  // MaxDim 12: ray beam delay 3, ray slice store 36 entries

// A slice of `beams` beams of `b` partial beams into a compositing ring
// (the sample values, positions and slice tags do not matter here: every
// other input keeps the value it has).
template <class M>
void slice(M& m, int beams, int b, bool first) {
  for (int y = 0; y < beams; ++y)
    for (int j = 0; j < b; ++j) {
      m.valid_i = 1;
      m.beam_start_i = j == 0;
      m.beam_end_i = j == b - 1;
      m.slice_start_i = y == 0;
      m.slice_end_i = y == beams - 1;
      m.first_slice_i = first;
      m.last_slice_i = 0;
      settle(m);
      rise(m);
    }
}

template <class M>
void run_slices(std::initializer_list<std::array<int, 2>> slices, const std::string& label,
                std::initializer_list<std::string> parts) {
  SvaBench<M> b;
  reset(*b);
  bool first = true;
  for (const auto& s : slices) {
    slice(*b, s[0], s[1], first);
    first = false;
  }
  if (label.empty())
    expect_quiet(b);
  else
    expect_fired(b, label, parts);
}

TEST(RtlCompositeSva, BeamFits) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  run_slices<P2>({{1, 8}}, "", {});
  run_slices<P2>({{1, 9}}, "a_beam_fits", {"cycle 9:", "partial beam 8 of a beam, but the ray beam delay holds 8"});
}

TEST(RtlCompositeSva, SliceFits) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  run_slices<P5>({{12, 3}}, "", {});
  run_slices<P5>({{13, 3}}, "a_slice_fits", {"cycle 37:", "sample 36 of a slice, but the ray slice store holds 36"});
}

// Slice 1 one beam longer than slice 0: its last beam has no stored rays.
TEST(RtlCompositeSva, SliceReadWritten) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  run_slices<P2>({{2, 3}, {2, 3}, {2, 3}}, "", {});
  run_slices<P2>({{2, 3}, {3, 3}}, "a_slice_read_written",
                 {"cycle 13:", "sample 6 of a slice continues a stored ray, but the slice before stored 6"});
}

// The checker alone: a step's ray written one cycle late.
TEST(RtlCompositeSva, RayStoreOrder) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  for (const int delay : {1, 2}) {
    SvaBench<Vcube4_composite_unit_sva> b;
    b->valid_i = 0;
    b->first_slice_i = 1;
    reset(*b);
    for (int cycle = 1; cycle <= 4; ++cycle) {
      b->step = cycle == 1;
      b->result_valid = cycle == 1 + delay;
      settle(*b);
      rise(*b);
    }
    if (delay == 1)
      expect_quiet(b);
    else
      expect_fired(b, "a_ray_store_order", {"cycle 2:", "ray store written 0, step in the cycle before 1"});
  }
}

// The datapath alone: a frame register changed within the 6 cycles after a
// sample entered (stages 2 .. 7 still read it), and one cycle later.
TEST(RtlCompositeSva, FrameRegistersStable) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  struct Case {
    int change_cycle;
    bool crop;
    const char* message;
  };
  for (const Case c : {Case{8, false, ""}, Case{7, false, "blend mode 0 -> 1, cropping changed 0, cut plane changed 0"},
                       Case{2, true, "blend mode 0 -> 0, cropping changed 1, cut plane changed 0"}}) {
    SvaBench<Vcube4_composite> b;
    b->blend_mode_i = 0;
    b->crop_enabled_i = 0;
    b->crop_x_lo_i = 0;
    b->poly_enabled_i = 0;
    b->valid_i = 0;
    reset(*b);
    for (int cycle = 1; cycle <= 10; ++cycle) {
      b->valid_i = cycle == 1;
      if (cycle == c.change_cycle) {
        if (c.crop)
          b->crop_x_lo_i = 3;
        else
          b->blend_mode_i = 1;
      }
      settle(*b);
      rise(*b);
    }
    if (*c.message)
      expect_fired(b, "a_frame_registers_stable",
                   {"cycle " + std::to_string(c.change_cycle) + ":", c.message});
    else
      expect_quiet(b);
  }
}

// Polygons only with the composite blend, and with sample slices below 2^15
// (so that kZNone hides nothing); the same streams within the rules are quiet.
TEST(RtlCompositeSva, PolygonPreconditions) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  struct Case {
    int mode;
    unsigned k;
    const char* label;
    const char* message;
  };
  for (const Case c : {Case{0, 32767, "", ""}, Case{3, 5, "", ""},
                       Case{1, 5, "a_polygons_composite", "polygons with blend mode 1"},
                       Case{0, 32768, "a_slice_in_range", "sample slice 32768 with polygons: at most 32767"}}) {
    SvaBench<Vcube4_composite> b;
    b->blend_mode_i = static_cast<uint8_t>(c.mode);
    b->crop_enabled_i = 0;
    b->cut_enabled_i = 0;
    b->window_enabled_i = 0;
    b->poly_enabled_i = 1;
    b->slice_k_i = static_cast<uint16_t>(c.k);
    b->valid_i = 0;
    reset(*b);
    for (int cycle = 1; cycle <= 10; ++cycle) {
      b->valid_i = cycle == 2;
      settle(*b);
      rise(*b);
    }
    if (*c.label)
      expect_fired(b, c.label, {"cycle 2:", c.message});
    else
      expect_quiet(b);
  }
}

}  // namespace
