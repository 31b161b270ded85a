// Cube-5's polygons in the golden model (docs/fixed-point.md, "Polygons"):
// the compositor's Z test and double composition, the run-length slab
// images and Algorithm 1, the host rasteriser's coverage and ties, the
// renderers with polygons against the specification's own expected chains,
// and fixed against float against the reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "golden/errors.hpp"
#include "golden/polygon_connections.hpp"
#include "golden/polygons.hpp"
#include "golden/rasterise.hpp"
#include "golden/rle_buffer.hpp"
#include "golden/units/composite_polygon.hpp"
#include "golden/units/rle_decode.hpp"
#include "tb/tests/test_support.hpp"
#include "tb/translucency.hpp"

using namespace cube4;
using golden::Pixel;
using golden::RayAcc;

namespace {

bool same(const Pixel& a, const Pixel& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }

std::string str(const Pixel& p) {
  return "(" + std::to_string(p.r) + ", " + std::to_string(p.g) + ", " + std::to_string(p.b) + ", " +
         std::to_string(p.a) + ")";
}

// A random polygon pixel: premultiplied, so no colour above α; never blank.
Pixel random_pixel(std::mt19937& gen, int bits) {
  const uint32_t full = (1u << bits) - 1;
  const uint32_t a = std::uniform_int_distribution<uint32_t>(1, full)(gen);
  std::uniform_int_distribution<uint32_t> c(0, a);
  return {static_cast<uint16_t>(c(gen)), static_cast<uint16_t>(c(gen)), static_cast<uint16_t>(c(gen)),
          static_cast<uint16_t>(a)};
}

// A line is canonical: flits that add up to its width, no empty run, no
// two runs in a row, nothing after the last flit.
bool canonical(golden::RleWords line, int width) {
  size_t at = 0;
  int total = 0;
  bool last_run = false;
  while (at < line.size()) {
    if (at + 4 > line.size()) return false;
    const bool run = (line[at] | line[at + 1] | line[at + 2] | line[at + 3]) == 0;
    if (run) {
      if (at + 5 > line.size() || last_run) return false;
      total += line[at + 4] + 1;
      at += 5;
    } else {
      total += 1;
      at += 4;
    }
    last_run = run;
  }
  return total == width;
}

}  // namespace

// ---- the compositor's functions ----

TEST(PolygonUnits, ZTestHidesSamplesAtOrBehindTheSurface) {
  const int f = golden::kZFracBits;
  EXPECT_TRUE(golden::sample_before_z(6, 7u << f));
  EXPECT_FALSE(golden::sample_before_z(7, 7u << f));           // at the surface
  EXPECT_TRUE(golden::sample_before_z(7, (7u << f) + 1));      // 1/256 of a slice behind the sample
  EXPECT_FALSE(golden::sample_before_z(0, 0));                 // a surface in front of the volume
  EXPECT_TRUE(golden::sample_before_z(8 * 4096 - 1, golden::kZNone));  // no surface hides nothing
}

TEST(PolygonUnits, DoubleCompositionIsTheSampleThenTheSlabPixel) {
  const golden::Precision p;
  std::mt19937 gen(3);
  for (int trial = 0; trial < 2000; ++trial) {
    const Pixel prior = random_pixel(gen, p.alpha_bits), slab = random_pixel(gen, p.alpha_bits);
    const RayAcc acc = golden::pixel_to_acc(prior, p);
    golden::ShadedSample s;
    s.rgb = {std::uniform_int_distribution<uint32_t>(0, 65535)(gen), 1000, 65535};
    s.alpha = std::uniform_int_distribution<uint32_t>(0, 65535)(gen);
    const RayAcc with_sample = golden::blend_front_to_back(acc, s, p);
    // Sample, then the slab pixel behind it.
    EXPECT_EQ(golden::double_composite(acc, s, true, slab, p),
              golden::compose_over(with_sample, golden::pixel_to_acc(slab, p), p));
    // A hidden sample leaves the slab pixel alone; a blank slab the sample alone.
    EXPECT_EQ(golden::double_composite(acc, s, false, slab, p),
              golden::compose_over(acc, golden::pixel_to_acc(slab, p), p));
    EXPECT_EQ(golden::double_composite(acc, s, true, Pixel{}, p), with_sample);
    // Widening is undone exactly at the base plane.
    EXPECT_TRUE(same(golden::pixel_of(golden::pixel_to_acc(slab, p), p), slab));
    // The RLE buffer's Blend: a blank side gives the other, the result is never blank.
    EXPECT_TRUE(same(golden::pixel_over(Pixel{}, slab, p), slab));
    EXPECT_TRUE(same(golden::pixel_over(slab, Pixel{}, p), slab));
    EXPECT_FALSE(golden::blank(golden::pixel_over(prior, slab, p)));
  }
  // An opaque fragment as a pixel is its colour; an opaque front hides the back.
  const Pixel opaque = golden::polygon_pixel({100, 200, 300}, 65535, p);
  EXPECT_TRUE(same(opaque, Pixel{100, 200, 300, 65535}));
  EXPECT_TRUE(same(golden::pixel_over(opaque, Pixel{5, 5, 5, 9}, p), opaque));
  EXPECT_TRUE(golden::blank(golden::polygon_pixel({65535, 65535, 65535}, 0, p)));
}

// ---- run-length slab images ----

// pixel_over() returns the back pixel when the front is blank instead of
// running the node; the node gives exactly that at every α width: a blank
// front leaves full transparency, and mul_frac by full is the identity.
TEST(PolygonUnits, BlankFrontSkipsANodeThatWouldGiveTheBackExactly) {
  for (int bits = 8; bits <= 16; ++bits) {
    const int64_t full = golden::max_unsigned(bits);
    for (int64_t f = 0; f <= full; ++f) ASSERT_EQ(golden::mul_frac(full, f, bits), f) << bits << " bits, " << f;
    golden::Precision p;
    p.alpha_bits = bits;
    std::mt19937 gen(static_cast<unsigned>(bits));
    for (int trial = 0; trial < 1000; ++trial) {
      const Pixel back = random_pixel(gen, bits);
      const RayAcc node = golden::compose_over(golden::pixel_as_node(Pixel{}), golden::pixel_as_node(back),
                                               golden::pixel_precision(p));
      ASSERT_TRUE(same(Pixel{static_cast<uint16_t>(node.r), static_cast<uint16_t>(node.g),
                             static_cast<uint16_t>(node.b), static_cast<uint16_t>(node.a)},
                       back));
      ASSERT_TRUE(same(golden::pixel_over(Pixel{}, back, p), back));
    }
  }
}

