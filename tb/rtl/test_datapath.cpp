// RTL equivalence tests of the datapath units against the golden functions:
// cube4_lerp, cube4_udiv, cube4_trilinear, cube4_gradient, cube4_magnitude
// (default and non-default parameters) and cube4_skew_addr (p = 1, 2, 4, 5, 8).
// The golden functions are the checkers; nothing here re-implements them.
// Every pipelined unit is driven with one input set per clock, and again with
// random valid gaps; each output is compared with the golden result of the
// input that entered `latency` cycles earlier (rtl_check.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include "Vcube4_gradient.h"
#include "Vcube4_gradient_v16.h"
#include "Vcube4_gradient_v8.h"
#include "Vcube4_lerp.h"
#include "Vcube4_magnitude.h"
#include "Vcube4_magnitude_g10.h"
#include "Vcube4_magnitude_n0.h"
#include "Vcube4_skew_addr.h"
#include "Vcube4_skew_addr_p1.h"
#include "Vcube4_skew_addr_p2.h"
#include "Vcube4_skew_addr_p5.h"
#include "Vcube4_skew_addr_p8.h"
#include "Vcube4_trilinear.h"
#include "Vcube4_trilinear_w10.h"
#include "Vcube4_trilinear_w6.h"
#include "Vcube4_udiv.h"
#include "golden/pipeline.hpp"
#include "golden/units/magnitude.hpp"
#include "golden/units/skew.hpp"
#include "golden/units/trilinear.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
using cube4::rtl::Fields;
using cube4::rtl::Random;
using cube4::rtl::Scoreboard;
using cube4::rtl::get_bits;
using cube4::rtl::put_bits;
using cube4::rtl::sign_extend;

// Latencies stated in the module headers.
constexpr int kTrilinearLatency = 3;
constexpr int kGradientLatency = 3;
constexpr int kSkewStartLatency = 7;
constexpr int magnitude_latency(int nr_iterations) { return nr_iterations + 1; }

// Random vectors per unit and parameter set: a stream with valid_i always
// high, and one with random valid gaps (CUBE4_RTL_VECTORS overrides).
const long kRandom = cube4::rtl::vector_count(1000000);
const long kRandomGaps = cube4::rtl::vector_count(1000000);
constexpr double kGapValid = 0.6;  // probability of valid_i in the gap stream

struct Timer {
  const char* what;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  explicit Timer(const char* w) : what(w) {}
  ~Timer() {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("  [%s: %.2f s]\n", what, s);
  }
};

// Drives a valid-only pipeline: `count` input sets from gen(i), each in a
// cycle with valid_i high (probability valid_prob, junk inputs otherwise),
// then drains. Returns the number of cycles run.
template <class M, class In, class Out, class Gen, class Drive, class Golden, class Read>
uint64_t stream(M& m, Scoreboard<In, Out>& sb, long count, double valid_prob, Random& rng, Gen gen,
                Drive drive, Golden golden, Read read, int latency) {
  cube4::rtl::reset(m);
  uint64_t cycle = 0;
  long sent = 0;
  uint64_t drain = 0;
  while (sent < count || drain <= static_cast<uint64_t>(latency)) {
    const bool v = sent < count && (valid_prob >= 1.0 || rng.chance(valid_prob));
    const In in = v ? gen(sent) : gen(-1);
    drive(m, in);
    m.valid_i = v;
    if (v) sb.expect(cycle, in, golden(in));
    cube4::rtl::settle(m);
    sb.observe(cycle, m.valid_o, read(m));
    cube4::rtl::rise(m);
    if (v) ++sent;
    if (sent >= count) ++drain;
    ++cycle;
  }
  sb.finish();
  return cycle;
}

// ===========================================================================
// cube4_lerp (combinational), cube4_udiv (combinational)

TEST(RtlLerp, MatchesGolden) {
  constexpr int V = 12, W = 8;
  constexpr int64_t vmax = (1 << V) - 1, wmax = 1 << W;
  Vcube4_lerp m;
  cube4::rtl::Checker c("cube4_lerp");
  uint64_t n = 0;
  auto one = [&](int64_t a, int64_t b, int64_t w) {
    m.a_i = a;
    m.b_i = b;
    m.w_i = w;
    m.eval();
    const int64_t exp = g::lerp(a, b, w, W), got = m.y_o;
    c.check_lazy(n++, exp == got, [&] { return Fields{{"a", a}, {"b", b}, {"w", w}}; },
                 [&] { return Fields{{"y", exp}}; }, [&] { return Fields{{"y", got}}; });
  };
  // Directed: extreme and mid values against every weight 0 .. 2^W.
  const int64_t vals[] = {0, 1, 2, vmax / 2, vmax / 2 + 1, vmax - 2, vmax - 1, vmax};
  for (int64_t a : vals)
    for (int64_t b : vals)
      for (int64_t w = 0; w <= wmax; ++w) one(a, b, w);
  // Every difference b - a with the rounding-critical weights.
  for (int64_t d = -vmax; d <= vmax; ++d)
    for (int64_t w : {int64_t{1}, wmax / 2 - 1, wmax / 2, wmax / 2 + 1, wmax - 1})
      one(d < 0 ? -d : 0, d < 0 ? 0 : d, w);
  Random rng(1);
  for (long i = 0; i < kRandom; ++i) one(rng.bits(V), rng.bits(V), rng.edgy(wmax));
  m.final();
  EXPECT_TRUE(c.ok()) << c.report();
  std::printf("  cube4_lerp: %llu vectors\n", static_cast<unsigned long long>(c.checked()));
}

