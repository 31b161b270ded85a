// Cube-4's perspective projection (§3) as one pipeline does it: the
// per-slice constants the weight generator makes from the registers, and
// the per-sample steps built from the unit functions (dda_perspective,
// interp_box, gradient). render_fixed() runs render_perspective() for
// registers with `perspective` set; docs/perspective.md is the prose.
#pragma once
#include <cstdint>

#include "golden/pipeline.hpp"
#include "golden/units/dda_perspective.hpp"
#include "golden/units/interp_box.hpp"

namespace cube4::golden {

// What the weight generator computes once per sample slice.
struct PerspectiveSlice {
  int k = 0;
  int z_voxel = 0;                 // voxel slices z_voxel and z_voxel + 1 ...
  uint32_t wz = 0;                 // ... and the lerp weight between them
  int64_t spacing = 0;             // rays' spacing m_k
  int64_t ray0_x = 0, ray0_y = 0;  // ray 0's position c_k
  RayRange rays_x, rays_y;         // rays sampling the slice (register ray indices)
  uint64_t box_reciprocal = 0;     // round(2^Q / extent^2)
  int64_t lateral_reciprocal = 0;  // gradient x/y scale, 1 / m_k
  RealignDda behind_x, behind_y, ahead_x, ahead_y;  // straight behind/ahead, in slices k -/+ 1's rays
};

inline PerspectiveSlice perspective_slice(const Registers& r, int k) {
  const Precision& p = r.p;
  const int F = p.dda_frac_bits;
  PerspectiveSlice s;
  s.k = k;
  s.z_voxel = z_voxel_slice(k, r.supersampling);
  s.wz = z_weight(k, r.supersampling, p.weight_bits);
  s.spacing = r.ray_spacing(k);
  s.ray0_x = r.ray0(0, k);
  s.ray0_y = r.ray0(1, k);
  s.rays_x = r.rays_in_slice(0, k);
  s.rays_y = r.rays_in_slice(1, k);
  s.box_reciprocal = box_reciprocal(box_extent(s.spacing, F, p.weight_bits), box_recip_bits(p));
  s.lateral_reciprocal = lateral_reciprocal(s.spacing, F, lateral_recip_bits(p));
  // Slices outside the volume have no samples; their realignment is unused.
  const int K = r.sample_slices();
  if (k > 0) {
    s.behind_x = realign_dda(s.ray0_x, s.spacing, r.ray0(0, k - 1), r.ray_spacing(k - 1), F);
    s.behind_y = realign_dda(s.ray0_y, s.spacing, r.ray0(1, k - 1), r.ray_spacing(k - 1), F);
  }
  if (k + 1 < K) {
    s.ahead_x = realign_dda(s.ray0_x, s.spacing, r.ray0(0, k + 1), r.ray_spacing(k + 1), F);
    s.ahead_y = realign_dda(s.ray0_y, s.spacing, r.ray0(1, k + 1), r.ray_spacing(k + 1), F);
  }
  return s;
}

// Whether ray (u, v) samples the slice.
inline bool samples(const PerspectiveSlice& s, int64_t u, int64_t v) {
  return u >= s.rays_x.lo && u < s.rays_x.hi && v >= s.rays_y.lo && v < s.rays_y.hi;
}

// Ray (u, v)'s value of a field given on the voxels: box filters of the two
// voxel slices, then the z lerp. `voxel(x, y, dz)` reads voxel slice
// z_voxel + dz (0 outside) as a T.
template <class T, class Voxel>
T perspective_filtered(const Registers& r, const PerspectiveSlice& s, int64_t u, int64_t v, Voxel&& voxel) {
  const int F = r.p.dda_frac_bits, W = r.p.weight_bits;
  const BoxAxis bx = box_axis(ray_position(s.ray0_x, s.spacing, u), s.spacing, F, W);
  const BoxAxis by = box_axis(ray_position(s.ray0_y, s.spacing, v), s.spacing, F, W);
  auto filtered = [&](int dz) {
    std::array<std::array<T, 4>, 4> n{};
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) n[static_cast<size_t>(j)][static_cast<size_t>(i)] = voxel(bx.first + i, by.first + j, dz);
    return box_filter_t<T>(n, bx, by, s.box_reciprocal, box_recip_bits(r.p));
  };
  const T lo = filtered(0);
  return s.wz == 0 ? lo : static_cast<T>(lerp(lo, filtered(1), s.wz, W));
}

// The sample of ray (u, v).
template <class Voxel>
uint32_t perspective_sample(const Registers& r, const PerspectiveSlice& s, int64_t u, int64_t v, Voxel&& voxel) {
  return perspective_filtered<uint32_t>(r, s, u, v, voxel);
}

// The voxel whose tag ray (u, v)'s sample carries (bela's voxel tags): the
// voxel nearest the sample, in voxel slice z_voxel + dz (dz 0 or 1).
struct TagVoxel {
  int x = 0, y = 0, dz = 0;
};
inline TagVoxel perspective_tag_voxel(const Registers& r, const PerspectiveSlice& s, int64_t u, int64_t v) {
  const int F = r.p.dda_frac_bits;
  return {nearest_voxel(ray_position(s.ray0_x, s.spacing, u), F), nearest_voxel(ray_position(s.ray0_y, s.spacing, v), F),
          upper_corner(s.wz, r.p.weight_bits)};
}

