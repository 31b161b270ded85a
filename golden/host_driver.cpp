#include "golden/host_driver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "golden/errors.hpp"

#include "golden/fixed.hpp"
#include "golden/shading_model.hpp"
#include "golden/units/shade_cube_map.hpp"

namespace cube4::golden {
int64_t quantise_unit(double v, int bits) {
  return sat_unsigned(std::llround(std::clamp(v, 0.0, 1.0) * max_unsigned(bits)), bits);
}

namespace {

// Reflectance-map entries saturate at the map's width by design (bright
// lights clip); clamping before rounding keeps that true for any intensity,
// where llround of a value beyond int64 would be undefined.
int64_t quantise_fixed(double v, int frac_bits, int bits) {
  const double scaled = v * static_cast<double>(int64_t{1} << frac_bits);
  return sat_unsigned(std::llround(std::clamp(scaled, 0.0, static_cast<double>(max_unsigned(bits)))), bits);
}

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// A scene value becomes round(value * scale) in a register that holds
// lo..hi: refused, naming the key and the value, when it does not fit,
// rather than wrapped or saturated into a different image.
int64_t to_register(const Scene& s, const std::string& key, double value, double scale, int64_t lo, int64_t hi,
                    const std::string& reg) {
  const double x = std::nearbyint(value * scale);
  if (!(x >= static_cast<double>(lo) && x <= static_cast<double>(hi)))
    throw InputError((s.file.empty() ? std::string("scene") : s.file) + ": \"" + key + "\" = " + fmt(value) +
                     " does not fit the " + reg + " register (" + fmt(static_cast<double>(lo) / scale) + ".." +
                     fmt(static_cast<double>(hi) / scale) + ")");
  return static_cast<int64_t>(x);
}

uint32_t coef_register(const Scene& s, const std::string& key, double value, const char* reg) {
  const Precision& p = s.precision;
  return static_cast<uint32_t>(to_register(s, key, value,
                                           std::ldexp(1.0, p.coef_frac_bits), 0, max_unsigned(p.coef_bits),
                                           std::string(reg) + " (precision.coef_bits, coef_frac_bits)"));
}

}  // namespace

std::vector<ClassEntry> build_classification(const Scene& s, double step_ratio) {
  const Precision& p = s.precision;
  const int64_t n = int64_t{1} << p.voxel_bits;
  // One table of 2^voxel_bits entries per tag, at address {tag, value}.
  std::vector<ClassEntry> lut(static_cast<size_t>(n) * s.tag_count());
  for (int t = 0; t < s.tag_count(); ++t)
    for (int64_t i = 0; i < n; ++i) {
      const double x = static_cast<double>(i) / (n - 1);
      const Vec3 c = eval_color(s.color_of(t), x);
      const double a = correct_alpha(eval_piecewise(s.opacity_of(t), x), step_ratio);
      lut[class_address(static_cast<uint32_t>(t), static_cast<uint32_t>(i), p)] = {
          static_cast<uint16_t>(quantise_unit(c[0], p.color_bits)),
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
  // Scaled by the largest component first: the squares of a normal such as
  // [1e200, 0, 0] or [1e-200, 0, 0] would overflow or vanish.
  const double m = std::max({std::fabs(c.normal[0]), std::fabs(c.normal[1]), std::fabs(c.normal[2])});
  const Vec3 n{c.normal[0] / m, c.normal[1] / m, c.normal[2] / m};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  // n·o = d in object voxels becomes a·p = d - offset in permuted voxels.
  PermutedCutPlane r;
  double offset = 0;
  for (int i = 0; i < 3; ++i) {
    const double ni = n[f.perm[i]] / len;
    r.a[i] = f.flip[i] ? -ni : ni;
    if (f.flip[i]) offset += ni * (f.pdim[i] - 1);
  }
  r.dmin = c.dmin / m / len - offset;
  r.dmax = c.dmax / m / len - offset;
  r.falloff = c.falloff / m / len;
  r.keep_inside = c.keep_inside;
  return r;
}

double PermutedCutPlane::factor(double d) const {
  const double outside = d < dmin ? dmin - d : (d > dmax ? d - dmax : 0.0);
  double inside_factor = 1;
  if (outside > 0) inside_factor = outside >= falloff ? 0.0 : (falloff - outside) / falloff;
  return keep_inside ? inside_factor : 1 - inside_factor;
}

CutRegs permute_cut_plane(const Scene& s, const ViewFactorisation& f) {
  const CutPlane& c = s.cut;
  const Precision& p = s.precision;
  const PermutedCutPlane real = permute_cut_plane_real(c, f);
  const double scale = std::ldexp(1.0, kCutNormalBits);
  const double dscale = std::ldexp(1.0, kCutNormalBits + p.weight_bits);
  // The distance registers are 64 bits; one bit is kept spare so that the
  // hardware's d - dmax and dmin - d cannot overflow.
  constexpr int64_t kDistance = int64_t{1} << 62;
  CutRegs r;
  const int64_t one = int64_t{1} << kCutNormalBits;
  r.a = static_cast<int32_t>(to_register(s, "cut_plane.normal", real.a[0], scale, -one, one, "CUT_A"));
  r.b = static_cast<int32_t>(to_register(s, "cut_plane.normal", real.a[1], scale, -one, one, "CUT_B"));
  r.c = static_cast<int32_t>(to_register(s, "cut_plane.normal", real.a[2], scale, -one, one, "CUT_C"));
  // The message shows the user's value; the range is in permuted voxels,
  // which differ from the user's by the normal's length and an offset.
  auto distance = [&](const char* key, double user, double permuted, const char* reg) {
    const double x = std::nearbyint(permuted * dscale);
    if (!(x >= static_cast<double>(-kDistance) && x <= static_cast<double>(kDistance)))
      throw InputError((s.file.empty() ? std::string("scene") : s.file) + ": \"" + key + "\" = " + fmt(user) +
                       " does not fit the " + reg + " register (64-bit signed, 2^" +
                       std::to_string(kCutNormalBits + p.weight_bits) + " per voxel: about " +
                       fmt(static_cast<double>(kDistance) / dscale) + " voxels either way)");
    return static_cast<int64_t>(x);
  };
  r.dmin = distance("cut_plane.dmin", c.dmin, real.dmin, "CUT_DMIN");
  r.dmax = distance("cut_plane.dmax", c.dmax, real.dmax, "CUT_DMAX");
  r.falloff = distance("cut_plane.falloff", c.falloff, real.falloff, "CUT_FALLOFF");
  r.inv_falloff = r.falloff > 0 ? static_cast<uint64_t>(std::llround(
                                      std::ldexp(static_cast<double>(max_unsigned(p.alpha_bits)), kCutInvShift) /
                                      static_cast<double>(r.falloff)))
                                : 0;
  r.keep_inside = c.keep_inside;
  return r;
}

// Perspective (Cube-4 §3): the eye lies d voxels in front of the front
// face, so on sample slice k (z = k / S) the rays are m_k = 1 + z / d apart,
// and ray u, which crosses the base plane at X_u = ray_offset + u, lies at
// e + (X_u - e) m_k (e: the eye's x). The steps are rounded once; the
// positions then follow them exactly, ray 0's through the spacing register
// so that the eye stays where the rays meet.
static void program_perspective(const Scene& s, const ViewFactorisation& f, Registers& r) {
  const Vec3 eye = f.eye_permuted();
  const double d = -eye[2];
  const double one = std::ldexp(1.0, s.precision.dda_frac_bits);
  constexpr int64_t kDda = std::numeric_limits<int64_t>::max() / 4;
  r.perspective = true;
  r.scale_start = int64_t{1} << s.precision.dda_frac_bits;
  r.scale_step = to_register(s, "view", 1.0 / (s.supersampling * d), one, 0, kDda, "SCALE_STEP");
  const double step = static_cast<double>(r.scale_step) / one;
  r.x_step = to_register(s, "view", (s.view.ray_offset[0] - eye[0]) * step, one, -kDda, kDda, "X_STEP");
  r.y_step = to_register(s, "view", (s.view.ray_offset[1] - eye[1]) * step, one, -kDda, kDda, "Y_STEP");
  // place_eye() keeps the last slice's spacing within the box filter's 3
  // voxels; rounding must not take it past them.
  const int64_t limit = 3 * r.scale_start;
  if (r.ray_spacing(r.sample_slices() - 1) > limit)
    throw InputError((s.file.empty() ? std::string("scene") : s.file) +
                     ": the eye is too close: the last slice's rays would be more than 3 voxels apart "
                     "(\"view.distance\" or \"view.eye\")");
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
  r.z_gradient = s.z_gradient;
  const double one = std::ldexp(1.0, p.dda_frac_bits);
  constexpr int64_t kDda = std::numeric_limits<int64_t>::max() / 2;  // 64-bit signed, with headroom for the sum
  r.x_start = to_register(s, "view.ray_offset", s.view.ray_offset[0], one, 0, kDda, "X_START");
  r.y_start = to_register(s, "view.ray_offset", s.view.ray_offset[1], one, 0, kDda, "Y_START");
  r.x_step = to_register(s, "view", f.shear_x / s.supersampling, one, -kDda, kDda, "X_STEP");
  r.y_step = to_register(s, "view", f.shear_y / s.supersampling, one, -kDda, kDda, "Y_STEP");
  if (f.perspective) program_perspective(s, f, r);

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
  if (e.shading) r.diffuse_map = build_diffuse_map(s, f);
  if (e.specular) r.specular_map = build_specular_map(s, f);
  // Each tag's material (only the scene's without tags); ks and the specular
  // colour only where the specular map exists.
  for (int t = 0; t < (e.shading ? s.tag_count() : 0); ++t) {
    const Material& m = s.material_of(t);
    const std::string key = s.tag_class(t) && s.tag_class(t)->material
                                ? "tags.classes[tag " + std::to_string(t) + "].material."
                                : std::string("material.");
    ShadeCoefs k;
    k.ke = coef_register(s, key + "ke", m.ke, "KE");
    k.kd = coef_register(s, key + "kd", m.kd, "KD");
    if (e.specular) {
      k.ks = coef_register(s, key + "ks", m.ks, "KS");
      for (int c = 0; c < 3; ++c) k.specular[c] = static_cast<uint32_t>(quantise_unit(m.specular_color[c], p.alpha_bits));
    }
    if (t == 0) r.coefs = k;
    if (e.tags) r.tag_coefs.push_back(k);
  }
  if (e.specular) {
    for (int c = 0; c < 3; ++c)
      r.eye[c] = static_cast<int32_t>(to_register(s, "view", f.eye_perm[c], static_cast<double>(max_signed(p.eye_bits)),
                                                  -max_signed(p.eye_bits), max_signed(p.eye_bits), "EYE"));
  }
  r.blend = s.blend == Blend::Mip ? BlendMode::Mip
            : s.blend == Blend::MinIp ? BlendMode::MinIp : BlendMode::Composite;
  r.crop_enabled = e.cropping;
  if (e.cropping) r.crop = permute_cropping(s.cropping, f);
  r.cut_enabled = e.cut_plane;
  if (e.cut_plane) r.cut = permute_cut_plane(s, f);
  return h;
}

std::vector<Scene> xy_subframes(const Scene& s) {
  const int n = s.xy_supersampling;
  std::vector<Scene> frames;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      Scene f = s;
      for (int axis = 0; axis < 2; ++axis) {
        const double o = s.view.ray_offset[static_cast<size_t>(axis)] + static_cast<double>(axis == 0 ? i : j) / n;
        f.view.ray_offset[static_cast<size_t>(axis)] = o >= 1 ? o - 1 : o;
      }
      frames.push_back(std::move(f));
    }
  return frames;
}

}  // namespace cube4::golden
