// Independent image-order ray caster in double precision: one ray per
// final-image pixel through the object-space volume, trilinear samples at a
// fixed step, central-difference gradients of the interpolated field, the
// same optical model. No base plane, no shear, no tables: the accuracy
// reference for both shear-warp renderers.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "golden/fixed.hpp"
#include "golden/polygons.hpp"
#include "golden/renderers.hpp"
#include "golden/shading_model.hpp"

namespace cube4::golden {
namespace {

// Trilinear interpolation of the zero-padded volume at object voxel coordinates.
double field(const Volume& v, const Vec3& p) {
  const double fx = std::floor(p[0]), fy = std::floor(p[1]), fz = std::floor(p[2]);
  const int x = static_cast<int>(fx), y = static_cast<int>(fy), z = static_cast<int>(fz);
  const double tx = p[0] - fx, ty = p[1] - fy, tz = p[2] - fz;
  auto at = [&](int i, int j, int k) -> double {
    if (i < 0 || j < 0 || k < 0 || i >= v.dim[0] || j >= v.dim[1] || k >= v.dim[2]) return 0.0;
    return v.at(i, j, k);
  };
  auto bil = [&](int k) {
    const double a = at(x, y, k) + tx * (at(x + 1, y, k) - at(x, y, k));
    const double b = at(x, y + 1, k) + tx * (at(x + 1, y + 1, k) - at(x, y + 1, k));
    return a + ty * (b - a);
  };
  const double lo = bil(z), hi = bil(z + 1);
  return lo + tz * (hi - lo);
}

bool object_crop_visible(const Cropping& c, const Vec3& p) {
  int index = 0;
  for (int i = 0; i < 3; ++i) {
    const int q = static_cast<int>(std::floor(p[i]));
    if (c.slab[i][0] <= q && q <= c.slab[i][1]) index |= 1 << i;
  }
  return (c.mask >> index) & 1;
}

// Möller–Trumbore: the t at which o + t·d meets triangle (a, b, c), edges
// and corners included, or nothing (a ray in the triangle's plane misses
// it). No tie rule: a ray exactly through an edge meets both triangles that
// share it, which the views measured never do (docs/accuracy.md).
std::optional<double> intersect(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  auto sub = [](const Vec3& x, const Vec3& y) { return Vec3{x[0] - y[0], x[1] - y[1], x[2] - y[2]}; };
  auto cross = [](const Vec3& x, const Vec3& y) {
    return Vec3{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  auto dot = [](const Vec3& x, const Vec3& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const Vec3 e1 = sub(b, a), e2 = sub(c, a), q = cross(d, e2);
  const double det = dot(e1, q);
  if (det == 0) return std::nullopt;
  const Vec3 s = sub(o, a);
  const double u = dot(s, q) / det;
  if (u < 0 || u > 1) return std::nullopt;
  const Vec3 r = cross(s, e1);
  const double v = dot(d, r) / det;
  if (v < 0 || u + v > 1) return std::nullopt;
  return dot(e2, r) / det;
}

struct Hit {
  double t;
  Vec3 rgb;
  double alpha;
};

// Whether object voxel point p lies in front of a perspective view's eye.
bool in_front_of_eye(const ViewFactorisation& f, const Vec3& p) {
  double depth = 0;
  for (int i = 0; i < 3; ++i) depth += f.view_dir_object[i] * (p[i] - f.eye_object[i]) * f.spacing[i];
  return depth > 0;
}

// Every polygon hit of every image pixel's ray, in depth order, and the
// nearest opaque one (t = infinity: none); translucent hits at or behind
// it are hidden and left out.
struct PolygonHits {
  std::vector<std::vector<Hit>> translucent;
  std::vector<Hit> opaque;
};

// The rays are the renderer's (ViewFactorisation::ray_of_image): in
// perspective from the eye, meeting what lies in front of it (t > 0).
PolygonHits polygon_hits(const Scene& s, const std::vector<Mesh>& meshes, const ViewFactorisation& f, int width,
                         int height) {
  const size_t n = static_cast<size_t>(width) * height;
  PolygonHits h{std::vector<std::vector<Hit>>(n), std::vector<Hit>(n, Hit{std::numeric_limits<double>::infinity(), {}, 1})};
  for_each_drawn_triangle(s, f, meshes, [&](const Mesh& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& rgb) {
    // The pixels whose rays can meet it: its projection's bounding box;
    // in perspective every pixel when a corner is not in front of the eye.
    double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    double hi[2] = {-lo[0], -lo[1]};
    for (const Vec3* v : {&a, &b, &c}) {
      if (f.perspective && !in_front_of_eye(f, *v)) {
        lo[0] = lo[1] = -std::numeric_limits<double>::infinity();
        hi[0] = hi[1] = std::numeric_limits<double>::infinity();
        break;
      }
      const auto xy = f.image_of(*v);
      for (int i = 0; i < 2; ++i) {
        lo[i] = std::min(lo[i], xy[static_cast<size_t>(i)]);
        hi[i] = std::max(hi[i], xy[static_cast<size_t>(i)]);
      }
    }
    const int x0 = static_cast<int>(std::clamp(std::floor(lo[0]), 0.0, double(width))),
              x1 = static_cast<int>(std::clamp(std::ceil(hi[0]), -1.0, double(width - 1))),
              y0 = static_cast<int>(std::clamp(std::floor(lo[1]), 0.0, double(height))),
              y1 = static_cast<int>(std::clamp(std::ceil(hi[1]), -1.0, double(height - 1)));
    for (int Y = y0; Y <= y1; ++Y)
      for (int X = x0; X <= x1; ++X) {
        const ViewFactorisation::Ray ray = f.ray_of_image(X, Y);
        const auto hit = intersect(ray.origin, ray.direction, a, b, c);
        if (!hit || (f.perspective && !(*hit > 0))) continue;
        const size_t i = static_cast<size_t>(Y) * width + X;
        if (m.opacity < 1) {
          h.translucent[i].push_back({*hit, rgb, m.opacity});
        } else if (*hit < h.opaque[i].t) {
          h.opaque[i] = {*hit, rgb, 1};
        }
      }
  });
  for (size_t i = 0; i < n; ++i) {
    auto& list = h.translucent[i];
    const double z = h.opaque[i].t;
    list.erase(std::remove_if(list.begin(), list.end(), [z](const Hit& x) { return x.t >= z; }), list.end());
    std::stable_sort(list.begin(), list.end(), [](const Hit& x, const Hit& y) { return x.t < y.t; });
  }
  return h;
}

}  // namespace

ImageF render_reference(const Volume& vol, const Scene& s, const ViewFactorisation& f,
                        const ReferenceOptions& opt, RenderStats* stats, const Progress& progress) {
  const EffectSet e = effects_of(s);
  const Precision& p = s.precision;
  const double vmax = static_cast<double>(vol.max_value());
  const double gscale = std::ldexp(1.0, -p.gradient_shift);
  const double gmax = max_gradient_magnitude(p);
  const Lighting L = lighting_of(s, f);
  const double unit = std::min({vol.spacing[0], vol.spacing[1], vol.spacing[2]});
  const double h = opt.step * unit;  // physical step
  double plen = 0;
  for (int i = 0; i < 3; ++i) plen += s.cut.normal[i] * s.cut.normal[i];
  plen = std::sqrt(plen);
  PermutedCutPlane cut;  // in object voxel coordinates here
  for (int i = 0; i < 3; ++i) cut.a[i] = s.cut.normal[i] / plen;
  cut.dmin = s.cut.dmin / plen;
  cut.dmax = s.cut.dmax / plen;
  cut.falloff = s.cut.falloff / plen;
  cut.keep_inside = s.cut.keep_inside;

  double diagonal = 0;  // of the sampled box, in the ray's units
  for (int i = 0; i < 3; ++i) diagonal += (vol.dim[i] - 1) * (vol.dim[i] - 1) * vol.spacing[i] * vol.spacing[i];
  diagonal = std::sqrt(diagonal);

  ImageF img;
  img.width = s.width;
  img.height = s.height;
  img.rgba.assign(static_cast<size_t>(img.width) * img.height * 4, 0.0f);
  const std::vector<Mesh> none;
  const std::vector<Mesh>& meshes = opt.meshes ? *opt.meshes : none;
  check_polygon_scene(s, meshes);
  const PolygonHits hits = polygon_hits(s, meshes, f, img.width, img.height);
  uint64_t samples = 0;
  for (int Y = 0; Y < img.height; ++Y) {
    for (int X = 0; X < img.width; ++X) {
      // A pinhole camera in perspective: each ray its own direction, and
      // its own eye vector for the specular term.
      const ViewFactorisation::Ray ray = f.ray_of_image(X, Y);
      const Vec3& o = ray.origin;
      const Vec3& d = ray.direction;
      const Vec3 eye{-d[0] * vol.spacing[0], -d[1] * vol.spacing[1], -d[2] * vol.spacing[2]};
      // Clip the ray to the box where samples have voxels: [0, n-1] per axis.
      double t0 = -std::numeric_limits<double>::infinity(), t1 = std::numeric_limits<double>::infinity();
      for (int i = 0; i < 3; ++i) {
        const double lo = 0, hi = vol.dim[i] - 1;
        if (d[i] == 0) {
          if (o[i] < lo || o[i] > hi) t0 = t1 + 1;
          continue;
        }
        double a = (lo - o[i]) / d[i], b = (hi - o[i]) / d[i];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
      }
      double r = 0, g = 0, b = 0, a = 0, best = 0;
      bool valid = false;
      const size_t pixel = static_cast<size_t>(Y) * img.width + X;
      const std::vector<Hit>& layers = hits.translucent[pixel];
      const Hit& surface = hits.opaque[pixel];
      size_t next_layer = 0;
      auto over = [&](const Hit& h) {
        const double w = (1 - a) * h.alpha;
        r += w * h.rgb[0]; g += w * h.rgb[1]; b += w * h.rgb[2]; a += w;
      };
      // Steps counted, not accumulated: far from the volume (a ray origin
      // at 1e17, say) t += h would not move t, and the loop would not end.
      // A ray crosses the box in at most its diagonal (twice that: a guard
      // only, against rays whose clipping came out infinite).
      const double steps = t1 >= t0 ? std::floor(std::min(t1 - t0, 2 * diagonal + h) / h) : -1.0;
      for (int64_t k = 0; k <= static_cast<int64_t>(steps); ++k) {
        const double t = t0 + static_cast<double>(k) * h;
        // Surfaces at or in front of the sample come first; at or behind
        // the opaque one nothing is seen.
        while (next_layer < layers.size() && layers[next_layer].t <= t) over(layers[next_layer++]);
        if (t >= surface.t) break;
        const Vec3 q{o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
        ++samples;
        const double v = field(vol, q);
        Vec3 grad{0, 0, 0};
        if (e.gradient) {
          for (int i = 0; i < 3; ++i) {
            Vec3 qp = q, qm = q;
            qp[i] += 1;
            qm[i] -= 1;
            grad[i] = (field(vol, qp) - field(vol, qm)) * gscale;
          }
        }
        const double mag = std::sqrt(grad[0] * grad[0] + grad[1] * grad[1] + grad[2] * grad[2]);
        const double gm = e.magnitude ? eval_piecewise(s.gm_lut, std::min(1.0, mag / gmax)) : 1.0;
        // A tag is not interpolated: the nearest voxel's (q lies in the box).
        int tag = 0;
        if (e.tags) {
          std::array<int, 3> c{};
          for (int i = 0; i < 3; ++i) c[i] = std::clamp(static_cast<int>(std::floor(q[i] + 0.5)), 0, vol.dim[i] - 1);
          tag = vol.tag_at(c[0], c[1], c[2]);
        }
        double alpha = correct_alpha(eval_piecewise(s.opacity_of(tag), v / vmax), opt.step);
        if (s.gm.opacity) alpha *= gm;
        Vec3 rgb = eval_color(s.color_of(tag), v / vmax);
        if (e.shading) {
          double id = 0, is = 0;
          if (mag > 0) {
            Vec3 n{};
            double nl = 0;
            for (int i = 0; i < 3; ++i) { n[i] = -grad[i] / vol.spacing[i]; nl += n[i] * n[i]; }
            nl = std::sqrt(nl);
            for (int i = 0; i < 3; ++i) n[i] /= nl;
            id = L.diffuse(n);
            if (e.specular) {
              const double ne = n[0] * eye[0] + n[1] * eye[1] + n[2] * eye[2];
              is = L.specular({2 * ne * n[0] - eye[0], 2 * ne * n[1] - eye[1], 2 * ne * n[2] - eye[2]});
            }
          }
          const Material& m = s.material_of(tag);
          const double fd = m.ke + m.kd * id * (s.gm.diffuse ? gm : 1.0);
          const double fs = e.specular ? m.ks * is * (s.gm.specular ? gm : 1.0) : 0.0;
          for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(rgb[c] * fd + m.specular_color[c] * fs, 0.0, 1.0);
        }
        bool visible = !e.cropping || object_crop_visible(s.cropping, q);
        if (e.cut_plane) {
          const double fac = cut.factor(cut.a[0] * q[0] + cut.a[1] * q[1] + cut.a[2] * q[2]);
          alpha *= fac;
          if (fac == 0) visible = false;
        }
        if (!visible) continue;
        if (s.blend == Blend::Composite) {
          const double w = (1 - a) * alpha;
          r += w * rgb[0]; g += w * rgb[1]; b += w * rgb[2]; a += w;
        } else if (!valid || (s.blend == Blend::Mip ? v > best : v < best)) {
          r = rgb[0] * alpha; g = rgb[1] * alpha; b = rgb[2] * alpha; a = alpha;
          best = v;
          valid = true;
        }
      }
      while (next_layer < layers.size()) over(layers[next_layer++]);
      if (surface.t < std::numeric_limits<double>::infinity()) over(surface);
      float* px = img.pixel(X, Y);
      px[0] = static_cast<float>(r); px[1] = static_cast<float>(g);
      px[2] = static_cast<float>(b); px[3] = static_cast<float>(a);
    }
    if (progress) progress(static_cast<double>(Y + 1) / img.height);
  }
  if (stats) {
    stats->samples = samples;
    stats->slices = 0;
  }
  return img;
}

}  // namespace cube4::golden
