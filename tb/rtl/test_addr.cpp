// RTL tests of the skewed-memory address generator cube4_addr against the
// golden functions (golden/units/addr.hpp) for p = 1, 2, 4, 5, 8: every
// traversal's addresses, one access per memory module per cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include "Vcube4_addr.h"
#include "Vcube4_addr_p1.h"
#include "Vcube4_addr_p2.h"
#include "Vcube4_addr_p5.h"
#include "Vcube4_addr_p8.h"
#include "golden/units/addr.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace {

namespace g = cube4::golden;
using cube4::rtl::Fields;
using cube4::rtl::Random;
using cube4::rtl::Timer;
using cube4::rtl::get_bits;
using cube4::rtl::put_bits;

constexpr int kAddrStartLatency = 7;  // cube4_addr's header

constexpr int kDimBits = 10;  // cube4_addr default
constexpr int clog2(int v) {
  int b = 0;
  while ((1 << b) < v) ++b;
  return b;
}
// cube4_addr's default IndexBits.
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
    if (cycle < static_cast<uint64_t>(kAddrStartLatency) && m.valid_o)
      c.fail(cycle, in_fields(k), "valid_o before the stated start latency");
    if (advance_prob >= 1.0 && cycle >= static_cast<uint64_t>(kAddrStartLatency) && !m.valid_o)
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
  Timer timer("cube4_addr");
  auto m = cube4::rtl::make_dut<M>();
  cube4::rtl::reset(*m);
  m->start_i = 0;
  m->advance_i = 1;
  m->repeat_slice_i = 0;
  m->again_i = 0;
  cube4::rtl::settle(*m);
  EXPECT_FALSE(m->valid_o);
  EXPECT_FALSE(m->busy_o);
  cube4::rtl::Checker c("cube4_addr p=" + std::to_string(p));
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
  std::printf("  cube4_addr p=%d: %d frames (48 traversals x %zu dims), %llu partial beams checked\n", p,
              frames, kSkewDims.size(), static_cast<unsigned long long>(c.checked()));
}

// The system's walk: each slice walked 1..3 times in a row (repeat_slice_i
// with its last partial beam, as supersampling reads it), the frame started
// over (again_i with its last partial beam) two more times without setup,
// advance_i random. Every issued partial beam against beam_access() of the
// expected position; last_o on each walk's end; busy_o high throughout.
template <class M>
void test_skew_walks(int p) {
  auto m = cube4::rtl::make_dut<M>();
  cube4::rtl::reset(*m);
  cube4::rtl::Checker c("cube4_addr walks p=" + std::to_string(p));
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
      const bool can_issue = cycle >= static_cast<uint64_t>(kAddrStartLatency) - 1 && issued < walk.size();
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

TEST(RtlAddr, WalksWithRepeatedSlicesAndFramesAgain) {
  test_skew_walks<Vcube4_addr_p1>(1);
  test_skew_walks<Vcube4_addr>(4);
  test_skew_walks<Vcube4_addr_p5>(5);
}

TEST(RtlAddr, Pipes1) { test_skew<Vcube4_addr_p1>(1); }
TEST(RtlAddr, Pipes2) { test_skew<Vcube4_addr_p2>(2); }
TEST(RtlAddr, Pipes4) { test_skew<Vcube4_addr>(4); }
TEST(RtlAddr, Pipes5) { test_skew<Vcube4_addr_p5>(5); }
TEST(RtlAddr, Pipes8) { test_skew<Vcube4_addr_p8>(8); }


}  // namespace
