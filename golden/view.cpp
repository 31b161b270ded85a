#include "golden/view.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "golden/errors.hpp"

namespace cube4::golden {
namespace {

constexpr double kPi = 3.14159265358979323846;

Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

Mat3 axis_rotation(int axis, double degrees) {
  // Reduced to one turn first (exact: fmod), so that any finite angle gives
  // a rotation; -1e308 degrees in radians would overflow to -inf and NaN.
  const double turn = std::fmod(degrees, 360.0);
  const double c = std::cos(turn * kPi / 180), s = std::sin(turn * kPi / 180);
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  Mat3 r{};
  r[axis][axis] = 1;
  r[a][a] = c; r[a][b] = -s;
  r[b][a] = s; r[b][b] = c;
  return r;
}

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalised(const Vec3& v) {
  const double n = std::sqrt(dot(v, v));
  return {v[0] / n, v[1] / n, v[2] / n};
}

std::string scene_name(const Scene& s) { return s.file.empty() ? std::string("scene") : s.file; }

std::string show(const Vec3& v) {
  std::ostringstream o;
  o << '[' << v[0] << ',' << v[1] << ',' << v[2] << ']';
  return o.str();
}

std::string show(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

// The perspective camera: the eye, and the checks that Cube-4's slice
// order and box filter hold for it. Rays run from the eye towards +z
// (permuted), so the eye must lie in front of the front face; the rays of
// the last sample slice are 1 + z/d voxels apart (d: the eye's distance in
// front of the face), which the box filter's three extra stages cover up
// to 3 voxels (docs/perspective.md).
void place_eye(const Scene& s, const Volume& vol, double radius, ViewFactorisation& f) {
  const double half = s.view.fov / 2 * kPi / 180;
  f.perspective = true;
  f.pixel_tan = 2 * std::tan(half) / s.view.zoom / s.height;
  std::string key;
  if (s.view.eye) {
    f.eye_object = *s.view.eye;
    double d2 = 0;
    for (int i = 0; i < 3; ++i) d2 += std::pow((f.look_at[i] - f.eye_object[i]) * vol.spacing[i], 2);
    f.eye_distance = std::sqrt(d2);
    key = "\"view.eye\" = " + show(*s.view.eye);
  } else {
    // By default the volume's bounding sphere just fits the field of view,
    // unless that brings the eye nearer than the box filter allows (a deep
    // volume, a wide field): then the eye stays at that limit.
    const double depth = f.pdim[2] - 1.0 / s.supersampling;
    const double nearest = (depth / 2 + f.to_permuted(f.look_at)[2]) / std::fabs(f.view_dir_voxel[f.perm[2]]);
    f.eye_distance = s.view.distance ? *s.view.distance : std::max(radius / std::sin(half), nearest * (1 + 1e-9));
    for (int i = 0; i < 3; ++i) f.eye_object[i] = f.look_at[i] - f.view_dir_object[i] * f.eye_distance / vol.spacing[i];
    key = s.view.distance ? "\"view.distance\" = " + show(*s.view.distance)
                          : "the default \"view.distance\" (" + show(f.eye_distance) + ", from \"view.fov\")";
  }
  bool inside = true;
  for (int i = 0; i < 3; ++i) inside = inside && f.eye_object[i] >= 0 && f.eye_object[i] <= vol.dim[i] - 1;
  if (inside) throw InputError(scene_name(s) + ": " + key + " puts the eye inside the volume");
  const double front = -f.eye_permuted()[2];  // eye in front of the front face, permuted voxels
  const double depth = f.pdim[2] - 1.0 / s.supersampling;  // of the last sample slice
  const double need = depth / 2;
  if (!(front > 0))
    throw InputError(scene_name(s) + ": " + key + " puts the eye level with or behind the volume's front face (axis " +
                     "xyz"[f.perm[2]] + "): the rays must enter through it; move the eye back at least " +
                     show(need - front) + " voxels");
  if (!(front >= need))
    throw InputError(scene_name(s) + ": " + key + " puts the eye " + show(front) +
                     " voxels in front of the volume's front face (axis " + "xyz"[f.perm[2]] +
                     "); the last slice's rays would be " + show(1 + depth / std::max(front, 1e-9)) +
                     " voxels apart, and Cube-4's box filter covers at most 3: the eye must be at least " +
                     show(need) + " voxels in front");
}

}  // namespace

Affine2 Affine2::inverse() const {
  const double det = m[0] * m[4] - m[1] * m[3];
  Affine2 r;
  r.m = {m[4] / det, -m[1] / det, 0, -m[3] / det, m[0] / det, 0};
  r.m[2] = -(r.m[0] * m[2] + r.m[1] * m[5]);
  r.m[5] = -(r.m[3] * m[2] + r.m[4] * m[5]);
  return r;
}

Mat3 rotation_looking(const Vec3& direction, const Vec3& up) {
  const Vec3 z = normalised({-direction[0], -direction[1], -direction[2]});
  Vec3 x = cross(up, z);
  if (dot(x, x) < 1e-20) throw InputError("view.up is parallel to the viewing direction");
  x = normalised(x);
  return {x, cross(z, x), z};
}

// Rows of the result are the world axes in object coordinates.
Mat3 rotation_of(const View& v) {
  if (v.direction) return rotation_looking(*v.direction, v.up);
  // Object to world: about x first, then y, then z.
  return multiply(axis_rotation(2, v.rotate[2]),
                  multiply(axis_rotation(1, v.rotate[1]), axis_rotation(0, v.rotate[0])));
}

ViewFactorisation factorise_view(const Scene& s, const Volume& vol) {
  ViewFactorisation f;
  if (s.view.look_at) {
    f.look_at = *s.view.look_at;
  } else {
    for (int i = 0; i < 3; ++i) f.look_at[i] = (vol.dim[i] - 1) / 2.0;
  }
  if (s.view.eye) {
    Vec3 d{};
    for (int i = 0; i < 3; ++i) d[i] = (f.look_at[i] - (*s.view.eye)[i]) * vol.spacing[i];
    if (!(dot(d, d) > 0))
      throw InputError(scene_name(s) + ": \"view.eye\" = " + show(*s.view.eye) +
                       " is the point looked at (\"view.look_at\"); the eye must be away from it");
    f.object_to_world = rotation_looking(d, s.view.up);
  } else {
    f.object_to_world = rotation_of(s.view);
  }
  f.spacing = vol.spacing;
  f.image_width = s.width;
  f.image_height = s.height;
  f.window = s.view.window;
  for (int i = 0; i < 3; ++i) f.view_dir_object[i] = -f.object_to_world[2][i];
  for (int i = 0; i < 3; ++i) f.view_dir_voxel[i] = f.view_dir_object[i] / vol.spacing[i];

  // The principal axis is chosen in voxel-index space, where the rays step:
  // that is what keeps the shear within one voxel per slice for anisotropic
  // spacing (choosing it in isotropic space would not).
  const Vec3& d = f.view_dir_voxel;
  int c = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(d[i]) > std::fabs(d[c])) c = i;
  f.perm = {(c + 1) % 3, (c + 2) % 3, c};
  Vec3 dp{};
  for (int i = 0; i < 3; ++i) {
    const double di = d[f.perm[i]];
    f.flip[i] = di < 0;
    dp[i] = std::fabs(di);
    f.pdim[i] = vol.dim[f.perm[i]];
  }
  f.shear_x = std::min(1.0, dp[0] / dp[2]);
  f.shear_y = std::min(1.0, dp[1] / dp[2]);
  const Vec3 e = normalised(dp);
  f.eye_perm = {-e[0], -e[1], -e[2]};

