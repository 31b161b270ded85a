// Translucent material stays numerically stable: fixed point against float
// within the bound derived in docs/fixed-point.md ("Compositing error") over
// a grid of α per sample, ray lengths, supersampling and shading, and on
// random translucent cases; VolumePro's widths stay reachable and show the
// instability the guard bits remove.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tb/translucency.hpp"

namespace {

using cube4::tb::TranslucentCase;
using cube4::tb::TranslucentResult;

void expect_within(const TranslucentCase& c, const TranslucentResult& r) {
  const char* names[] = {"red", "green", "blue"};
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_LE(std::fabs(r.color[ch].fixed - r.color[ch].real), r.color[ch].bound)
        << c.label() << ": " << names[ch] << " fixed " << r.color[ch].fixed << " float " << r.color[ch].real;
  EXPECT_LE(std::fabs(r.alpha.fixed - r.alpha.real), r.alpha.bound)
      << c.label() << ": alpha fixed " << r.alpha.fixed << " float " << r.alpha.real;
}

bool within_headline(const cube4::tb::TranslucentChannel& c) {
  return std::fabs(c.fixed - c.real) <= 2.0 / 255 + 0.02 * std::fabs(c.real);
}

TEST(Translucency, HardCaseGridWithinTheDerivedBound) {
  for (const TranslucentCase& c : cube4::tb::translucent_grid()) expect_within(c, cube4::tb::run_translucent_case(c));
}

TEST(Translucency, TheDerivedBoundIsWithinTwoLevelsAndTwoPercentOnTheGrid) {
  // The bound itself (not only the measured error) meets the headline, so
  // the headline is a consequence of the derivation, for every grid case.
  for (const TranslucentCase& c : cube4::tb::translucent_grid()) {
    const TranslucentResult r = cube4::tb::run_translucent_case(c);
    for (const auto* ch : {&r.alpha, &r.color[0], &r.color[1], &r.color[2]})
      EXPECT_LE(ch->bound, 2.0 / 255 + 0.02 * std::fabs(ch->real)) << c.label();
  }
}

TEST(Translucency, IssueRowsAtTheDefaultWidths) {
  for (const TranslucentCase& c : cube4::tb::issue_table_rows(cube4::golden::Precision{})) {
    const TranslucentResult r = cube4::tb::run_translucent_case(c);
    expect_within(c, r);
    EXPECT_TRUE(within_headline(r.alpha)) << c.label();
    for (const auto& ch : r.color) EXPECT_TRUE(within_headline(ch)) << c.label();
  }
}

TEST(Translucency, VolumeProWidthsReproduceTheInstability) {
  // S = 4 at 0.002 per unit step: the per-sample α rounds to 2 LSB and the
  // premultiplied colour of a dark channel to zero (issue 15's table, with
  // its scene's colour: 0.000488 against 0.0500).
  const auto rows = cube4::tb::issue_table_rows(cube4::golden::volumepro_precision());
  const TranslucentResult r = cube4::tb::run_translucent_case(rows[4]);
  // Blue, 0.1 · ke = 0.075 of full scale: 0.15 LSB per sample, rounded to
  // nothing, so the channel is lost.
  EXPECT_LT(r.color[2].fixed, 0.1 * r.color[2].real) << rows[4].label();
  // And the derived bound says why: N steps of rounding at 12 bits.
  EXPECT_GT(r.color[0].bound, 0.1);
}

TEST(Translucency, RandomTranslucentCases) {
  std::mt19937 gen(1515);
  std::uniform_real_distribution<double> log_alpha(std::log(1.0 / 4095), std::log(1.0 / 8));
  std::uniform_int_distribution<int> S(1, 8), slices(4, 128), coin(0, 1);
  std::uniform_real_distribution<double> colour(0.0, 1.0);
  for (int i = 0; i < 40; ++i) {
    TranslucentCase c;
    c.alpha_per_sample = std::exp(log_alpha(gen));
    c.supersampling = S(gen);
    c.samples = slices(gen) * c.supersampling;
    c.shading = coin(gen) != 0;
    for (double& v : c.color) v = colour(gen);
    expect_within(c, cube4::tb::run_translucent_case(c));
  }
}

}  // namespace
