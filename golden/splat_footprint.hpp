// bela's energy footprints (bela §III.B): what one voxel's energy covers on
// the image, built by the host from the view as four small look-up tables,
// one for each sub-pixel in which the voxel's centre of projection can fall.
// Host-side floating point for the splatting comparison renderer
// (render_splat, golden/renderers.hpp); no hardware of ours uses them.
#pragma once
#include <array>
#include <vector>

#include "golden/view.hpp"

namespace cube4::golden {

// The convolution kernel: a Gaussian of standard deviation `sigma`,
// truncated at radius `width` (bela's distribution width k, §IV), both in
// voxel spacings. It is spherical in voxel-index space, so unequal spacing
// makes it an ellipsoid in object space and an ellipse on the image.
// The defaults and why: docs/accuracy.md, "Splatting (bela's projection)".
struct SplatKernel {
  double sigma = 0.5;
  double width = 1.25;
};

struct FootprintTables {
  // Pixels per side of the footprint, odd: bela's extent width, 3 at bela's
  // magnification 1, larger when a voxel spacing projects onto more than
  // about one pixel (§IV: w = z·[2kM/N] + 1).
  int extent = 3;
  // weight[q][(j + h) * extent + (i + h)], h = extent / 2: the share of the
  // voxel's energy on the pixel (i, j) away from the pixel its centre of
  // projection falls in, for sub-pixel q; each table sums to one.
  std::array<std::vector<double>, 4> weight;
  // Pixels² one voxel of a slice stands for (the projected area of the
  // slice's voxel cell): a voxel's energy, so that a slice of equal voxels
  // covers every pixel once on average.
  double cell_area = 1;
  // The projected kernel's covariance (pixels²: xx, xy, yy), before truncation.
  std::array<double, 3> covariance{};

  // Which table serves a centre of projection (dx, dy) from its pixel's
  // centre, each in [-1/2, 1/2): the sub-pixel it falls in.
  static int subpixel(double dx, double dy) { return (dx >= 0 ? 1 : 0) + (dy >= 0 ? 2 : 0); }
  // The centre of sub-pixel q from its pixel's centre: the quantised centre of projection.
  static std::array<double, 2> subpixel_centre(int q) { return {q & 1 ? 0.25 : -0.25, q & 2 ? 0.25 : -0.25}; }
};

// The widest footprint the splat model spreads, in pixels per side: a voxel
// spacing on about 25 pixels at the default kernel. Beyond it a frame would
// take minutes (w² pixels per voxel); render_splat refuses the view.
constexpr int kMaxFootprintExtent = 65;

// The footprint's extent for the view (kMaxFootprintExtent + 1 for any wider).
int footprint_extent(const ViewFactorisation& f, const SplatKernel& kernel);

// Builds the tables for the view: the kernel projected along the rays
// (a Gaussian's projection is a Gaussian, its covariance the image of the
// kernel's under the projection: the affine map that turns bela's circle
// into an ellipse for unequal spacing), truncated at the distribution width,
// integrated over each pixel and normalised to one.
FootprintTables footprint_tables(const ViewFactorisation& f, const SplatKernel& kernel);

}  // namespace cube4::golden
