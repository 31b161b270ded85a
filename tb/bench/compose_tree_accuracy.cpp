// Tree against chain (bela §III.D: "each image plane encounters log2 N
// compositions ... which can lead to fewer round-off errors in narrow
// fixed-point implementations"): N partial images composed over by a
// balanced tree of golden compositing nodes (compose_tree, depth
// ceil(log2 N)), by a linear chain front to back (compose_chain, the front
// image through N − 1 nodes) and by a chain back to front, each against the
// same composition in double precision.
//
// Partial images: per pixel, N front-to-back partial rays (a slab of
// `--samples` sample slices each, default 8) of random translucent samples
// (α per sample uniform in [0, 2τ/(N·M)] for an optical depth τ of the
// whole ray, log-uniform in [0.05, 5] per pixel; colours uniform in
// [0, α]), each partial ray composited in double and rounded once to the
// node's domain (A = n + g bits, colour <= α): the same images at every
// width, so that the rows differ only in the nodes' widths. (Partial rays
// composited by the golden compositor at n = 8 bits would lose most of
// these samples to α = 0 before any node.) The reference composes those
// same partial pixels (their values, exactly) in double, so only the
// nodes' rounding is measured. Error = (node result / (2^A − 1) − reference) · (2^n − 1): in
// LSB of an n-bit base-plane pixel, before its final rounding
// (acc_to_pixel), over R, G, B and α of every pixel. Deterministic (fixed
// seed): the same table on every run.
//
//   build/tb/bench/compose_tree_accuracy [--pixels K] [--samples M] [--seed S]
// Writes a Markdown table to stdout (scripts/compose_tree.sh puts it into
// docs/accuracy.md).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include "golden/units/compose.hpp"

namespace g = cube4::golden;

namespace {

struct Stat {
  double max = 0, sum_abs = 0, sum = 0;
  long count = 0;
  void add(double e) {
    max = std::max(max, std::abs(e));
    sum_abs += std::abs(e);
    sum += e;
    ++count;
  }
  double mean() const { return count ? sum_abs / static_cast<double>(count) : 0; }
  double bias() const { return count ? sum / static_cast<double>(count) : 0; }
};

struct Real {
  double r = 0, g = 0, b = 0, a = 0;
};
// front over back, premultiplied, in double.
Real over(const Real& f, const Real& b) {
  const double t = 1 - f.a;
  return {f.r + t * b.r, f.g + t * b.g, f.b + t * b.b, f.a + t * b.a};
}

struct Row {
  Stat tree, chain, back_chain;
};

Row measure(int n_bits, int guard, int n, long pixels, int samples, uint64_t seed) {
  g::Precision p;
  p.alpha_bits = n_bits;
  p.acc_guard_bits = guard;
  const double full = static_cast<double>(g::max_unsigned(g::acc_bits(p)));
  const double pixel_lsb = static_cast<double>(g::max_unsigned(n_bits));
  std::mt19937_64 gen(seed + static_cast<uint64_t>(n_bits) * 1000 + static_cast<uint64_t>(guard) * 100 +
                      static_cast<uint64_t>(n));
  std::uniform_real_distribution<double> unit(0, 1);
  Row row;
  std::vector<g::RayAcc> px(static_cast<size_t>(n));
  for (long k = 0; k < pixels; ++k) {
    const double tau = 0.05 * std::pow(100.0, unit(gen));  // log-uniform in [0.05, 5]
    const double alpha_max = std::min(1.0, 2 * tau / (n * samples));
    for (g::RayAcc& part : px) {
      Real ray;
      for (int s = 0; s < samples; ++s) {
        const double a = unit(gen) * alpha_max;
        ray = over(ray, {unit(gen) * a, unit(gen) * a, unit(gen) * a, a});
      }
      // The partial pixel in the node's domain, premultiplied colour <= α.
      auto q = [&](double v) { return static_cast<uint32_t>(std::lround(v * full)); };
      part.a = q(ray.a);
      part.r = std::min(q(ray.r), part.a);
      part.g = std::min(q(ray.g), part.a);
      part.b = std::min(q(ray.b), part.a);
    }
    Real ref;
    for (auto it = px.rbegin(); it != px.rend(); ++it)
      ref = over({it->r / full, it->g / full, it->b / full, it->a / full}, ref);
    g::RayAcc back = px.back();
    for (int i = n - 2; i >= 0; --i) back = g::compose_over(px[static_cast<size_t>(i)], back, p);
    const g::RayAcc tree = g::compose_tree(g::BlendMode::Composite, px.data(), n, p);
    const g::RayAcc chain = g::compose_chain(g::BlendMode::Composite, px.data(), n, p);
    auto add = [&](Stat& st, const g::RayAcc& x) {
      st.add((x.r / full - ref.r) * pixel_lsb);
      st.add((x.g / full - ref.g) * pixel_lsb);
      st.add((x.b / full - ref.b) * pixel_lsb);
      st.add((x.a / full - ref.a) * pixel_lsb);
    };
    add(row.tree, tree);
    add(row.chain, chain);
    add(row.back_chain, back);
  }
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  long pixels = 20000;
  int samples = 8;
  uint64_t seed = 20261202;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--pixels")) pixels = std::atol(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--samples")) samples = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--seed")) seed = std::strtoull(argv[i + 1], nullptr, 10);
    else {
      std::fprintf(stderr, "usage: compose_tree_accuracy [--pixels K] [--samples M] [--seed S]\n");
      return 2;
    }
  }
  if (pixels < 1 || samples < 1) {
    std::fprintf(stderr, "compose_tree_accuracy: --pixels and --samples must be positive\n");
    return 2;
  }
  std::printf("%ld pixels per row, each N partial rays of %d samples; error in LSB of an n-bit pixel "
              "(max |e|, mean |e|, mean e), R, G, B and α.\n\n",
              pixels, samples);
  std::printf("| n (α bits) | g (guard) | N | tree max | tree mean | tree bias | chain max | chain mean | chain bias "
              "| back-to-front chain max | mean | bias |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int guard : {0, 8})
    for (int n_bits : {8, 12, 16})
      for (int n : {4, 8, 16, 64}) {
        const Row r = measure(n_bits, guard, n, pixels, samples, seed);
        auto cells = [](const Stat& s) {
          static char buf[3][64];
          static int k = 0;
          char* b = buf[k++ % 3];
          std::snprintf(b, 64, "%.3g | %.3g | %+.3g", s.max, s.mean(), s.bias());
          return b;
        };
        const char* t = cells(r.tree);
        const char* c = cells(r.chain);
        const char* bc = cells(r.back_chain);
        std::printf("| %d | %d | %d | %s | %s | %s |\n", n_bits, guard, n, t, c, bc);
      }
  return 0;
}
