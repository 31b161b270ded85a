// View factorisation (VolumePro §2): permutation and flips so that z is the
// principal viewing axis and rays run towards +x, +y, +z; the shear of the
// rays per slice; and the affine map from base plane to final image.
// Host-side floating point: the hardware sees only the registers made from it.
#pragma once
#include <array>
#include <optional>

#include "golden/scene.hpp"
#include "golden/volume.hpp"

namespace cube4::golden {

using Mat3 = std::array<Vec3, 3>;  // rows

struct Affine2 {                    // (X, Y) = (m[0]u + m[1]v + m[2], m[3]u + m[4]v + m[5])
  std::array<double, 6> m{1, 0, 0, 0, 1, 0};
  std::array<double, 2> apply(double u, double v) const {
    return {m[0] * u + m[1] * v + m[2], m[3] * u + m[4] * v + m[5]};
  }
  Affine2 inverse() const;
};

struct ViewFactorisation {
  Mat3 object_to_world{};           // rotation only (physical object space -> world)
  Vec3 view_dir_object{};           // unit viewing direction, physical object space
  Vec3 view_dir_voxel{};            // the same in voxel-index space (not unit)
  std::array<int, 3> perm{0, 1, 2}; // permuted axis i is object axis perm[i]
  std::array<bool, 3> flip{};       // permuted axis i runs against object axis perm[i]
  std::array<int, 3> pdim{};        // volume size in permuted axes
  double shear_x = 0, shear_y = 0;  // ray movement per voxel slice, each in [0, 1]
  Vec3 eye_perm{};                  // unit vector towards the viewer, permuted voxel space
  double pixel_size = 1;            // physical size of a final-image pixel (view.zoom applied)
  Vec3 look_at{};                   // object voxel coordinates at the image centre (view.look_at)
  int image_width = 0, image_height = 0;
  std::array<double, 3> spacing{1, 1, 1};
  // Perspective (view.projection): the eye, object voxel coordinates; the
  // tangent of the angle one pixel spans at the image centre; the eye's
  // distance from look_at (physical units).
  std::array<double, 4> window{-1, -1, 1, 1};  // view.window
  bool perspective = false;
  Vec3 eye_object{};
  double pixel_tan = 0;
  double eye_distance = 0;

  // Permuted voxel coordinates of object voxel coordinates, and back.
  Vec3 to_permuted(const Vec3& object_voxel) const;
  Vec3 to_object(const Vec3& permuted_voxel) const;
  // Directions (no translation): permuted -> object voxel space.
  Vec3 direction_to_object(const Vec3& permuted) const;
  // Final-image position (pixel centres at integers) of a point in object voxel coordinates.
  std::array<double, 2> image_of(const Vec3& object_voxel) const;
  // Object voxel coordinates of the image plane point (X, Y) at depth 0 and
  // the unit step along the viewing ray in object voxel coordinates.
  Vec3 object_of_image(double X, double Y) const;
  // Base plane pixel (u, v) -> final image, for a base plane whose ray u
  // starts at permuted x = u - shift_x (likewise y). Parallel projection only.
  Affine2 base_to_image(double shift_x, double shift_y) const;

  // The ray through final-image point (X, Y): its origin (the eye in
  // perspective, the image plane point at depth 0 in parallel projection)
  // and its direction, both in object voxel coordinates, the direction per
  // physical unit of length.
  struct Ray {
    Vec3 origin, direction;
  };
  Ray ray_of_image(double X, double Y) const;
  // Where the ray through (X, Y) crosses the base plane (permuted z = 0), in
  // base-plane pixels of a base plane shifted by (shift_x, shift_y); nullopt
  // for a perspective ray that never reaches it. Both projections.
  std::optional<std::array<double, 2>> base_of_image(double X, double Y, double shift_x, double shift_y) const;
  // The eye in permuted voxel coordinates (perspective).
  Vec3 eye_permuted() const { return to_permuted(eye_object); }
  // Image point (X, Y) (pixel centres at integers) -> view-plane coordinates
  // (physical units in parallel projection, tangents in perspective), x
  // right, y up, through view.window; and back.
  std::array<double, 2> view_plane(double X, double Y) const;
  std::array<double, 2> image_point(double wx, double wy) const;
};

Mat3 rotation_of(const View& v);
// Rows: the world axes in object coordinates, for viewing direction
// `direction` (object space, any length) and image up `up`.
Mat3 rotation_looking(const Vec3& direction, const Vec3& up);
ViewFactorisation factorise_view(const Scene& s, const Volume& vol);

}  // namespace cube4::golden