TEST(RtlUdiv, MatchesCppDivision) {
  constexpr int N = 16, D = 9;  // cube4_udiv defaults
  constexpr uint64_t nmax = (1u << N) - 1, dmax = (1u << D) - 1;
  Vcube4_udiv m;
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

// ===========================================================================
// cube4_trilinear

struct TriIn {
  std::array<uint32_t, 8> v{};
  uint32_t wx = 0, wy = 0, wz = 0;
  Fields fields() const {
    Fields f;
    for (int i = 0; i < 8; ++i) f.push_back({"v" + std::to_string(i), v[i]});
    f.push_back({"wx", wx});
    f.push_back({"wy", wy});
    f.push_back({"wz", wz});
    return f;
  }
};
struct TriOut {
  uint32_t sample = 0;
  bool operator==(const TriOut& o) const { return sample == o.sample; }
  Fields fields() const { return {{"sample", sample}}; }
};

template <class M>
void test_trilinear(const char* unit, int V, int W) {
  const uint32_t vmax = (1u << V) - 1, wmax = 1u << W;
  // Directed: every {0, max} voxel pattern with every combination of corner
  // weights; then constant volumes (every weight must return the voxel).
  std::vector<TriIn> directed;
  const uint32_t wc[] = {0, 1, wmax / 2, wmax - 1, wmax};
  for (uint32_t pat = 0; pat < 256; ++pat)
    for (uint32_t wx : wc)
      for (uint32_t wy : wc)
        for (uint32_t wz : wc) {
          TriIn in;
          for (int i = 0; i < 8; ++i) in.v[i] = (pat >> i & 1) ? vmax : 0;
          in.wx = wx, in.wy = wy, in.wz = wz;
          directed.push_back(in);
        }
  Random rng(10 + V * 100 + W);
  for (int k = 0; k < 2000; ++k) {
    TriIn in;
    in.v.fill(static_cast<uint32_t>(rng.edgy(vmax)));
    in.wx = rng.range(0, wmax), in.wy = rng.range(0, wmax), in.wz = rng.range(0, wmax);
    directed.push_back(in);
  }
  auto random_in = [&] {
    TriIn in;
    for (auto& x : in.v) x = static_cast<uint32_t>(rng.edgy(vmax, 0.05));
    in.wx = rng.edgy(wmax), in.wy = rng.edgy(wmax), in.wz = rng.edgy(wmax);
    return in;
  };
  auto drive = [&](M& m, const TriIn& in) {
    for (int i = 0; i < 8; ++i) put_bits(m.voxels_i, i * V, V, in.v[i]);
    m.wx_i = in.wx;
    m.wy_i = in.wy;
    m.wz_i = in.wz;
  };
  auto golden = [&](const TriIn& in) { return TriOut{g::trilinear(in.v, in.wx, in.wy, in.wz, W)}; };
  auto read = [](M& m) { return TriOut{static_cast<uint32_t>(m.sample_o)}; };

  auto m = std::make_unique<M>();
  const long nd = static_cast<long>(directed.size());
  {
    Timer t(unit);
    Scoreboard<TriIn, TriOut> sb(unit, kTrilinearLatency);
    auto gen = [&](long i) { return i >= 0 && i < nd ? directed[i] : random_in(); };
    stream(*m, sb, nd + kRandom, 1.0, rng, gen, drive, golden, read, kTrilinearLatency);
    EXPECT_TRUE(sb.ok()) << sb.report();
    Scoreboard<TriIn, TriOut> gaps(std::string(unit) + " (valid gaps)", kTrilinearLatency);
    stream(*m, gaps, kRandomGaps, kGapValid, rng, [&](long) { return random_in(); }, drive, golden, read,
           kTrilinearLatency);
    EXPECT_TRUE(gaps.ok()) << gaps.report();
    std::printf("  %s V=%d W=%d: %llu directed+random, %llu with gaps\n", unit, V, W,
                static_cast<unsigned long long>(sb.checked()), static_cast<unsigned long long>(gaps.checked()));
  }
  m->final();
}

TEST(RtlTrilinear, DefaultWidths) { test_trilinear<Vcube4_trilinear>("cube4_trilinear", 12, 8); }
TEST(RtlTrilinear, Voxel8Weight6) { test_trilinear<Vcube4_trilinear_w6>("cube4_trilinear_w6", 8, 6); }
TEST(RtlTrilinear, Voxel16Weight10) { test_trilinear<Vcube4_trilinear_w10>("cube4_trilinear_w10", 16, 10); }

// ===========================================================================
// cube4_gradient

struct GradIn {
  uint32_t left = 0, right = 0, up = 0, down = 0;
  std::array<uint32_t, 4> behind{}, ahead{};
  uint32_t bwx = 0, bwy = 0, awx = 0, awy = 0;
  int s = 1;
  Fields fields() const {
    Fields f{{"left", left}, {"right", right}, {"up", up}, {"down", down}};
    for (int i = 0; i < 4; ++i) f.push_back({"behind" + std::to_string(i), behind[i]});
    for (int i = 0; i < 4; ++i) f.push_back({"ahead" + std::to_string(i), ahead[i]});
    f.insert(f.end(), {{"behind_wx", bwx}, {"behind_wy", bwy}, {"ahead_wx", awx}, {"ahead_wy", awy}, {"S", s}});
    return f;
  }
};
struct GradOut {
  int32_t x = 0, y = 0, z = 0;
  bool operator==(const GradOut& o) const { return x == o.x && y == o.y && z == o.z; }
  Fields fields() const { return {{"gx", x}, {"gy", y}, {"gz", z}}; }
};

template <class M>
void test_gradient(const char* unit, const g::Precision& p) {
  const int V = p.voxel_bits, W = p.weight_bits, G = p.gradient_bits;
  const uint32_t vmax = (1u << V) - 1, wmax = 1u << W;
  std::vector<GradIn> directed;
  // Every S with extreme neighbourhoods and end-point weights: zero and
  // saturated gradients of both signs in all three components.
  for (int s = 1; s <= 8; ++s)
    for (int lr = 0; lr < 16; ++lr)
      for (uint32_t b : {0u, vmax / 2, vmax})
        for (uint32_t a : {0u, vmax / 2, vmax})
          for (int wsel = 0; wsel < 16; ++wsel) {
            GradIn in;
            in.left = (lr & 1) ? vmax : 0, in.right = (lr & 2) ? vmax : 0;
            in.up = (lr & 4) ? vmax : 0, in.down = (lr & 8) ? vmax : 0;
            in.behind.fill(b), in.ahead.fill(a);
            in.bwx = (wsel & 1) ? wmax : 0, in.bwy = (wsel & 2) ? wmax : 0;
            in.awx = (wsel & 4) ? wmax : 0, in.awy = (wsel & 8) ? wmax : 0;
            in.s = s;
            directed.push_back(in);
          }
  // Every full difference -vmax .. vmax in x, y and z, for every S: each
  // rounding step and the saturation threshold of all three components.
  for (int s = 1; s <= 8; ++s)
    for (int64_t d = -int64_t{vmax}; d <= int64_t{vmax}; ++d) {
      GradIn in;
      const uint32_t lo = d < 0 ? static_cast<uint32_t>(-d) : 0, hi = d < 0 ? 0 : static_cast<uint32_t>(d);
      in.left = lo, in.right = hi, in.up = hi, in.down = lo;
      in.behind.fill(lo), in.ahead.fill(hi);
      in.bwx = in.bwy = in.awx = in.awy =
          (d & 3) == 0 ? 0 : (d & 3) == 1 ? wmax : static_cast<uint32_t>(d & 0x7f) % (wmax + 1);
      in.s = s;
      directed.push_back(in);
    }
  Random rng(20 + V * 100 + W);
  auto random_in = [&] {
    GradIn in;
    // Half the vectors in a smooth neighbourhood (small differences, where
    // gz does not saturate), half anywhere.
    const bool smooth = rng.chance(0.5);
    const int64_t c = rng.bits(V), spread = smooth ? (int64_t{1} << std::max(1, V - 6)) : vmax;
    auto val = [&] {
      return static_cast<uint32_t>(smooth ? std::clamp<int64_t>(c + rng.range(-spread, spread), 0, vmax)
                                          : rng.edgy(vmax, 0.05));
    };
    in.left = val(), in.right = val(), in.up = val(), in.down = val();
    for (auto& x : in.behind) x = val();
    for (auto& x : in.ahead) x = val();
    in.bwx = rng.edgy(wmax), in.bwy = rng.edgy(wmax), in.awx = rng.edgy(wmax), in.awy = rng.edgy(wmax);
    in.s = static_cast<int>(rng.range(1, 8));
    return in;
  };
  auto drive = [&](M& m, const GradIn& in) {
    m.left_i = in.left, m.right_i = in.right, m.up_i = in.up, m.down_i = in.down;
    for (int i = 0; i < 4; ++i) {
      put_bits(m.behind_i, i * V, V, in.behind[i]);
      put_bits(m.ahead_i, i * V, V, in.ahead[i]);
    }
    m.behind_wx_i = in.bwx, m.behind_wy_i = in.bwy, m.ahead_wx_i = in.awx, m.ahead_wy_i = in.awy;
    m.supersampling_i = in.s;
  };
  // The golden checker: sample_gradient() of the pipeline composition.
  g::Registers regs;
  regs.p = p;
  auto golden = [&](const GradIn& in) {
    regs.supersampling = in.s;
    g::SliceControl c;
    c.behind_x.weight = in.bwx, c.behind_y.weight = in.bwy;
    c.ahead_x.weight = in.awx, c.ahead_y.weight = in.awy;
    g::Neighbourhood n;
    n.left = in.left, n.right = in.right, n.up = in.up, n.down = in.down;
    n.behind = in.behind, n.ahead = in.ahead;
    const g::Gradient r = g::sample_gradient(regs, c, n);
    return GradOut{r.x, r.y, r.z};
  };
  auto read = [&](M& m) {
    return GradOut{static_cast<int32_t>(sign_extend(m.gx_o, G)), static_cast<int32_t>(sign_extend(m.gy_o, G)),
                   static_cast<int32_t>(sign_extend(m.gz_o, G))};
  };

  auto m = std::make_unique<M>();
  const long nd = static_cast<long>(directed.size());
  {
    Timer t(unit);
    Scoreboard<GradIn, GradOut> sb(unit, kGradientLatency);
    auto gen = [&](long i) { return i >= 0 && i < nd ? directed[i] : random_in(); };
    stream(*m, sb, nd + kRandom, 1.0, rng, gen, drive, golden, read, kGradientLatency);
    EXPECT_TRUE(sb.ok()) << sb.report();
    Scoreboard<GradIn, GradOut> gaps(std::string(unit) + " (valid gaps)", kGradientLatency);
    stream(*m, gaps, kRandomGaps, kGapValid, rng, [&](long) { return random_in(); }, drive, golden, read,
           kGradientLatency);
    EXPECT_TRUE(gaps.ok()) << gaps.report();
    std::printf("  %s V=%d W=%d G=%d shift=%d: %llu directed+random, %llu with gaps\n", unit, V, W, G,
                p.gradient_shift, static_cast<unsigned long long>(sb.checked()),
                static_cast<unsigned long long>(gaps.checked()));
  }
  m->final();
}

TEST(RtlGradient, DefaultWidths) { test_gradient<Vcube4_gradient>("cube4_gradient", g::Precision{}); }
TEST(RtlGradient, Voxel8Weight6Shift1) {
  g::Precision p;
  p.voxel_bits = 8, p.weight_bits = 6, p.gradient_bits = 8, p.gradient_shift = 1;
  test_gradient<Vcube4_gradient_v8>("cube4_gradient_v8", p);
}
TEST(RtlGradient, Voxel16Weight10Gradient12) {
  g::Precision p;
  p.voxel_bits = 16, p.weight_bits = 10, p.gradient_bits = 12, p.gradient_shift = 6;
  test_gradient<Vcube4_gradient_v16>("cube4_gradient_v16", p);
}

// ===========================================================================
// cube4_magnitude

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
  auto m = std::make_unique<M>();
  {
    Timer t(unit);
    Scoreboard<MagIn, MagOut> sb(unit, b.latency);
    auto gen = [&](long i) { return i >= 0 && i < nb ? directed[i] : random_in(); };
    stream(*m, sb, nb + kRandom, 1.0, rng, gen, drive, golden, read, b.latency);
    EXPECT_TRUE(sb.ok()) << sb.report();
    Scoreboard<MagIn, MagOut> gaps(std::string(unit) + " (valid gaps)", b.latency);
    stream(*m, gaps, kRandomGaps, kGapValid, rng, [&](long) { return random_in(); }, drive, golden, read, b.latency);
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
    stream(*m, sb, static_cast<long>(side * side * side), 1.0, rng, gen, drive, golden, read, b.latency);
    EXPECT_TRUE(sb.ok()) << sb.report();
    std::printf("  %s exhaustive: %llu gradients\n", unit, static_cast<unsigned long long>(sb.checked()));
  }
  m->final();
}

