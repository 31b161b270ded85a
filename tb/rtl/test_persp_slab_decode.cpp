// RTL equivalence tests of cube4_persp_slab_decode, the run-length decoders
// of a perspective compositing ring (docs/rtl-rle-decode.md, "In
// perspective"), against golden: every request's pixel must be the slab
// image's pixel behind its ray, as golden decodes the image
// (SlabImage::decode_beam(), golden RleDecoder line by line; what
// PerspPolygonPixels reads for the TLM unit).
//
// The slab memory is the system's (PerspSlabLines,
// systemc/rtl/persp_slab_lines.hpp: per bank the lines of every other row
// of rays, read positions advancing by consume_o, moving on two rows after
// line_o), showing junk beyond a line's end. The
// requests are a perspective ring's: each row's rays in rank order, spread
// over the lanes with random gaps (cells without rays, idle cycles), a row
// ending and the next starting within one cycle, at most two rows a cycle.
// The slab images are random (empty ones, sparse and dense fragments), wider
// and taller than their slices' rays or exactly as wide, so that lines are
// left undecoded past the rays.
//
// CUBE4_RTL_VECTORS overrides the pixel count per variant (default 1,000,000).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "Vcube4_persp_slab_decode.h"
#include "Vcube4_persp_slab_decode_p1.h"
#include "Vcube4_persp_slab_decode_p5.h"
#include "Vcube4_persp_slab_decode_p8.h"
#include "golden/precision.hpp"
#include "golden/rle_buffer.hpp"
#include "systemc/rtl/persp_slab_lines.hpp"
#include "tb/rtl/rtl_check.hpp"
#include "tb/rtl/sva_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;
using rtl::Random;

constexpr int kMaxLanes = 8;

// A slice's slab image and its rectangle of rays (rays_x by rays_y, from
// the image's corner: pixel (x, y) lies behind ray (rays_x.lo + x,
// rays_y.lo + y)), with golden's decoded pixels.
struct Slice {
  g::SlabImage image;
  int rays_x = 0, rays_y = 0;
  std::vector<g::Pixel> pixels;  // width x beams; blank for an empty image
  const g::Pixel& at(int x, int y) const { return pixels[static_cast<size_t>(y) * image.width() + x]; }
};

// A premultiplied pixel, some channel non-zero, extremes often.
g::Pixel random_pixel(Random& rnd) {
  const auto a = static_cast<uint16_t>(rnd.range(1, 65535));
  auto channel = [&] { return static_cast<uint16_t>(rnd.chance(0.2) ? (rnd.chance(0.5) ? 0 : a) : rnd.range(0, a)); };
  return {channel(), channel(), channel(), a};
}

Slice random_slice(Random& rnd, int p) {
  const int width = static_cast<int>(rnd.chance(0.1) ? rnd.range(1, 3) : rnd.range(1, 40));
  const int beams = static_cast<int>(rnd.range(1, 8));
  Slice s{g::SlabImage(width, beams, p), 0, 0, {}};
  s.rays_x = rnd.chance(0.3) ? width : static_cast<int>(rnd.range(1, width));
  s.rays_y = rnd.chance(0.3) ? beams : static_cast<int>(rnd.range(1, beams));
  if (!rnd.chance(0.15)) {  // else empty: no fragment, every line cleared
    const g::Precision precision;
    const double density = rnd.chance(0.5) ? 0.1 : rnd.chance(0.5) ? 0.6 : 1.5;
    const int fragments = static_cast<int>(density * width * beams) + 1;
    for (int i = 0; i < fragments; ++i)
      s.image.insert(static_cast<int>(rnd.range(0, width - 1)), static_cast<int>(rnd.range(0, beams - 1)),
                     random_pixel(rnd), precision);
  }
  s.pixels.assign(static_cast<size_t>(width) * beams, g::Pixel{});
  if (!s.image.empty())
    for (int y = 0; y < beams; ++y) s.image.decode_beam(y, &s.pixels[static_cast<size_t>(y) * width]);
  return s;
}

struct Row {
  int slice, y;
};

struct Request {
  bool valid = false, first = false, last = false;
  int row = 0, x = 0;
};
using Lanes = std::array<Request, kMaxLanes>;