TEST(PolygonUnits, EmptyRaySkipsANodeThatWouldGiveThePixelExactly) {
  // ray_over_pixel's shortcut rests on mul_frac(full, f) = f at the
  // accumulator's widths too (alpha_bits + acc_guard_bits, up to 24).
  for (int bits = 17; bits <= 24; ++bits) {
    const int64_t full = golden::max_unsigned(bits);
    for (int64_t f = 0; f <= full; ++f) ASSERT_EQ(golden::mul_frac(full, f, bits), f) << bits << " bits, " << f;
  }
  std::mt19937 gen(5);
  for (int alpha = 8; alpha <= 16; ++alpha)
    for (int guard : {0, 4, 8}) {
      golden::Precision p;
      p.alpha_bits = alpha;
      p.acc_guard_bits = guard;
      for (int trial = 0; trial < 1000; ++trial) {
        const Pixel px = random_pixel(gen, alpha);
        RayAcc empty;
        empty.value = static_cast<uint16_t>(trial);
        empty.valid = trial % 2 == 1;
        ASSERT_EQ(golden::ray_over_pixel(empty, px, p), golden::compose_over(empty, golden::pixel_to_acc(px, p), p))
            << alpha << " + " << guard << " bits, trial " << trial;
      }
    }
}

TEST(Rle, RoundTripsAndCanonicalLines) {
  const golden::Precision p;
  std::mt19937 gen(11);
  for (int width : {0, 1, 2, 3, 7, 64, 257, 4096})
    for (double density : {0.0, 0.03, 0.5, 1.0})
      for (int trial = 0; trial < 5; ++trial) {
        std::vector<Pixel> px(static_cast<size_t>(width));
        int runs = 0, pixels = 0;
        for (int x = 0; x < width; ++x) {
          if (std::bernoulli_distribution(density)(gen)) {
            px[static_cast<size_t>(x)] = random_pixel(gen, p.alpha_bits);
            ++pixels;
          } else if (x == 0 || !golden::blank(px[static_cast<size_t>(x - 1)])) {
            ++runs;
          }
        }
        const golden::RleLine line = golden::rle_encode(px.data(), width);
        ASSERT_TRUE(canonical(line, width)) << width << " " << density;
        EXPECT_EQ(golden::rle_flits(line), static_cast<size_t>(runs + pixels));
        const std::vector<Pixel> back = golden::rle_decode(line, width);
        for (int x = 0; x < width; ++x) ASSERT_TRUE(same(back[static_cast<size_t>(x)], px[static_cast<size_t>(x)])) << x;
        EXPECT_EQ(golden::rle_encode(back.data(), width), line);
        // The pipeline's decoder, one pixel a cycle, delivers the same.
        golden::RleDecoder d(line.data(), line.size());
        for (int x = 0; x < width; ++x) ASSERT_TRUE(same(d.next(), px[static_cast<size_t>(x)])) << x;
        EXPECT_TRUE(d.finished());
      }
  EXPECT_EQ(golden::rle_clear(300), (golden::RleLine{0, 0, 0, 0, 299}));
  EXPECT_TRUE(golden::rle_clear(0).empty());
}

TEST(Rle, MalformedLinesAreCaught) {
  const golden::RleLine short_run{0, 0, 0, 0, 2};  // 3 pixels
  EXPECT_THROW(golden::rle_decode(short_run, 4), std::logic_error);
  EXPECT_THROW(golden::rle_decode(short_run, 2), std::logic_error);
  EXPECT_THROW(golden::rle_decode(golden::RleLine{0, 0, 0, 0}, 1), std::logic_error);
  EXPECT_NO_THROW(golden::rle_decode(short_run, 3));
}

namespace {
// The naive insert Algorithm 1 must equal: the dense line, the fragment
// blended behind what is there, encoded again.
golden::RleLine naive_insert(const golden::RleLine& line, int width, int x, const Pixel& px, const golden::Precision& p) {
  std::vector<Pixel> dense = golden::rle_decode(line, width);
  dense[static_cast<size_t>(x)] = golden::pixel_over(dense[static_cast<size_t>(x)], px, p);
  return golden::rle_encode(dense.data(), width);
}
}  // namespace

TEST(Rle, AlgorithmOneEqualsANaiveInsertForFragmentsInAnyOrder) {
  const golden::Precision p;
  std::mt19937 gen(5);
  for (int trial = 0; trial < 3000; ++trial) {
    const int width = std::uniform_int_distribution<int>(1, trial % 10 == 0 ? 300 : 24)(gen);
    const int count = std::uniform_int_distribution<int>(1, 2 * width)(gen);
    golden::RleLine fast = golden::rle_clear(width), slow = fast;
    for (int i = 0; i < count; ++i) {
      const int x = std::uniform_int_distribution<int>(0, width - 1)(gen);
      const Pixel px = random_pixel(gen, p.alpha_bits);
      fast = golden::rle_insert(fast, width, x, px, p);
      slow = naive_insert(slow, width, x, px, p);
      ASSERT_EQ(fast, slow) << "width " << width << ", fragment " << i << " at " << x;
      ASSERT_TRUE(canonical(fast, width));
    }
  }
}

TEST(Rle, AlgorithmOneAtEveryPositionOfEveryKindOfFlit) {
  // The places the paper's pseudo-code, read literally, gets wrong: the
  // last pixel of a run, a run of one pixel, the first and last pixel of
  // the line; and pixels already there.
  const golden::Precision p;
  std::mt19937 gen(8);
  const Pixel a = random_pixel(gen, p.alpha_bits), b = random_pixel(gen, p.alpha_bits);
  const std::vector<std::vector<Pixel>> lines = {
      {Pixel{}},
      {a},
      {Pixel{}, a, Pixel{}},
      {a, Pixel{}, a},
      {Pixel{}, Pixel{}, Pixel{}, a, Pixel{}, b, b, Pixel{}, Pixel{}},
      {a, Pixel{}, Pixel{}, Pixel{}, Pixel{}, Pixel{}, b},
  };
  for (const auto& dense : lines) {
    const int width = static_cast<int>(dense.size());
    const golden::RleLine line = golden::rle_encode(dense.data(), width);
    for (int x = 0; x < width; ++x) {
      const golden::RleLine got = golden::rle_insert(line, width, x, b, p);
      EXPECT_EQ(got, naive_insert(line, width, x, b, p)) << "width " << width << " at " << x;
      EXPECT_TRUE(canonical(got, width));
    }
    EXPECT_EQ(golden::rle_insert(line, width, 0, Pixel{}, p), line);  // a blank fragment changes nothing
  }
}