TEST(RtlMagnitude, DefaultWidths) { test_magnitude_random<Vcube4_magnitude>("cube4_magnitude", g::Precision{}, true); }
TEST(RtlMagnitude, Gradient10Magnitude9Iterations2) {
  g::Precision p;
  p.gradient_bits = 10, p.magnitude_bits = 9, p.nr_iterations = 2;
  test_magnitude_random<Vcube4_magnitude_g10>("cube4_magnitude_g10", p, false);
}
TEST(RtlMagnitude, NoIterations) {
  g::Precision p;
  p.nr_iterations = 0;
  test_magnitude_random<Vcube4_magnitude_n0>("cube4_magnitude_n0", p, false);
}

// ===========================================================================
// cube4_skew_addr

constexpr int kDimBits = 10;  // cube4_skew_addr default
constexpr int clog2(int v) {
  int b = 0;
  while ((1 << b) < v) ++b;
  return b;
}
// cube4_skew_addr's default IndexBits.
constexpr int skew_index_bits(int p) { return 3 * kDimBits + 4 - clog2(p + 1); }

// The golden skew functions are constexpr: a few values by hand (8x6x5 on
// p = 4 pads to 8x8x8, B_x = 2; x fastest, index = x/4 + 2*(y + 8*z)).
constexpr g::SkewLayout kL865{{8, 6, 5}, 4};
static_assert(kL865.words_per_module() == 128);
static_assert(g::skew_address(kL865, 5, 2, 1) == g::SkewAddress{0, 1 + 2 * (2 + 8 * 1)});
// Object x backwards (n = 8): pipeline 0 of partial beam 0 reads x = 7.
static_assert(g::beam_access(kL865, g::SkewTraversal{{0, 1, 2}, {true, false, false}}, 0, 0, 0).lane[0] ==
              g::SkewAddress{3, 1});