// Every ray of every row, in order, placed on the lanes of the cycles: gaps
// of cells without rays and idle cycles between them, at most two rows a
// cycle (the ring's step holds one beam's cells and the last cells of the
// beam before).
std::vector<Lanes> schedule(const std::vector<Slice>& slices, const std::vector<Row>& rows, int p, Random& rnd) {
  std::vector<Lanes> cycles;
  std::vector<std::array<int, 2>> rows_in;  // per cycle: the rows it holds (-1: none)
  int64_t pos = 0;
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    const Slice& s = slices[static_cast<size_t>(rows[static_cast<size_t>(r)].slice)];
    if (rnd.chance(0.3)) pos += rnd.range(0, 3 * p);  // the row's first cell further on
    for (int x = 0; x < s.rays_x; ++x) {
      if (x > 0 && rnd.chance(0.2)) pos += rnd.range(1, rnd.chance(0.9) ? 2 : 2 * p);  // spacing > 1, idle cycles
      for (;;) {
        const auto c = static_cast<size_t>(pos / p);
        if (c >= cycles.size()) {
          cycles.resize(c + 1);
          rows_in.resize(c + 1, {-1, -1});
        }
        std::array<int, 2>& in = rows_in[c];
        if (in[0] == -1 || in[0] == r) { in[0] = r; break; }
        if (in[1] == -1 || in[1] == r) { in[1] = r; break; }
        pos = static_cast<int64_t>(c + 1) * p;  // a third row waits for the next cycle
      }
      Request& q = cycles[static_cast<size_t>(pos / p)][static_cast<size_t>(pos % p)];
      q = {true, x == 0, x + 1 == s.rays_x, r, x};
      ++pos;
    }
  }
  return cycles;
}

template <class M>
struct Bench {
  explicit Bench(int pipes, std::string name) : p(pipes), chk(std::move(name)), junk(77) {}
  ~Bench() { m.final(); }

  // Streams `slices` (their rows in order; slice after slice is frame after
  // frame too) through the unit from reset, checking every pixel. `damage`:
  // truncate line 0 of bank 0's first row (the test of error_o).
  void run(const std::vector<Slice>& slices, Random& rnd, bool damage = false) {
    m.req_valid_i = 0;
    rtl::reset(m);
    std::vector<Row> rows;
    for (int k = 0; k < static_cast<int>(slices.size()); ++k)
      for (int y = 0; y < slices[static_cast<size_t>(k)].rays_y; ++y) rows.push_back({k, y});
    const std::vector<Lanes> cycles = schedule(slices, rows, p, rnd);
    for (const Lanes& c : cycles) {
      int lo = -1, hi = -1;
      for (int i = 0; i < p; ++i)
        if (c[static_cast<size_t>(i)].valid) {
          if (lo < 0) lo = c[static_cast<size_t>(i)].row;
          hi = c[static_cast<size_t>(i)].row;
        }
      two_rows += lo != hi;
    }
    std::vector<rtl::PerspSlabLines::Row> memory_rows;
    for (const Row& r : rows) memory_rows.push_back({&slices[static_cast<size_t>(r.slice)].image, r.y});
    rtl::PerspSlabLines memory(memory_rows, p);
    if (damage) memory.truncate(0, 0);
    Lanes before{};  // the requests of the cycle before
    for (size_t c = 0; c <= cycles.size(); ++c) {
      const Lanes now = c < cycles.size() ? cycles[c] : Lanes{};
      for (int i = 0; i < p; ++i) {
        const Request& q = now[static_cast<size_t>(i)];
        rtl::put_bits(m.req_valid_i, i, 1, q.valid);
        rtl::put_bits(m.req_first_i, i, 1, q.valid ? q.first : junk.bits(1));
        rtl::put_bits(m.req_last_i, i, 1, q.valid ? q.last : junk.bits(1));
      }
      memory.present(m, [&] { return junk.bits(16); });
      rtl::settle(m);
      observe(slices, rows, before);
      memory.take(m);
      rtl::rise(m);
      memory.clocked();
      ++cycle;
      before = now;
    }
    // The last cycle's pixels, then the unit idle.
    m.req_valid_i = 0;
    rtl::settle(m);
    observe(slices, rows, before);
    rtl::rise(m);
    ++cycle;
  }

