// RTL equivalence tests of the compositing node, cube4_compose_node,
// against golden compose() (golden/units/compose.hpp): two partial-image
// pixels, front and back, into one, for over, MIP and MinIP.
//
// Driven cycle by cycle, back to back and with random valid gaps (junk data
// in the gaps); every output is compared with the golden result of the
// input that entered exactly kLatency cycles earlier (Scoreboard,
// rtl_check.hpp: a result one cycle early or late is a mismatch, reported
// with the inputs, the expected and the received pixel). The blend mode is
// a frame register: it changes only after the pipeline has drained.
//
// CUBE4_RTL_VECTORS overrides the random vector count per mode (default
// 1,000,000).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "Vcube4_compose_node.h"
#include "Vcube4_compose_node_a12.h"
#include "Vcube4_compose_node_a8.h"
#include "Vcube4_compose_node_l0.h"
#include "Vcube4_compose_node_l1.h"
#include "golden/units/compose.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;
using rtl::Random;

// The verilated widths (rtl/groups/compose.cmake holds the same values).
struct Config {
  g::Precision p;
  int latency = 2;
  int acc_bits() const { return g::acc_bits(p); }
  int64_t accmax() const { return g::max_unsigned(acc_bits()); }
  int64_t vmax() const { return g::max_unsigned(p.voxel_bits); }
};
Config with(int voxel_bits, int alpha_bits, int guard_bits, int latency) {
  Config c;
  c.p.voxel_bits = voxel_bits;
  c.p.alpha_bits = alpha_bits;
  c.p.acc_guard_bits = guard_bits;
  c.latency = latency;
  return c;
}
const Config kDefault = with(12, 16, 8, 2);  // Vcube4_compose_node: the package's defaults
const Config kA8 = with(8, 8, 0, 2);         // Vcube4_compose_node_a8: 8-bit pixels, no guard bits
const Config kA12 = with(12, 12, 4, 2);      // Vcube4_compose_node_a12
const Config kL1 = with(12, 16, 8, 1);       // Vcube4_compose_node_l1: Latency 1 (cube4_composite's blend)
const Config kL0 = with(12, 16, 8, 0);       // Vcube4_compose_node_l0: Latency 0 (cube4_composite's blend with polygons)

Fields pixel_fields(const char* prefix, const g::RayAcc& x) {
  const std::string p(prefix);
  return {{p + "red", x.r},     {p + "green", x.g},     {p + "blue", x.b},
          {p + "alpha", x.a},   {p + "value", x.value}, {p + "selected", x.valid}};
}

struct NodeIn {
  g::RayAcc front, back;
  uint8_t mode_bits = 0;  // as driven: 3 is over, like 0
  Fields fields() const {
    Fields f = pixel_fields("front_", front);
    for (const auto& x : pixel_fields("back_", back)) f.push_back(x);
    f.push_back({"blend_mode", mode_bits});
    return f;
  }
};
struct NodeOut {
  g::RayAcc px;
  bool operator==(const NodeOut& o) const { return px == o.px; }
  Fields fields() const { return pixel_fields("", px); }
};

g::BlendMode mode_of(uint8_t bits) { return bits == 3 ? g::BlendMode::Composite : static_cast<g::BlendMode>(bits); }

// What the random and directed stimulus reached (each must be non-zero).
struct Coverage {
  uint64_t saturated = 0, front_empty = 0, front_opaque = 0, back_taken = 0, front_kept = 0, tie = 0,
           none_selected = 0, gaps = 0;
};

// EXPECT_TRUE with the scoreboard's summary printed either way.
void expect_equal(const testing::AssertionResult& r) {
  EXPECT_TRUE(r);
  if (r) std::printf("  %s\n", r.message());
}

template <class M>
class NodeBench {
 public:
  NodeBench(const Config& c, std::string name)
      : cfg_(c), sb_(std::move(name), c.latency), junk_(977), m_(cube4::rtl::make_dut<M>()) {
    rtl::reset(*m_);
  }

