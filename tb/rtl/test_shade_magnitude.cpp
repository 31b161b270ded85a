// RTL equivalence tests of the shading unit's gradient magnitude against the
// golden function (golden/units/shade_magnitude.hpp): cube4_udiv
// (combinational) and cube4_shade_magnitude at default and non-default
// parameters. The rest of the shading unit: test_shade.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include "Vcube4_udiv.h"
#include "Vcube4_shade_magnitude.h"
#include "Vcube4_shade_magnitude_g10.h"
#include "Vcube4_shade_magnitude_n0.h"
#include "golden/precision.hpp"
#include "golden/units/shade_magnitude.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
using cube4::rtl::Fields;
using cube4::rtl::Random;
using cube4::rtl::Scoreboard;
using cube4::rtl::Timer;
using cube4::rtl::run_stream;
using cube4::rtl::sign_extend;

constexpr int magnitude_latency(int nr_iterations) { return nr_iterations + 1; }  // the module's header
// Random vectors per parameter set: a stream with valid_i always high, and
// one with random valid gaps (CUBE4_RTL_VECTORS overrides).
const long kRandom = cube4::rtl::vector_count(1000000);
const long kRandomGaps = cube4::rtl::vector_count(1000000);

TEST(RtlUdiv, MatchesCppDivision) {
  constexpr int N = 16, D = 9;  // cube4_udiv defaults
  constexpr uint64_t nmax = (1u << N) - 1, dmax = (1u << D) - 1;
  const auto dut = cube4::rtl::make_dut<Vcube4_udiv>();
  Vcube4_udiv& m = *dut;
  cube4::rtl::Checker c("cube4_udiv");
  uint64_t n = 0;
  auto one = [&](uint64_t a, uint64_t b) {
    m.dividend_i = a;
    m.divisor_i = b;
    m.eval();
    const uint64_t eq = a / b, er = a % b, gq = m.quotient_o, gr = m.remainder_o;
    c.check_lazy(n++, eq == gq && er == gr, [&] { return Fields{{"dividend", int64_t(a)}, {"divisor", int64_t(b)}}; },
                 [&] { return Fields{{"quotient", int64_t(eq)}, {"remainder", int64_t(er)}}; },
                 [&] { return Fields{{"quotient", int64_t(gq)}, {"remainder", int64_t(gr)}}; });
  };
  for (uint64_t b : {uint64_t{1}, uint64_t{2}, uint64_t{3}, uint64_t{7}, uint64_t{255}, uint64_t{256}, dmax - 1, dmax})
    for (uint64_t a = 0; a <= nmax; ++a) one(a, b);
  Random rng(2);
  for (long i = 0; i < kRandom; ++i) {
    const uint64_t b = 1 + rng.bits(D) % dmax;
    // Dividends near multiples of the divisor as often as uniform ones.
    uint64_t a = rng.bits(N);
    if (rng.chance(0.5)) a = std::min<uint64_t>(nmax, a / b * b + rng.range(0, 2) - (a >= b ? 1 : 0));
    one(a, b);
  }
  // A zero divisor gives an all-ones quotient (documented, never X).
  m.dividend_i = 12345;
  m.divisor_i = 0;
  m.eval();
  EXPECT_EQ(m.quotient_o, nmax);
  m.final();
  EXPECT_TRUE(c.ok()) << c.report();
  std::printf("  cube4_udiv: %llu vectors\n", static_cast<unsigned long long>(c.checked()));
}

struct MagIn {
  int32_t x = 0, y = 0, z = 0;
  Fields fields() const {
    return {{"gx", x}, {"gy", y}, {"gz", z}, {"q", int64_t{x} * x + int64_t{y} * y + int64_t{z} * z}};
  }
};
struct MagOut {
  uint32_t m = 0;
  bool operator==(const MagOut& o) const { return m == o.m; }
  Fields fields() const { return {{"magnitude", m}}; }
};

// A gradient (a >= b >= c >= 0, a <= amax) with a^2 + b^2 + c^2 = q, if any.
bool find_triple(int64_t q, int64_t amax, std::array<int32_t, 3>& out) {
  auto isqrt = [](int64_t v) {
    int64_t r = static_cast<int64_t>(std::sqrt(static_cast<double>(v)));
    while (r * r > v) --r;
    while ((r + 1) * (r + 1) <= v) ++r;
    return r;
  };
  for (int64_t a = std::min(amax, isqrt(q)); a >= 0 && 3 * a * a >= q; --a) {
    const int64_t r1 = q - a * a;
    for (int64_t b = std::min(a, isqrt(r1)); b >= 0 && 2 * b * b >= r1; --b) {
      const int64_t r2 = r1 - b * b, c = isqrt(r2);
      if (c * c == r2 && c <= b) {
        out = {static_cast<int32_t>(a), static_cast<int32_t>(b), static_cast<int32_t>(c)};
        return true;
      }
    }
  }
  return false;
}

template <class M>
struct MagnitudeBench {
  g::Precision p;
  int latency;
  int G;
  explicit MagnitudeBench(const g::Precision& prec)
      : p(prec), latency(magnitude_latency(prec.nr_iterations)), G(prec.gradient_bits) {}
  void drive(M& m, const MagIn& in) const {
    m.gx_i = static_cast<uint32_t>(in.x) & ((1u << G) - 1);
    m.gy_i = static_cast<uint32_t>(in.y) & ((1u << G) - 1);
    m.gz_i = static_cast<uint32_t>(in.z) & ((1u << G) - 1);
  }
  MagOut golden(const MagIn& in) const { return MagOut{g::gradient_magnitude(g::Gradient{in.x, in.y, in.z}, p)}; }
  static MagOut read(M& m) { return MagOut{static_cast<uint32_t>(m.magnitude_o)}; }

