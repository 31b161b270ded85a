#include "golden/shading_model.hpp"

#include <algorithm>
#include <cmath>

#include "golden/fixed.hpp"

namespace cube4::golden {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 unit_or_zero(const Vec3& v) {
  const double n = std::sqrt(dot(v, v));
  if (n == 0) return {0, 0, 0};
  return {v[0] / n, v[1] / n, v[2] / n};
}

// Index of the segment containing x and the position within it.
template <class P>
std::pair<size_t, double> locate(const std::vector<P>& pts, double x) {
  if (x <= pts.front().x) return {0, 0.0};
  if (x >= pts.back().x) return {pts.size() - 1, 0.0};
  size_t i = 1;
  while (pts[i].x < x) ++i;
  return {i - 1, (x - pts[i - 1].x) / (pts[i].x - pts[i - 1].x)};
}

}  // namespace

double eval_piecewise(const std::vector<ScalarPoint>& pts, double x) {
  if (pts.empty()) return 0;
  const auto [i, t] = locate(pts, x);
  if (t == 0) return pts[i].y;
  return pts[i].y + t * (pts[i + 1].y - pts[i].y);
}

Vec3 eval_color(const std::vector<ColorPoint>& pts, double x) {
  if (pts.empty()) return {1, 1, 1};
  const auto [i, t] = locate(pts, x);
  if (t == 0) return pts[i].rgb;
  Vec3 c{};
  for (int k = 0; k < 3; ++k) c[k] = pts[i].rgb[k] + t * (pts[i + 1].rgb[k] - pts[i].rgb[k]);
  return c;
}

double correct_alpha(double alpha, double ratio) {
  if (alpha >= 1) return 1;
  return 1 - std::pow(1 - alpha, ratio);
}

double sample_step_ratio(const ViewFactorisation& f, int supersampling) {
  const double sx = f.shear_x * f.spacing[f.perm[0]];
  const double sy = f.shear_y * f.spacing[f.perm[1]];
  const double sz = f.spacing[f.perm[2]];
  const double unit = std::min({f.spacing[0], f.spacing[1], f.spacing[2]});
  return std::sqrt(sx * sx + sy * sy + sz * sz) / supersampling / unit;
}

double max_gradient_magnitude(const Precision& p) {
  return static_cast<double>(max_signed(p.gradient_bits)) * std::sqrt(3.0);
}

double Lighting::diffuse(const Vec3& n) const {
  double sum = 0;
  for (const auto& [l, i] : lights) sum += i * std::max(0.0, dot(n, l));
  return sum;
}

double Lighting::specular(const Vec3& r) const {
  double sum = 0;
  for (const auto& [l, i] : lights) {
    const double c = dot(r, l);
    if (c > 0) sum += i * std::pow(c, exponent);
  }
  return sum;
}

Lighting lighting_of(const Scene& s, const ViewFactorisation& f) {
  Lighting L;
  L.exponent = s.material.exponent;
  for (const Light& light : s.lights) {
    // World to object is the transpose of the rotation.
    Vec3 o{};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) o[i] += f.object_to_world[k][i] * light.direction[k];
    L.lights.push_back({unit_or_zero(o), light.intensity});
  }
  return L;
}

Vec3 polygon_color(const Scene& s, const Lighting& L, const ViewFactorisation& f, const Vec3& a, const Vec3& b,
                   const Vec3& c, const Vec3& color, bool lit) {
  if (!lit) return color;
  Vec3 e1{}, e2{};
  for (int i = 0; i < 3; ++i) {
    e1[i] = (b[i] - a[i]) * f.spacing[i];
    e2[i] = (c[i] - a[i]) * f.spacing[i];
  }
  Vec3 n = unit_or_zero({e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]});
  const Vec3 eye{-f.view_dir_object[0], -f.view_dir_object[1], -f.view_dir_object[2]};
  double ne = dot(n, eye);
  if (ne < 0) {
    n = {-n[0], -n[1], -n[2]};
    ne = -ne;
  }
  const Material& m = s.material;
  const double fd = m.ke + m.kd * L.diffuse(n);
  const double fs = m.ks > 0 ? m.ks * L.specular({2 * ne * n[0] - eye[0], 2 * ne * n[1] - eye[1], 2 * ne * n[2] - eye[2]})
                             : 0.0;
  Vec3 rgb{};
  for (int i = 0; i < 3; ++i) rgb[i] = std::clamp(color[i] * fd + m.specular_color[i] * fs, 0.0, 1.0);
  return rgb;
}

Vec3 normal_from_permuted_gradient(const ViewFactorisation& f, const Vec3& g_perm) {
  const Vec3 g_obj = f.direction_to_object(g_perm);
  // A gradient per voxel becomes per physical unit by dividing by the spacing.
  const Vec3 g_phys{g_obj[0] / f.spacing[0], g_obj[1] / f.spacing[1], g_obj[2] / f.spacing[2]};
  const Vec3 u = unit_or_zero(g_phys);
  return {-u[0], -u[1], -u[2]};
}

Vec3 object_direction(const ViewFactorisation& f, const Vec3& d_perm) {
  return unit_or_zero(f.direction_to_object(d_perm));
}

SampleShading::SampleShading(const Scene& s, const ViewFactorisation& f, double vmax, double ratio)
    : s_(s), f_(f), e_(effects_of(s)), lighting_(lighting_of(s, f)), vmax_(vmax),
      gmax_(max_gradient_magnitude(s.precision)), ratio_(ratio) {}

ShadedF SampleShading::operator()(double v, const Vec3& g, int tag) const {
  const Scene& s = s_;
  const double mag = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  const double gm = e_.magnitude ? eval_piecewise(s.gm_lut, std::min(1.0, mag / gmax_)) : 1.0;
  ShadedF out;
  out.alpha = correct_alpha(eval_piecewise(s.opacity_of(tag), v / vmax_), ratio_);
  if (s.gm.opacity) out.alpha *= gm;
  Vec3& rgb = out.rgb;
  rgb = eval_color(s.color_of(tag), v / vmax_);
  if (!e_.shading) return out;
  double id = 0, is = 0;
  if (mag > 0) {
    id = lighting_.diffuse(normal_from_permuted_gradient(f_, g));
    if (e_.specular) {
      const Vec3& E = f_.eye_perm;
      const double ne = g[0] * E[0] + g[1] * E[1] + g[2] * E[2], nn = mag * mag;
      is = lighting_.specular(
          object_direction(f_, {2 * ne * g[0] - nn * E[0], 2 * ne * g[1] - nn * E[1], 2 * ne * g[2] - nn * E[2]}));
    }
  }
  const Material& m = s.material_of(tag);
  const double fd = m.ke + m.kd * id * (s.gm.diffuse ? gm : 1.0);
  const double fs = e_.specular ? m.ks * is * (s.gm.specular ? gm : 1.0) : 0.0;
  for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(rgb[c] * fd + m.specular_color[c] * fs, 0.0, 1.0);
  return out;
}

}  // namespace cube4::golden
