#include "golden/host_driver.hpp"

#include <algorithm>
#include <cmath>

#include "golden/fixed.hpp"
#include "golden/shading_model.hpp"
#include "golden/units/cube_map.hpp"

namespace cube4::golden {
namespace {

int64_t quantise_unit(double v, int bits) {
  return sat_unsigned(std::llround(std::clamp(v, 0.0, 1.0) * max_unsigned(bits)), bits);
}

int64_t quantise_fixed(double v, int frac_bits, int bits) {
  return sat_unsigned(std::llround(v * static_cast<double>(int64_t{1} << frac_bits)), bits);
}

}  // namespace

std::vector<ClassEntry> build_classification(const Scene& s, double step_ratio) {
  const Precision& p = s.precision;
  const int64_t n = int64_t{1} << p.voxel_bits;
  std::vector<ClassEntry> lut(static_cast<size_t>(n));
  for (int64_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) / (n - 1);
    const Vec3 c = eval_color(s.color, x);
    const double a = correct_alpha(eval_piecewise(s.opacity, x), step_ratio);
    lut[i] = {static_cast<uint16_t>(quantise_unit(c[0], p.color_bits)),
              static_cast<uint16_t>(quantise_unit(c[1], p.color_bits)),
              static_cast<uint16_t>(quantise_unit(c[2], p.color_bits)),
              static_cast<uint16_t>(quantise_unit(a, p.alpha_bits))};
  }
  return lut;
}

std::vector<uint16_t> build_gm_lut(const Scene& s) {
  const Precision& p = s.precision;
  const size_t n = size_t{1} << p.magnitude_bits;
  std::vector<uint16_t> lut(n);
  const double full = max_gradient_magnitude(p);
  for (size_t m = 0; m < n; ++m)
    lut[m] = static_cast<uint16_t>(
        quantise_unit(eval_piecewise(s.gm_lut, std::min(1.0, m / full)), p.gmlut_bits));
  return lut;
}

Vec3 map_direction(int face, int u, int v, int res) {
  const int axis = face / 2;
  Vec3 d{};
  d[axis] = (face & 1) ? -1.0 : 1.0;
  d[face_axis_u(axis)] = -1.0 + 2.0 * u / (res - 1);
  d[face_axis_v(axis)] = -1.0 + 2.0 * v / (res - 1);
  return d;
}

namespace {
template <class F>
std::vector<uint32_t> build_map(const Precision& p, F intensity_of_direction) {
  const int res = p.map_face_res;
  std::vector<uint32_t> map(static_cast<size_t>(6) * res * res);
  for (int face = 0; face < 6; ++face)
    for (int v = 0; v < res; ++v)
      for (int u = 0; u < res; ++u)
        map[map_index(face, u, v, res)] = static_cast<uint32_t>(quantise_fixed(
            intensity_of_direction(map_direction(face, u, v, res)), p.map_frac_bits, p.map_bits));
  return map;
}
}  // namespace

std::vector<uint32_t> build_diffuse_map(const Scene& s, const ViewFactorisation& f) {
  const Lighting L = lighting_of(s, f);
  return build_map(s.precision, [&](const Vec3& g) { return L.diffuse(normal_from_permuted_gradient(f, g)); });
}

std::vector<uint32_t> build_specular_map(const Scene& s, const ViewFactorisation& f) {
  const Lighting L = lighting_of(s, f);
  return build_map(s.precision, [&](const Vec3& r) { return L.specular(object_direction(f, r)); });
}

CropRegs permute_cropping(const Cropping& c, const ViewFactorisation& f) {
  CropRegs r;
  for (int i = 0; i < 3; ++i) {
    const int n = f.pdim[i];
    const int lo = std::clamp(c.slab[f.perm[i]][0], 0, n - 1);
    const int hi = std::clamp(c.slab[f.perm[i]][1], 0, n - 1);
    // A slab wholly outside the volume stays empty rather than being clamped onto an edge.
    const bool empty = c.slab[f.perm[i]][0] > n - 1 || c.slab[f.perm[i]][1] < 0;
    if (empty) {
      r.slab[i] = {1, 0};
    } else {
      r.slab[i] = f.flip[i] ? std::array<int32_t, 2>{n - 1 - hi, n - 1 - lo}
                            : std::array<int32_t, 2>{lo, hi};
    }
  }
  // Table bit j (inX | inY<<1 | inZ<<2 in permuted axes) is the user's bit
  // for the same slabs in object axes.
  r.mask = 0;
  for (int j = 0; j < 8; ++j) {
    int object_index = 0;
    for (int i = 0; i < 3; ++i)
      if (j >> i & 1) object_index |= 1 << f.perm[i];
    if (c.mask >> object_index & 1) r.mask |= static_cast<uint8_t>(1 << j);
  }
  return r;
}

