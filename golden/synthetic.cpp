// Synthetic volumes: analytic test objects whose exact values are known, so
// the renderers can be checked against geometry rather than against images.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "golden/quantise.hpp"
#include "golden/volume_io.hpp"

namespace cube4::golden {

namespace {

constexpr int kMaxSize = 1024;
constexpr double kPi = 3.14159265358979323846;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string dims_text(const std::array<int, 3>& s) {
  return std::to_string(s[0]) + "x" + std::to_string(s[1]) + "x" + std::to_string(s[2]);
}

void check_size(const std::array<int, 3>& s) {
  for (int a = 0; a < 3; ++a)
    if (s[a] < 1 || s[a] > kMaxSize)
      throw InputError("volume.size: " + dims_text(s) + " has a component outside 1.." +
                       std::to_string(kMaxSize));
}

void check_unit(double v, const char* key) {
  if (!(v >= 0 && v <= 1))
    throw InputError(std::string(key) + ": " + num(v) + " is outside [0, 1]");
}

Vec3 centre_of(const VolumeSource& src) {
  if (src.center) {
    for (double c : *src.center)
      if (!std::isfinite(c)) throw InputError("volume.center: components must be finite");
    return *src.center;
  }
  return {(src.size[0] - 1) / 2.0, (src.size[1] - 1) / 2.0, (src.size[2] - 1) / 2.0};
}

int smallest(const std::array<int, 3>& s) { return std::min({s[0], s[1], s[2]}); }

double dist(double x, double y, double z, const Vec3& c) {
  const double dx = x - c[0], dy = y - c[1], dz = z - c[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// Evaluates f at every voxel centre (voxel i at coordinate i) and scales its
// [0,1] result with the loaders' rounding, so synthetic and file volumes agree.
template <class F>
std::vector<uint16_t> sample(const std::array<int, 3>& s, int voxel_bits, F f) {
  std::vector<uint16_t> out(static_cast<size_t>(s[0]) * s[1] * s[2]);
  size_t i = 0;
  for (int z = 0; z < s[2]; ++z)
    for (int y = 0; y < s[1]; ++y)
      for (int x = 0; x < s[0]; ++x) out[i++] = quantise_value(f(x, y, z), {0, 1}, voxel_bits);
  return out;
}

double clamp01(double v) { return std::min(1.0, std::max(0.0, v)); }

// Grid index to [-1, 1]; a single voxel sits at 0.
double unit_coord(int i, int n) { return n > 1 ? -1.0 + 2.0 * i / (n - 1) : 0.0; }
double ramp(int i, int n) { return n > 1 ? static_cast<double>(i) / (n - 1) : 0.0; }

// Marschner & Lobb 1994, "An evaluation of reconstruction filters for volume
// rendering": already normalised to [0,1]; clamped only against rounding.
double marschner_lobb(double x, double y, double z) {
  constexpr double fm = 6, alpha = 0.25;
  const double r = std::sqrt(x * x + y * y);
  const double rho_r = std::cos(2 * kPi * fm * std::cos(kPi * r / 2));
  return clamp01((1 - std::sin(kPi * z / 2) + alpha * (1 + rho_r)) / (2 * (1 + alpha)));
}

// The radius asked for, or `fraction` of the smallest size when none is.
double radius_of(const VolumeSource& src, double fraction) {
  if (!(src.radius >= 0) || !std::isfinite(src.radius))
    throw InputError("volume.radius: " + num(src.radius) + " must be >= 0 (0 = default)");
  return src.radius > 0 ? src.radius : fraction * smallest(src.size);
}

Volume sphere(const VolumeSource& src, int bits) {
  const double r = radius_of(src, 3.0 / 8.0);
  const Vec3 c = centre_of(src);
  Volume v;
  // Volume-sampled (Wang & Kaufman): a ramp two voxels wide across the surface
  // instead of a binary step, so the object is band-limited enough to resample.
  v.data = sample(src.size, bits,
                  [&](int x, int y, int z) { return clamp01(0.5 + (r - dist(x, y, z, c)) / 2); });
  v.source = "sphere " + dims_text(src.size) + " r=" + num(r);
  if (src.center) v.source += " center=(" + num(c[0]) + "," + num(c[1]) + "," + num(c[2]) + ")";
  return v;
}

// Two spheres of radius r (default 1/4 of the smallest size) that touch at
// the centre, their centres at c ± (r, 0, 0): the tagged scene's volume
// (scenes/tagged_spheres.json), one value, told apart only by tags.
Volume spheres(const VolumeSource& src, int bits) {
  const double r = radius_of(src, 1.0 / 4.0);
  const Vec3 c = centre_of(src);
  const Vec3 a{c[0] - r, c[1], c[2]}, b{c[0] + r, c[1], c[2]};
  Volume v;
  v.data = sample(src.size, bits, [&](int x, int y, int z) {
    return clamp01(0.5 + (r - std::min(dist(x, y, z, a), dist(x, y, z, b))) / 2);
  });
  v.source = "spheres " + dims_text(src.size) + " r=" + num(r);
  return v;
}

Volume field(const VolumeSource& src, int bits) {
  const auto& s = src.size;
  Volume v;
  if (src.field == "marschner_lobb") {
    v.data = sample(s, bits, [&](int x, int y, int z) {
      return marschner_lobb(unit_coord(x, s[0]), unit_coord(y, s[1]), unit_coord(z, s[2]));
    });
  } else if (src.field == "gaussian") {
    const double sigma = smallest(s) / 6.0;
    const Vec3 c = centre_of(src);
    v.data = sample(s, bits, [&](int x, int y, int z) {
      const double d = dist(x, y, z, c);
      return std::exp(-d * d / (2 * sigma * sigma));
    });
  } else if (src.field == "ramp_x") {
    v.data = sample(s, bits, [&](int x, int, int) { return ramp(x, s[0]); });
  } else if (src.field == "ramp_y") {
    v.data = sample(s, bits, [&](int, int y, int) { return ramp(y, s[1]); });
  } else if (src.field == "ramp_z") {
    v.data = sample(s, bits, [&](int, int, int z) { return ramp(z, s[2]); });
  } else {
    throw InputError("volume.field: unknown field '" + src.field +
                     "' (expected marschner_lobb, gaussian, ramp_x, ramp_y or ramp_z)");
  }
  v.source = "field " + src.field + " " + dims_text(s);
  return v;
}

Volume noise(const VolumeSource& src, int bits) {
  // Raw generator bits, not a distribution: std::uniform_int_distribution is
  // implementation-defined, and the noise must be identical on every platform.
  std::mt19937 gen(src.seed);
  Volume v;
  v.data.resize(static_cast<size_t>(src.size[0]) * src.size[1] * src.size[2]);
  for (auto& d : v.data) d = static_cast<uint16_t>(gen() >> (32 - bits));
  v.source = "noise " + dims_text(src.size) + " seed=" + std::to_string(src.seed);
  return v;
}

Volume constant(const VolumeSource& src, int bits) {
  check_unit(src.value, "volume.value");
  Volume v;
  v.data.assign(static_cast<size_t>(src.size[0]) * src.size[1] * src.size[2],
                quantise_value(src.value, {0, 1}, bits));
  v.source = "constant " + dims_text(src.size) + " value=" + num(src.value);
  return v;
}

Volume single_voxel(const VolumeSource& src, int bits) {
  check_unit(src.value, "volume.value");
  const auto& a = src.at;
  for (int k = 0; k < 3; ++k)
    if (a[k] < 0 || a[k] >= src.size[k])
      throw InputError("volume.at: (" + std::to_string(a[0]) + "," + std::to_string(a[1]) + "," +
                       std::to_string(a[2]) + ") is outside the " + dims_text(src.size) +
                       " volume");
  Volume v;
  v.data.assign(static_cast<size_t>(src.size[0]) * src.size[1] * src.size[2], 0);
  v.dim = src.size;  // index() needs the dimensions
  v.data[v.index(a[0], a[1], a[2])] = quantise_value(src.value, {0, 1}, bits);
  v.source = "single_voxel " + dims_text(src.size) + " at=(" + std::to_string(a[0]) + "," +
             std::to_string(a[1]) + "," + std::to_string(a[2]) + ") value=" + num(src.value);
  return v;
}

}  // namespace

Volume make_synthetic(const VolumeSource& src, int voxel_bits, bool header_only) {
  check_voxel_bits(voxel_bits);
  check_size(src.size);
  check_memory("volume.size", "the synthetic " + src.kind, 2.0 * static_cast<double>(src.size[0]) * src.size[1] * src.size[2],
               dims_text(src.size) + " voxels");
  Volume v;
  if (header_only) {
    v.source = src.kind + " " + dims_text(src.size);
  } else if (src.kind == "sphere")
    v = sphere(src, voxel_bits);
  else if (src.kind == "spheres")
    v = spheres(src, voxel_bits);
  else if (src.kind == "field")
    v = field(src, voxel_bits);
  else if (src.kind == "noise")
    v = noise(src, voxel_bits);
  else if (src.kind == "constant")
    v = constant(src, voxel_bits);
  else if (src.kind == "single_voxel")
    v = single_voxel(src, voxel_bits);
  else
    throw InputError("volume.kind: unknown volume kind '" + src.kind +
                     "' (synthetic kinds are sphere, spheres, field, noise, constant, single_voxel)");
  v.dim = src.size;
  v.spacing = {1, 1, 1};
  v.bits = voxel_bits;
  return v;
}

}  // namespace cube4::golden