TEST(Rle, SlabImagesDecodePerPipelineToTheSameBeam) {
  const golden::Precision p;
  std::mt19937 gen(21);
  for (int width : {1, 7, 13, 64})
    for (int lanes : {1, 2, 3, 5, 16}) {
      golden::SlabImage slab(width, 3, lanes);
      EXPECT_TRUE(slab.empty());
      std::vector<Pixel> dense(static_cast<size_t>(width) * 3);
      for (int i = 0; i < 40; ++i) {
        const int x = std::uniform_int_distribution<int>(0, width - 1)(gen), y = i % 3;
        const Pixel px = random_pixel(gen, p.alpha_bits);
        slab.insert(x, y, px, p);
        Pixel& d = dense[static_cast<size_t>(y) * width + x];
        d = golden::pixel_over(d, px, p);
      }
      std::vector<Pixel> beam(static_cast<size_t>(width));
      for (int y = 0; y < 3; ++y) {
        slab.decode_beam(y, beam.data());
        for (int x = 0; x < width; ++x)
          ASSERT_TRUE(same(beam[static_cast<size_t>(x)], dense[static_cast<size_t>(y) * width + x]))
              << "width " << width << ", lanes " << lanes << ", (" << x << ", " << y << ")";
        for (int l = 0; l < lanes; ++l) EXPECT_TRUE(canonical(slab.line(y, l), slab.lane_width(l)));
        // The compositor's walk: the same pixels without the blank ones.
        std::vector<Pixel> walked(static_cast<size_t>(width));
        slab.for_each_pixel(y, [&](int x, const Pixel& px) {
          ASSERT_FALSE(golden::blank(px));
          ASSERT_TRUE(golden::blank(walked[static_cast<size_t>(x)])) << "pixel " << x << " visited twice";
          walked[static_cast<size_t>(x)] = px;
        });
        for (int x = 0; x < width; ++x)
          ASSERT_TRUE(same(walked[static_cast<size_t>(x)], beam[static_cast<size_t>(x)])) << "(" << x << ", " << y << ")";
      }
      // The totals kept as the lines change are the lines' own sums, in the
      // image built by inserts and in one built from its lines (as a bus
      // delivers them).
      std::vector<golden::RleLine> lines;
      for (int y = 0; y < 3; ++y)
        for (int l = 0; l < lanes; ++l) lines.push_back(slab.line(y, l).line());
      const golden::SlabImage delivered(width, 3, lanes, lines);
      for (const golden::SlabImage* image : {static_cast<const golden::SlabImage*>(&slab), &delivered}) {
        uint64_t words = 0, odd = 0;
        for (const golden::RleLine& l : lines) words += l.size(), odd += l.size() % 2;
        EXPECT_EQ(image->words(), words) << "width " << width << ", lanes " << lanes;
        EXPECT_EQ(image->odd_lines(), odd) << "width " << width << ", lanes " << lanes;
        for (int l = 0; l < lanes; ++l) {
          uint64_t flits = 0;
          for (int y = 0; y < 3; ++y) flits += golden::rle_flits(lines[static_cast<size_t>(y * lanes + l)]);
          EXPECT_EQ(image->lane_flits(l), flits) << "width " << width << ", lanes " << lanes << ", lane " << l;
        }
      }
    }
}

// rle_for_each_pixel() reads the format as the decoder does: on any words,
// well formed or not, it accepts exactly the lines rle_decode_line() does,
// and visits exactly its non-blank pixels.
TEST(Rle, RunWalkAgreesWithTheDecoderOnAnyWords) {
  std::mt19937 gen(34);
  int accepted = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    // Half of the trials random words; half a line of random pixels, then
    // perhaps cut short or with one word changed, asked for its width or
    // a pixel more or less.
    golden::RleLine words;
    int pixels = std::uniform_int_distribution<int>(0, 8)(gen);
    if (trial % 2 == 0) {
      words.resize(std::uniform_int_distribution<size_t>(0, 14)(gen));
      for (uint16_t& w : words) w = static_cast<uint16_t>(std::uniform_int_distribution<int>(0, 3)(gen) == 0 ? gen() % 4 : 0);
    } else {
      std::vector<Pixel> dense(static_cast<size_t>(pixels));
      for (Pixel& px : dense)
        if (gen() % 2) px = random_pixel(gen, 8);
      words = golden::rle_encode(dense.data(), pixels);
      if (!words.empty() && gen() % 4 == 0) words.pop_back();
      if (!words.empty() && gen() % 4 == 0) words[gen() % words.size()] = static_cast<uint16_t>(gen() % 3);
      pixels += static_cast<int>(gen() % 5 == 0) - static_cast<int>(gen() % 5 == 0);
      pixels = std::max(pixels, 0);
    }
    std::vector<Pixel> dense(static_cast<size_t>(pixels) + 1);
    const bool decoded = golden::rle_decode_line(words.data(), words.size(), pixels, dense.data());
    std::vector<Pixel> walked(static_cast<size_t>(pixels) + 1);
    bool in_range = true;
    const bool walked_ok = golden::rle_for_each_pixel(words.data(), words.size(), pixels, [&](int i, const Pixel& px) {
      if (i < 0 || i >= pixels) in_range = false;
      else walked[static_cast<size_t>(i)] = px;
    });
    ASSERT_EQ(walked_ok, decoded) << "trial " << trial;
    if (!decoded) continue;
    ++accepted;
    ASSERT_TRUE(in_range) << "trial " << trial;
    for (int i = 0; i < pixels; ++i)
      ASSERT_TRUE(same(walked[static_cast<size_t>(i)], dense[static_cast<size_t>(i)])) << "trial " << trial << ", pixel " << i;
  }
  EXPECT_GT(accepted, 5000);  // the well-formed half mostly stays so: enough lines to compare pixels
}

