// One rendering pipeline's work on one sample, composed only of the unit
// functions in golden/units/: what the fixed-point renderer runs for every
// sample, and what a transaction-level model calls per transaction.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "golden/registers.hpp"
#include "golden/units/shade_classify.hpp"
#include "golden/units/composite.hpp"
#include "golden/units/composite_crop.hpp"
#include "golden/units/shade_cube_map.hpp"
#include "golden/units/composite_cut_plane.hpp"
#include "golden/units/composite_window.hpp"
#include "golden/units/dda.hpp"
#include "golden/units/gradient.hpp"
#include "golden/units/shade_magnitude.hpp"
#include "golden/units/shade_phong.hpp"
#include "golden/units/composite_ray_align.hpp"
#include "golden/units/shade_reflection.hpp"
#include "golden/units/interp.hpp"

namespace cube4::golden {

// Per-slice constants from the weight generator; they travel with the data.
struct SliceControl {
  int k = 0;                       // sample slice
  int z_voxel = 0;                 // voxel slice below the sample slice
  uint32_t wx = 0, wy = 0, wz = 0; // trilinear weights
  int ix = 0, iy = 0;              // DDA integer offsets
  int dx = 0, dy = 0;              // offset change since slice k-1 (ray alignment)
  Realign behind_x, behind_y, ahead_x, ahead_y;  // ABC re-alignment
};

inline SliceControl slice_control(const Registers& r, int k) {
  const Precision& p = r.p;
  const SliceOffset ox = r.x_offset(k), oy = r.y_offset(k);
  const SliceOffset px = r.x_offset(k - 1), py = r.y_offset(k - 1);
  const SliceOffset nx = r.x_offset(k + 1), ny = r.y_offset(k + 1);
  SliceControl c;
  c.k = k;
  c.z_voxel = z_voxel_slice(k, r.supersampling);
  c.wx = ox.weight;
  c.wy = oy.weight;
  c.wz = z_weight(k, r.supersampling, p.weight_bits);
  c.ix = ox.integer;
  c.iy = oy.integer;
  c.dx = k == 0 ? 0 : ox.integer - px.integer;
  c.dy = k == 0 ? 0 : oy.integer - py.integer;
  c.behind_x = realign(ox.weight, px.weight, p.weight_bits);
  c.behind_y = realign(oy.weight, py.weight, p.weight_bits);
  c.ahead_x = realign(ox.weight, nx.weight, p.weight_bits);
  c.ahead_y = realign(oy.weight, ny.weight, p.weight_bits);
  return c;
}

// The 12-neighbourhood of a sample (plus the sample): four in its own slice,
// and 2x2 around the re-aligned position in the slices behind and ahead
// ([0] at (base, base), [1] x+1, [2] y+1, [3] both).
// `tag` is the centre's (sample_tag()): it travels with the centre sample
// through the gradient unit, and only the classification and the material
// use it.
// With the voxel-difference z gradient, `z_difference` is the sample's
// interpolated_z_difference() and behind/ahead are not used.
struct Neighbourhood {
  uint32_t centre = 0, left = 0, right = 0, up = 0, down = 0;
  std::array<uint32_t, 4> behind{}, ahead{};
  int64_t z_difference = 0;
  uint32_t tag = 0;
};

template <class R>
inline Gradient sample_gradient(const R& r, const SliceControl& c, const Neighbourhood& n) {
  if (r.z_gradient == ZGradient::VoxelDifferences) return gradient_voxel_z(n.left, n.right, n.up, n.down, n.z_difference, r.p);
  const int w = r.p.weight_bits;
  const uint32_t behind = abc_sample(n.behind[0], n.behind[1], n.behind[2], n.behind[3],
                                     c.behind_x.weight, c.behind_y.weight, w);
  const uint32_t ahead = abc_sample(n.ahead[0], n.ahead[1], n.ahead[2], n.ahead[3],
                                    c.ahead_x.weight, c.ahead_y.weight, w);
  return gradient_12n(n.left, n.right, n.up, n.down, behind, ahead, r.supersampling, r.p);
}

// The cube-map divider's table (same values) for the registers' shading,
// or null where it does not pay: up to 10-bit gradients it holds 1 MB at
// most and is cheaper to fill than dividing per sample.
inline std::unique_ptr<FacePositionTable> make_face_table(const Registers& r) {
  if (!r.shading || r.p.gradient_bits > 10) return nullptr;
  return std::make_unique<FacePositionTable>(static_cast<int>(max_signed(r.p.gradient_bits)), r.p.map_face_res,
                                             r.p.weight_bits);
}

// What a sample's shading takes from its gradient alone: the magnitude as a
// unit value (full without the magnitude unit) and the diffuse and specular
// reflectance-map values (zero without shading, specular). Nothing else of
// the sample enters them, so a software renderer may reuse them for equal
// gradients of a frame (GradientShadingCache). `faces`, if given, replaces
// the cube-map divider by its table (same values).
struct GradientShading {
  uint32_t gm = 0, id = 0, is = 0;
};
template <class R>
inline GradientShading gradient_shading(const R& r, const Gradient& g,
                                        const FacePositionTable* faces = nullptr) {
  const Precision& p = r.p;
  GradientShading out;
  out.gm = r.magnitude ? gm_unit(r.gm_lut[gradient_magnitude(g, p)], p) : static_cast<uint32_t>(max_unsigned(p.alpha_bits));
  if (r.shading) {
    auto coords = [&](const Gradient& v) {
      return faces ? cube_coordinates_with(v.x, v.y, v.z, *faces) : cube_coordinates(v.x, v.y, v.z, p);
    };
    out.id = reflectance_lookup(r.diffuse_map, coords(g), p);
    if (r.specular) out.is = reflectance_lookup(r.specular_map, coords(reflection_vector(g, r.eye, p)), p);
  }
  return out;
}

// Classification and shading of a sample with value `centre` and tag `tag`
// whose gradient gave `gs`: the classification entry is {tag, centre}'s and
// the material the tag's.
template <class R>
inline ShadedSample shade_with(const R& r, uint32_t centre, uint32_t tag, const GradientShading& gs) {
  const Precision& p = r.p;
  const uint32_t one = static_cast<uint32_t>(max_unsigned(p.alpha_bits));
  ShadedSample out;
  out.value = centre;
  const ClassEntry& e = classify(r.classification, tag, centre, p);
  out.alpha = e.a;
  out.rgb = widen_color(e.r, e.g, e.b, p);
  if (r.gm_opacity) out.alpha = modulate_alpha(out.alpha, gs.gm, p);
  if (r.shading)
    out.rgb = phong(out.rgb, gs.id, gs.is, r.gm_diffuse ? gs.gm : one, r.gm_specular ? gs.gm : one, r.coefs_of(tag), p);
  return out;
}

// True when compositing and the sample of value `centre` and tag `tag`
// classifies to α = 0: it leaves its ray exactly as it is, whatever its
// gradient and shading (α only shrinks on the way through the pipeline,
// and blend_front_to_back adds nothing for α = 0), so a model whose
// gradient and shading streams nobody else reads may skip them.
template <class R>
inline bool sample_cannot_change_ray(const R& r, uint32_t centre, uint32_t tag) {
  return r.blend == BlendMode::Composite && classify(r.classification, tag, centre, r.p).a == 0;
}

// Magnitude, classification and shading of a sample with value `centre`,
// tag `tag` and gradient `g` (Gradient{} when the gradient unit is off): the
// shading unit's work (rtl/cube4_shade_unit.sv). Units the registers leave
// off are not evaluated at all, exactly as the hardware would skip them.
template <class R>
inline ShadedSample shade_classified(const R& r, uint32_t centre, uint32_t tag, const Gradient& g,
                                     const FacePositionTable* faces = nullptr) {
  return shade_with(r, centre, tag, gradient_shading(r, g, faces));
}

// gradient_shading() of a frame's gradients, remembered in a small direct-
// mapped table: neighbouring samples of smooth material often have equal
// gradients. Equal by construction (an entry holds the function's value for
// exactly its gradient). One per thread. R: the registers' type (Registers,
// or DefaultPrecisionRegisters for widths known at compile time).
template <class R>
class BasicGradientShadingCache {
 public:
  BasicGradientShadingCache(const R& r, const FacePositionTable* faces) : r_(r), faces_(faces), entries_(kSize) {}
  const GradientShading& operator()(const Gradient& g) {
    // Components are at most 16 bits signed: 21-bit fields keep them apart,
    // and the top bit marks a filled entry.
    auto field = [](int32_t c) { return static_cast<uint64_t>(c) & 0x1FFFFF; };
    const uint64_t key = uint64_t{1} << 63 | field(g.x) << 42 | field(g.y) << 21 | field(g.z);
    Entry& e = entries_[(key * 0x9E3779B97F4A7C15ull) >> (64 - kBits)];
    if (e.key != key) e = {key, gradient_shading(r_, g, faces_)};
    return e.value;
  }