// VolumePro's voxel-difference z gradient in perspective: the voxel z
// differences D(z) = V(z + 1) - V(z - 1) (voxel_z_difference()) of voxel
// slices z_voxel and z_voxel + 1 through the sample's own box filters and z
// lerp, as the parallel pipeline puts them through its trilinear weights.
// `difference(x, y, dz)` reads D of voxel slice z_voxel + dz.
template <class Difference>
int32_t perspective_z_difference(const Registers& r, const PerspectiveSlice& s, int64_t u, int64_t v,
                                 Difference&& difference) {
  return perspective_filtered<int32_t>(r, s, u, v, difference);
}

// The sample's position as the parallel pipeline's crop and cut-plane
// steps see it: column x, row y and their weights.
struct SamplePlace {
  int x = 0, y = 0;
  uint32_t wx = 0, wy = 0;
};
inline SamplePlace sample_place(const Registers& r, const PerspectiveSlice& s, int64_t u, int64_t v) {
  const int F = r.p.dda_frac_bits, W = r.p.weight_bits;
  const SliceOffset x = dda_split(ray_position(s.ray0_x, s.spacing, u), F, W);
  const SliceOffset y = dda_split(ray_position(s.ray0_y, s.spacing, v), F, W);
  return {x.integer, y.integer, x.weight, y.weight};
}
// The parallel pipeline's slice control of a sample at that place (its
// slice, voxel slice and weights), which cropping and the cut plane read.
inline SliceControl placed_control(const PerspectiveSlice& s, const SamplePlace& place) {
  SliceControl c;
  c.k = s.k;
  c.z_voxel = s.z_voxel;
  c.wz = s.wz;
  c.wx = place.wx;
  c.wy = place.wy;
  return c;
}
// Ray (u, v)'s shaded sample on slice s, cropped and cut at its place: the
// compositor's first stages (crop_and_cut(), rtl/cube4_composite.sv).
inline ShadedSample perspective_crop_and_cut(const Registers& r, const PerspectiveSlice& s, int64_t u, int64_t v,
                                             const ShadedSample& shaded) {
  const SamplePlace place = sample_place(r, s, u, v);
  return crop_and_cut(r, placed_control(s, place), place.x, place.y, shaded);
}

// The neighbouring slice's sample straight behind (or ahead of) ray (u, v):
// bilinear between the four rays of that slice around the point.
// `sample(u, v)` reads that slice's samples (0 for rays that miss it).
template <class Sample>
uint32_t realigned_sample(const Registers& r, const RealignDda& dx, const RealignDda& dy, int64_t u, int64_t v,
                          Sample&& sample) {
  const int F = r.p.dda_frac_bits, W = r.p.weight_bits;
  const RayPoint px = realigned_ray(dx, u, F, W), py = realigned_ray(dy, v, F, W);
  return abc_sample(sample(px.ray, py.ray), sample(px.ray + 1, py.ray), sample(px.ray, py.ray + 1),
                    sample(px.ray + 1, py.ray + 1), px.weight, py.weight, W);
}

// Ray (u, v)'s gradient on slice s with the 12-neighbourhood z
// (docs/perspective.md, "Gradient"): its neighbouring rays' samples on the
// slice, and the samples straight behind and ahead realigned from the
// neighbouring slices' rays. `current(u, v)`, `behind(u, v)` and
// `ahead(u, v)` read slices k, k - 1 and k + 1 (0 for rays that miss them).
// The renderer and the gradient ring's model (systemc/tlm/
// tlm_gradient_persp.hpp) both take it from here.
template <class Current, class Behind, class Ahead>
Gradient perspective_gradient(const Registers& r, const PerspectiveSlice& s, int64_t u, int64_t v, Current&& current,
                              Behind&& behind, Ahead&& ahead) {
  return gradient_perspective(current(u - 1, v), current(u + 1, v), current(u, v - 1), current(u, v + 1),
                              realigned_sample(r, s.behind_x, s.behind_y, u, v, behind),
                              realigned_sample(r, s.ahead_x, s.ahead_y, u, v, ahead), r.supersampling,
                              s.lateral_reciprocal, r.p);
}

// Ray (u, v)'s gradient with VolumePro's z: x and y as
// perspective_gradient()'s, z its filtered voxel z difference
// (perspective_z_difference()). The renderer, the gradient unit's model
// and the system's checker take it from here.
template <class Current>
Gradient perspective_gradient_voxel_z(const Registers& r, const PerspectiveSlice& s, int64_t u, int64_t v,
                                      Current&& current, int64_t z_difference) {
  return gradient_perspective_z(current(u - 1, v), current(u + 1, v), current(u, v - 1), current(u, v + 1),
                                z_difference, s.lateral_reciprocal, r.p);
}

}  // namespace cube4::golden
