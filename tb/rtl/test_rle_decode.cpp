// RTL equivalence tests of the run-length decoder of slab images,
// cube4_rle_decode, against golden RleDecoder (golden/units/rle_decode.hpp):
// every pixel, and error() and finished() after every pixel.
//
// The bench plays the word source of the decoder's header: a line in C++
// memory, a read position that advances by consume_o at each clock edge, the
// five words from it on window_i (junk beyond the line's end, which the
// decoder must ignore) and their count on avail_i. Lines follow each other
// with start_i, alone or in the cycle of the new line's first pixel; pixels
// are asked back to back or with random idle cycles between them.
//
// CUBE4_RTL_VECTORS overrides the random vector count (decoded pixels;
// default 1,000,000).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "Vcube4_rle_decode.h"
#include "golden/rle_buffer.hpp"
#include "golden/units/rle_decode.hpp"
#include "tb/rtl/hybrid_scene.hpp"
#include "tb/rtl/rtl_check.hpp"
#include "tb/rtl/sva_check.hpp"

namespace {

namespace g = cube4::golden;
namespace rtl = cube4::rtl;
using rtl::Fields;
using rtl::Random;
using Line = std::vector<uint16_t>;

Fields pixel_fields(const g::Pixel& p) { return {{"r", p.r}, {"g", p.g}, {"b", p.b}, {"a", p.a}}; }

class RleBench {
 public:
  RleBench() : chk("cube4_rle_decode"), junk_(4242) {
    m.start_i = 0;
    m.next_i = 0;
    present();
    rtl::reset(m);
  }
  ~RleBench() { m.final(); }

  // Decodes `pixels` pixels of `line`; an idle cycle before a pixel with
  // probability `gap`; start_i with the first pixel if `start_with_pixel`
  // (else in a cycle of its own). Checks every pixel, error_o after each and
  // finished_o at the end against golden.
  void line(const Line& line, int pixels, double gap, bool start_with_pixel) {
    // The source shows a new line from its start_i on (a_source_advances).
    const bool start_alone = !start_with_pixel || pixels == 0;
    if (!start_alone)
      while (junk_.chance(gap)) cycle_(false, false);
    line_ = line;
    at_ = 0;
    golden_.emplace(line_.data(), line_.size());
    ++lines;
    bool start = true;
    if (start_alone) {
      cycle_(true, false);
      start = false;
    }
    for (int i = 0; i < pixels; ++i) {
      if (!start)
        while (junk_.chance(gap)) cycle_(false, false);
      cycle_(start, true);
      start = false;
    }
    cycle_(false, false);  // the last pixel's output, finished_o and error_o
    if (m.finished_o != golden_->finished())
      chk.fail(cycle, {{"line", static_cast<int64_t>(lines)}, {"words", static_cast<int64_t>(line_.size())},
                       {"pixels", pixels}},
               "finished_o " + std::to_string(m.finished_o) + ", golden finished() " +
                   std::to_string(golden_->finished()));
    finished += golden_->finished();
    errors += golden_->error();
  }

  cube4::rtl::Dut<Vcube4_rle_decode> dut = cube4::rtl::make_dut<Vcube4_rle_decode>();
  Vcube4_rle_decode& m = *dut;
  rtl::Checker chk;
  uint64_t cycle = 0, vectors = 0, lines = 0, finished = 0, errors = 0;

 private:
  // The source's window at the read position.
  void present() {
    const size_t left = line_.size() - std::min(at_, line_.size());
    m.avail_i = static_cast<uint8_t>(std::min<size_t>(5, left));
    for (int i = 0; i < 5; ++i) {
      const uint16_t w = static_cast<size_t>(i) < left ? line_[at_ + i] : static_cast<uint16_t>(junk_.bits(16));
      rtl::put_bits(m.window_i, i * 16, 16, w);
    }
  }

  void cycle_(bool start, bool next) {
    m.start_i = start;
    m.next_i = next;
    present();
    rtl::settle(m);
    // The pixel asked in the cycle before, and the error after it.
    const bool valid = m.pixel_valid_o;
    const g::Pixel got{static_cast<uint16_t>(m.pixel_red_o), static_cast<uint16_t>(m.pixel_green_o),
                       static_cast<uint16_t>(m.pixel_blue_o), static_cast<uint16_t>(m.pixel_alpha_o)};
    if (valid != expected_.has_value()) {
      chk.fail(cycle, {{"line", static_cast<int64_t>(lines)}}, "pixel_valid_o " + std::to_string(valid));
    } else if (valid) {
      const g::Pixel& e = *expected_;
      chk.check_lazy(
          cycle, got.r == e.r && got.g == e.g && got.b == e.b && got.a == e.a,
          [&] { return Fields{{"line", static_cast<int64_t>(lines)}, {"at", static_cast<int64_t>(at_)}}; },
          [&] { return pixel_fields(e); }, [&] { return pixel_fields(got); });
      if (!start && m.error_o != golden_->error())
        chk.fail(cycle, {{"line", static_cast<int64_t>(lines)}}, "error_o differs from golden error()");
    }
    expected_.reset();
    if (next) {
      expected_ = golden_->next();
      ++vectors;
    }
    const int consumed = m.consume_o;
    rtl::rise(m);
    at_ += static_cast<size_t>(consumed);
    ++cycle;
  }

