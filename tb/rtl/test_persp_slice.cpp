// RTL equivalence tests of the perspective weight generator's divisions,
// cube4_persp_slice, against golden perspective_slice()
// (golden/perspective.hpp): every divided constant of a slice, given the
// positions of slices k - 1, k and k + 1 (golden Registers::ray0() and
// ray_spacing(): what cube4_dda's walks hold, tested there), for random
// frame registers and slices (the first and last slice among them). (Every
// slice of the host's perspective scenes is tested through the whole
// weight generator, tb/rtl/test_dda.cpp.) Each slice takes
// the unit's documented cycle count exactly; a start while the unit is
// busy starts it over.
//
// CUBE4_RTL_VECTORS overrides the random slice count (default 20,000: a
// slice is about 840 cycles of the serial divider).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "Vcube4_persp_slice.h"
#include "golden/perspective.hpp"
#include "systemc/rtl/dda_control.hpp"
#include "tb/rtl/persp_registers.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;

constexpr int kFracBits = 20;  // the unit's default FracBits
constexpr int kPosBits = 48;
constexpr int kDivBits = kPosBits + kFracBits;
// The header's count: the start cycle, then per division a load, DivBits
// quotient bits and a finish.
constexpr int kSliceCycles = 1 + 12 * (kDivBits + 2);

// A PosBits port's value: Verilator reads its inputs without masking.
uint64_t port(int64_t v) { return static_cast<uint64_t>(v) & ((uint64_t{1} << kPosBits) - 1); }

class Bench {
 public:
  Bench() { rtl::reset(m_); }

  // Runs slice k of r; checks every constant and the cycle count.
  void check(const g::Registers& r, int k, rtl::Checker& c, bool interrupted = false) {
    const int K = r.sample_slices();
    // A slice's neighbours outside the frame are the DDAs' continuation,
    // as cube4_dda's walks hold them; the unit must not use them.
    m_.spacing_behind_i = port(r.ray_spacing(k - 1));
    m_.spacing_i = port(r.ray_spacing(k));
    m_.spacing_ahead_i = port(r.ray_spacing(k + 1));
    m_.ray0_x_behind_i = port(r.ray0(0, k - 1));
    m_.ray0_x_i = port(r.ray0(0, k));
    m_.ray0_x_ahead_i = port(r.ray0(0, k + 1));
    m_.ray0_y_behind_i = port(r.ray0(1, k - 1));
    m_.ray0_y_i = port(r.ray0(1, k));
    m_.ray0_y_ahead_i = port(r.ray0(1, k + 1));
    m_.has_behind_i = k > 0;
    m_.has_ahead_i = k + 1 < K;
    m_.dim_x_i = static_cast<uint32_t>(r.dim[0]);
    m_.dim_y_i = static_cast<uint32_t>(r.dim[1]);
    if (interrupted) {
      // Another slice's divisions, started over part-way: none of their
      // results may remain.
      m_.spacing_i = port(r.ray_spacing(k + 5));
      m_.ray0_x_i = port(r.ray0(0, k + 5));
      m_.start_i = 1;
      for (int i = 0; i < kSliceCycles / 2 + k % 97; ++i, ++cycle_) {
        rtl::settle(m_);
        rtl::rise(m_);
        m_.start_i = 0;
      }
      m_.spacing_i = port(r.ray_spacing(k));
      m_.ray0_x_i = port(r.ray0(0, k));
    }
    m_.start_i = 1;
    rtl::settle(m_);
    rtl::rise(m_);
    ++cycle_;
    m_.start_i = 0;
    int cycles = 1;
    for (;; ++cycles) {
      rtl::settle(m_);
      if (m_.done_o || cycles > 4 * kSliceCycles) break;
      rtl::rise(m_);
      ++cycle_;
    }
    const g::PerspectiveSlice s = g::perspective_slice(r, k);
    auto in = [&] {
      return Fields{{"k", k},           {"K", K}, {"scale_start", r.scale_start},
                    {"scale_step", r.scale_step}, {"x_start", r.x_start}, {"x_step", r.x_step},
                    {"y_start", r.y_start}, {"y_step", r.y_step}, {"nx", r.dim[0]}, {"ny", r.dim[1]}};
    };
    g::PerspectiveSlice out;
    rtl::read_divided_constants(m_, kPosBits, out);
    Fields expected{{"cycles", kSliceCycles}}, got{{"cycles", m_.done_o ? cycles : -1}};
    const Fields want_divided = rtl::divided_fields(s), got_divided = rtl::divided_fields(out);
    expected.insert(expected.end(), want_divided.begin(), want_divided.end());
    got.insert(got.end(), got_divided.begin(), got_divided.end());
    c.check(cycle_, in(), expected, got);
    rtl::rise(m_);  // the done cycle
    ++cycle_;
  }

 private:
  cube4::rtl::Dut<Vcube4_persp_slice> dut_ = cube4::rtl::make_dut<Vcube4_persp_slice>();
  Vcube4_persp_slice& m_ = *dut_;
  uint64_t cycle_ = 0;
};

TEST(RtlPerspSlice, FracBitsIsGoldens) { EXPECT_EQ(g::Precision{}.dda_frac_bits, kFracBits); }

TEST(RtlPerspSlice, RandomRegistersAndSlicesMatchGolden) {
  rtl::Random rng(41);
  Bench b;
  rtl::Checker c("cube4_persp_slice");
  const long n = rtl::vector_count(20000);
  rtl::Timer t("cube4_persp_slice: " + std::to_string(n) + " random slices");
  for (long i = 0; i < n && c.ok(); ++i) {
    const g::Registers r = cube4::rtl::random_perspective_registers(rng, kFracBits);
    const int K = r.sample_slices();
    // The first and the last slice (no neighbour behind, none ahead) often.
    const int k = i % 4 == 0 ? 0 : i % 4 == 1 ? K - 1 : static_cast<int>(rng.range(0, K - 1));
    b.check(r, k, c, i % 16 == 7);
  }
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_EQ(c.checked(), static_cast<uint64_t>(n));
}

}  // namespace