// Object y as beam axis, backwards (n = 6, P = 8): partial beam 1 is y = 1, 0, 7, 6.
static_assert(g::beam_access(kL865, g::SkewTraversal{{1, 2, 0}, {true, false, false}}, 0, 0, 1).lane[2] ==
              g::SkewAddress{3, 2 * 7});
static_assert(g::beam_access(kL865, g::SkewTraversal{{1, 2, 0}, {true, false, false}}, 0, 0, 1).rotation == 1);

// For a padded layout, the voxel stored at each (module, index): checks that
// skew_address() is a bijection onto p modules of words_per_module() words.
struct Inverse {
  g::SkewLayout l;
  std::vector<int64_t> voxel;  // [module * words + index] -> linear padded voxel, -1 if none
  int64_t words = 0;
  bool bijective = true;
  explicit Inverse(const g::SkewLayout& layout) : l(layout) {
    words = l.words_per_module();
    voxel.assign(static_cast<size_t>(words * l.p), -1);
    const int px = l.padded(0), py = l.padded(1), pz = l.padded(2);
    for (int z = 0; z < pz; ++z)
      for (int y = 0; y < py; ++y)
        for (int x = 0; x < px; ++x) {
          const g::SkewAddress a = g::skew_address(l, x, y, z);
          const int64_t lin = x + int64_t{px} * (y + int64_t{py} * z);
          if (a.module < 0 || a.module >= l.p || a.index < 0 || a.index >= words ||
              voxel[static_cast<size_t>(a.module * words + a.index)] != -1) {
            bijective = false;
            continue;
          }
          voxel[static_cast<size_t>(a.module * words + a.index)] = lin;
        }
    for (int64_t v : voxel) bijective = bijective && v != -1;
  }
};

