// The integer register values: the one interface between the host (which
// may use floating point) and the hardware (which never does). The golden
// fixed-point renderer and the RTL consume exactly these.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "golden/precision.hpp"
#include "golden/units/shade_classify.hpp"
#include "golden/units/composite.hpp"
#include "golden/units/composite_crop.hpp"
#include "golden/units/composite_cut_plane.hpp"
#include "golden/units/composite_window.hpp"
#include "golden/units/dda.hpp"
#include "golden/units/dda_perspective.hpp"
#include "golden/units/gradient.hpp"
#include "golden/units/shade_phong.hpp"
#include "golden/units/shade_reflection.hpp"

namespace cube4::golden {

struct Registers {
  Precision p;
  // Address generation: permuted axis i walks object axis perm[i], backwards if flip[i].
  std::array<int, 3> dim{0, 0, 0};  // permuted nx, ny, nz
  std::array<int, 3> perm{0, 1, 2};
  std::array<bool, 3> flip{false, false, false};
  int supersampling = 1;
  // Ray-offset DDA, dda_frac_bits of fraction, per sample slice. In
  // perspective: the position of ray 0 on each sample slice.
  int64_t x_start = 0, x_step = 0, y_start = 0, y_step = 0;
  // Perspective (Cube-4 §3, golden/units/dda_perspective.hpp): the rays'
  // spacing on sample slice k is scale_start + k * scale_step (dda_frac_bits
  // of fraction; scale_start is one: the base plane's pixel pitch).
  bool perspective = false;
  int64_t scale_start = 0, scale_step = 0;
  // Tables.
  std::vector<ClassEntry> classification;  // 2^(tag_bits + voxel_bits) entries, address {tag, value}
  std::vector<uint16_t> gm_lut;            // 2^magnitude_bits entries, gmlut_bits wide
  std::vector<uint32_t> diffuse_map;       // 6 * map_face_res^2, map_bits wide
  std::vector<uint32_t> specular_map;
  ShadeCoefs coefs;
  // With tags and shading: the material of each tag, 2^tag_bits entries
  // (entry 0 = coefs); empty otherwise, and every sample uses coefs.
  std::vector<ShadeCoefs> tag_coefs;
  Eye eye{0, 0, 0};
  // Mode bits: decided by the scene's effect set.
  bool gradient = false, magnitude = false, shading = false, specular = false;
  bool gm_opacity = false, gm_diffuse = false, gm_specular = false;
  ZGradient z_gradient = ZGradient::Abc;  // the gradient unit's z method (units/gradient.hpp)
  BlendMode blend = BlendMode::Composite;
  bool crop_enabled = false;
  CropRegs crop;
  bool cut_enabled = false;
  CutRegs cut;
  // Set only for a block of a partitioned volume (golden/blocks.hpp).
  bool window_enabled = false;
  WindowRegs window;

  // Cube-5 polygons (golden/polygons.hpp): base-plane pixels added before
  // (lo) and after (hi) the volume's footprint in u and v, so that polygons
  // beside the volume have rays too. Zero without polygons.
  std::array<int, 2> margin_lo{0, 0}, margin_hi{0, 0};

  const ShadeCoefs& coefs_of(uint32_t tag) const { return tag_coefs.empty() ? coefs : tag_coefs[tag]; }
  // Values per tag in the classification table (2^voxel_bits when it is whole).
  size_t class_values() const { return classification.size() >> p.tag_bits; }
  // Whether value v is visible (α != 0) under some tag: what value-range
  // empty-space skipping may use without knowing the tags.
  bool value_visible(size_t v) const {
    for (size_t t = 0, n = class_values(); t < classification.size(); t += n)
      if (classification[t + v].a != 0) return true;
    return false;
  }

  int sample_slices() const { return dim[2] * supersampling; }
  SliceOffset x_offset(int k) const {
    return dda_split(dda_position(x_start, x_step, k), p.dda_frac_bits, p.weight_bits);
  }
  SliceOffset y_offset(int k) const {
    return dda_split(dda_position(y_start, y_step, k), p.dda_frac_bits, p.weight_bits);
  }
  // Base plane: one pixel per ray; rays enter through the front or a side face.
  // The sample (x, y) of slice k lies on the ray of pixel
  // (x - ix_k + base_origin_x(), y - iy_k + base_origin_y()).
  int base_origin_x() const {
    return margin_lo[0] + (perspective ? -rays_entering(0).lo : x_offset(sample_slices() - 1).integer);
  }
  int base_origin_y() const {
    return margin_lo[1] + (perspective ? -rays_entering(1).lo : y_offset(sample_slices() - 1).integer);
  }
  int base_width() const {
    return base_origin_x() + (perspective ? static_cast<int>(rays_entering(0).hi) : dim[0]) + margin_hi[0];
  }
  int base_height() const {
    return base_origin_y() + (perspective ? static_cast<int>(rays_entering(1).hi) : dim[1]) + margin_hi[1];
  }

