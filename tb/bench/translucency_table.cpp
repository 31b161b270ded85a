// Prints, as Markdown, translucent material rendered in fixed point against
// float: issue 15's six rows at VolumePro's widths (before) and at the
// defaults (after), and a summary of the hard-case grid, each with the
// derived bound of docs/fixed-point.md. scripts/translucency.sh puts the
// output into docs/accuracy.md. Exit 1 if a default-width case exceeds its
// bound.
#include <cmath>
#include <cstdio>

#include "tb/translucency.hpp"

namespace {

using cube4::tb::TranslucentCase;
using cube4::tb::TranslucentResult;

// The stated headline: within 2/255 plus 2 % of the float value.
bool within_headline(const cube4::tb::TranslucentChannel& c) {
  return std::fabs(c.fixed - c.real) <= 2.0 / 255 + 0.02 * std::fabs(c.real);
}

void rows(const char* title, const cube4::golden::Precision& p) {
  std::printf("\n%s\n\n", title);
  std::printf("| α per unit step | S | samples | fixed r | float r | fixed b | float b | fixed α | float α | "
              "largest error | its bound | within |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const TranslucentCase& c : cube4::tb::issue_table_rows(p)) {
    const TranslucentResult r = cube4::tb::run_translucent_case(c);
    const double per_step = 1.0 - std::pow(1.0 - c.alpha_per_sample, c.supersampling);
    // The bound of the channel with the largest error.
    double bound = r.alpha.bound, largest = std::fabs(r.alpha.fixed - r.alpha.real);
    for (const auto& ch : r.color)
      if (std::fabs(ch.fixed - ch.real) > largest) largest = std::fabs(ch.fixed - ch.real), bound = ch.bound;
    std::printf("| %.4g | %d | %d | %.6f | %.6f | %.6f | %.6f | %.4f | %.4f | %.6f | %.6f | %s |\n", per_step,
                c.supersampling, c.samples, r.color[0].fixed, r.color[0].real, r.color[2].fixed, r.color[2].real,
                r.alpha.fixed, r.alpha.real, r.worst_error(), bound, r.within() ? "yes" : "**no**");
  }
}

}  // namespace

int main() {
  cube4::golden::Precision after;
  rows("Before: VolumePro's widths (`alpha_bits` 12, `acc_guard_bits` 0)", cube4::golden::volumepro_precision());
  rows("After: the defaults (`alpha_bits` 16, `acc_guard_bits` 8)", after);

  int cases = 0, within = 0, headline = 0;
  double worst = 0, worst_ratio = 0;
  std::string worst_label;
  for (const TranslucentCase& c : cube4::tb::translucent_grid()) {
    const TranslucentResult r = cube4::tb::run_translucent_case(c);
    ++cases;
    within += r.within();
    bool h = within_headline(r.alpha);
    for (const auto& ch : r.color) h = h && within_headline(ch);
    headline += h;
    for (const auto* ch : {&r.alpha, &r.color[0], &r.color[1], &r.color[2]}) {
      const double e = std::fabs(ch->fixed - ch->real);
      if (e > worst) worst = e, worst_label = c.label();
      if (ch->bound > 0) worst_ratio = std::max(worst_ratio, e / ch->bound);
    }
  }
  std::printf("\nHard-case grid at the defaults (α per sample 1/4095 .. 1, S = 1, 2, 4, 8, rays of 16 to 2048 "
              "samples, shading on and off, colour (1, 0.5, 0.1)): %d cases, %d within the derived bound, %d "
              "within 2/255 + 2 %% of float; largest error %.6f (%s); largest error / bound %.3f.\n",
              cases, within, headline, worst, worst_label.c_str(), worst_ratio);
  return within == cases ? 0 : 1;
}
