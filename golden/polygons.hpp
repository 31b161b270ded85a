// The host side of Cube-5's hybrid volume and polygon rendering (Kreeger
// and Kaufman 1999, §§2, 5): the scene's meshes rasterised under the
// volume's permutation and shear onto the base plane, into the integer
// images the compositor consumes (golden/polygon_frame.hpp). Host code,
// like the warp: floating point up to the vertices' snapped positions and
// the fragments' quantised colours, integers from there on.
// The rules (coverage, depth, ties, slabs) are in docs/fixed-point.md,
// "Polygons"; the scan conversion itself in golden/rasterise.hpp.
#pragma once
#include <array>
#include <vector>

#include "golden/host_driver.hpp"
#include "golden/mesh.hpp"
#include "golden/polygon_connections.hpp"
#include "golden/polygon_frame.hpp"

namespace cube4::golden {

// A renderer's rays on its base plane: the ray of pixel (u, v) passes,
// at depth d (in sample slices; permuted z = d / S), through permuted
//   x = x0 + d·sx + (u - origin_x)·w(d),   y = y0 + d·sy + (v - origin_y)·w(d),
// w(d) = 1 + d·ms the rays' spacing: 1 in parallel projection (ms = 0); in
// perspective the rays leave an eye at w = 0 (Cube-4 §3).
struct BaseFrame {
  double x0 = 0, sx = 0, y0 = 0, sy = 0;  // ray 0's (parallel: the ray offset's) position at slice 0 and its step per sample slice, voxels
  int origin_x = 0, origin_y = 0;         // base_origin_x/y(): the pixel of ray 0
  int S = 1;
  double ms = 0;                          // the spacing's growth per sample slice
  double w(double d) const { return 1 + d * ms; }
  // (u, v, d) of a point in permuted voxel coordinates (in front of the eye: w > 0).
  Vec3 to_base(const Vec3& permuted) const;
};

// In perspective, polygons are drawn where the rays' spacing is at least
// kNearSpacing (1/16 of the eye's distance to the base plane, and further):
// the near plane; the part of a triangle nearer the eye is not drawn.
// Parallel projection draws every triangle whole.
inline constexpr double kNearSpacing = 1.0 / 16;
// A triangle's corner projected onto the base plane: (u, v, d) of to_base()
// and h = 1 / w(d), what perspective-correct depth needs (golden/rasterise.hpp).
struct BaseCorner {
  Vec3 uvd{};
  double h = 1;
};
// Calls draw(const BaseCorner (&)[3]) for the part of triangle (a, b, c)
// (permuted voxel coordinates) on or beyond the near plane: once (the
// triangle itself, always so in parallel projection), twice (a clipped
// quadrilateral, split along a diagonal: the halves share it, so no pixel
// is drawn twice) or not at all.
template <class Draw>
void project_triangle(const BaseFrame& frame, const Vec3& a, const Vec3& b, const Vec3& c, Draw&& draw);
// The fixed renderer's rays: the registers' DDA, exactly (a sample's own
// position differs from it by its weights' truncation, under 2^-weight_bits),
// in perspective its rays' positions and spacing (Registers::ray0, ray_spacing).
BaseFrame base_frame(const Registers& r);

// Base-plane pixels to add before and after a width x height base plane in
// u and v, so that every mesh that draws anything (opacity > 0) has rays
// over its footprint: as far as the final image shows (the warp's inverse
// of the image's corners) and at most width (height) on each side. Parts
// beyond are not drawn.
struct Margins {
  std::array<int, 2> lo{0, 0}, hi{0, 0};
};
Margins polygon_margins(const std::vector<Mesh>& meshes, const ViewFactorisation& f, const BaseFrame& frame,
                        int width, int height);

// Refuses (InputError, naming the scene file and key) what polygons cannot
// be combined with: a blend other than composite (surfaces have no place in
// a maximum or minimum).
void check_polygon_scene(const Scene& s, const std::vector<Mesh>& meshes);

// program_host(s, vol), with the base plane grown by polygon_margins() for
// the meshes; the same registers as program_host(s, vol) without meshes.
HostProgram program_host(const Scene& s, const Volume& vol, const std::vector<Mesh>& meshes);

// The frame's polygon images for the registers of `h` (made by the
// program_host above, with these meshes). Each scene pipeline's slab
// lines are its own (lanes = s.pipelines). Throws InputError for a vertex
// beyond the rasteriser's range (±2^30 pixels or sample slices from the
// base plane's origin) of a triangle that reaches the base plane.
PolygonFrame rasterise_polygons(const Scene& s, const std::vector<Mesh>& meshes, const HostProgram& h);

// What moving a frame's polygon images costs (Cube-5 §5-6), counted from
// the frame itself. The run-length connection sends every slab line the
// decoders read (an empty slab as cleared lines, a run flit each), a flit
// per pipeline per cycle; without encoding every slab would be a full RGBA
// image of the slice. Widths are the frame's: RGBA channels alpha_bits wide
// (whole bytes), Z kZBits.
struct PolygonTraffic {
  uint64_t slabs = 0;            // one per sample slice
  uint64_t flits = 0;            // over every line of every slab
  uint64_t rle_bytes = 0;        // those lines' 16-bit words
  uint64_t raw_bytes = 0;        // every slab as a plain RGBA image, nx x ny
  uint64_t image_bytes = 0;      // front and back (RGBA) and Z, once per frame
  uint64_t slice_cycles = 0;     // a pass's beats: ny ceil(nx / p) (passes back to back)
  // Sum over slabs of max(the busiest pipeline's flits, slice_cycles):
  // Cube-5's T = sum max(flits / f_rle, slice time) for the run-length
  // connection, in cycles of the volume pipeline's clock.
  uint64_t rle_cycles = 0;
  uint64_t slabs_over_slice = 0; // slabs whose busiest pipeline needs more than slice_cycles
};
// `loads`: slab_loads(f) (golden/polygon_connections.hpp), when the caller
// has them already.
PolygonTraffic polygon_traffic(const PolygonFrame& f, const Precision& p);
PolygonTraffic polygon_traffic(const PolygonFrame& f, const std::vector<SlabLoad>& loads, const Precision& p);

// Snapped vertex positions: 1/2^kSubpixelBits of a pixel, depth in units of
// 2^-kZFracBits sample slices, both rounded half up; in perspective h = 1/w
// in units of 2^-kInverseSpacingBits, rounded half up and at least 1 unit.
inline constexpr int kSubpixelBits = 8;
inline constexpr int kInverseSpacingBits = 20;

template <class Draw>
void project_triangle(const BaseFrame& frame, const Vec3& a, const Vec3& b, const Vec3& c, Draw&& draw) {
  const auto corner = [&](const Vec3& p) {
    BaseCorner k;
    k.uvd = frame.to_base(p);
    k.h = 1 / frame.w(k.uvd[2]);
    return k;
  };
  const Vec3* in[3] = {&a, &b, &c};
  // w is affine in permuted z: its value at each vertex, less the near plane's.
  double s[3];
  int nearer = 0;
  for (int i = 0; i < 3; ++i) {
    s[i] = frame.w((*in[i])[2] * frame.S) - kNearSpacing;
    nearer += s[i] < 0;
  }
  if (nearer == 0) {
    const BaseCorner t[3] = {corner(a), corner(b), corner(c)};
    draw(t);
    return;
  }
  if (nearer == 3) return;
  // Sutherland-Hodgman against the one plane: 3 or 4 corners, in order.
  Vec3 poly[4];
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (s[i] >= 0) poly[n++] = *in[i];
    if ((s[i] < 0) != (s[j] < 0)) {
      const double t = s[i] / (s[i] - s[j]);
      Vec3 p{};
      for (int q = 0; q < 3; ++q) p[q] = (*in[i])[q] + t * ((*in[j])[q] - (*in[i])[q]);
      poly[n++] = p;
    }
  }
  const BaseCorner t0[3] = {corner(poly[0]), corner(poly[1]), corner(poly[2])};
  draw(t0);
  if (n == 4) {
    const BaseCorner t1[3] = {corner(poly[0]), corner(poly[2]), corner(poly[3])};
    draw(t1);
  }
}

}  // namespace cube4::golden
