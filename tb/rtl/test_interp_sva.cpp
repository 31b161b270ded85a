// The interpolation ring's assertions (rtl/assert/cube4_interp_unit_sva.sv,
// cube4_interp_sva.sv, cube4_delay_ram_sva.sv), each driven into its
// violation: it must fire, in the cycle of the violation, with the values
// at fault in its message; the same stream without the fault must not. The
// ring and datapath tests (test_interp_ring.cpp, test_interp.cpp) run the
// same assertions on correct streams, where any of them would abort.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>

#include "Vcube4_delay_ram_d13.h"
#include "Vcube4_interp.h"
#include "Vcube4_interp_ring_p2.h"
#include "Vcube4_interp_ring_p5.h"
#include "tb/rtl/rtl_check.hpp"
#include "tb/rtl/sva_check.hpp"

namespace {

using namespace cube4::rtl;

// One valid cycle of an interpolation ring: flags, weights (wx, wy, wz).
struct Beat {
  bool bs, be, ss, se;
  int wx = 0, wy = 0, wz = 0;
  bool fl = false;
};

template <class M>
void drive(M& m, const Beat& b) {
  m.valid_i = 1;
  m.beam_start_i = b.bs;
  m.beam_end_i = b.be;
  m.slice_start_i = b.ss;
  m.slice_end_i = b.se;
  m.flush_i = b.fl;
  m.wx_i = static_cast<uint32_t>(b.wx);
  m.wy_i = static_cast<uint32_t>(b.wy);
  m.wz_i = static_cast<uint32_t>(b.wz);
  m.voxel_i = 0x123;
  m.tag_i = 0;
  settle(m);
  rise(m);
}

// A pass: beams 0 .. ny-1 and (flush) a flush beam, each of `b` partial
// beams; `edit` may change beat (y, j) (y = ny: the flush beam) to plant a
// fault.
using Edit = std::function<void(int y, int j, Beat&)>;
template <class M>
void pass(M& m, int ny, int b, int wz, const Edit& edit = nullptr, bool flush = true) {
  for (int y = 0; y < ny + (flush ? 1 : 0); ++y)
    for (int j = 0; j < b; ++j) {
      Beat beat{j == 0, j == b - 1, y == 0 && y < ny, y == ny - 1, 16, 32, wz, y == ny};
      if (edit) edit(y, j, beat);
      drive(m, beat);
    }
}

// Runs `stream` on a fresh ring M; expects assertion `label` with `parts`
// in its message, or (label empty) no assertion.
template <class M>
void run(const std::function<void(M&)>& stream, const std::string& label, std::initializer_list<std::string> parts) {
  run_expecting<M>(stream, label, parts);
}

using P2 = Vcube4_interp_ring_p2;  // MaxDim 16: beam delay 8, slice store 128 entries
using P5 = Vcube4_interp_ring_p5;  // MaxDim 12: beam delay 3, slice store 36 entries

TEST(RtlInterpSva, StreamFraming) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  // Two passes of 2 beams x 3 partial beams and a flush beam (9 cycles
  // each), correct; so are passes back to back, one flush beam at the end,
  // and a flush beam after a flush beam.
  run<P2>([](P2& m) { pass(m, 2, 3, 0); pass(m, 2, 3, 0); }, "", {});
  run<P2>([](P2& m) { pass(m, 2, 3, 0, nullptr, false); pass(m, 1, 3, 0, nullptr, false); pass(m, 2, 3, 0); }, "",
          {});
  run<P2>([](P2& m) { pass(m, 2, 3, 0); pass(m, 0, 3, 0); }, "", {});
  // A flush beam that also claims a slice flag.
  run<P2>([](P2& m) { pass(m, 2, 3, 0, [](int y, int, Beat& b) { if (y == 2) b.ss = true; }); },
          "a_stream_framing", {"cycle 7:", "slice_start 1 slice_end 0 flush 1"});
  run<P2>([](P2& m) { pass(m, 2, 3, 0, [](int y, int, Beat& b) { if (y == 2) b.se = true; }); },
          "a_stream_framing", {"cycle 7:", "slice_end 1 flush 1"});
  // A flush beam shorter than the pass's beams.
  run<P2>([](P2& m) { pass(m, 2, 3, 0, [](int y, int j, Beat& b) { if (y == 2 && j == 1) b.be = true; }); },
          "a_stream_framing", {"cycle 8:", "flush 1 at partial beam 1 (beams of this pass: 3 partial beams"});
  // A pass's second beam after its last (slice_end) beam, not a new pass.
  run<P2>([](P2& m) { pass(m, 2, 3, 0, [](int y, int, Beat& b) { if (y == 0) b.se = true; }, false); },
          "a_stream_framing", {"cycle 4:", "slice_start 0 slice_end 1"});
  // The second partial beam marked as a beam start.
  run<P2>([](P2& m) { pass(m, 2, 3, 0, [](int y, int j, Beat& b) { if (y == 0 && j == 1) b.bs = true; }); },
          "a_stream_framing", {"cycle 2:", "flags beam_start 1 beam_end 0 slice_start 1"});
  // Beam 1 marked as a slice start (a pass's second beam).
  run<P2>([](P2& m) { pass(m, 2, 3, 0, [](int y, int j, Beat& b) { if (y == 1 && j == 0) b.ss = true; }); },
          "a_stream_framing", {"cycle 4:", "slice_start 1"});
  // Beam 1 a partial beam shorter than beam 0.
  run<P2>([](P2& m) { pass(m, 2, 3, 0, [](int y, int j, Beat& b) { if (y == 1 && j == 1) b.be = true; }); },
          "a_stream_framing", {"cycle 5:", "at partial beam 1 (beams of this pass: 3 partial beams"});
}