// The in-place insert returns what the hardware copies: the line's flits
// before the fragment.
TEST(Rle, InPlaceInsertCountsTheFlitsItCopies) {
  const golden::Precision p;
  std::mt19937 gen(35);
  golden::RleLine line = golden::rle_clear(40);
  for (int i = 0; i < 60; ++i) {
    const size_t before = golden::rle_flits(line);
    const golden::RleLine copy = golden::rle_insert(line, 40, i * 7 % 40, random_pixel(gen, p.alpha_bits), p);
    golden::RleLine in_place = line;
    EXPECT_EQ(golden::rle_insert_into(in_place, 40, i * 7 % 40, random_pixel(gen, p.alpha_bits), p), before);
    line = copy;
  }
  golden::RleLine cut_short{0, 0, 0, 0};  // a run without its length word
  EXPECT_THROW(golden::rle_insert_into(cut_short, 40, 3, Pixel{1, 1, 1, 1}, p), std::logic_error);
}

// ---- the rasteriser ----

namespace {
// A square of (g x g) quads, each split along a random diagonal, its outer
// edges between pixel centres and its inner vertices jittered, some onto
// pixel centres exactly; every pixel must be covered once inside, never
// outside.
template <class T>
void check_watertight(T one, unsigned seed) {
  std::mt19937 gen(seed);
  const int g = 6, side = 24;  // pixels 1 .. 24 inside: the square is [0.5, 24.5]
  std::vector<golden::BaseVertex<T>> v;
  for (int j = 0; j <= g; ++j)
    for (int i = 0; i <= g; ++i) {
      double x = 0.5 + side * static_cast<double>(i) / g, y = 0.5 + side * static_cast<double>(j) / g;
      if (i > 0 && i < g && j > 0 && j < g) {
        if (std::bernoulli_distribution(0.3)(gen)) {
          x = std::round(x);
          y = std::round(y);
        } else {
          x += std::uniform_real_distribution<double>(-1.5, 1.5)(gen);
          y += std::uniform_real_distribution<double>(-1.5, 1.5)(gen);
        }
      }
      if constexpr (std::is_integral_v<T>) {
        v.push_back({static_cast<T>(std::llround(x * one)), static_cast<T>(std::llround(y * one)), 0});
      } else {
        v.push_back({x, y, 0});
      }
    }
  std::vector<int> count(28 * 28, 0);
  auto emit = [&](int u, int vv, T) { ++count[static_cast<size_t>(vv) * 28 + u]; };
  for (int j = 0; j < g; ++j)
    for (int i = 0; i < g; ++i) {
      const auto& a = v[static_cast<size_t>(j * (g + 1) + i)];
      const auto& b = v[static_cast<size_t>(j * (g + 1) + i + 1)];
      const auto& c = v[static_cast<size_t>((j + 1) * (g + 1) + i)];
      const auto& d = v[static_cast<size_t>((j + 1) * (g + 1) + i + 1)];
      const bool flip = std::bernoulli_distribution(0.5)(gen);
      // Windings mixed on purpose: the rule must not depend on them.
      if (flip) {
        golden::scan_triangle<T>(a, b, d, one, 28, 28, emit);
        golden::scan_triangle<T>(a, c, d, one, 28, 28, emit);
      } else {
        golden::scan_triangle<T>(a, b, c, one, 28, 28, emit);
        golden::scan_triangle<T>(c, d, b, one, 28, 28, emit);
      }
    }
  for (int y = 0; y < 28; ++y)
    for (int x = 0; x < 28; ++x) {
      const bool inside = x >= 1 && x <= side && y >= 1 && y <= side;
      ASSERT_EQ(count[static_cast<size_t>(y) * 28 + x], inside ? 1 : 0) << "pixel (" << x << ", " << y << "), seed " << seed;
    }
}
}  // namespace

TEST(Rasterise, SharedEdgesAndVerticesCoverEveryPixelOnce) {
  for (unsigned seed = 1; seed <= 40; ++seed) {
    check_watertight<int64_t>(int64_t{1} << golden::kSubpixelBits, seed);
    check_watertight<double>(1.0, seed);
  }
}

TEST(Rasterise, DepthIsThePlaneAtThePixelCentre) {
  // d = 3u - 2v + 40 (in units of the vertices' depth), snapped vertices.
  const int64_t one = 256;
  auto vertex = [&](double u, double v) {
    return golden::BaseVertex<int64_t>{std::llround(u * one), std::llround(v * one), std::llround((3 * u - 2 * v + 40) * 256)};
  };
  int covered = 0;
  golden::scan_triangle<int64_t>(vertex(0.25, 0.5), vertex(17.75, 2), vertex(5, 14.5), one, 20, 20,
                                 [&](int u, int v, int64_t d) {
                                   ++covered;
                                   EXPECT_LE(std::fabs(d - (3.0 * u - 2.0 * v + 40) * 256), 0.5) << u << "," << v;
                                 });
  EXPECT_GT(covered, 80);
  // Edge-on: nothing.
  golden::scan_triangle<int64_t>(vertex(0, 0), vertex(4, 4), vertex(8, 8), one, 20, 20,
                                 [&](int, int, int64_t) { ADD_FAILURE() << "an edge-on triangle covered a pixel"; });
}

TEST(Rasterise, VerticesFarOffTheBasePlaneGiveTheSamePlane) {
  // A triangle whose corners lie 2^29 pixels away covers the whole 20 x 20
  // base plane; its edge functions there pass 2^61, so its rows are stepped
  // in 128 bits (the small triangle above: in 64). Both are the plane
  // d = 3u - 2v + 40, exactly at pixel centres, with every pixel covered once.
  const int64_t one = 256, far = int64_t{1} << 29;
  auto vertex = [&](int64_t u, int64_t v) { return golden::BaseVertex<int64_t>{u * one, v * one, (3 * u - 2 * v + 40) * 256}; };
  std::vector<int> count(20 * 20, 0);
  golden::scan_triangle<int64_t>(vertex(-far, -far), vertex(far, -far), vertex(0, far), one, 20, 20,
                                 [&](int u, int v, int64_t d) {
                                   ++count[static_cast<size_t>(v) * 20 + u];
                                   EXPECT_EQ(d, (3 * int64_t{u} - 2 * int64_t{v} + 40) * 256) << u << "," << v;
                                 });
  for (int i = 0; i < 20 * 20; ++i) EXPECT_EQ(count[static_cast<size_t>(i)], 1) << "pixel " << i;
}

// ---- the fixed renderer with polygons ----

