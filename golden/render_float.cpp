// The fixed-point renderer's algorithm in double precision: same sheared
// slices, gradient estimators and ray alignment, but exact weights,
// no rounding or saturation, and the optical model evaluated directly instead
// of through tables. The difference to render_fixed is the price of the widths.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "golden/fixed.hpp"
#include "golden/permuted_volume.hpp"
#include "golden/polygons.hpp"
#include "golden/polygons_float.hpp"
#include "golden/renderers.hpp"
#include "golden/shading_model.hpp"
#include "golden/units/composite_ray_align.hpp"

namespace cube4::golden {
namespace {

struct PlaneF {
  int nx = 0, ny = 0, pitch = 0;
  std::vector<double> v;
  PlaneF(int nx_, int ny_) : nx(nx_), ny(ny_), pitch(nx_ + 2), v(static_cast<size_t>(nx_ + 2) * (ny_ + 2), 0.0) {}
  double at(int x, int y) const { return v[static_cast<size_t>(y + 1) * pitch + x + 1]; }
  double& at(int x, int y) { return v[static_cast<size_t>(y + 1) * pitch + x + 1]; }
  void clear() { std::fill(v.begin(), v.end(), 0.0); }
};

struct Offset { int integer; double frac; };

struct FloatView {
  const Volume& vol;
  const ViewFactorisation& f;
  int K, S;
  double ox0, oy0, stepx, stepy;
  Offset x_offset(int k) const { return split(ox0 + k * stepx); }
  Offset y_offset(int k) const { return split(oy0 + k * stepy); }
  static Offset split(double v) {
    const double i = std::floor(v);
    return {static_cast<int>(i), v - i};
  }
};

// Voxel slice z in permuted order, one zero column and row beyond the volume.
void load_slice(const PermutedVolume& pv, int z, PlaneF& out) {
  std::vector<double> beam(static_cast<size_t>(out.nx));
  for (int y = 0; y <= out.ny; ++y) {
    pv.load_beam(y, z, beam.data());
    for (int x = 0; x < out.nx; ++x) out.at(x, y) = beam[x];
    out.at(out.nx, y) = 0;
  }
}

// Sample slice k's values, or with dz != 0 those of the same rays dz voxel
// slices further in z (VolumePro's z gradient: interpolating voxel
// differences is, in real arithmetic, the difference of these).
void interpolate(const FloatView& fv, const PermutedVolume& pv, int k, PlaneF& lo, PlaneF& hi, PlaneF& out,
                 int dz = 0) {
  if (k < 0 || k >= fv.K) { out.clear(); return; }
  const Offset ox = fv.x_offset(k), oy = fv.y_offset(k);
  const int z = k / fv.S + dz;
  const double wz = static_cast<double>(k % fv.S) / fv.S;
  load_slice(pv, z, lo);
  load_slice(pv, z + 1, hi);
  for (int y = 0; y < out.ny; ++y)
    for (int x = 0; x < out.nx; ++x) {
      auto bil = [&](const PlaneF& v) {
        const double a = v.at(x, y) + ox.frac * (v.at(x + 1, y) - v.at(x, y));
        const double b = v.at(x, y + 1) + ox.frac * (v.at(x + 1, y + 1) - v.at(x, y + 1));
        return a + oy.frac * (b - a);
      };
      const double l = bil(lo), h = bil(hi);
      out.at(x, y) = l + wz * (h - l);
    }
}

// The neighbouring slice's value straight ahead of/behind (x, y): the
// position x + (frac_here - frac_there) in that slice's grid.
double realigned(const PlaneF& s, int x, int y, double ddx, double ddy) {
  const int bx = x + static_cast<int>(std::floor(ddx)), by = y + static_cast<int>(std::floor(ddy));
  const double wx = ddx - std::floor(ddx), wy = ddy - std::floor(ddy);
  const double a = s.at(bx, by) + wx * (s.at(bx + 1, by) - s.at(bx, by));
  const double b = s.at(bx, by + 1) + wx * (s.at(bx + 1, by + 1) - s.at(bx, by + 1));
  return a + wy * (b - a);
}

}  // namespace

BasePlaneF render_float(const Volume& vol, const Scene& s, const ViewFactorisation& f, RenderStats* stats,
                        const Progress& progress, const std::vector<Mesh>& meshes) {
  check_polygon_scene(s, meshes);
  if (f.perspective) return render_float_perspective(vol, s, f, stats, progress, meshes);
  const int nx = f.pdim[0], ny = f.pdim[1];
  const int S = s.supersampling, K = f.pdim[2] * S;
  FloatView fv{vol, f, K, S, s.view.ray_offset[0], s.view.ray_offset[1], f.shear_x / S, f.shear_y / S};
  const EffectSet e = effects_of(s);
  const Precision& p = s.precision;
  const double vmax = static_cast<double>(vol.max_value());
  const double gscale = std::ldexp(1.0, -p.gradient_shift);
  const SampleShading shade(s, f, vmax, sample_step_ratio(f, S));
  const CropRegs crop = permute_cropping(s.cropping, f);
  const PermutedCutPlane cut = permute_cut_plane_real(s.cut, f);

  // Sample (x, y) of slice k is on the ray of pixel (x - ix_k + origin_x, y - iy_k + origin_y).
  BaseFrame frame{fv.ox0, fv.stepx, fv.oy0, fv.stepy, fv.x_offset(K - 1).integer, fv.y_offset(K - 1).integer, S};
  Margins margins;
  if (!meshes.empty()) margins = polygon_margins(meshes, f, frame, nx + frame.origin_x, ny + frame.origin_y);
  frame.origin_x += margins.lo[0];
  frame.origin_y += margins.lo[1];
  const int ix_last = frame.origin_x, iy_last = frame.origin_y;
  BasePlaneF out;
  out.image.width = nx + ix_last + margins.hi[0];
  out.image.height = ny + iy_last + margins.hi[1];
  out.image.rgba.assign(static_cast<size_t>(out.image.width) * out.image.height * 4, 0.0f);
  out.shift_x = ix_last - fv.ox0;
  out.shift_y = iy_last - fv.oy0;
  std::optional<PolygonsF> poly;
  if (!meshes.empty()) poly.emplace(s, meshes, f, frame, out.image.width, out.image.height);
  auto index = [&](int u, int v) { return static_cast<size_t>(v) * out.image.width + u; };
  auto write = [&](int u, int v, const AccF& ray) {
    const AccF a = poly ? poly->leave(index(u, v), ray) : ray;
    float* px = out.image.pixel(u, v);
    px[0] = static_cast<float>(a.r); px[1] = static_cast<float>(a.g);
    px[2] = static_cast<float>(a.b); px[3] = static_cast<float>(a.a);
  };

  const PermutedVolume pv(vol, f.perm, f.flip);
  PlaneF vox_lo(nx, ny), vox_hi(nx, ny);
  auto interpolate_slice = [&](int k, PlaneF& out) { interpolate(fv, pv, k, vox_lo, vox_hi, out); };
  PlaneF behind(nx, ny), current(nx, ny), ahead(nx, ny);
  const bool voxel_z = e.gradient && s.z_gradient == ZGradient::VoxelDifferences;
  PlaneF below(nx, ny), above(nx, ny);
  interpolate_slice(0, current);
  if (e.gradient) interpolate_slice(1, ahead);
  std::vector<AccF> prev(static_cast<size_t>(nx) * ny), cur(prev.size());
  for (int k = 0; k < K; ++k) {
    const Offset ox = fv.x_offset(k), oy = fv.y_offset(k);
    const Offset pox = fv.x_offset(k - 1), poy = fv.y_offset(k - 1);
    const Offset nox = fv.x_offset(k + 1), noy = fv.y_offset(k + 1);
    const int dx = k == 0 ? 0 : ox.integer - pox.integer, dy = k == 0 ? 0 : oy.integer - poy.integer;
    const int zv = k / S;
    const double z = zv + static_cast<double>(k % S) / S;
    if (voxel_z) {
      interpolate(fv, pv, k, vox_lo, vox_hi, below, -1);
      interpolate(fv, pv, k, vox_lo, vox_hi, above, +1);
    }
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const double v = current.at(x, y);
        Vec3 g{0, 0, 0};
        if (e.gradient) {
          const double dz = voxel_z ? above.at(x, y) - below.at(x, y)
                                    : (realigned(ahead, x, y, ox.frac - nox.frac, oy.frac - noy.frac) -
                                       realigned(behind, x, y, ox.frac - pox.frac, oy.frac - poy.frac)) * S;
          g = {(current.at(x + 1, y) - current.at(x - 1, y)) * gscale,
               (current.at(x, y + 1) - current.at(x, y - 1)) * gscale, dz * gscale};
        }
        // The nearest voxel's tag, as the interpolation unit picks it (ties up).
        const int tag = e.tags ? pv.tag_at(x + (ox.frac >= 0.5), y + (oy.frac >= 0.5), zv + (z - zv >= 0.5)) : 0;
        const ShadedF sh = shade(v, g, tag);
        double alpha = sh.alpha;
        const Vec3& rgb = sh.rgb;
        bool visible = !e.cropping || crop_visible(x, y, zv, crop);
        if (e.cut_plane) {
          const double fac = cut.factor(cut.a[0] * (x + ox.frac) + cut.a[1] * (y + oy.frac) + cut.a[2] * z);
          alpha *= fac;
          if (fac == 0) visible = false;
        }
        const Predecessor pred = ray_predecessor(x, y, dx, dy);
        AccF acc = pred.exists ? prev[static_cast<size_t>(pred.y) * nx + pred.x] : AccF{};
        if (poly && !poly->before_sample(index(x - ox.integer + ix_last, y - oy.integer + iy_last), k, acc))
          visible = false;
        if (visible) {
          if (s.blend == Blend::Composite) {
            const double t = (1 - acc.a) * alpha;
            acc.r += t * rgb[0]; acc.g += t * rgb[1]; acc.b += t * rgb[2]; acc.a += t;
          } else if (!acc.valid || (s.blend == Blend::Mip ? v > acc.value : v < acc.value)) {
            acc = {rgb[0] * alpha, rgb[1] * alpha, rgb[2] * alpha, alpha, v, true};
          }
        }
        cur[static_cast<size_t>(y) * nx + x] = acc;
      }
    if (k > 0)
      for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x)
          if (ray_leaves(x, y, dx, dy, nx, ny))
            write(x - pox.integer + ix_last, y - poy.integer + iy_last, prev[static_cast<size_t>(y) * nx + x]);
    std::swap(prev, cur);
    if (e.gradient) {
      std::swap(behind, current);
      std::swap(current, ahead);
      interpolate_slice(k + 2, ahead);
    } else if (k + 1 < K) {
      interpolate_slice(k + 1, current);
    }
    if (progress) progress(static_cast<double>(k + 1) / K);
  }
  const Offset lx = fv.x_offset(K - 1), ly = fv.y_offset(K - 1);
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x)
      write(x - lx.integer + ix_last, y - ly.integer + iy_last, prev[static_cast<size_t>(y) * nx + x]);
  // Rays that met no sample: their polygons alone.
  if (poly)
    for (int v = 0; v < out.image.height; ++v)
      for (int u = 0; u < out.image.width; ++u)
        if (!poly->done(index(u, v))) write(u, v, AccF{});
  if (stats) {
    stats->samples = static_cast<uint64_t>(nx) * ny * K;
    stats->slices = K;
  }
  return out;
}

}  // namespace cube4::golden