  // Perspective: the rays' spacing and ray 0's position on sample slice k.
  int64_t ray_spacing(int k) const { return dda_position(scale_start, scale_step, k); }
  int64_t ray0(int axis, int k) const {
    return axis == 0 ? dda_position(x_start, x_step, k) : dda_position(y_start, y_step, k);
  }
  RayRange rays_in_slice(int axis, int k) const {
    return rays_inside(ray0(axis, k), ray_spacing(k), dim[static_cast<size_t>(axis)], p.dda_frac_bits);
  }
  // Every ray that samples some slice along `axis`: the union of the first
  // and last slices' ranges (the bounds move monotonically with k).
  RayRange rays_entering(int axis) const {
    const RayRange a = rays_in_slice(axis, 0), b = rays_in_slice(axis, sample_slices() - 1);
    if (b.empty()) return a;
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
  }
};

// Registers whose precision is the default one, known at compile time: its
// `p` hides Registers::p, so a renderer's loops instantiated for this type
// (the unit functions of golden/pipeline.hpp and the compositor are
// templates on the registers' type) fold every width to a constant and
// drop the shifts, branches and loops that run-time widths cost, with the
// same functions and so the same bits. Only for registers whose own
// precision is the default (has_default_precision()).
struct DefaultPrecisionRegisters : Registers {
  static constexpr Precision p{};
  explicit DefaultPrecisionRegisters(const Registers& r) : Registers(r) {
    if (!has_default_precision(r))
      throw std::logic_error("DefaultPrecisionRegisters: the registers' precision is not the default");
  }
  static bool has_default_precision(const Registers& r) { return first_difference(r.p, Precision{}) == nullptr; }
};

// The view's DDA registers as the machine is built for them. Parallel: rays
// move forwards by at most one voxel a sample slice (0 <= step <= 1.0: the
// view's permutation and flips make every shear so, and the compositor's
// rays move at most one cell a slice) from a start at or past 0 (a block's
// start is its first slice's offset); outside that the base plane's origin
// and the rays leaving through a side face are not what the renderers
// assume (a negative step read and wrote outside the ray memory).
// Perspective: ray 0's position on every slice within ±2^61 (|start| +
// |step|·(K − 1), in 128 bits), so that no sum of the DDA, no ray's
// position and no ray index times the spacing overflows 64 bits. Returns
// the first field outside ("x_start", "x_step", "y_start", "y_step"), or
// nullptr.
inline const char* dda_out_of_range(const Registers& r) {
  if (r.perspective) {
    const __int128 bound = __int128{1} << 61;
    const __int128 k = r.sample_slices() > 0 ? r.sample_slices() - 1 : 0;
    auto magnitude = [](int64_t v) { return v < 0 ? -__int128{v} : __int128{v}; };
    if (magnitude(r.x_start) > bound) return "x_start";
    if (magnitude(r.x_start) + magnitude(r.x_step) * k > bound) return "x_step";
    if (magnitude(r.y_start) > bound) return "y_start";
    if (magnitude(r.y_start) + magnitude(r.y_step) * k > bound) return "y_step";
    return nullptr;
  }
  const int64_t one = int64_t{1} << r.p.dda_frac_bits;
  if (r.x_start < 0) return "x_start";
  if (r.x_step < 0 || r.x_step > one) return "x_step";
  if (r.y_start < 0) return "y_start";
  if (r.y_step < 0 || r.y_step > one) return "y_step";
  return nullptr;
}

// dda_out_of_range() as an error naming the field and its value.
inline void check_dda(const Registers& r) {
  const char* field = dda_out_of_range(r);
  if (!field) return;
  const std::string f = field;
  const int64_t v = f == "x_start" ? r.x_start : f == "x_step" ? r.x_step : f == "y_start" ? r.y_start : r.y_step;
  const std::string range = r.perspective ? "ray 0 within 2^41 voxels of the volume's origin on every slice"
                            : f.find("step") != std::string::npos ? "0 to 1 voxel a sample slice"
                                                                   : "0 or more voxels";
  throw std::invalid_argument("registers: " + f + " = " + std::to_string(v) + " (" +
                              std::to_string(static_cast<double>(v) / static_cast<double>(int64_t{1} << r.p.dda_frac_bits)) +
                              " voxels) is outside what a " + (r.perspective ? "perspective" : "parallel") +
                              " view takes: " + range);
}

}  // namespace cube4::golden