namespace {

// A hybrid scene and its expected values.

struct Hybrid {
  golden::Scene scene;
  golden::Volume volume;
  std::vector<golden::Mesh> meshes;
  golden::HostProgram host;
  golden::PolygonFrame frame;
};

Hybrid hybrid(const std::string& json) {
  Hybrid h;
  h.scene = golden::parse_scene(json, "test.json");
  h.volume = golden::load_volume(h.scene.volume, h.scene.precision.voxel_bits, ".");
  h.meshes = golden::load_meshes(h.scene, CUBE4_SOURCE_DIR "/scenes");
  h.host = golden::program_host(h.scene, h.volume, h.meshes);
  h.frame = golden::rasterise_polygons(h.scene, h.meshes, h.host);
  return h;
}

golden::BasePlane render(const Hybrid& h, int threads = 1, golden::SampleProbe* probe = nullptr) {
  golden::FixedOptions o;
  o.polygons = &h.frame;
  o.threads = threads;
  o.probe = probe;
  return golden::render_fixed(h.volume, h.host.regs, o);
}

Pixel at(const golden::BasePlane& bp, int u, int v) {
  const uint16_t* p = &bp.rgba[(static_cast<size_t>(v) * bp.width + u) * 4];
  return {p[0], p[1], p[2], p[3]};
}

std::string direction(int axis, int sign) {
  std::array<int, 3> d{0, 0, 0};
  d[static_cast<size_t>(axis)] = sign;
  return R"({"direction": [)" + std::to_string(d[0]) + "," + std::to_string(d[1]) + "," + std::to_string(d[2]) +
         R"(], "up": )" + (axis == 1 ? "[0, 0, 1]" : "[0, 1, 0]") + "}";
}

// A constant, unshaded, translucent volume: every sample of every ray is
// the same, so a ray's expected value is a chain of unit functions.
std::string constant_scene(int n, const std::string& view, const std::string& polygons, const std::string& extra = "",
                           int S = 1) {
  const std::string size = std::to_string(n);
  return R"({"volume": {"synthetic": "constant", "size": [)" + size + "," + size + "," + size +
         R"(], "value": 0.5}, "view": )" + view + R"(, "shading": false, "supersampling": )" + std::to_string(S) +
         R"(, "transfer": {"color": [[0, 1, 0.5, 0.25], [1, 1, 0.5, 0.25]], "opacity": [[0, 0.05], [1, 0.05]]},
             "polygons": [)" + polygons + "]" + extra + "}";
}

// A plane of `size` voxels facing `axis`, its centre at `centre`.
std::string plane(int axis, golden::Vec3 centre, double size, const std::string& color, double opacity) {
  const std::string rotate = axis == 0 ? "[0, 90, 0]" : axis == 1 ? "[90, 0, 0]" : "[0, 0, 0]";
  char t[160];
  std::snprintf(t, sizeof t, "[%.17g, %.17g, %.17g]", centre[0], centre[1], centre[2]);
  return R"({"shape": "plane", "size": [)" + std::to_string(size) + "," + std::to_string(size) +
         R"(], "transform": {"rotate": )" + rotate + R"(, "translate": )" + t + R"(}, "color": )" + color +
         R"(, "opacity": )" + std::to_string(opacity) + R"(, "lit": false})";
}

// The one sample of the constant volume, as the compositor receives it.
golden::ShadedSample the_sample(const Hybrid& h) {
  return golden::shade_classified(h.host.regs, h.volume.at(0, 0, 0), 0, golden::Gradient{});
}

// The pixel a mesh's fragments have: its colour and opacity, quantised.
Pixel fragment(const Hybrid& h, size_t mesh) {
  const golden::Precision& p = h.scene.precision;
  golden::Rgb q{};
  for (int i = 0; i < 3; ++i)
    q[static_cast<size_t>(i)] = static_cast<uint32_t>(golden::quantise_unit(h.meshes[mesh].color[static_cast<size_t>(i)], p.alpha_bits));
  return golden::polygon_pixel(q, static_cast<uint32_t>(golden::quantise_unit(h.meshes[mesh].opacity, p.alpha_bits)), p);
}

// Samples 0 .. n-1 of a ray into acc.
RayAcc samples(RayAcc acc, const golden::ShadedSample& s, int n, const golden::Precision& p) {
  for (int k = 0; k < n; ++k) acc = golden::blend(golden::BlendMode::Composite, acc, s, p);
  return acc;
}

}  // namespace


TEST(Polygons, AnOpaquePlaneHidesExactlyTheSamplesAtOrBehindIt) {
  const int n = 12;
  for (int S : {1, 2})
    for (double c : {7.0, 7.5, 0.25, 11.0}) {
      const auto h = hybrid(constant_scene(n, direction(2, 1), plane(2, {5.5, 5.5, c}, 40, "[0.2, 0.9, 0.4]", 1), "", S));
      const golden::Precision& p = h.scene.precision;
      const golden::Registers& r = h.host.regs;
      const golden::BasePlane bp = render(h);
      const Pixel surface = fragment(h, 0);
      int before = 0;  // samples strictly in front of the plane, counted in real numbers
      while (before < n * S && before < c * S) ++before;
      const Pixel want = golden::leave_with_polygons(samples(RayAcc{}, the_sample(h), before, p), surface, p);
      for (int v = 0; v < bp.height; ++v)
        for (int u = 0; u < bp.width; ++u) {
          const int x = u - r.base_origin_x(), y = v - r.base_origin_y();
          const bool in_volume = x >= 0 && x < n && y >= 0 && y < n;
          ASSERT_TRUE(same(at(bp, u, v), in_volume ? want : surface))
              << "S " << S << ", plane at " << c << ", pixel (" << u << ", " << v << "): " << str(at(bp, u, v))
              << ", want " << str(in_volume ? want : surface);
        }
    }
}