  void observe(const std::vector<Slice>& slices, const std::vector<Row>& rows, const Lanes& asked) {
    errors += m.error_o;
    for (int i = 0; i < p; ++i) {
      const Request& q = asked[static_cast<size_t>(i)];
      const bool valid = rtl::get_bits(m.pixel_valid_o, i, 1) != 0;
      const Fields where{{"lane", i}, {"row", q.row}, {"x", q.x}};
      if (valid != q.valid) {
        chk.fail(cycle, where, "pixel_valid_o " + std::to_string(valid));
        continue;
      }
      if (!valid) continue;
      const Row& r = rows[static_cast<size_t>(q.row)];
      const g::Pixel& want = slices[static_cast<size_t>(r.slice)].at(q.x, r.y);
      auto ch = [&](const auto& port) { return static_cast<int64_t>(rtl::get_bits(port, i * 16, 16)); };
      chk.check(cycle, Fields{{"lane", i}, {"slice", r.slice}, {"y", r.y}, {"x", q.x}},
                {{"r", want.r}, {"g", want.g}, {"b", want.b}, {"a", want.a}},
                {{"r", ch(m.pixel_red_o)}, {"g", ch(m.pixel_green_o)}, {"b", ch(m.pixel_blue_o)},
                 {"a", ch(m.pixel_alpha_o)}});
      ++pixels;
      blank += want.a == 0 && want.r == 0 && want.g == 0 && want.b == 0;
    }
  }

  rtl::Dut<M> dut = rtl::make_dut<M>();
  M& m = *dut;
  int p;
  rtl::Checker chk;
  Random junk;
  uint64_t cycle = 0, pixels = 0, blank = 0, errors = 0;
  uint64_t two_rows = 0;  // cycles holding rays of two rows
};

template <class M>
void random_frames(int p, uint64_t salt) {
  const std::string name = "cube4_persp_slab_decode p=" + std::to_string(p);
  Bench<M> b(p, name);
  Random rnd(salt);
  const long n = rtl::vector_count(1000000);
  rtl::Timer t(name + ": " + std::to_string(n) + " pixels");
  long streams = 0;
  while (b.pixels < static_cast<uint64_t>(n) && b.chk.ok()) {
    std::vector<Slice> slices;
    for (int k = static_cast<int>(rnd.range(1, 12)); k > 0; --k) slices.push_back(random_slice(rnd, p));
    b.run(slices, rnd);
    ++streams;
  }
  std::printf("  [%s: %ld streams, %llu pixels (%llu blank), %llu cycles, %llu holding two rows]\n",
              name.c_str(), streams, static_cast<unsigned long long>(b.pixels),
              static_cast<unsigned long long>(b.blank), static_cast<unsigned long long>(b.cycle),
              static_cast<unsigned long long>(b.two_rows));
  EXPECT_TRUE(b.chk.ok()) << b.chk.report();
  EXPECT_EQ(b.errors, 0u) << "error_o on well-formed lines";
  EXPECT_GE(b.pixels, static_cast<uint64_t>(n));
  EXPECT_GT(b.blank, 0u);
  EXPECT_LT(b.blank, b.pixels);
  if (p > 1) {
    EXPECT_GT(b.two_rows, 1000u);
  }
}

TEST(RtlPerspSlabDecode, EveryRaysPixelIsGoldensAtP4) { random_frames<Vcube4_persp_slab_decode>(4, 11); }
TEST(RtlPerspSlabDecode, EveryRaysPixelIsGoldensAtP1) { random_frames<Vcube4_persp_slab_decode_p1>(1, 12); }
TEST(RtlPerspSlabDecode, EveryRaysPixelIsGoldensAtP5) { random_frames<Vcube4_persp_slab_decode_p5>(5, 13); }
TEST(RtlPerspSlabDecode, EveryRaysPixelIsGoldensAtP8) { random_frames<Vcube4_persp_slab_decode_p8>(8, 14); }