  double diag2 = 0;
  for (int i = 0; i < 3; ++i) diag2 += std::pow(vol.dim[i] * vol.spacing[i], 2);
  f.pixel_size = std::sqrt(diag2) / std::min(s.width, s.height) / s.view.zoom;
  if (s.view.perspective()) place_eye(s, vol, std::sqrt(diag2) / 2, f);
  return f;
}

Vec3 ViewFactorisation::to_permuted(const Vec3& o) const {
  Vec3 p{};
  for (int i = 0; i < 3; ++i) {
    const double v = o[perm[i]];
    p[i] = flip[i] ? (pdim[i] - 1) - v : v;
  }
  return p;
}

Vec3 ViewFactorisation::to_object(const Vec3& p) const {
  Vec3 o{};
  for (int i = 0; i < 3; ++i) o[perm[i]] = flip[i] ? (pdim[i] - 1) - p[i] : p[i];
  return o;
}

Vec3 ViewFactorisation::direction_to_object(const Vec3& p) const {
  Vec3 o{};
  for (int i = 0; i < 3; ++i) o[perm[i]] = flip[i] ? -p[i] : p[i];
  return o;
}

std::array<double, 2> ViewFactorisation::image_of(const Vec3& ov) const {
  if (perspective) {
    Vec3 phys{};
    for (int i = 0; i < 3; ++i) phys[i] = (ov[i] - eye_object[i]) * spacing[i];
    const double depth = dot(view_dir_object, phys);
    return image_point(dot(object_to_world[0], phys) / depth, dot(object_to_world[1], phys) / depth);
  }
  const Vec3& c = look_at;
  Vec3 phys{};
  for (int i = 0; i < 3; ++i) phys[i] = (ov[i] - c[i]) * spacing[i];
  return image_point(dot(object_to_world[0], phys), dot(object_to_world[1], phys));
}

Vec3 ViewFactorisation::object_of_image(double X, double Y) const {
  const auto [wx, wy] = view_plane(X, Y);
  const Vec3& c = look_at;
  Vec3 o{};
  for (int i = 0; i < 3; ++i)
    o[i] = (object_to_world[0][i] * wx + object_to_world[1][i] * wy) / spacing[i] + c[i];
  return o;
}

Affine2 ViewFactorisation::base_to_image(double shift_x, double shift_y) const {
  auto at = [&](double u, double v) { return image_of(to_object({u - shift_x, v - shift_y, 0})); };
  const auto p0 = at(0, 0), pu = at(1, 0), pv = at(0, 1);
  Affine2 a;
  a.m = {pu[0] - p0[0], pv[0] - p0[0], p0[0], pu[1] - p0[1], pv[1] - p0[1], p0[1]};
  return a;
}

}  // namespace cube4::golden