TEST(Polygons, ATranslucentPlaneBetweenTwoSlicesIsCompositedOnceInOrderFromAllSixBasePlanes) {
  const int n = 10;
  for (int S : {1, 2})
    for (int axis = 0; axis < 3; ++axis)
      for (int sign : {1, -1}) {
        golden::Vec3 centre{4.5, 4.5, 4.5};
        centre[static_cast<size_t>(axis)] = 3.5;  // between object slices 3 and 4
        const auto h = hybrid(constant_scene(n, direction(axis, sign), plane(axis, centre, 30, "[0.1, 0.3, 1]", 0.4), "", S));
        const golden::Precision& p = h.scene.precision;
        const golden::Registers& r = h.host.regs;
        ASSERT_EQ(r.perm[2], axis);
        const double depth = h.host.view.to_permuted(centre)[2] * S;  // 3.5 or 5.5 voxel slices
        int before = 0;
        while (before < depth) ++before;
        const Pixel frag = fragment(h, 0);
        const golden::ShadedSample s = the_sample(h);
        RayAcc ray = golden::ray_over_pixel(samples(RayAcc{}, s, before, p), frag, p);
        const Pixel want = golden::pixel_of(samples(ray, s, n * S - before, p), p);
        const golden::BasePlane bp = render(h);
        for (int y = 0; y < n; ++y)
          for (int x = 0; x < n; ++x) {
            const Pixel got = at(bp, x + r.base_origin_x(), y + r.base_origin_y());
            ASSERT_TRUE(same(got, want)) << "axis " << axis << " sign " << sign << " S " << S << ", ray (" << x
                                         << ", " << y << "): " << str(got) << ", want " << str(want);
          }
        EXPECT_EQ(h.frame.counts.in_slabs, static_cast<uint64_t>(n * n));
      }
}

TEST(Polygons, PolygonsCrossingACropSlabOrTheCutPlaneAreNotCut) {
  const int n = 12;
  for (const std::string& cut : {std::string(R"(, "cropping": {"x": [0, 5]})"),
                                 std::string(R"(, "cut_plane": {"normal": [1, 0, 0], "dmin": -100, "dmax": 5.5})")}) {
    const auto h = hybrid(constant_scene(n, direction(2, 1), plane(2, {5.5, 5.5, 4.5}, 40, "[1, 1, 0]", 0.5), cut));
    const golden::Precision& p = h.scene.precision;
    const golden::Registers& r = h.host.regs;
    const Pixel frag = fragment(h, 0);
    const golden::ShadedSample s = the_sample(h);
    const Pixel kept = golden::pixel_of(samples(golden::ray_over_pixel(samples(RayAcc{}, s, 5, p), frag, p), s, n - 5, p), p);
    const golden::BasePlane bp = render(h);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        // Samples at x <= 5 stay; the plane crosses the boundary whole.
        const Pixel want = x <= 5 ? kept : frag;
        ASSERT_TRUE(same(at(bp, x + r.base_origin_x(), y + r.base_origin_y()), want)) << cut << " at x " << x;
      }
  }
}

TEST(Polygons, PolygonsOutsideTheVolumeStillAppear) {
  const int n = 12;
  const std::string zoomed = R"({"direction": [0, 0, 1], "zoom": 0.5})";
  struct Case {
    const char* name;
    golden::Vec3 centre;
    double size, opacity;
  };
  for (const Case& c : {Case{"in front", {5.5, 5.5, -3}, 40, 0.5}, Case{"behind", {5.5, 5.5, 15}, 40, 0.5},
                        Case{"opaque in front", {5.5, 5.5, -2}, 40, 1}, Case{"opaque behind", {5.5, 5.5, 15}, 40, 1},
                        Case{"beside", {-6, 5.5, 5}, 6.5, 0.5}}) {
    const auto h = hybrid(constant_scene(n, zoomed, plane(2, c.centre, c.size, "[0, 1, 1]", c.opacity)));
    const golden::Precision& p = h.scene.precision;
    const golden::Registers& r = h.host.regs;
    const Pixel frag = fragment(h, 0);
    const golden::ShadedSample s = the_sample(h);
    const RayAcc all = samples(RayAcc{}, s, n, p);
    Pixel want;
    if (c.centre[2] < 0) {
      want = c.opacity < 1 ? golden::pixel_of(samples(golden::pixel_to_acc(frag, p), s, n, p), p) : frag;
    } else {
      want = golden::leave_with_polygons(all, frag, p);
    }
    const golden::BasePlane bp = render(h);
    if (std::string(c.name) == "beside") {
      // Rays beside the volume exist for it: the base plane grew by 9 pixels in u.
      EXPECT_EQ(r.margin_lo[0], 9);
      EXPECT_EQ(r.margin_hi[0], 0);
      for (int y = 3; y <= 8; ++y)
        for (int x = -9; x <= -3; ++x)
          ASSERT_TRUE(same(at(bp, x + r.base_origin_x(), y + r.base_origin_y()), frag)) << x << "," << y;
      want = golden::pixel_of(all, p);
    }
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        ASSERT_TRUE(same(at(bp, x + r.base_origin_x(), y + r.base_origin_y()), want)) << c.name << " at " << x << "," << y;
    // And the final image shows it where the polygon is.
    const golden::ImageF img = golden::warp(bp.to_float(), bp.shift_x, bp.shift_y, h.host.view);
    const auto xy = h.host.view.image_of(c.centre[0] < 0 ? c.centre : golden::Vec3{5.5, 5.5, 5.5});
    const float* px = img.pixel(static_cast<int>(std::lround(xy[0])), static_cast<int>(std::lround(xy[1])));
    EXPECT_NEAR(px[1], (c.centre[0] < 0 ? frag.g : want.g) / 65535.0, 1e-3) << c.name;
  }
}

TEST(Polygons, AnEmptyPolygonListGivesTheVolumeOnlyImageBitForBit) {
  const std::string volume = R"({"volume": {"synthetic": "sphere", "size": [24, 24, 24]},
      "view": {"direction": [0.4, -0.3, 1]}, "supersampling": 2, "cropping": {"x": [3, 30]})";
  const auto plain = test::setup(volume + "}");
  const golden::BasePlane want = golden::render_fixed(plain.volume, plain.host.regs);
  // No list, an empty list: the same registers and base plane.
  const auto empty = hybrid(volume + R"(, "polygons": []})");
  EXPECT_EQ(empty.host.regs.base_width(), plain.host.regs.base_width());
  EXPECT_EQ(golden::render_fixed(empty.volume, empty.host.regs).rgba, want.rgba);
  // A mesh that draws nothing takes the polygon path (front, back, Z and
  // slab images, all blank) and must change nothing either.
  const auto invisible = hybrid(volume + R"(, "polygons": [{"shape": "box", "size": [30, 30, 30],
      "transform": {"translate": [11.5, 11.5, 11.5]}, "opacity": 0}]})");
  EXPECT_EQ(invisible.host.regs.margin_lo, (std::array<int, 2>{0, 0}));
  EXPECT_EQ(render(invisible).rgba, want.rgba);
  EXPECT_EQ(render(invisible, 3).rgba, want.rgba);
}

namespace {
struct CountingProbe : golden::SampleProbe {
  uint64_t seen = 0;
  void sample(int, int, const golden::SliceControl&, uint32_t, const golden::Gradient&) override { ++seen; }
};
}  // namespace