TEST(RtlInterpSva, WeightsConstant) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  // A new pass may bring new weights ...
  run<P2>([](P2& m) { pass(m, 2, 3, 0); pass(m, 2, 3, 0, [](int, int, Beat& b) { b.wx = 17; }); }, "", {});
  // ... a pass may not change them.
  run<P2>([](P2& m) { pass(m, 2, 3, 0, [](int y, int, Beat& b) { if (y == 1) b.wx = 17; }); },
          "a_weights_constant", {"cycle 4:", "weights (17, 32, 0) changed inside a pass that began with (16, 32, 0)"});
  // A flush beam's weights are ignored.
  run<P2>([](P2& m) { pass(m, 2, 3, 0, [](int y, int, Beat& b) { if (y == 2) b.wx = 17; }); }, "", {});
}

TEST(RtlInterpSva, BeamFits) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  run<P2>([](P2& m) { pass(m, 1, 8, 0); }, "", {});
  run<P2>([](P2& m) { pass(m, 1, 9, 0); }, "a_beam_fits",
          {"cycle 9:", "partial beam 8 of a beam, but the beam delay holds 8"});
}

TEST(RtlInterpSva, SliceFits) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  run<P5>([](P5& m) { pass(m, 12, 3, 0); }, "", {});
  run<P5>([](P5& m) { pass(m, 13, 3, 0); }, "a_slice_fits",
          {"cycle 37:", "voxel 36 of a pass, but the slice store holds 36"});
}

TEST(RtlInterpSva, StoreFilled) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  // wz = 0 fills the store, the wz > 0 passes after it read it.
  run<P2>([](P2& m) { pass(m, 2, 3, 0); pass(m, 2, 3, 128); pass(m, 2, 3, 64); }, "", {});
  // A wz > 0 pass first after reset: nothing stored.
  run<P2>([](P2& m) { pass(m, 2, 3, 128); }, "a_store_filled",
          {"cycle 1:", "a wz = 128 pass reads slice-store entry 0, but the last wz = 0 pass wrote 0 entries"});
  // A wz > 0 pass longer than the slice stored (3 beams after 2).
  run<P2>([](P2& m) { pass(m, 2, 3, 0); pass(m, 3, 3, 128); }, "a_store_filled",
          {"cycle 16:", "entry 6, but the last wz = 0 pass wrote 6 entries"});
}

// The datapath alone: a weight above 2^WeightBits.
TEST(RtlInterpSva, WeightsInRange) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  for (const int w : {256, 257}) {
    SvaBench<Vcube4_interp> b;
    reset(*b);
    b->valid_i = 0;  // cycle 1: out of range, but not valid
    b->wx_i = 511;
    settle(*b);
    rise(*b);
    b->valid_i = 1;  // cycle 2
    b->wx_i = 0;
    b->wy_i = 0;
    b->wz_i = static_cast<uint32_t>(w);
    settle(*b);
    rise(*b);
    if (w > 256)
      expect_fired(b, "a_weights_in_range", {"cycle 2:", "weights (0, 0, 257) must lie in [0, 256]"});
    else
      expect_quiet(b);
  }
}

// The delay RAM alone (MaxDepth 13): a step with depth_i 0 or 14; a clear
// with any depth_i is no step.
TEST(RtlInterpSva, DelayRamDepthInRange) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  for (const int depth : {1, 13, 0, 14}) {
    SvaBench<Vcube4_delay_ram_d13> b;
    reset(*b);
    b->advance_i = 1;  // cycle 1: a clear, not a step
    b->clear_i = 1;
    b->depth_i = 0;
    settle(*b);
    rise(*b);
    b->clear_i = 0;  // cycle 2: a step
    b->last_i = 0;
    b->write_i = 1;
    b->wdata_i = 5;
    b->depth_i = static_cast<uint32_t>(depth);
    settle(*b);
    rise(*b);
    if (depth == 0 || depth > 13)
      expect_fired(b, "a_depth_in_range", {"cycle 2:", "depth_i = " + std::to_string(depth) + ", outside 1 .. 13"});
    else
      expect_quiet(b);
  }
}

}  // namespace