PermutedCutPlane permute_cut_plane_real(const CutPlane& c, const ViewFactorisation& f) {
  const double len = std::sqrt(c.normal[0] * c.normal[0] + c.normal[1] * c.normal[1] + c.normal[2] * c.normal[2]);
  // n·o = d in object voxels becomes a·p = d - offset in permuted voxels.
  PermutedCutPlane r;
  double offset = 0;
  for (int i = 0; i < 3; ++i) {
    const double ni = c.normal[f.perm[i]] / len;
    r.a[i] = f.flip[i] ? -ni : ni;
    if (f.flip[i]) offset += ni * (f.pdim[i] - 1);
  }
  r.dmin = c.dmin / len - offset;
  r.dmax = c.dmax / len - offset;
  r.falloff = c.falloff / len;
  r.keep_inside = c.keep_inside;
  return r;
}

double PermutedCutPlane::factor(double d) const {
  const double outside = d < dmin ? dmin - d : (d > dmax ? d - dmax : 0.0);
  double inside_factor = 1;
  if (outside > 0) inside_factor = outside >= falloff ? 0.0 : (falloff - outside) / falloff;
  return keep_inside ? inside_factor : 1 - inside_factor;
}

CutRegs permute_cut_plane(const CutPlane& c, const ViewFactorisation& f, const Precision& p) {
  const PermutedCutPlane real = permute_cut_plane_real(c, f);
  const double scale = std::ldexp(1.0, kCutNormalBits);
  const double dscale = std::ldexp(1.0, kCutNormalBits + p.weight_bits);
  CutRegs r;
  r.a = static_cast<int32_t>(std::lround(real.a[0] * scale));
  r.b = static_cast<int32_t>(std::lround(real.a[1] * scale));
  r.c = static_cast<int32_t>(std::lround(real.a[2] * scale));
  r.dmin = std::llround(real.dmin * dscale);
  r.dmax = std::llround(real.dmax * dscale);
  r.falloff = std::llround(real.falloff * dscale);
  r.inv_falloff = r.falloff > 0 ? static_cast<uint64_t>(std::llround(
                                      std::ldexp(static_cast<double>(max_unsigned(p.alpha_bits)), kCutInvShift) /
                                      static_cast<double>(r.falloff)))
                                : 0;
  r.keep_inside = c.keep_inside;
  return r;
}

HostProgram program_host(const Scene& s, const Volume& vol) {
  HostProgram h;
  h.view = factorise_view(s, vol);
  h.effects = effects_of(s);
  const ViewFactorisation& f = h.view;
  const Precision& p = s.precision;
  Registers& r = h.regs;
  r.p = p;
  r.dim = f.pdim;
  r.perm = f.perm;
  r.flip = f.flip;
  r.supersampling = s.supersampling;
  const double one = std::ldexp(1.0, p.dda_frac_bits);
  r.x_start = std::llround(s.view.ray_offset[0] * one);
  r.y_start = std::llround(s.view.ray_offset[1] * one);
  r.x_step = std::llround(f.shear_x / s.supersampling * one);
  r.y_step = std::llround(f.shear_y / s.supersampling * one);

  r.classification = build_classification(s, sample_step_ratio(f, s.supersampling));
  const EffectSet& e = h.effects;
  r.gradient = e.gradient;
  r.magnitude = e.magnitude;
  r.shading = e.shading;
  r.specular = e.specular;
  r.gm_opacity = s.gm.opacity;
  r.gm_diffuse = e.shading && s.gm.diffuse;
  r.gm_specular = e.specular && s.gm.specular;
  if (e.magnitude) r.gm_lut = build_gm_lut(s);
  if (e.shading) {
    r.diffuse_map = build_diffuse_map(s, f);
    r.coefs.ke = static_cast<uint32_t>(quantise_fixed(s.material.ke, p.coef_frac_bits, p.coef_bits));
    r.coefs.kd = static_cast<uint32_t>(quantise_fixed(s.material.kd, p.coef_frac_bits, p.coef_bits));
  }
  if (e.specular) {
    r.specular_map = build_specular_map(s, f);
    r.coefs.ks = static_cast<uint32_t>(quantise_fixed(s.material.ks, p.coef_frac_bits, p.coef_bits));
    for (int c = 0; c < 3; ++c)
      r.coefs.specular[c] = static_cast<uint32_t>(quantise_unit(s.material.specular_color[c], p.alpha_bits));
    for (int c = 0; c < 3; ++c)
      r.eye[c] = static_cast<int32_t>(std::lround(f.eye_perm[c] * max_signed(p.eye_bits)));
  }
  r.blend = s.blend == Blend::Mip ? BlendMode::Mip
            : s.blend == Blend::MinIp ? BlendMode::MinIp : BlendMode::Composite;
  r.crop_enabled = e.cropping;
  if (e.cropping) r.crop = permute_cropping(s.cropping, f);
  r.cut_enabled = e.cut_plane;
  if (e.cut_plane) r.cut = permute_cut_plane(s.cut, f, p);
  return h;
}

}  // namespace cube4::golden