std::string traversal_name(const g::SkewTraversal& t) {
  std::string s = "perm ";
  for (int i = 0; i < 3; ++i) s += static_cast<char>('0' + t.perm[i]);
  s += " flip ";
  for (int i = 0; i < 3; ++i) s += t.flip[i] ? '1' : '0';
  return s;
}

std::vector<g::SkewTraversal> all_traversals() {
  std::vector<g::SkewTraversal> v;
  std::array<int, 3> perm{0, 1, 2};
  do {
    for (int f = 0; f < 8; ++f) v.push_back({perm, {(f & 1) != 0, (f & 2) != 0, (f & 4) != 0}});
  } while (std::next_permutation(perm.begin(), perm.end()));
  return v;
}

// Runs one frame (or its first max_beams partial beams) and checks every
// issued partial beam against beam_access(), that the de-skew gives each
// pipeline its own module and the voxel it must process, and (for whole
// frames) that every object voxel is read exactly once.
template <class M>
void skew_frame(M& m, int p, const std::array<int, 3>& n, const g::SkewTraversal& t, double advance_prob,
                Random& rng, cube4::rtl::Checker& c, const Inverse* inv, int64_t max_beams = -1) {
  const g::SkewLayout l{n, p};
  const int64_t total = g::skew_cycles(l, t);
  const int64_t beams = max_beams < 0 ? total : std::min(total, max_beams);
  const int px = l.padded(0), py = l.padded(1);
  std::vector<uint8_t> visits;
  if (inv) visits.assign(static_cast<size_t>(inv->words * p), 0);
  const std::string where = traversal_name(t) + " dims " + std::to_string(n[0]) + "x" + std::to_string(n[1]) +
                            "x" + std::to_string(n[2]) + " p " + std::to_string(p);
  auto in_fields = [&](int64_t k) {
    const g::BeamPosition pos = g::skew_position(l, t, k);
    return Fields{{where + ": beam#", k}, {"j", pos.j}, {"y", pos.y}, {"z", pos.z}};
  };

  // Start: registers valid in the start cycle only.
  m.perm_i = static_cast<uint32_t>(t.perm[0] | t.perm[1] << 2 | t.perm[2] << 4);
  m.flip_i = static_cast<uint32_t>(t.flip[0] | t.flip[1] << 1 | t.flip[2] << 2);
  m.dim_i = static_cast<uint32_t>(n[0] | n[1] << kDimBits | n[2] << 2 * kDimBits);
  m.start_i = 1;
  m.advance_i = rng.chance(0.5);
  m.repeat_slice_i = 0;
  m.again_i = 0;
  cube4::rtl::settle(m);
  cube4::rtl::rise(m);
  m.start_i = 0;
  m.perm_i = rng.bits(6), m.flip_i = rng.bits(3), m.dim_i = static_cast<uint32_t>(rng.bits(3 * kDimBits));

  int64_t k = 0;  // partial beams received
  for (uint64_t cycle = 1; k < beams; ++cycle) {
    if (cycle > static_cast<uint64_t>(total) * 3 + 100) {
      c.fail(cycle, in_fields(k), "timeout: the frame did not finish");
      return;
    }
    m.advance_i = advance_prob >= 1.0 || rng.chance(advance_prob);
    cube4::rtl::settle(m);
    if (cycle < static_cast<uint64_t>(kSkewStartLatency) && m.valid_o)
      c.fail(cycle, in_fields(k), "valid_o before the stated start latency");
    if (advance_prob >= 1.0 && cycle >= static_cast<uint64_t>(kSkewStartLatency) && !m.valid_o)
      c.fail(cycle, in_fields(k), "valid_o low with advance_i held high");
    if (m.valid_o) {
      const g::BeamPosition pos = g::skew_position(l, t, k);
      const g::BeamAccess e = g::beam_access(l, t, pos.y, pos.z, pos.j);
      // Values: every module's index, the de-skew, position and last flag.
      Fields exp, got;
      bool equal = true;
      auto cmp = [&](const char* name, int64_t ev, int64_t gv) {
        equal = equal && ev == gv;
        exp.push_back({name, ev});
        got.push_back({name, gv});
      };
      static const char* names[] = {"index0", "index1", "index2", "index3", "index4", "index5", "index6", "index7"};
      const int ib = skew_index_bits(p);
      for (int mod = 0; mod < p; ++mod) cmp(names[mod], e.module_index[mod], get_bits(m.index_o, mod * ib, ib));
      cmp("rotation", e.rotation, m.rotation_o);
      cmp("reverse", e.reverse, m.reverse_o);
      cmp("beam", pos.j, m.beam_o);
      cmp("y", pos.y, m.y_o);
      cmp("z", pos.z, m.z_o);
      cmp("last", k == total - 1, m.last_o);
      c.check_lazy(cycle, equal, [&] { return in_fields(k); }, [&] { return exp; }, [&] { return got; });
      // Properties: pipeline k reads module (rotation +- k) mod p; those are
      // p different modules (no module accessed twice in one cycle), the
      // same as the golden lanes, and hold the voxel pipeline k processes.
      uint64_t used = 0;
      std::array<int, 3> o{};
      o[t.perm[1]] = g::skew_object_coordinate(l, t, 1, pos.y);
      o[t.perm[2]] = g::skew_object_coordinate(l, t, 2, pos.z);
      for (int lane = 0; lane < p; ++lane) {
        const int mod = ((m.reverse_o ? -lane : lane) + static_cast<int>(m.rotation_o) + p * 8) % p;
        if (used >> mod & 1) c.fail(cycle, in_fields(k), "module " + std::to_string(mod) + " accessed twice");
        used |= uint64_t{1} << mod;
        if (e.lane[lane].module != mod)
          c.fail(cycle, in_fields(k), "pipeline " + std::to_string(lane) + " de-skews to module " +
                                          std::to_string(mod) + ", golden " + std::to_string(e.lane[lane].module));
        if (inv) {
          const int64_t idx = static_cast<int64_t>(get_bits(m.index_o, mod * ib, ib));
          if (idx >= inv->words) {
            c.fail(cycle, in_fields(k), "index out of range");
            continue;
          }
          o[t.perm[0]] = g::skew_object_coordinate(l, t, 0, pos.j * p + lane);
          const int64_t want = o[0] + int64_t{px} * (o[1] + int64_t{py} * o[2]);
          const size_t slot = static_cast<size_t>(mod * inv->words + idx);
          if (inv->voxel[slot] != want)
            c.fail(cycle, in_fields(k), "pipeline " + std::to_string(lane) + " reads the wrong voxel");
          ++visits[slot];
        }
      }
      ++k;
    }
    cube4::rtl::rise(m);
  }
  if (beams < total) return;
  // The frame ends: busy_o falls, nothing more is issued.
  for (int i = 0; i < 4; ++i) {
    m.advance_i = 1;
    cube4::rtl::settle(m);
    if (m.valid_o || m.busy_o) c.fail(0, in_fields(k), "valid_o or busy_o after the last beam");
    cube4::rtl::rise(m);
  }
  if (!inv) return;
  // Every object voxel read exactly once; padding at most once.
  for (size_t slot = 0; slot < visits.size(); ++slot) {
    const int64_t lin = inv->voxel[slot];
    const int x = static_cast<int>(lin % px), y = static_cast<int>(lin / px % py),
              z = static_cast<int>(lin / (int64_t{px} * py));
    const bool object = x < n[0] && y < n[1] && z < n[2];
    if ((object && visits[slot] != 1) || visits[slot] > 1) {
      c.fail(0, {{where + ": voxel x", x}, {"y", y}, {"z", z}, {"visits", visits[slot]}},
             "voxel not read exactly once");
      break;
    }
  }
}