  Line line_;
  size_t at_ = 0;
  std::optional<g::RleDecoder> golden_;
  std::optional<g::Pixel> expected_;
  Random junk_;
};

// A pixel with some channel non-zero (one channel alone, often).
g::Pixel random_pixel(Random& rnd) {
  g::Pixel p;
  do {
    if (rnd.chance(0.3)) {
      uint16_t* ch[] = {&p.r, &p.g, &p.b, &p.a};
      *ch[rnd.range(0, 3)] = static_cast<uint16_t>(rnd.edgy(65535, 0.3));
    } else {
      p = {static_cast<uint16_t>(rnd.edgy(65535, 0.2)), static_cast<uint16_t>(rnd.edgy(65535, 0.2)),
           static_cast<uint16_t>(rnd.edgy(65535, 0.2)), static_cast<uint16_t>(rnd.edgy(65535, 0.2))};
    }
  } while (g::blank(p));
  return p;
}

void put_pixel(Line& l, const g::Pixel& p) { l.insert(l.end(), {p.r, p.g, p.b, p.a}); }
void put_run(Line& l, uint16_t word) { l.insert(l.end(), {0, 0, 0, 0, word}); }

// A canonical line (the encoder's) of `width` pixels, blank with probability `blank`.
Line canonical(Random& rnd, int width, double blank) {
  std::vector<g::Pixel> px(static_cast<size_t>(width));
  for (g::Pixel& p : px)
    if (!rnd.chance(blank)) p = random_pixel(rnd);
  return g::rle_encode(px.data(), width);
}

// Any sequence of flits: runs of any length (zero-word runs, runs in a row),
// which golden decodes as well; returns the pixels it holds.
int64_t any_flits(Random& rnd, Line& l, int flits) {
  int64_t pixels = 0;
  for (int i = 0; i < flits; ++i) {
    if (rnd.chance(0.5)) {
      put_pixel(l, random_pixel(rnd));
      ++pixels;
    } else {
      const uint16_t w = static_cast<uint16_t>(rnd.chance(0.9) ? rnd.range(0, 6) : rnd.range(0, 300));
      put_run(l, w);
      pixels += w + 1;
    }
  }
  return pixels;
}

void expect_ok(RleBench& b) {
  std::printf("  %s; %llu lines, %llu finished exactly, %llu with an error (%llu cycles)\n", b.chk.report().c_str(),
              static_cast<unsigned long long>(b.lines), static_cast<unsigned long long>(b.finished),
              static_cast<unsigned long long>(b.errors), static_cast<unsigned long long>(b.cycle));
  EXPECT_TRUE(b.chk.ok()) << b.chk.report();
}

// ---------------------------------------------------------------------------

void random_lines(long n) {
  RleBench b;
  Random rnd(1201);
  rtl::Timer t("cube4_rle_decode random");
  while (b.vectors < static_cast<uint64_t>(n)) {
    Line l;
    int pixels = 0;
    const double kind = rnd.range(0, 99);
    if (kind < 60) {  // canonical, asked exactly its width
      pixels = static_cast<int>(rnd.chance(0.1) ? rnd.range(0, 3) : rnd.range(1, 200));
      const double blanks[] = {0.0, 0.3, 0.7, 0.95, 1.0};
      l = canonical(rnd, pixels, blanks[rnd.range(0, 4)]);
    } else if (kind < 80) {  // any flits
      pixels = static_cast<int>(any_flits(rnd, l, static_cast<int>(rnd.range(0, 30))));
    } else {  // malformed: truncated, asked too many or too few pixels, or junk words
      const int width = static_cast<int>(rnd.range(0, 100));
      l = canonical(rnd, width, 0.5);
      pixels = width;
      const int how = static_cast<int>(rnd.range(0, 3));
      if (how == 0 && !l.empty()) l.resize(l.size() - static_cast<size_t>(rnd.range(1, std::min<int64_t>(5, l.size()))));
      if (how == 1) pixels += static_cast<int>(rnd.range(1, 8));
      if (how == 2) pixels = static_cast<int>(rnd.range(0, std::max(0, width - 1)));
      if (how == 3)
        for (int i = static_cast<int>(rnd.range(1, 12)); i > 0; --i)
          l.push_back(static_cast<uint16_t>(rnd.chance(0.5) ? 0 : rnd.bits(16)));
    }
    b.line(l, pixels, rnd.chance(0.5) ? 0.0 : 0.3, rnd.chance(0.7));
  }
  expect_ok(b);
  EXPECT_GE(b.vectors, static_cast<uint64_t>(n));
  EXPECT_GT(b.errors, 0u);
  EXPECT_GT(b.finished, b.lines / 2);
}

TEST(RtlRleDecode, Random) { random_lines(rtl::vector_count(1000000)); }

// A line of width 0 (no flits), asked nothing or a pixel; a full line (no
// blank pixel: all pixel flits), including pixels with one non-zero channel
// alone, which are pixels, not runs.
TEST(RtlRleDecode, EmptyAndFullLines) {
  RleBench b;
  Random rnd(1202);
  b.line({}, 0, 0, true);
  b.line({}, 1, 0, true);
  b.line({}, 0, 0, false);
  for (int width : {1, 2, 5, 64, 256}) {
    b.line(canonical(rnd, width, 0.0), width, 0.0, true);
    b.line(canonical(rnd, width, 1.0), width, 0.0, true);  // one run: a cleared line
    b.line(g::rle_clear(width), width, 0.2, false);
  }
  for (int ch = 0; ch < 4; ++ch) {
    Line l;
    for (uint16_t v : {uint16_t{1}, uint16_t{0x8000}, uint16_t{0xFFFF}}) {
      g::Pixel p;
      uint16_t* c[] = {&p.r, &p.g, &p.b, &p.a};
      *c[ch] = v;
      put_pixel(l, p);
    }
    b.line(l, 3, 0.0, true);
  }
  expect_ok(b);
}

// The longest run (65536 pixels in one flit), back to back with the next line.
TEST(RtlRleDecode, LongestRun) {
  RleBench b;
  Random rnd(1203);
  b.line(g::rle_clear(g::kRleRunMax), g::kRleRunMax, 0.0, true);
  Line l = g::rle_clear(g::kRleRunMax - 1);
  put_pixel(l, random_pixel(rnd));
  b.line(l, g::kRleRunMax, 0.0, true);
  b.line(l, g::kRleRunMax + 1, 0.0, true);  // one pixel too many
  expect_ok(b);
}

// Lines made by Algorithm 1 (golden rle_insert) with a fragment at every
// position of lines of every kind: first and last pixel, each end of a
// run, a one-pixel run, next to pixel flits.
TEST(RtlRleDecode, FragmentsAtEveryPositionOfALine) {
  RleBench b;
  Random rnd(1204);
  const g::Precision p;
  for (int width : {1, 2, 3, 7, 16, 33})
    for (double blank : {1.0, 0.7, 0.3})
      for (int x = 0; x < width; ++x) {
        const Line base = canonical(rnd, width, blank);
        b.line(g::rle_insert(base, width, x, random_pixel(rnd), p), width, 0.0, true);
        b.line(g::rle_insert(base, width, x, random_pixel(rnd), p), width, 0.3, false);
      }
  expect_ok(b);
}

// One decoder per pipeline over the beams of slab images: each lane's lines
// of consecutive beams back to back (start_i with the first pixel, no idle
// cycle), so a run that ends one beam's line is followed at once by the next
// beam's, which may start with a run too; the lanes' pixels, interleaved,
// are golden decode_beam()'s.
void decode_slab(const g::SlabImage& slab, std::vector<RleBench>& lanes, const std::string& what) {
  const int p = slab.lanes();
  for (int y = 0; y < slab.beams(); ++y) {
    std::vector<g::Pixel> want(static_cast<size_t>(slab.width()));
    slab.decode_beam(y, want.data());
    for (int l = 0; l < p && l < slab.width(); ++l) {
      const Line line = slab.line(y, l).line();  // an empty slab's: its lane's cleared line
      // The bench compares with golden RleDecoder on this line; decode_beam's
      // interleaving is the lane's x = l, l + p, ...
      std::vector<g::Pixel> lane(static_cast<size_t>(slab.lane_width(l)));
      ASSERT_TRUE(g::rle_decode_line(line.data(), line.size(), slab.lane_width(l), lane.data())) << what;
      for (int i = 0; i < slab.lane_width(l); ++i) {
        const g::Pixel& a = lane[static_cast<size_t>(i)];
        const g::Pixel& e = want[static_cast<size_t>(i * p + l)];
        ASSERT_TRUE(a.r == e.r && a.g == e.g && a.b == e.b && a.a == e.a) << what;
      }
      lanes[static_cast<size_t>(l)].line(line, slab.lane_width(l), 0.0, true);
    }
  }
}

TEST(RtlRleDecode, RunsAcrossBeamBoundaries) {
  Random rnd(1205);
  const g::Precision prec;
  for (int p : {1, 4, 5}) {
    std::vector<RleBench> lanes(static_cast<size_t>(p));
    for (int width : {1, 4, 9, 37}) {
      g::SlabImage slab(width, 6, p);
      // Fragments near the ends of beams, so lines end and start with runs
      // and pixels alike.
      for (int i = 0; i < 2 * width; ++i) {
        const int x = static_cast<int>(rnd.chance(0.5) ? rnd.range(0, width - 1) : (rnd.chance(0.5) ? 0 : width - 1));
        slab.insert(x, static_cast<int>(rnd.range(0, 5)), random_pixel(rnd), prec);
      }
      decode_slab(slab, lanes, "p " + std::to_string(p) + ", width " + std::to_string(width));
    }
    for (RleBench& b : lanes) expect_ok(b);
  }
}

// A translucent plane exactly on a slab boundary: at depth D = 4 sample
// slices, which golden puts in slab 3 (3 < D <= 4), behind sample 3 and
// before sample 4. Every slab image of the frame through the decoders of
// p = 4 pipelines; the plane's fragments arrive in slab 3's beams only.
TEST(RtlRleDecode, AFragmentExactlyOnASlabBoundary) {
  const std::string json =
      R"({"volume": {"synthetic": "constant", "size": [10, 10, 10], "value": 0.5},
          "view": {"direction": [0, 0, 1], "up": [0, 1, 0]}, "shading": false, "pipelines": 4,
          "polygons": [{"shape": "plane", "size": [30, 30],
                        "transform": {"rotate": [0, 0, 0], "translate": [4.5, 4.5, 4.0]},
                        "color": [0.1, 0.3, 1], "opacity": 0.4, "lit": false}]})";
  const rtl::HybridScene hs = rtl::hybrid_scene(json, "test_rle_decode scene");
  const g::PolygonFrame& f = hs.frame;
  ASSERT_EQ(f.counts.in_slabs, 100u) << "the plane's fragments lie in the slabs";
  const double depth = hs.host.view.to_permuted({4.5, 4.5, 4.0})[2] * hs.scene.supersampling;  // 4 (or 5 if z is flipped)
  ASSERT_EQ(depth, std::round(depth));
  const size_t boundary = static_cast<size_t>(depth) - 1;
  std::vector<RleBench> lanes(4);
  for (size_t k = 0; k < f.slabs.size(); ++k) {
    const g::SlabImage& slab = f.slabs[k];
    EXPECT_EQ(slab.empty(), k != boundary) << "slab " << k;
    if (slab.empty()) continue;
    ASSERT_EQ(slab.lanes(), 4);
    decode_slab(slab, lanes, "slab " + std::to_string(k));
  }
  for (RleBench& b : lanes) expect_ok(b);
}