  // q at every power-of-two boundary (2^k - 1, 2^k, 2^k + 1) and around
  // every perfect square (r^2 - 1, r^2, r^2 + 1), each reached by some
  // gradient when q is a sum of three squares; signs varied.
  std::vector<MagIn> boundaries(int* unreachable) const {
    const int64_t amax = int64_t{1} << (G - 1);
    const int64_t qmax = 3 * amax * amax;
    std::vector<int64_t> qs;
    for (int k = 0; (int64_t{1} << k) <= qmax + 1; ++k)
      for (int64_t d : {-1, 0, 1}) qs.push_back((int64_t{1} << k) + d);
    for (int64_t r = 0; r * r <= qmax + 1; ++r)
      for (int64_t d : {-1, 0, 1}) qs.push_back(r * r + d);
    std::sort(qs.begin(), qs.end());
    qs.erase(std::unique(qs.begin(), qs.end()), qs.end());
    std::vector<MagIn> v;
    *unreachable = 0;
    int sign = 0;
    for (int64_t q : qs) {
      if (q < 0 || q > qmax) continue;
      std::array<int32_t, 3> t;
      if (!find_triple(q, amax, t)) {
        ++*unreachable;
        continue;
      }
      ++sign;
      // +2^(G-1) is not representable: only its negation is.
      auto sg = [&](int32_t x, int bit) { return (x == amax || (sign >> bit & 1)) ? -x : x; };
      v.push_back({sg(t[0], 0), sg(t[1], 1), sg(t[2], 2)});
    }
    return v;
  }
};

template <class M>
void test_magnitude_random(const char* unit, const g::Precision& p, bool exhaustive) {
  MagnitudeBench<M> b(p);
  const int G = p.gradient_bits;
  const int32_t lo = -(1 << (G - 1)), hi = (1 << (G - 1)) - 1;
  int unreachable = 0;
  std::vector<MagIn> directed = b.boundaries(&unreachable);
  const long nb = static_cast<long>(directed.size());
  Random rng(30 + G);
  auto random_in = [&] {
    MagIn in;
    // Small gradients as often as arbitrary ones: the low q range is where
    // the start value and the few iterations matter most.
    const int bits = rng.chance(0.5) ? static_cast<int>(rng.range(1, G)) : G;
    auto comp = [&] { return static_cast<int32_t>(sign_extend(rng.bits(bits), bits)); };
    in.x = comp(), in.y = comp(), in.z = comp();
    return in;
  };
  auto drive = [&](M& m, const MagIn& in) { b.drive(m, in); };
  auto golden = [&](const MagIn& in) { return b.golden(in); };
  auto read = [](M& m) { return MagnitudeBench<M>::read(m); };
  auto m = cube4::rtl::make_dut<M>();
  {
    Timer t(unit);
    Scoreboard<MagIn, MagOut> sb(unit, b.latency);
    auto gen = [&](long i) { return i >= 0 && i < nb ? directed[i] : random_in(); };
    run_stream(*m, sb, nb + kRandom, 1.0, rng, gen, drive, golden, read, b.latency);
    EXPECT_TRUE(sb.ok()) << sb.report();
    Scoreboard<MagIn, MagOut> gaps(std::string(unit) + " (valid gaps)", b.latency);
    run_stream(*m, gaps, kRandomGaps, cube4::rtl::kGapValid, rng, [&](long) { return random_in(); }, drive, golden, read, b.latency);
    EXPECT_TRUE(gaps.ok()) << gaps.report();
    std::printf("  %s G=%d M=%d N=%d: %ld boundary q (%d not sums of three squares), %llu directed+random, "
                "%llu with gaps\n",
                unit, G, p.magnitude_bits, p.nr_iterations, nb, unreachable,
                static_cast<unsigned long long>(sb.checked()), static_cast<unsigned long long>(gaps.checked()));
  }
  if (exhaustive) {
    // Every gradient of the input range, one per clock.
    Timer t("exhaustive");
    Scoreboard<MagIn, MagOut> sb(std::string(unit) + " (exhaustive)", b.latency);
    const int64_t side = int64_t{hi} - lo + 1;
    auto gen = [&](long i) {
      if (i < 0) return MagIn{};
      return MagIn{static_cast<int32_t>(lo + i % side), static_cast<int32_t>(lo + i / side % side),
                   static_cast<int32_t>(lo + i / (side * side))};
    };
    run_stream(*m, sb, static_cast<long>(side * side * side), 1.0, rng, gen, drive, golden, read, b.latency);
    EXPECT_TRUE(sb.ok()) << sb.report();
    std::printf("  %s exhaustive: %llu gradients\n", unit, static_cast<unsigned long long>(sb.checked()));
  }
  m->final();
}

TEST(RtlShadeMagnitude, DefaultWidths) { test_magnitude_random<Vcube4_shade_magnitude>("cube4_shade_magnitude", g::Precision{}, true); }
TEST(RtlShadeMagnitude, Gradient10Magnitude9Iterations2) {
  g::Precision p;
  p.gradient_bits = 10, p.magnitude_bits = 9, p.nr_iterations = 2;
  test_magnitude_random<Vcube4_shade_magnitude_g10>("cube4_shade_magnitude_g10", p, false);
}
TEST(RtlShadeMagnitude, NoIterations) {
  g::Precision p;
  p.nr_iterations = 0;
  test_magnitude_random<Vcube4_shade_magnitude_n0>("cube4_shade_magnitude_n0", p, false);
}

}  // namespace
