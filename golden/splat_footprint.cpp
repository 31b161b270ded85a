#include "golden/splat_footprint.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cube4::golden {
namespace {

using Vec2 = std::array<double, 2>;

// Image displacement (pixels) of one step along object axis `axis`.
Vec2 axis_on_image(const ViewFactorisation& f, int axis) {
  Vec3 step{0, 0, 0};
  step[axis] = 1;
  const auto a = f.image_of({0, 0, 0}), b = f.image_of(step);
  return {b[0] - a[0], b[1] - a[1]};
}

// Midpoints per pixel side for the integral over a pixel: a power of two,
// so that the points are exact binary fractions, symmetric about the pixel
// centre, and mirrored tables come out mirrored.
constexpr int kPointsPerSide = 32;

std::array<double, 3> projected_covariance(const ViewFactorisation& f, const SplatKernel& kernel) {
  // Σ = σ² C Cᵀ, C the 2×3 map of a voxel-index step onto the image.
  double sxx = 0, sxy = 0, syy = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec2 c = axis_on_image(f, axis);
    sxx += c[0] * c[0];
    sxy += c[0] * c[1];
    syy += c[1] * c[1];
  }
  const double s2 = kernel.sigma * kernel.sigma;
  return {s2 * sxx, s2 * sxy, s2 * syy};
}

}  // namespace

int footprint_extent(const ViewFactorisation& f, const SplatKernel& kernel) {
  if (!(kernel.sigma > 0) || !(kernel.width > 0) || !std::isfinite(kernel.sigma) || !std::isfinite(kernel.width))
    throw std::invalid_argument("splat kernel: sigma and width must be positive and finite");
  // The truncated ellipse u·Σ⁻¹·u <= (width/σ)² reaches sqrt(Σxx)·width/σ
  // along x; from a sub-pixel centre a quarter pixel off the pixel centre it
  // must stay inside the extent's outer pixel edge, h + 1/2 away.
  const std::array<double, 3> cov = projected_covariance(f, kernel);
  const double reach = std::sqrt(std::max(cov[0], cov[2])) * kernel.width / kernel.sigma;
  const double h = std::max(1.0, std::ceil(reach - 0.25 - 1e-9));
  return 2 * h + 1 > kMaxFootprintExtent ? kMaxFootprintExtent + 1 : 2 * static_cast<int>(h) + 1;
}

FootprintTables footprint_tables(const ViewFactorisation& f, const SplatKernel& kernel) {
  FootprintTables t;
  t.extent = footprint_extent(f, kernel);
  if (t.extent > kMaxFootprintExtent)
    throw std::invalid_argument("splat footprint wider than " + std::to_string(kMaxFootprintExtent) + " pixels");
  const int h = t.extent / 2;
  t.covariance = projected_covariance(f, kernel);
  const Vec2 cx = axis_on_image(f, f.perm[0]), cy = axis_on_image(f, f.perm[1]);
  t.cell_area = std::fabs(cx[0] * cy[1] - cx[1] * cy[0]);

  const double m2 = (kernel.width / kernel.sigma) * (kernel.width / kernel.sigma);
  const double det = t.covariance[0] * t.covariance[2] - t.covariance[1] * t.covariance[1];
  const double ixx = t.covariance[2] / det, ixy = -t.covariance[1] / det, iyy = t.covariance[0] / det;
  auto kernel_at = [&](double u, double v) {
    const double q = ixx * u * u + 2 * ixy * u * v + iyy * v * v;  // squared Mahalanobis radius
    return q <= m2 ? std::exp(-0.5 * q) : 0.0;
  };
  for (int q = 0; q < 4; ++q) {
    const Vec2 centre = FootprintTables::subpixel_centre(q);
    std::vector<double>& w = t.weight[q];
    w.assign(static_cast<size_t>(t.extent) * t.extent, 0.0);
    double total = 0;
    for (int j = -h; j <= h; ++j)
      for (int i = -h; i <= h; ++i) {
        double sum = 0;
        for (int b = 0; b < kPointsPerSide; ++b)
          for (int a = 0; a < kPointsPerSide; ++a) {
            const double u = i + (a + 0.5) / kPointsPerSide - 0.5 - centre[0];
            const double v = j + (b + 0.5) / kPointsPerSide - 0.5 - centre[1];
            sum += kernel_at(u, v);
          }
        w[static_cast<size_t>(j + h) * t.extent + (i + h)] = sum;
        total += sum;
      }
    // A kernel narrower than the integration points (a voxel spacing on a
    // small fraction of a pixel) is a point: all its energy on its pixel.
    if (total == 0) {
      w[static_cast<size_t>(h) * t.extent + h] = 1;
      continue;
    }
    for (double& x : w) x /= total;
  }
  return t;
}

}  // namespace cube4::golden