const std::vector<std::array<int, 3>> kSkewDims = {{8, 6, 5}, {10, 10, 10}, {1, 1, 1}, {3, 7, 2},
                                                    {13, 4, 9}, {5, 5, 5},   {16, 1, 3}};

template <class M>
void test_skew(int p) {
  Timer timer("cube4_skew_addr");
  auto m = std::make_unique<M>();
  cube4::rtl::reset(*m);
  m->start_i = 0;
  m->advance_i = 1;
  m->repeat_slice_i = 0;
  m->again_i = 0;
  cube4::rtl::settle(*m);
  EXPECT_FALSE(m->valid_o);
  EXPECT_FALSE(m->busy_o);
  cube4::rtl::Checker c("cube4_skew_addr p=" + std::to_string(p));
  Random rng(40 + p);
  int frames = 0;
  for (const auto& n : kSkewDims) {
    const Inverse inv(g::SkewLayout{n, p});
    ASSERT_TRUE(inv.bijective) << "skew_address() is not a bijection for p " << p;
    int i = 0;
    for (const auto& t : all_traversals()) {
      skew_frame(*m, p, n, t, (i++ % 2) ? 0.7 : 1.0, rng, c, &inv);
      ++frames;
    }
  }
  // A frame restarted in the middle, then a whole one.
  const auto ts = all_traversals();
  skew_frame(*m, p, {13, 4, 9}, ts[5], 1.0, rng, c, nullptr, 17);
  const Inverse inv865(g::SkewLayout{{8, 6, 5}, p});
  skew_frame(*m, p, {8, 6, 5}, ts[44], 0.8, rng, c, &inv865);
  // Large dims (the setup products and index widths): the first beams of
  // every traversal, where the backwards axes start at their far ends.
  for (const auto& t : ts) skew_frame(*m, p, {1023, 1021, 1000}, t, 1.0, rng, c, nullptr, 3000);
  m->final();
  EXPECT_TRUE(c.ok()) << c.report();
  std::printf("  cube4_skew_addr p=%d: %d frames (48 traversals x %zu dims), %llu partial beams checked\n", p,
              frames, kSkewDims.size(), static_cast<unsigned long long>(c.checked()));
}

