// render_perspective()'s algorithm in double precision: the same rays from
// the eye, box filter, gradient and compositing, with exact weights, exact
// positions and the optical model evaluated directly. The difference to the
// fixed renderer is the price of the widths; the difference to the
// reference ray caster (a pinhole camera) the price of the algorithm.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "golden/host_driver.hpp"
#include "golden/permuted_volume.hpp"
#include "golden/polygons_float.hpp"
#include "golden/renderers.hpp"
#include "golden/shading_model.hpp"

namespace cube4::golden {
namespace {

struct Geometry {
  double ex, ey, d;  // eye (permuted voxels), d in front of the front face
  double ox, oy;     // ray j crosses the base plane at (ox + j, oy + j')
  int S;
  double spacing(int k) const { return 1 + static_cast<double>(k) / S / d; }
  double x(double X, int k) const { return ex + (X - ex) * spacing(k); }
  double y(double Y, int k) const { return ey + (Y - ey) * spacing(k); }
  // Rays j whose position on slice k lies in [0, n): [lo, hi).
  static std::pair<long, long> inside(double o, double e, double m, int n) {
    // e + (o + j - e) m in [0, n)  <=>  j in [e - o - e/m, e - o + (n - e)/m)
    return {static_cast<long>(std::ceil(e - o - e / m)), static_cast<long>(std::ceil(e - o + (n - e) / m))};
  }
};

// The area-weighted mean of a nearest-voxel field, `field(i, j)` at voxel
// (i, j), over the box [x - m/2, x + m/2) x [y - m/2, y + m/2).
template <class Field>
double box_mean(Field&& field, double x, double y, double m) {
  auto weights = [m](double c, int& first, double w[4]) {
    const double a = c + 0.5 - m / 2, b = a + m;
    first = static_cast<int>(std::floor(a));
    for (int j = 0; j < 4; ++j) w[j] = std::max(0.0, std::min(b, first + j + 1.0) - std::max(a, first + j + 0.0));
  };
  int fx = 0, fy = 0;
  double wx[4], wy[4];
  weights(x, fx, wx);
  weights(y, fy, wy);
  double sum = 0;
  for (int j = 0; j < 4; ++j) {
    if (wy[j] == 0) continue;
    double row = 0;
    for (int i = 0; i < 4; ++i)
      if (wx[i] != 0) row += wx[i] * field(fx + i, fy + j);
    sum += wy[j] * row;
  }
  return sum / (m * m);
}

struct Slice {
  int k = -1;
  long x0 = 0, x1 = 0, y0 = 0, y1 = 0;  // rays inside, base-plane pixels
  std::vector<double> v, z;  // values; with the voxel-difference z gradient, the filtered z differences
  bool has(long u, long w) const { return k >= 0 && u >= x0 && u < x1 && w >= y0 && w < y1; }
};

}  // namespace

BasePlaneF render_float_perspective(const Volume& vol, const Scene& s, const ViewFactorisation& f,
                                    RenderStats* stats, const Progress& progress, const std::vector<Mesh>& meshes) {
  const int nx = f.pdim[0], ny = f.pdim[1];
  const int S = s.supersampling, K = f.pdim[2] * S;
  const Vec3 eye = f.eye_permuted();
  const Geometry geo{eye[0], eye[1], -eye[2], s.view.ray_offset[0], s.view.ray_offset[1], S};
  const auto span = [&](double o, double e, int n) {
    const auto a = Geometry::inside(o, e, 1, n), b = Geometry::inside(o, e, geo.spacing(K - 1), n);
    return b.first >= b.second ? a : std::make_pair(std::min(a.first, b.first), std::max(a.second, b.second));
  };
  auto jx = span(geo.ox, geo.ex, nx), jy = span(geo.oy, geo.ey, ny);
  // Polygons: the rays of base-plane pixel p - origin as a BaseFrame (ray j
  // at e + (o + j - e)·w(d)), and margins for polygons beside the volume.
  BaseFrame frame;
  frame.S = S;
  frame.ms = 1 / (S * geo.d);
  frame.x0 = geo.ox;
  frame.y0 = geo.oy;
  frame.sx = frame.ms * (geo.ox - geo.ex);
  frame.sy = frame.ms * (geo.oy - geo.ey);
  frame.origin_x = static_cast<int>(-jx.first);
  frame.origin_y = static_cast<int>(-jy.first);
  if (!meshes.empty()) {
    const Margins margins = polygon_margins(meshes, f, frame, static_cast<int>(jx.second - jx.first),
                                            static_cast<int>(jy.second - jy.first));
    jx = {jx.first - margins.lo[0], jx.second + margins.hi[0]};
    jy = {jy.first - margins.lo[1], jy.second + margins.hi[1]};
    frame.origin_x = static_cast<int>(-jx.first);
    frame.origin_y = static_cast<int>(-jy.first);
  }
  BasePlaneF out;
  out.image.width = static_cast<int>(jx.second - jx.first);
  out.image.height = static_cast<int>(jy.second - jy.first);
  out.image.rgba.assign(static_cast<size_t>(out.image.width) * out.image.height * 4, 0.0f);
  out.shift_x = -(static_cast<double>(jx.first) + geo.ox);
  out.shift_y = -(static_cast<double>(jy.first) + geo.oy);
  const int W = out.image.width;
  // Base-plane pixel p is ray j = p + jx.first, crossing the base plane at X.
  auto X = [&](long p) { return geo.ox + static_cast<double>(p + jx.first); };
  auto Y = [&](long p) { return geo.oy + static_cast<double>(p + jy.first); };

  const EffectSet e = effects_of(s);
  const double vmax = static_cast<double>(vol.max_value());
  const double gscale = std::ldexp(1.0, -s.precision.gradient_shift);
  const SampleShading shade(s, f, vmax, sample_step_ratio(f, S));
  const CropRegs crop = permute_cropping(s.cropping, f);
  const PermutedCutPlane cut = permute_cut_plane_real(s.cut, f);
  const PermutedVolume pv(vol, f.perm, f.flip);
  const bool voxel_z = e.gradient && s.z_gradient == ZGradient::VoxelDifferences;

  auto sample_slice = [&](int k, Slice& sl) {
    sl.k = k < 0 || k >= K ? -1 : k;
    if (sl.k < 0) return;
    const double m = geo.spacing(k);
    const auto rx = Geometry::inside(geo.ox, geo.ex, m, nx), ry = Geometry::inside(geo.oy, geo.ey, m, ny);
    sl.x0 = std::max(0L, rx.first - jx.first);
    sl.x1 = std::min<long>(W, rx.second - jx.first);
    sl.y0 = std::max(0L, ry.first - jy.first);
    sl.y1 = std::min<long>(out.image.height, ry.second - jy.first);
    sl.v.assign(static_cast<size_t>(W) * out.image.height, 0.0);
    if (voxel_z) sl.z.assign(sl.v.size(), 0.0);
    const int z = k / S;
    const double wz = static_cast<double>(k % S) / S;
    for (long w = sl.y0; w < sl.y1; ++w)
      for (long u = sl.x0; u < sl.x1; ++u) {
        const double x = geo.x(X(u), k), y = geo.y(Y(w), k);
        // The field of voxel slice z + dz: the voxels, or VolumePro's z
        // differences V(z + dz + 1) - V(z + dz - 1).
        auto filtered = [&](auto&& field_of) {
          const double lo = box_mean([&](int i, int j) { return field_of(i, j, z); }, x, y, m);
          return wz == 0 ? lo : lo + wz * (box_mean([&](int i, int j) { return field_of(i, j, z + 1); }, x, y, m) - lo);
        };
        const size_t at = static_cast<size_t>(w) * W + u;
        sl.v[at] = filtered([&](int i, int j, int zz) { return static_cast<double>(pv.at(i, j, zz)); });
        if (voxel_z)
          sl.z[at] = filtered([&](int i, int j, int zz) {
            return static_cast<double>(pv.at(i, j, zz + 1)) - static_cast<double>(pv.at(i, j, zz - 1));
          });
      }
  };
  auto at = [&](const Slice& sl, long u, long w) { return sl.has(u, w) ? sl.v[static_cast<size_t>(w) * W + u] : 0.0; };
  // The neighbouring slice's value at permuted (x, y): bilinear between its rays.
  auto straight = [&](const Slice& sl, double x, double y) {
    if (sl.k < 0) return 0.0;
    const double m = geo.spacing(sl.k);
    const double gu = (x - geo.x(X(0), sl.k)) / m, gv = (y - geo.y(Y(0), sl.k)) / m;
    const long u = static_cast<long>(std::floor(gu)), w = static_cast<long>(std::floor(gv));
    const double a = gu - u, b = gv - w;
    const double top = at(sl, u, w) + a * (at(sl, u + 1, w) - at(sl, u, w));
    const double bottom = at(sl, u, w + 1) + a * (at(sl, u + 1, w + 1) - at(sl, u, w + 1));
    return top + b * (bottom - top);
  };

  std::optional<PolygonsF> poly;
  if (!meshes.empty()) poly.emplace(s, meshes, f, frame, W, out.image.height);
  std::vector<AccF> rays(static_cast<size_t>(W) * out.image.height);
  Slice behind, current, ahead;
  sample_slice(0, current);
  if (e.gradient) sample_slice(1, ahead);
  uint64_t count = 0;
  for (int k = 0; k < K; ++k) {
    const double m = geo.spacing(k);
    const int zv = k / S;
    const double z = zv + static_cast<double>(k % S) / S;
    for (long w = current.y0; w < current.y1; ++w)
      for (long u = current.x0; u < current.x1; ++u) {
        ++count;
        const double x = geo.x(X(u), k), y = geo.y(Y(w), k);
        const double v = at(current, u, w);
        Vec3 g{0, 0, 0};
        if (e.gradient)
          g = {(at(current, u + 1, w) - at(current, u - 1, w)) / m * gscale,
               (at(current, u, w + 1) - at(current, u, w - 1)) / m * gscale,
               (voxel_z ? current.z[static_cast<size_t>(w) * W + u] : (straight(ahead, x, y) - straight(behind, x, y)) * S) *
                   gscale};
        const int tag = e.tags ? pv.tag_at(static_cast<int>(std::floor(x + 0.5)), static_cast<int>(std::floor(y + 0.5)),
                                           zv + (z - zv >= 0.5))
                               : 0;
        const ShadedF sh = shade(v, g, tag);
        double alpha = sh.alpha;
        bool visible = !e.cropping || crop_visible(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)), zv, crop);
        if (e.cut_plane) {
          const double fac = cut.factor(cut.a[0] * x + cut.a[1] * y + cut.a[2] * z);
          alpha *= fac;
          if (fac == 0) visible = false;
        }
        const size_t i = static_cast<size_t>(w) * W + u;
        AccF& acc = rays[i];
        if (poly && !poly->before_sample(i, k, acc)) visible = false;
        if (!visible) continue;
        if (s.blend == Blend::Composite) {
          const double t = (1 - acc.a) * alpha;
          acc.r += t * sh.rgb[0]; acc.g += t * sh.rgb[1]; acc.b += t * sh.rgb[2]; acc.a += t;
        } else if (!acc.valid || (s.blend == Blend::Mip ? v > acc.value : v < acc.value)) {
          acc = {sh.rgb[0] * alpha, sh.rgb[1] * alpha, sh.rgb[2] * alpha, alpha, v, true};
        }
      }
    if (e.gradient) {
      std::swap(behind, current);
      std::swap(current, ahead);
      sample_slice(k + 2, ahead);
    } else if (k + 1 < K) {
      sample_slice(k + 1, current);
    }
    if (progress) progress(static_cast<double>(k + 1) / K);
  }
  for (int w = 0; w < out.image.height; ++w)
    for (int u = 0; u < W; ++u) {
      const size_t i = static_cast<size_t>(w) * W + u;
      const AccF a = poly ? poly->leave(i, rays[i]) : rays[i];
      float* px = out.image.pixel(u, w);
      px[0] = static_cast<float>(a.r); px[1] = static_cast<float>(a.g);
      px[2] = static_cast<float>(a.b); px[3] = static_cast<float>(a.a);
    }
  if (stats) {
    stats->samples = count;
    stats->slices = K;
  }
  return out;
}

}  // namespace cube4::golden