// A line that ends inside a flit (its last word lost): error_o rises once
// the row's rays read that far, and not before.
TEST(RtlPerspSlabDecode, ALineEndingInsideAFlitRaisesError) {
  Bench<Vcube4_persp_slab_decode> b(4, "cube4_persp_slab_decode p=4 (damaged line)");
  Random rnd(15);
  const g::Precision precision;
  Slice s{g::SlabImage(9, 2, 4), 9, 2, {}};
  for (int x = 0; x < 9; ++x) s.image.insert(x, 0, {0, 0, 0, static_cast<uint16_t>(100 + x)}, precision);
  s.pixels.assign(18, g::Pixel{});
  for (int y = 0; y < 2; ++y) s.image.decode_beam(y, &s.pixels[static_cast<size_t>(y) * 9]);
  // Undamaged first: no error.
  b.run({s}, rnd);
  EXPECT_TRUE(b.chk.ok()) << b.chk.report();
  EXPECT_EQ(b.errors, 0u);
  // Line 0 of row 0 (x = 0, 4, 8) loses its last word: its third pixel errs
  // (and reads blank, which this bench's checker reports too).
  Bench<Vcube4_persp_slab_decode> d(4, "cube4_persp_slab_decode p=4 (damaged line)");
  d.run({s}, rnd, true);
  EXPECT_GT(d.errors, 0u);
}

// The request contract's assertions (rtl/assert/cube4_persp_slab_decode_sva.sv),
// each driven into its violation at p = 4 over a slab image of 8 x 4 pixels:
// quiet on a correct stream, firing in the cycle of the fault otherwise.
// A cycle's requests: per lane 0 (none), 'r' (a ray), 'f' (its row's
// first), 'l' (its row's last), 'b' (both: a row of one ray).
void request_stream(const std::vector<std::string>& cycles, const std::string& label,
                    std::initializer_list<std::string> parts) {
  const g::Precision precision;
  g::SlabImage image(8, 4, 4);
  for (int x = 0; x < 8; ++x) image.insert(x, x % 4, {0, 0, 0, static_cast<uint16_t>(1000 + x)}, precision);
  rtl::run_expecting<Vcube4_persp_slab_decode>(
      [&](Vcube4_persp_slab_decode& m) {
        rtl::PerspSlabLines memory({{&image, 0}, {&image, 1}, {&image, 2}, {&image, 3}}, 4);
        for (const std::string& c : cycles) {
          uint32_t valid = 0, first = 0, last = 0;
          for (int i = 0; i < 4; ++i) {
            const char r = c[static_cast<size_t>(i)];
            valid |= static_cast<uint32_t>(r != '0') << i;
            first |= static_cast<uint32_t>(r == 'f' || r == 'b') << i;
            last |= static_cast<uint32_t>(r == 'l' || r == 'b') << i;
          }
          m.req_valid_i = valid;
          m.req_first_i = first;
          m.req_last_i = last;
          memory.present(m, [] { return uint16_t{0}; });
          rtl::settle(m);
          memory.take(m);
          rtl::rise(m);
          memory.clocked();
        }
      },
      label, parts);
}

TEST(RtlPerspSlabDecodeSva, RaysWithinTheirRows) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  // Rows of 3 rays: the second's first in the cycle of the first's last.
  request_stream({"frr0", "lfrl", "00fr", "l000"}, "", {});
  request_stream({"frr0", "lfrl", "00rr", "l000"}, "a_row_open", {"cycle 3:", "after its last"});  // a ray past its row
  request_stream({"rr00"}, "a_row_open", {"cycle 1:", "before its row's first"});
}

TEST(RtlPerspSlabDecodeSva, ARowStartsOnlyWhereTheRowTwoBackEnded) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  // Row 0 never ends: row 2 (bank 0 again) would read its lines.
  request_stream({"frr0", "fr0l", "fr00"}, "a_row_ended", {"cycle 3:", "has not ended"});
}

TEST(RtlPerspSlabDecodeSva, AtMostTwoRowsACycle) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  request_stream({"frr0", "lbf0", "l000"}, "a_two_rows", {"cycle 2:", "rays of 3 rows"});
  request_stream({"frr0", "lf0r", "l000"}, "", {});
}

}  // namespace