  // One cycle: drives `in` with valid_i = v (junk when !v), checks the output.
  void step(bool v, const NodeIn& in) {
    const NodeIn d = v ? in : junk(in.mode_bits);
    drive(d);
    m_->valid_i = v;
    if (v) {
      const g::RayAcc out = g::compose(mode_of(d.mode_bits), d.front, d.back, cfg_.p);
      sb_.expect(cycle_, d, {out});
      count(d, out);
      ++vectors;
    } else {
      ++coverage.gaps;
    }
    rtl::settle(*m_);
    sb_.observe(cycle_, m_->valid_o, read());
    rtl::rise(*m_);
    ++cycle_;
  }
  // Idle cycles until everything in flight has left (before a mode change).
  void drain(uint8_t mode_bits) {
    for (int i = 0; i <= cfg_.latency; ++i) step(false, junk(mode_bits));
  }
  testing::AssertionResult result() {
    drain(0);
    sb_.finish();
    if (sb_.ok()) return testing::AssertionSuccess() << sb_.report();
    return testing::AssertionFailure() << sb_.report();
  }
  M& model() { return *m_; }

  uint64_t vectors = 0;
  Coverage coverage;

 private:
  template <class T>
  static void put(T& port, uint64_t v, int bits) {
    rtl::put_bits(port, 0, bits, v);
  }
  void drive(const NodeIn& in) {
    const int a = cfg_.acc_bits(), vb = cfg_.p.voxel_bits;
    M& m = *m_;
    m.blend_mode_i = in.mode_bits;
    auto pixel = [&](auto& r, auto& gr, auto& b, auto& al, auto& value, auto& selected, const g::RayAcc& x) {
      put(r, x.r, a);
      put(gr, x.g, a);
      put(b, x.b, a);
      put(al, x.a, a);
      put(value, x.value, vb);
      selected = x.valid;
    };
    pixel(m.front_red_i, m.front_green_i, m.front_blue_i, m.front_alpha_i, m.front_value_i, m.front_selected_i,
          in.front);
    pixel(m.back_red_i, m.back_green_i, m.back_blue_i, m.back_alpha_i, m.back_value_i, m.back_selected_i, in.back);
  }
  NodeOut read() const {
    const int a = cfg_.acc_bits(), vb = cfg_.p.voxel_bits;
    const M& m = *m_;
    NodeOut o;
    o.px.r = static_cast<uint32_t>(rtl::get_bits(m.red_o, 0, a));
    o.px.g = static_cast<uint32_t>(rtl::get_bits(m.green_o, 0, a));
    o.px.b = static_cast<uint32_t>(rtl::get_bits(m.blue_o, 0, a));
    o.px.a = static_cast<uint32_t>(rtl::get_bits(m.alpha_o, 0, a));
    o.px.value = static_cast<uint16_t>(rtl::get_bits(m.value_o, 0, vb));
    o.px.valid = m.selected_o;
    return o;
  }
  NodeIn junk(uint8_t mode_bits) {
    const int a = cfg_.acc_bits(), vb = cfg_.p.voxel_bits;
    NodeIn in;
    for (g::RayAcc* x : {&in.front, &in.back}) {
      x->r = static_cast<uint32_t>(junk_.bits(a));
      x->g = static_cast<uint32_t>(junk_.bits(a));
      x->b = static_cast<uint32_t>(junk_.bits(a));
      x->a = static_cast<uint32_t>(junk_.bits(a));
      x->value = static_cast<uint16_t>(junk_.bits(vb));
      x->valid = junk_.bits(1);
    }
    in.mode_bits = mode_bits;  // a frame register: held
    return in;
  }
  void count(const NodeIn& in, const g::RayAcc& out) {
    Coverage& c = coverage;
    if (mode_of(in.mode_bits) == g::BlendMode::Composite) {
      if (in.front == g::RayAcc{}) ++c.front_empty;
      if (in.front.a == cfg_.accmax()) ++c.front_opaque;
      for (uint32_t ch : {out.r, out.g, out.b})
        if (ch == cfg_.accmax() && in.front.a < cfg_.accmax()) ++c.saturated;
    } else {
      ++(out == in.front ? c.front_kept : c.back_taken);
      if (in.front.valid && in.back.valid && in.front.value == in.back.value) ++c.tie;
      if (!in.back.valid) ++c.none_selected;
    }
  }

  Config cfg_;
  rtl::Scoreboard<NodeIn, NodeOut> sb_;
  Random junk_;
  cube4::rtl::Dut<M> m_;
  uint64_t cycle_ = 0;
};