 private:
  static constexpr int kBits = 12;
  static constexpr size_t kSize = size_t{1} << kBits;
  struct Entry {
    uint64_t key = 0;
    GradientShading value;
  };
  const R& r_;
  const FacePositionTable* faces_;
  std::vector<Entry> entries_;
};
using GradientShadingCache = BasicGradientShadingCache<Registers>;

// Cropping, the block window and the cut plane of the shaded sample at
// (x, y) of slice c.k: the compositing unit's first steps
// (rtl/cube4_composite.sv).
template <class R>
inline ShadedSample crop_and_cut(const R& r, const SliceControl& c, int x, int y, ShadedSample s) {
  if (r.crop_enabled) s.visible = crop_visible(x, y, c.z_voxel, r.crop);
  if (r.window_enabled && !window_inside(x, y, c.z_voxel, r.window)) s.visible = false;
  if (r.cut_enabled) {
    const int w = r.p.weight_bits;
    const int64_t d = cut_distance(r.cut, (int64_t{x} << w) + c.wx, (int64_t{y} << w) + c.wy,
                                   (int64_t{c.z_voxel} << w) + c.wz, r.p);
    const uint32_t f = cut_factor(d, r.cut, r.p);
    s.alpha = cut_alpha(s.alpha, f, r.p);
    if (f == 0) s.visible = false;
  }
  return s;
}

// Gradient, magnitude, classification, shading, cropping and cut plane of
// the sample at (x, y) of slice c.k: one pipeline's work on one sample.
// `shading(g)` gives gradient_shading() of the sample's gradient g.
// Flattened: with every unit function inlined, an instantiation for
// DefaultPrecisionRegisters folds all its widths (GCC otherwise keeps some,
// expand_bits and the map lookups among them, as calls with run-time widths).
template <class R, class Shading>
[[gnu::flatten]] ShadedSample shade_sample_with(const R& r, const SliceControl& c, int x, int y, const Neighbourhood& n,
                               Shading&& shading) {
  const Gradient g = r.gradient ? sample_gradient(r, c, n) : Gradient{};
  return crop_and_cut(r, c, x, y, shade_with(r, n.centre, n.tag, shading(g)));
}
template <class R>
inline ShadedSample shade_sample(const R& r, const SliceControl& c, int x, int y,
                                 const Neighbourhood& n, const FacePositionTable* faces = nullptr) {
  return shade_sample_with(r, c, x, y, n, [&](const Gradient& g) { return gradient_shading(r, g, faces); });
}

}  // namespace cube4::golden