// ---------------------------------------------------------------------------
// The word source's contract (rtl/assert/cube4_rle_decode_sva.sv), broken on
// purpose: each assertion fires in the cycle of the fault, and the same
// stream with a correct source stays quiet.

// Two pixel flits, then a run flit; `lag`: the source does not advance
// after the first pixel; `avail`: the count it shows at the start.
void source_stream(bool lag, int avail, const std::string& label, std::initializer_list<std::string> parts) {
  rtl::SvaBench<Vcube4_rle_decode> b;
  rtl::reset(*b);
  const Line line = {1, 2, 3, 4, 5, 6, 7, 8, 0, 0, 0, 0, 2};
  size_t at = 0;
  for (int c = 0; c < 5; ++c) {
    b->start_i = c == 0;
    b->next_i = 1;
    const size_t left = line.size() - at;
    b->avail_i = static_cast<uint8_t>(c == 0 ? avail : std::min<size_t>(5, left));
    for (size_t i = 0; i < 5; ++i) rtl::put_bits(b->window_i, static_cast<int>(i) * 16, 16, i < left ? line[at + i] : 0);
    rtl::settle(*b);
    const int consumed = b->consume_o;
    rtl::rise(*b);
    if (!(lag && c == 0)) at += static_cast<size_t>(consumed);
  }
  if (label.empty())
    rtl::expect_quiet(b);
  else
    rtl::expect_fired(b, label, parts);
}

TEST(RtlRleDecodeSva, SourceAdvancesByTheWordsConsumed) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  source_stream(false, 5, "", {});
  source_stream(true, 5, "a_source_advances", {"cycle 2:", "advance by the 4 words consumed"});
}

TEST(RtlRleDecodeSva, AvailCountsAtMostFiveWords) {
  CUBE4_SKIP_WITHOUT_ASSERTIONS();
  source_stream(false, 6, "a_avail_in_range", {"cycle 1:", "avail_i 6"});
}

}  // namespace