// Each slab's triangle count (the triangle-rate term of Cube-5's connection
// times) counts a triangle once per slab it has fragments in, however its
// fragments interleave with other triangles' in depth order: the whole
// frame's count is the sum of the counts of each triangle rasterised alone
// (translucent only, so that none hides another's fragments).
TEST(Polygons, SlabTriangleCountsAreEachTrianglesSlabs) {
  for (const std::string& view : {std::string(R"({"direction": [0.4, -0.3, 1]})"),
                                  std::string(R"({"direction": [-1, 0.2, 0.1], "up": [0, 0, 1]})")}) {
    Hybrid h = hybrid(test::sphere_with_polygons(view));
    std::vector<golden::Mesh> translucent;
    for (const golden::Mesh& m : h.meshes)
      if (m.opacity < 1) translucent.push_back(m);
    h.frame = golden::rasterise_polygons(h.scene, translucent, h.host);
    std::vector<uint32_t> sum(h.frame.counts.slab_triangles.size(), 0);
    size_t triangles = 0;
    for (const golden::Mesh& m : translucent)
      for (const auto& t : m.triangles) {
        golden::Mesh one = m;
        one.triangles = {t};
        const golden::PolygonFrame f = golden::rasterise_polygons(h.scene, {one}, h.host);
        for (size_t k = 0; k < sum.size(); ++k) {
          ASSERT_LE(f.counts.slab_triangles[k], 1u);
          sum[k] += f.counts.slab_triangles[k];
        }
        ++triangles;
      }
    EXPECT_GT(triangles, 20u);
    EXPECT_EQ(h.frame.counts.slab_triangles, sum);
    EXPECT_GT(*std::max_element(sum.begin(), sum.end()), 2u) << "slabs where triangles meet";
  }
}

TEST(Polygons, SkippingAndThreadsStayExact) {
  for (const std::string& view : {std::string(R"({"direction": [0.4, -0.3, 1]})"),
                                  std::string(R"({"direction": [-1, 0.2, 0.1], "up": [0, 0, 1]})")}) {
    const auto h = hybrid(test::sphere_with_polygons(view));
    EXPECT_GT(h.frame.counts.opaque, 0u);
    EXPECT_GT(h.frame.counts.in_slabs, 0u);
    EXPECT_GT(h.frame.counts.in_front + h.frame.counts.behind, 0u);
    // A probe sees every sample the Z test lets through: no skipping at all
    // (samples behind the needle are the compositor's to drop, with or
    // without a probe).
    CountingProbe probe;
    const golden::BasePlane all = render(h, 1, &probe);
    EXPECT_LT(probe.seen, 24u * 24 * 24 * 2);
    EXPECT_GT(probe.seen, 24u * 24 * 24);
    EXPECT_EQ(render(h).rgba, all.rgba);
    EXPECT_EQ(render(h, 4).rgba, all.rgba);
  }
}

