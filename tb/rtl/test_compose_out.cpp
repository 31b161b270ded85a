// RTL equivalence tests of the composition network's output stage,
// cube4_compose_out (and through it cube4_acc_to_pixel, the rounding the
// compositing unit's pixel port shares), against golden pixel_of()
// (golden/units/composite.hpp): a composed pixel in the accumulator domain
// to a frame-buffer pixel, one per clock, latency 1.
//
// Random accumulators (edges favoured), every accumulator value of one
// channel where the domain is small enough, and the values around each
// rounding step; driven back to back and with gaps (junk in the gaps),
// each output checked against the input of exactly one cycle before.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>

#include "Vcube4_compose_out.h"
#include "Vcube4_compose_out_a12.h"
#include "Vcube4_compose_out_a8.h"
#include "golden/units/composite.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;
using rtl::Random;

g::Precision widths(int alpha_bits, int guard_bits) {
  g::Precision p;
  p.alpha_bits = alpha_bits;
  p.acc_guard_bits = guard_bits;
  return p;
}

struct OutIn {
  g::RayAcc px;
  Fields fields() const { return {{"red", px.r}, {"green", px.g}, {"blue", px.b}, {"alpha", px.a}}; }
};
struct OutOut {
  g::Pixel px;
  bool operator==(const OutOut& o) const {
    return px.r == o.px.r && px.g == o.px.g && px.b == o.px.b && px.a == o.px.a;
  }
  Fields fields() const { return {{"red", px.r}, {"green", px.g}, {"blue", px.b}, {"alpha", px.a}}; }
};

template <class M>
class OutBench {
 public:
  OutBench(const g::Precision& p, std::string name) : p_(p), sb_(std::move(name), 1), m_(cube4::rtl::make_dut<M>()) {
    rtl::reset(*m_);
  }
  void step(bool v, const g::RayAcc& in) {
    const int a = g::acc_bits(p_);
    rtl::put_bits(m_->red_i, 0, a, in.r);
    rtl::put_bits(m_->green_i, 0, a, in.g);
    rtl::put_bits(m_->blue_i, 0, a, in.b);
    rtl::put_bits(m_->alpha_i, 0, a, in.a);
    m_->valid_i = v;
    if (v) {
      sb_.expect(cycle_, {in}, {g::pixel_of(in, p_)});
      ++vectors;
    }
    rtl::settle(*m_);
    OutOut o;
    const int n = p_.alpha_bits;
    o.px = {static_cast<uint16_t>(rtl::get_bits(m_->red_o, 0, n)), static_cast<uint16_t>(rtl::get_bits(m_->green_o, 0, n)),
            static_cast<uint16_t>(rtl::get_bits(m_->blue_o, 0, n)), static_cast<uint16_t>(rtl::get_bits(m_->alpha_o, 0, n))};
    sb_.observe(cycle_, m_->valid_o, o);
    rtl::rise(*m_);
    ++cycle_;
  }
  testing::AssertionResult result() {
    for (int i = 0; i < 2; ++i) step(false, {});
    sb_.finish();
    if (sb_.ok()) return testing::AssertionSuccess() << sb_.report();
    return testing::AssertionFailure() << sb_.report();
  }
  uint64_t vectors = 0;

 private:
  g::Precision p_;
  rtl::Scoreboard<OutIn, OutOut> sb_;
  cube4::rtl::Dut<M> m_;
  uint64_t cycle_ = 0;
};

template <class M>
void out_stage(const g::Precision& p, const std::string& name, long random_vectors) {
  OutBench<M> b(p, name);
  Random rnd(313);
  const int64_t max = g::max_unsigned(g::acc_bits(p));
  auto any = [&] { return static_cast<uint32_t>(rnd.edgy(max, 0.2)); };
  while (b.vectors < static_cast<uint64_t>(random_vectors)) b.step(!rnd.chance(0.2), {any(), any(), any(), any()});
  // Every value of the accumulator domain up to 2^20 in one channel or
  // another (the others random); above, the values around each step of
  // the rounding: v - (v >> n) crossing a multiple of 2^g, ± half.
  const int64_t exhaustive = std::min<int64_t>(max, (int64_t{1} << 20) - 1);
  for (int64_t v = 0; v <= exhaustive; ++v) {
    g::RayAcc x{any(), any(), any(), any()};
    (&x.r)[v % 4] = static_cast<uint32_t>(v);
    b.step(true, x);
  }
  if (max > exhaustive)
    for (int64_t k = 0; k < 200000; ++k) {
      const int64_t step = rnd.range(0, g::max_unsigned(p.alpha_bits)) << p.acc_guard_bits;
      for (int64_t d = -2; d <= 2; ++d) {
        const int64_t v = std::clamp<int64_t>(step + (step >> p.alpha_bits) + d, 0, max);
        b.step(true, {static_cast<uint32_t>(v), any(), any(), static_cast<uint32_t>(max - v)});
      }
    }
  b.step(true, {0, 0, 0, 0});
  b.step(true, {static_cast<uint32_t>(max), static_cast<uint32_t>(max), static_cast<uint32_t>(max), static_cast<uint32_t>(max)});
  EXPECT_TRUE(b.result());
  EXPECT_GE(b.vectors, static_cast<uint64_t>(random_vectors));
}

}  // namespace

TEST(RtlComposeOut, DefaultWidths) {
  out_stage<Vcube4_compose_out>(widths(16, 8), "cube4_compose_out", rtl::vector_count(1000000));
}
TEST(RtlComposeOut, TwelveBitPixelsFourGuardBits) {
  out_stage<Vcube4_compose_out_a12>(widths(12, 4), "cube4_compose_out (12+4)", 300000);
}
TEST(RtlComposeOut, EightBitPixelsNoGuardBitsIsTheIdentity) {
  out_stage<Vcube4_compose_out_a8>(widths(8, 0), "cube4_compose_out (8+0)", 300000);
}