// The system's walk: each slice walked 1..3 times in a row (repeat_slice_i
// with its last partial beam, as supersampling reads it), the frame started
// over (again_i with its last partial beam) two more times without setup,
// advance_i random. Every issued partial beam against beam_access() of the
// expected position; last_o on each walk's end; busy_o high throughout.
template <class M>
void test_skew_walks(int p) {
  auto m = std::make_unique<M>();
  cube4::rtl::reset(*m);
  cube4::rtl::Checker c("cube4_skew_addr walks p=" + std::to_string(p));
  Random rng(70 + p);
  const auto ts = all_traversals();
  for (int trial = 0; trial < 24; ++trial) {
    const std::array<int, 3> n = {static_cast<int>(rng.range(1, 9)), static_cast<int>(rng.range(1, 9)),
                                  static_cast<int>(rng.range(1, 9))};
    const g::SkewTraversal t = ts[static_cast<size_t>(rng.range(0, 47))];
    const g::SkewLayout l{n, p};
    const int nj = g::skew_partial_beams(l, t), ny = g::skew_beams(l, t), nz = g::skew_slices(l, t);
    // The expected walk: frames x slices x repeats x beams x partial beams.
    struct Pos { int j, y, z; bool slice_end, frame_end, last_walk_of_slice, last_frame; };
    std::vector<Pos> walk;
    const int frames = 3;
    for (int f = 0; f < frames; ++f)
      for (int z = 0; z < nz; ++z) {
        const int times = static_cast<int>(rng.range(1, 3));
        for (int r = 0; r < times; ++r)
          for (int y = 0; y < ny; ++y)
            for (int j = 0; j < nj; ++j) {
              const bool slice_end = y == ny - 1 && j == nj - 1;
              walk.push_back({j, y, z, slice_end, slice_end && z == nz - 1 && r == times - 1, r == times - 1,
                              f == frames - 1});
            }
      }
    m->perm_i = static_cast<uint32_t>(t.perm[0] | t.perm[1] << 2 | t.perm[2] << 4);
    m->flip_i = static_cast<uint32_t>(t.flip[0] | t.flip[1] << 1 | t.flip[2] << 2);
    m->dim_i = static_cast<uint32_t>(n[0] | n[1] << kDimBits | n[2] << 2 * kDimBits);
    m->start_i = 1;
    m->advance_i = 0;
    cube4::rtl::settle(*m);
    cube4::rtl::rise(*m);
    m->start_i = 0;
    size_t issued = 0, received = 0;
    const int ib = skew_index_bits(p);
    for (uint64_t cycle = 1; received < walk.size(); ++cycle) {
      if (cycle > 4 * walk.size() + 100) {
        c.fail(cycle, {{"trial", trial}}, "timeout");
        break;
      }
      const bool can_issue = cycle >= static_cast<uint64_t>(kSkewStartLatency) - 1 && issued < walk.size();
      m->advance_i = can_issue && rng.chance(0.8);
      // The walk's controls belong to the partial beam issued this cycle.
      const Pos* next = issued < walk.size() ? &walk[issued] : nullptr;
      m->repeat_slice_i = next && next->slice_end && !next->last_walk_of_slice;
      m->again_i = next && next->frame_end && !next->last_frame;
      if (!m->repeat_slice_i && rng.chance(0.3)) m->repeat_slice_i = next && !next->slice_end;  // ignored mid-slice
      cube4::rtl::settle(*m);
      if (m->valid_o) {
        const Pos& e = walk[received];
        const g::BeamAccess a = g::beam_access(l, t, e.y, e.z, e.j);
        bool ok = m->beam_o == static_cast<uint32_t>(e.j) && m->y_o == static_cast<uint32_t>(e.y) &&
                  m->z_o == static_cast<uint32_t>(e.z) && m->rotation_o == static_cast<uint32_t>(a.rotation) &&
                  m->last_o == e.frame_end;
        for (int mod = 0; mod < p; ++mod)
          ok = ok && static_cast<int64_t>(get_bits(m->index_o, mod * ib, ib)) == a.module_index[mod];
        c.check_lazy(
            cycle, ok, [&] { return Fields{{"trial", trial}, {"beam#", static_cast<int64_t>(received)}}; },
            [&] { return Fields{{"j", e.j}, {"y", e.y}, {"z", e.z}, {"last", e.frame_end}}; },
            [&] {
              return Fields{{"j", m->beam_o}, {"y", m->y_o}, {"z", m->z_o}, {"last", m->last_o}};
            });
        ++received;
      }
      if (cycle > 1 && issued < walk.size() && !m->busy_o) c.fail(cycle, {{"trial", trial}}, "busy_o fell mid-walk");
      if (m->advance_i && issued < walk.size()) ++issued;
      cube4::rtl::rise(*m);
    }
    m->advance_i = 0;
    m->repeat_slice_i = 0;
    m->again_i = 0;
    cube4::rtl::settle(*m);
    if (m->busy_o) c.fail(0, {{"trial", trial}}, "busy_o high after the last frame");
    cube4::rtl::rise(*m);
  }
  m->final();
  EXPECT_TRUE(c.ok()) << c.report();
  EXPECT_GT(c.checked(), 2000u) << "the walks issued too few partial beams to mean anything";
}

TEST(RtlSkewAddr, WalksWithRepeatedSlicesAndFramesAgain) {
  test_skew_walks<Vcube4_skew_addr_p1>(1);
  test_skew_walks<Vcube4_skew_addr>(4);
  test_skew_walks<Vcube4_skew_addr_p5>(5);
}

TEST(RtlSkewAddr, Pipes1) { test_skew<Vcube4_skew_addr_p1>(1); }
TEST(RtlSkewAddr, Pipes2) { test_skew<Vcube4_skew_addr_p2>(2); }
TEST(RtlSkewAddr, Pipes4) { test_skew<Vcube4_skew_addr>(4); }
TEST(RtlSkewAddr, Pipes5) { test_skew<Vcube4_skew_addr_p5>(5); }
TEST(RtlSkewAddr, Pipes8) { test_skew<Vcube4_skew_addr_p8>(8); }

}  // namespace
