#include "tb/translucency.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "golden/host_driver.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"

namespace cube4::tb {
namespace {

constexpr int kSide = 9;        // x and y voxels: the centre ray (4, 4) is interior
constexpr double kKe = 0.75;    // ambient-only shading: the Phong unit's multiply on every sample

int voxel_slices(const TranslucentCase& c) { return c.samples / c.supersampling; }

double unit(int bits) { return 1.0 / (std::ldexp(1.0, bits) - 1.0); }

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

}  // namespace

bool TranslucentChannel::within() const { return std::fabs(fixed - real) <= bound; }

bool TranslucentResult::within() const {
  return color[0].within() && color[1].within() && color[2].within() && alpha.within();
}

double TranslucentResult::worst_error() const {
  double e = std::fabs(alpha.fixed - alpha.real);
  for (const auto& ch : color) e = std::max(e, std::fabs(ch.fixed - ch.real));
  return e;
}

std::string TranslucentCase::label() const {
  char b[160];
  std::snprintf(b, sizeof b, "alpha/sample %.6g, S %d, %d samples, shading %s, alpha_bits %d, guard %d",
                alpha_per_sample, supersampling, samples, shading ? "on" : "off", precision.alpha_bits,
                precision.acc_guard_bits);
  return b;
}

std::string translucent_scene_json(const TranslucentCase& c) {
  // The scene's opacity is per unit step; the host corrects it for 1/S.
  const double a = 1.0 - std::pow(1.0 - c.alpha_per_sample, c.supersampling);
  const std::string rgb = num(c.color[0]) + ", " + num(c.color[1]) + ", " + num(c.color[2]);
  return R"({"volume": {"synthetic": "constant", "size": [)" + std::to_string(kSide) + ", " +
         std::to_string(kSide) + ", " + std::to_string(voxel_slices(c)) +
         R"(], "value": 0.5}, "view": {"direction": [0, 0, 1]}, "supersampling": )" +
         std::to_string(c.supersampling) + R"(, "transfer": {"color": [[0, )" + rgb + "], [1, " + rgb +
         R"(]], "opacity": [[0, )" + num(a) + "], [1, " + num(a) + R"(]]}, "shading": )" +
         (c.shading ? "true" : "false") + R"(, "material": {"ke": )" + num(kKe) +
         R"(, "kd": 0, "ks": 0}, "precision": {"alpha_bits": )" + std::to_string(c.precision.alpha_bits) +
         R"(, "acc_guard_bits": )" + std::to_string(c.precision.acc_guard_bits) + "}}";
}

CompositingBound compositing_bound(const golden::Precision& p, int samples, double alpha, double color,
                                   double ke) {
  const int n = p.alpha_bits;
  const double u = unit(n), eps = std::ldexp(1.0, -(n + p.acc_guard_bits)), N = samples;
  const double final_alpha = 1.0 - std::pow(1.0 - alpha, N);
  // α table: rounded to n bits, so off by at most u/2; through N samples
  // (mean value theorem on 1 - (1 - α)^N) at most N (1 - α_lo)^(N-1) u/2.
  const double da = 0.5 * u;
  const double d_final_alpha = std::min(1.0, N * std::pow(1.0 - std::max(alpha - da, 0.0), N - 1) * da);
  // Colour table (color_bits, widened to n bits: exact when n is a multiple
  // of color_bits, else within one n-bit LSB), then the shading product.
  double dc = 0.5 * unit(p.color_bits) + (n % p.color_bits ? u : 0.0);
  double c = color;
  if (ke > 0) {
    const double half_coef = std::ldexp(0.5, -p.coef_frac_bits);
    dc = dc * (ke + half_coef) + color * half_coef + 0.5 * u;
    c = std::min(1.0, color * ke);
  }
  // Compositing, per step: the premultiplied colour's and the blend's
  // roundings (eps/2 each), the [0, 2^n] mapping of both fractions (at most
  // 2^-n of the increment, summing to 2^-n F per fraction), and the α
  // channel's own rounding (at most 2 eps a step, carried into later
  // colour increments through 1 - α_acc: at most 2 N eps in all).
  const double arith_color = N * (0.5 + 0.5 + 2.0) * eps + 2.0 * std::ldexp(1.0, -n) * final_alpha;
  const double arith_alpha = 2.0 * N * eps;
  // pixel_of: scaled to n bits within 2^-g of an LSB, then rounded.
  const double output = (0.5 + std::ldexp(1.0, -p.acc_guard_bits)) * u;
  return {c * d_final_alpha + final_alpha * dc + arith_color + output, d_final_alpha + arith_alpha + output};
}

TranslucentResult run_translucent_case(const TranslucentCase& c) {
  const golden::Scene s = golden::parse_scene(translucent_scene_json(c), "translucent case");
  const golden::Volume vol = golden::make_synthetic(s.volume, s.precision.voxel_bits);
  const golden::HostProgram h = golden::program_host(s, vol);
  const golden::BasePlane bp = golden::render_fixed(vol, h.regs);
  const golden::BasePlaneF fp = golden::render_float(vol, s, h.view);
  const int centre = kSide / 2;
  const size_t i = (static_cast<size_t>(centre) * bp.width + centre) * 4;
  const size_t j = (static_cast<size_t>(centre) * fp.image.width + centre) * 4;
  const double scale = 1.0 / (std::ldexp(1.0, bp.bits) - 1.0);
  TranslucentResult r;
  for (int ch = 0; ch < 3; ++ch) {
    const CompositingBound b =
        compositing_bound(s.precision, c.samples, c.alpha_per_sample, c.color[ch], c.shading ? kKe : 0.0);
    r.color[ch] = {bp.rgba[i + ch] * scale, fp.image.rgba[j + ch], b.color};
  }
  const CompositingBound b = compositing_bound(s.precision, c.samples, c.alpha_per_sample, 1.0, 0.0);
  r.alpha = {bp.rgba[i + 3] * scale, fp.image.rgba[j + 3], b.alpha};
  return r;
}

std::vector<TranslucentCase> translucent_grid() {
  std::vector<TranslucentCase> grid;
  const double lsb12 = 1.0 / 4095.0;
  for (double a : {lsb12, 2 * lsb12, 1.0 / 1024, 1.0 / 256, 1.0 / 64, 1.0 / 16, 0.25, 1.0})
    for (int S : {1, 2, 4, 8})
      for (int slices : {16, 64, 256})
        for (bool shading : {false, true}) {
          TranslucentCase c;
          c.alpha_per_sample = a;
          c.supersampling = S;
          c.samples = slices * S;
          c.shading = shading;
          grid.push_back(c);
        }
  return grid;
}

std::vector<TranslucentCase> issue_table_rows(const golden::Precision& p) {
  const std::pair<double, int> rows[] = {{0.0003, 1}, {0.001, 1}, {0.002, 1}, {0.002, 2}, {0.002, 4}, {0.002, 8}};
  std::vector<TranslucentCase> out;
  for (const auto& [a, S] : rows) {
    TranslucentCase c;
    c.alpha_per_sample = 1.0 - std::pow(1.0 - a, 1.0 / S);
    c.supersampling = S;
    c.samples = 200 * S;
    c.precision = p;
    out.push_back(c);
  }
  return out;
}

}  // namespace cube4::tb