namespace cube4::golden {

ViewFactorisation::Ray ViewFactorisation::ray_of_image(double X, double Y) const {
  Ray r;
  if (!perspective) {
    r.origin = object_of_image(X, Y);
    for (int i = 0; i < 3; ++i) r.direction[i] = view_dir_object[i] / spacing[i];
    return r;
  }
  const auto [tx, ty] = view_plane(X, Y);
  Vec3 d{};
  for (int i = 0; i < 3; ++i) d[i] = view_dir_object[i] + tx * object_to_world[0][i] + ty * object_to_world[1][i];
  d = normalised(d);
  r.origin = eye_object;
  for (int i = 0; i < 3; ++i) r.direction[i] = d[i] / spacing[i];
  return r;
}

std::optional<std::array<double, 2>> ViewFactorisation::base_of_image(double X, double Y, double shift_x,
                                                                      double shift_y) const {
  if (!perspective) {
    const auto uv = base_to_image(shift_x, shift_y).inverse().apply(X, Y);
    return uv;
  }
  const Ray r = ray_of_image(X, Y);
  const Vec3 o = to_permuted(r.origin);
  Vec3 d{};
  for (int i = 0; i < 3; ++i) d[i] = flip[i] ? -r.direction[perm[i]] : r.direction[perm[i]];
  if (!(d[2] > 0)) return std::nullopt;
  const double t = -o[2] / d[2];
  return std::array<double, 2>{o[0] + t * d[0] + shift_x, o[1] + t * d[1] + shift_y};
}

}  // namespace cube4::golden

namespace cube4::golden {

// The whole view spans [-1, 1] in both axes at one view-plane unit per
// pixel (pixel_size or pixel_tan); the window picks the part the image shows.
namespace {
constexpr std::array<double, 4> kWholeView{-1, -1, 1, 1};
}  // namespace

// Without a window the arithmetic is the one images were always made with,
// so that no default image moves by a rounding.
std::array<double, 2> ViewFactorisation::view_plane(double X, double Y) const {
  const double unit = perspective ? pixel_tan : pixel_size;
  if (window == kWholeView) return {(X - image_width / 2.0 + 0.5) * unit, -(Y - image_height / 2.0 + 0.5) * unit};
  const double hx = image_width / 2.0 * unit, hy = image_height / 2.0 * unit;
  const double fx = (X + 0.5) / image_width, fy = (Y + 0.5) / image_height;
  return {(window[0] + fx * (window[2] - window[0])) * hx, (window[3] - fy * (window[3] - window[1])) * hy};
}

std::array<double, 2> ViewFactorisation::image_point(double wx, double wy) const {
  const double unit = perspective ? pixel_tan : pixel_size;
  if (window == kWholeView) return {image_width / 2.0 - 0.5 + wx / unit, image_height / 2.0 - 0.5 - wy / unit};
  const double hx = image_width / 2.0 * unit, hy = image_height / 2.0 * unit;
  return {(wx / hx - window[0]) / (window[2] - window[0]) * image_width - 0.5,
          (window[3] - wy / hy) / (window[3] - window[1]) * image_height - 0.5};
}

}  // namespace cube4::golden