// A random partial-image pixel: a channel anywhere in the domain, or a
// premultiplied one (colour <= α), with the domain's edges more often.
g::RayAcc random_pixel(Random& rnd, const Config& c) {
  const int64_t amax = c.accmax();
  g::RayAcc x;
  x.a = static_cast<uint32_t>(rnd.edgy(amax, 0.15));
  const int64_t cmax = rnd.chance(0.7) ? x.a : amax;
  x.r = static_cast<uint32_t>(rnd.edgy(cmax, 0.15));
  x.g = static_cast<uint32_t>(rnd.edgy(cmax, 0.15));
  x.b = static_cast<uint32_t>(rnd.edgy(cmax, 0.15));
  if (rnd.chance(0.03)) x = g::RayAcc{};  // the empty pixel
  x.value = static_cast<uint16_t>(rnd.edgy(c.vmax()));
  x.valid = rnd.chance(0.8);
  return x;
}
NodeIn random_in(Random& rnd, const Config& c, uint8_t mode_bits) {
  NodeIn in;
  in.mode_bits = mode_bits;
  in.front = random_pixel(rnd, c);
  in.back = random_pixel(rnd, c);
  if (rnd.chance(0.1)) in.back.value = in.front.value;  // a tie
  return in;
}

// n random vectors in every mode (over driven as 0 and as 3), half of them
// back to back, half with random valid gaps.
template <class M>
void node_random(const Config& c, const std::string& name, long n) {
  NodeBench<M> b(c, name);
  Random rnd(1101);
  for (uint8_t mode : {0, 1, 2, 3}) {
    const long count = mode == 3 ? n / 10 : n;  // 3 is the same datapath as 0
    long sent = 0;
    b.drain(mode);
    while (sent < count) {
      const bool gaps = (sent / 5000) % 2 == 1;
      const bool v = !gaps || rnd.chance(rtl::kGapValid);
      b.step(v, random_in(rnd, c, mode));
      sent += v;
    }
    b.drain(mode);
  }
  expect_equal(b.result());
  EXPECT_GE(b.vectors, static_cast<uint64_t>(3 * n + n / 10));
  const Coverage& k = b.coverage;
  for (uint64_t x : {k.saturated, k.front_empty, k.front_opaque, k.back_taken, k.front_kept, k.tie, k.none_selected,
                     k.gaps})
    EXPECT_GT(x, 0u) << "random stimulus missed a case";
}

// Directed: α = 0 and full in front, saturation, ties, nothing selected,
// every mode, each case back to back and with gaps around it.
template <class M>
void node_directed(const Config& c, const std::string& name) {
  NodeBench<M> b(c, name);
  Random rnd(1102);
  const uint32_t amax = static_cast<uint32_t>(c.accmax());
  const uint16_t vmax = static_cast<uint16_t>(c.vmax());
  const uint32_t aedge[] = {0, 1, amax / 2, amax / 2 + 1, amax - 1, amax};
  const uint16_t vedge[] = {0, 1, static_cast<uint16_t>(vmax / 2), static_cast<uint16_t>(vmax - 1), vmax};
  for (uint8_t mode : {0, 1, 2, 3}) {
    b.drain(mode);
    auto send = [&](const NodeIn& in) { b.step(true, in); if (rnd.chance(0.2)) b.step(false, in); };
    // Every edge of front α against every edge of a back channel, colours
    // at their edges too (full front colour with a full back: saturation).
    for (uint32_t fa : aedge)
      for (uint32_t fc : aedge)
        for (uint32_t bc : aedge)
          for (uint32_t ba : aedge) {
            NodeIn in;
            in.mode_bits = mode;
            in.front = {fc, fc, amax - fc, fa, 7, true};
            in.back = {bc, amax - bc, bc, ba, 9, true};
            send(in);
          }
    // The empty pixel on either side, and an opaque front.
    for (int i = 0; i < 200; ++i) {
      NodeIn in = random_in(rnd, c, mode);
      in.front = g::RayAcc{};
      send(in);
      in = random_in(rnd, c, mode);
      in.back = g::RayAcc{};
      send(in);
      in = random_in(rnd, c, mode);
      in.front.a = amax;
      send(in);
    }
    // MIP/MinIP: ties, neighbours and every selected combination.
    for (uint16_t fv : vedge)
      for (int dv : {-1, 0, 1})
        for (bool fs : {false, true})
          for (bool bs : {false, true}) {
            NodeIn in = random_in(rnd, c, mode);
            in.front.value = fv;
            in.back.value = static_cast<uint16_t>(std::clamp<int>(fv + dv, 0, vmax));
            in.front.valid = fs;
            in.back.valid = bs;
            send(in);
          }
    b.drain(mode);
  }
  expect_equal(b.result());
  const Coverage& k = b.coverage;
  for (uint64_t x : {k.saturated, k.front_empty, k.front_opaque, k.back_taken, k.front_kept, k.tie, k.none_selected})
    EXPECT_GT(x, 0u) << "a directed case is missing";
}

