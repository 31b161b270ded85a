// Translucent material in fixed point against float: a constant volume seen
// along z, so every ray of its centre composites the same sample N times.
// The derived error bound (docs/fixed-point.md, "Compositing error") is
// computed here from the widths, so the tests, the table in
// docs/accuracy.md and the derivation are one formula.
#pragma once
#include <string>
#include <vector>

#include "golden/precision.hpp"

namespace cube4::tb {

struct TranslucentCase {
  double alpha_per_sample = 0.001;  // α of one sample after α-correction for S
  int supersampling = 1;            // S
  int samples = 200;                // N along the centre ray (voxel slices = N / S)
  bool shading = true;              // ambient-only Phong (ke), on every sample
  double color[3] = {1.0, 0.5, 0.1};
  golden::Precision precision;      // default: the golden defaults
  std::string label() const;
};

// One channel's values on the centre ray's base-plane pixel (premultiplied,
// in [0, 1]) and the derived bound on |fixed - float|.
struct TranslucentChannel {
  double fixed = 0, real = 0, bound = 0;
  bool within() const;
};

struct TranslucentResult {
  TranslucentChannel color[3], alpha;
  bool within() const;
  // The largest |fixed - float| over the four channels, and its bound.
  double worst_error() const;
};

// The scene JSON of a case (also what scripts/translucency.sh writes out).
std::string translucent_scene_json(const TranslucentCase& c);

// Renders the case with render_fixed and render_float and fills the bound.
TranslucentResult run_translucent_case(const TranslucentCase& c);

// The bound of docs/fixed-point.md for a ray of N samples of per-sample α
// and float colour c: table rounding of α and colour, shading rounding,
// N steps of compositing rounding in the accumulator domain, output rounding.
struct CompositingBound {
  double color, alpha;
};
CompositingBound compositing_bound(const golden::Precision& p, int samples, double alpha, double color,
                                   double ke);

// The hard-case grid the tests and the docs table use: α from one LSB of
// VolumePro's 12-bit α to 1, rays up to 2048 samples, S = 1..8, shading on
// and off.
std::vector<TranslucentCase> translucent_grid();

// The six rows of issue 15's table (α per unit step, S, 200 voxel slices).
std::vector<TranslucentCase> issue_table_rows(const golden::Precision& p);

}  // namespace cube4::tb