namespace {
// The InputError a hybrid scene is refused with ("" if none).
std::string refusal(const std::string& json) {
  try {
    hybrid(json);
  } catch (const golden::InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Polygons, FarVerticesAreSkippedBesideTheBasePlaneAndRefusedOnIt) {
  const std::string far = plane(2, {1e12, 0, 0}, 4, "[1, 1, 1]", 1);
  EXPECT_EQ(hybrid(constant_scene(8, direction(2, 1), far)).frame.counts.opaque, 0u);
  const std::string across = R"({"shape": "box", "size": [1e10, 2, 2], "transform": {"translate": [3.5, 3.5, 3.5]}})";
  const std::string e = refusal(constant_scene(8, direction(2, 1), far + ", " + across));
  EXPECT_NE(e.find("test.json: \"polygons[1]\" has a vertex at base-plane (u, v, depth) = (-5e+09"), std::string::npos)
      << e;
}

TEST(Polygons, MaximumIntensityProjectionIsRefused) {
  const std::string e = refusal(
      constant_scene(8, direction(2, 1), plane(2, {3.5, 3.5, 3.5}, 10, "[1, 1, 1]", 1), R"(, "blend": "mip")"));
  EXPECT_NE(e.find("test.json: \"blend\" = \"mip\" cannot be combined with \"polygons\""), std::string::npos) << e;
}

// ---- accuracy ----

TEST(PolygonAccuracy, FixedAgainstFloatWithinTheDerivedBound) {
  // The constant volume along z: per ray, N1 samples, a translucent
  // fragment, N2 samples, the opaque surface. Fixed and float composite
  // the same layers in the same order; the fixed errors of the layers add
  // up (over is 1-Lipschitz in the front's colour and the back's, and
  // moves colour by at most |Δα| of the front), so the bound is the sum of:
  //  - each run of samples: its compositing bound (docs/fixed-point.md),
  //    colour and α, the α part carried into everything behind;
  //  - the fragment: colour and α quantised (u/2 each), premultiplied
  //    (u/2 and the fraction mapping 2^-n), so colour 3u/2 + 2^-n, α u/2;
  //  - the opaque colour (u/2);
  //  - three more nodes (fragment, surface, and the back's own), each
  //    rounding half an accumulator LSB and mapping its fraction (2^-A).
  for (double z_fragment : {4.5, 0.6, 9.9})
    for (int S : {1, 4}) {
      const int n = 12;
      const double z_surface = 10.25;
      const auto h = hybrid(constant_scene(n, direction(2, 1),
                                           plane(2, {5.5, 5.5, z_fragment}, 40, "[0.3, 0.6, 0.9]", 0.35) + ", " +
                                               plane(2, {5.5, 5.5, z_surface}, 40, "[0.8, 0.7, 0.1]", 1),
                                           "", S));
      const golden::Precision& p = h.scene.precision;
      const golden::BasePlane bp = render(h);
      const golden::BasePlaneF fp = golden::render_float(h.volume, h.scene, h.host.view, nullptr, {}, h.meshes);
      const double alpha = 1 - std::pow(1 - 0.05, 1.0 / S);
      const int n1 = static_cast<int>(std::ceil(z_fragment * S)), n2 = static_cast<int>(std::ceil(z_surface * S)) - n1;
      const double u = 1.0 / 65535, eps = std::ldexp(1.0, -(p.alpha_bits + p.acc_guard_bits));
      const double layers = 2 * u + std::ldexp(1.0, -p.alpha_bits) + u / 2 + 3 * (eps + eps);
      // The float base plane's own origin (its margins may differ by a pixel).
      const int fx = static_cast<int>(std::lround(fp.shift_x)), fy = static_cast<int>(std::lround(fp.shift_y));
      double worst = 0, bound = 0;
      for (int ch = 0; ch < 4; ++ch) {
        const double colour = ch == 3 ? 1.0 : std::array<double, 3>{1, 0.5, 0.25}[static_cast<size_t>(ch)];
        const tb::CompositingBound b1 = tb::compositing_bound(p, n1, alpha, colour, 0),
                                   b2 = tb::compositing_bound(p, n2, alpha, colour, 0);
        bound = b1.color + b1.alpha + b2.color + b2.alpha + layers;
        for (int y = 0; y < n; ++y)
          for (int x = 0; x < n; ++x) {
            const double fixed = bp.rgba[(static_cast<size_t>(y + h.host.regs.base_origin_y()) * bp.width + x +
                                          h.host.regs.base_origin_x()) * 4 + ch] / 65535.0;
            const float* f = fp.image.pixel(x + fx, y + fy);
            worst = std::max(worst, std::fabs(fixed - f[ch]));
            ASSERT_LE(std::fabs(fixed - f[ch]), bound) << "channel " << ch << " ray " << x << "," << y;
          }
      }
      std::printf("fragment at %.2f, S %d: worst |fixed - float| %.3g, bound %.3g\n", z_fragment, S, worst, bound);
    }
}

TEST(PolygonTraffic, CountsTheSlabLinesTheDecodersReadAndTheFullImagesTheyReplace) {
  // A translucent plane covering every ray between object slices 3 and 4 of
  // a 10^3 volume, p = 4: nine empty slabs, whose cleared lines are a run
  // flit each (10 beams x 4 lanes), and one slab with a pixel flit per ray.
  const int n = 10;
  golden::Vec3 centre{4.5, 4.5, 3.5};
  const auto h = hybrid(constant_scene(n, direction(2, 1), plane(2, centre, 30, "[0.1, 0.3, 1]", 0.4), "", 1));
  ASSERT_EQ(h.frame.counts.in_slabs, static_cast<uint64_t>(n * n));
  const golden::PolygonTraffic t = golden::polygon_traffic(h.frame, h.scene.precision);
  EXPECT_EQ(t.slabs, 10u);
  EXPECT_EQ(t.flits, 9u * 10 * 4 + 100);
  // 16-bit channels: 8 bytes a pixel, plain.
  EXPECT_EQ(t.raw_bytes, 10u * 10 * 10 * 8);
  EXPECT_EQ(t.image_bytes, static_cast<uint64_t>(h.frame.width) * h.frame.height * (16 + 3));
  // A pass is ny beams of ceil(nx / p) beats; the busiest lane's 30 pixel
  // flits fit it, so the run-length connection costs no cycle.
  EXPECT_EQ(t.slice_cycles, 10u * 3);
  EXPECT_EQ(t.slabs_over_slice, 0u);
  EXPECT_EQ(t.rle_cycles, 10u * t.slice_cycles);
  EXPECT_GT(t.raw_bytes, t.rle_bytes);
}

TEST(PolygonConnections, SlabLoadsCountTheInsertsTheirCopyingAndTheBusiestRead) {
  // One line of 8 pixels, one lane: inserting x = 0, 1, 2 in turn copies
  // the line as it stands, a run (1 flit), then pixel + run (2), then 3.
  golden::PolygonFrame f;
  f.slabs.assign(2, golden::SlabImage(8, 1, 1));
  f.counts.slab_triangles = {0, 7};
  const golden::Precision p;
  Pixel px{};
  px.a = 100;
  for (int x = 0; x < 3; ++x) f.slabs[1].insert(x, 0, px, p);
  const std::vector<golden::SlabLoad> l = golden::slab_loads(f);
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[0].fragments, 0u);
  EXPECT_EQ(l[0].copied_flits, 0u);
  EXPECT_EQ(l[0].read_flits, 1u);  // the cleared line
  EXPECT_EQ(l[1].fragments, 3u);
  EXPECT_EQ(l[1].copied_flits, 1u + 2 + 3);
  EXPECT_EQ(l[1].read_flits, 4u);  // three pixels and the run after them
  EXPECT_EQ(l[1].words, 3u * 4 + 5);
  EXPECT_EQ(l[1].triangles, 7u);
}

TEST(PolygonConnections, FrameTimesOfTheRunLengthAndTheDualUseBuffer) {
  // Slices of 1 µs (100 cycles at 100 MHz); rates of a nanosecond a
  // fragment, triangle and flit, the dual-use buffer twice as fast.
  golden::PolygonEngine e;
  e.fill_rate = 1e9;
  e.triangle_rate = 1e9;
  e.dual_fill_rate = 2e9;
  e.rle_clock_hz = 1e9;
  std::vector<golden::SlabLoad> slabs(2);
  slabs[0].fragments = 500;  // drawn in 0.5 µs, copied in 2 µs
  slabs[0].triangles = 1;
  slabs[0].copied_flits = 2000;
  slabs[0].read_flits = 50;
  slabs[1].fragments = 3000;  // drawn in 3 µs; read in 3 µs at 100 MHz
  slabs[1].copied_flits = 1000;
  slabs[1].read_flits = 300;
  const golden::ConnectionTimes t = golden::connection_times(slabs, 100, 100e6, 1000, 10, e);
  EXPECT_NEAR(t.volume_s, 2e-6, 1e-15);
  EXPECT_NEAR(t.opaque_s, 1e-6, 1e-15);
  // Slab 0 drawn first (2 µs); slice 0 waits for slab 1's drawing (3 µs);
  // slice 1 for its slab's reading (3 µs).
  EXPECT_NEAR(t.rle_s, 8e-6, 1e-15);
  EXPECT_EQ(t.rle_slabs_over_slice, 2u);
  // Opaque first (0.5 µs), then each slice and its slab's drawing in turn.
  EXPECT_NEAR(t.dual_s, 0.5e-6 + (1e-6 + 0.25e-6) + (1e-6 + 1.5e-6), 1e-15);
  // Without polygons both are the volume alone.
  const golden::ConnectionTimes v = golden::connection_times(std::vector<golden::SlabLoad>(2), 100, 100e6, 0, 0, e);
  EXPECT_EQ(v.rle_s, v.volume_s);
  EXPECT_EQ(v.dual_s, v.volume_s);
}