// The latency: one pixel after reset, valid_o exactly kLatency cycles later
// and at no other time; then a pixel every cycle gives a result every cycle.
template <class M>
void node_latency(const Config& c) {
  const auto dut = cube4::rtl::make_dut<M>();
  M& m = *dut;
  rtl::reset(m);
  m.blend_mode_i = 0;
  int seen_at = -1, seen = 0;
  for (int cycle = 0; cycle < 10; ++cycle) {
    m.valid_i = cycle == 0;
    rtl::settle(m);
    if (m.valid_o) {
      ++seen;
      seen_at = cycle;
    }
    rtl::rise(m);
  }
  EXPECT_EQ(seen, 1);
  EXPECT_EQ(seen_at, c.latency);
  int streamed = 0;
  for (int cycle = 0; cycle < 20; ++cycle) {
    m.valid_i = 1;
    rtl::settle(m);
    streamed += m.valid_o;
    rtl::rise(m);
  }
  EXPECT_EQ(streamed, 20 - c.latency) << "one pixel per clock";
}

// Overlay and underlay: the node with one input held at a layer pixel (a
// register); the stream is the other input.
template <class M>
void node_layers(const Config& c, const std::string& name) {
  NodeBench<M> b(c, name);
  Random rnd(1103);
  const uint32_t amax = static_cast<uint32_t>(c.accmax());
  const g::RayAcc black{0, 0, 0, amax, 0, false};  // an opaque black background
  for (uint8_t mode : {0, 1, 2}) {
    b.drain(mode);
    const g::RayAcc glass = random_pixel(rnd, c);
    for (int i = 0; i < 2000; ++i) {
      NodeIn under;  // underlay: the stream's pixel in front of the background
      under.mode_bits = mode;
      under.front = random_pixel(rnd, c);
      under.back = black;
      b.step(!rnd.chance(0.2), under);
      NodeIn over;  // overlay: a transparent surface in front of the stream
      over.mode_bits = mode;
      over.front = glass;
      over.back = random_pixel(rnd, c);
      b.step(!rnd.chance(0.2), over);
    }
    b.drain(mode);
  }
  expect_equal(b.result());
}

TEST(RtlCompose, Random) {
  node_random<Vcube4_compose_node>(kDefault, "cube4_compose_node", rtl::vector_count(1000000));
}
TEST(RtlCompose, Directed) { node_directed<Vcube4_compose_node>(kDefault, "cube4_compose_node"); }
TEST(RtlCompose, LatencyIsTwoCyclesOnePixelPerClock) { node_latency<Vcube4_compose_node>(kDefault); }
TEST(RtlCompose, OverlayAndUnderlayAreTheNodeWithALayerRegister) {
  node_layers<Vcube4_compose_node>(kDefault, "cube4_compose_node");
}

TEST(RtlCompose, EightBitPixels) {
  const std::string name = "cube4_compose_node (AlphaBits=8, AccGuardBits=0, VoxelBits=8)";
  node_random<Vcube4_compose_node_a8>(kA8, name, rtl::vector_count(1000000));
  node_directed<Vcube4_compose_node_a8>(kA8, name);
  node_latency<Vcube4_compose_node_a8>(kA8);
}
TEST(RtlCompose, TwelveBitPixelsFourGuardBits) {
  const std::string name = "cube4_compose_node (AlphaBits=12, AccGuardBits=4)";
  node_random<Vcube4_compose_node_a12>(kA12, name, rtl::vector_count(300000));
  node_directed<Vcube4_compose_node_a12>(kA12, name);
}
// Latency 1 is the instance inside cube4_composite (its blend stage).
TEST(RtlCompose, LatencyOne) {
  const std::string name = "cube4_compose_node (Latency=1)";
  node_random<Vcube4_compose_node_l1>(kL1, name, rtl::vector_count(300000));
  node_directed<Vcube4_compose_node_l1>(kL1, name);
  node_latency<Vcube4_compose_node_l1>(kL1);
}

// Latency 0 (no register) is the blend node inside cube4_composite with
// polygons, which feeds the slab node in the same cycle.
TEST(RtlCompose, LatencyZero) {
  const std::string name = "cube4_compose_node (Latency=0)";
  node_random<Vcube4_compose_node_l0>(kL0, name, rtl::vector_count(300000));
  node_directed<Vcube4_compose_node_l0>(kL0, name);
  node_latency<Vcube4_compose_node_l0>(kL0);
}

}  // namespace
