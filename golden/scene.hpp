// A scene as the user writes it (JSON, see docs/scene.md): everything in
// floating point and user units. The host driver turns it into registers.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "golden/precision.hpp"
#include "golden/units/gradient.hpp"

namespace cube4::golden {

using Vec3 = std::array<double, 3>;

// How input values are mapped onto [0, 2^voxel_bits - 1].
struct Quantisation {
  enum class Mode { Full, MinMax, Window } mode = Mode::Full;
  double lo = 0, hi = 0;  // Window only: input values lo..hi map to 0..max
};

struct VolumeSource {
  // "den", "raw", "nifti" (files) or "sphere", "field", "noise", "constant",
  // "single_voxel" (synthetic).
  std::string kind = "den";
  std::string path;                       // files: resolved against the scene's folder
  // raw files
  std::array<int, 3> dim{0, 0, 0};
  std::string type = "uint8";             // uint8, uint16, int16, uint32, int32, float32, float64
  std::string endian = "little";          // little, big
  uint64_t header_bytes = 0;
  // synthetic volumes
  std::array<int, 3> size{64, 64, 64};
  double radius = 0;                      // sphere; 0 = 3/8 of the smallest size
  std::optional<Vec3> center;             // sphere; default the volume centre
  std::string field = "marschner_lobb";   // field: marschner_lobb, gaussian, ramp_x, ramp_y, ramp_z
  double value = 1.0;                     // constant / single_voxel, in [0, 1]
  std::array<int, 3> at{0, 0, 0};         // single_voxel position
  uint32_t seed = 1;                      // noise
  // all
  std::optional<Vec3> spacing;            // overrides the file's spacing
  Quantisation quantisation;
};

struct View {
  Vec3 rotate{0, 0, 0};                   // degrees about x, then y, then z (object to world)
  std::optional<Vec3> direction;          // or: viewing direction in object space ...
  Vec3 up{0, 1, 0};                       // ... and the up vector
  std::array<double, 2> ray_offset{0, 0}; // sub-pixel start of rays on the base plane, [0,1)
  // The camera of the parallel projection (docs/scene.md): image scale
  // (1: the volume's diagonal fits the smaller image side) and the point of
  // the volume, in voxel coordinates, at the image centre (default: the
  // volume's centre). The hardware never sees them: only the warp of the
  // base plane and the reference ray caster do.
  double zoom = 1;
  std::optional<Vec3> look_at;
  // The part of the (zoomed) view the image shows: [x0, y0, x1, y1] in
  // [-1, 1], x right, y up (glOrtho's and glFrustum's window); the default
  // is all of it. Both projections; the hardware never sees it.
  std::array<double, 4> window{-1, -1, 1, 1};
  // Cube-4's perspective projection (docs/scene.md, docs/perspective.md):
  // the eye at `distance` (physical units) from look_at against the viewing
  // direction, or at `eye` (voxel coordinates; then the direction is
  // look_at - eye); `fov` the full vertical field of view in degrees. These
  // do reach the hardware: the rays' spread per slice is a register.
  enum class Projection { Parallel, Perspective } projection = Projection::Parallel;
  double fov = 30;
  std::optional<double> distance;
  std::optional<Vec3> eye;
  bool perspective() const { return projection == Projection::Perspective; }
};

struct ColorPoint { double x; Vec3 rgb; };     // x: normalised sample value [0,1]
struct ScalarPoint { double x; double y; };    // piecewise-linear control point

struct Light { Vec3 direction{0, 0, 1}; double intensity = 1.0; };  // towards the light, world space

struct Material {
  double ke = 0.15, kd = 0.85, ks = 0.35;
  Vec3 specular_color{1, 1, 1};
  double exponent = 20;
};

enum class Blend { Composite, Mip, MinIp };

struct GradientModulation { bool opacity = false, diffuse = false, specular = false; };

struct Cropping {
  bool enabled = false;
  std::array<std::array<int, 2>, 3> slab{{{0, 0}, {0, 0}, {0, 0}}};  // inclusive voxel ranges x, y, z
  uint8_t mask = 0x80;  // visible = bit (inX | inY<<1 | inZ<<2); 0x80 = intersection
};

struct CutPlane {
  bool enabled = false;
  Vec3 normal{0, 0, 1};       // A, B, C in object voxel coordinates (normalised by the host)
  double dmin = 0, dmax = 0;  // voxel units from the volume origin
  double falloff = 0;         // width of the linear transition, voxel units
  bool keep_inside = true;    // false: keep what is outside the slab
};

// ---- polygons (meshes; golden/mesh.hpp loads them) ----

// Local (file or shape) coordinates to volume coordinates:
//   p' = translate + R · (scale ⊙ p)
// scale first (per axis), then rotate (degrees about x, then y, then z, the
// convention of view.rotate), then translate; or `matrix` instead of all
// three: a row-major 4×4 affine matrix applied to column vectors [x y z 1].
struct MeshTransform {
  Vec3 scale{1, 1, 1};
  Vec3 rotate{0, 0, 0};
  Vec3 translate{0, 0, 0};
  std::optional<std::array<double, 16>> matrix;
};

enum class MeshShape { Box, Sphere, Cylinder, Needle, Plane };

struct MeshSpec {
  std::string key;   // where the scene gives it, for messages: "polygons[1]"
  // A file (path as written; relative paths resolve against the scene's
  // folder when loaded) or, when `file` is empty, a built-in shape.
  std::string file;
  MeshShape shape = MeshShape::Box;
  // Shape parameters in local units (docs/scene.md, "polygons"):
  Vec3 size{1, 1, 1};   // box: x, y, z; plane: x, y (z unused)
  double radius = 1;    // sphere, cylinder, needle
  double length = 1;    // cylinder, needle: along local +z from z = 0
  double tip = 0;       // needle: length of the conical tip (0 = length / 4)
  int segments = 32;    // sphere (around z), cylinder, needle: 3..1024
  int rings = 16;       // sphere: latitude bands, 2..1024
  MeshTransform transform;
  Vec3 color{1, 1, 1};  // RGB, each 0..1
  double opacity = 1;   // 0..1; 1 = opaque
  bool lit = true;      // shaded by the scene's lights (false: flat colour)
};

// ---- voxel tags (bela §III; docs/scene.md, "tags") ----

// Built-in labelling: a rule gives `tag` to the voxels it selects.
struct TagRule {
  enum class Kind { Threshold, Box, Sphere } kind = Kind::Threshold;
  std::string key;                       // where the scene gives it, for messages: "tags.label[1]"
  int tag = 0;
  std::array<double, 2> range{0, 1};     // threshold: voxel value / max value within [lo, hi]
  std::array<int, 3> lo{0, 0, 0}, hi{0, 0, 0};  // box: inclusive voxel ranges x, y, z
  Vec3 center{0, 0, 0};                  // sphere: voxel coordinates, distance <= radius
  double radius = 0;
};

// A tag's own classification and material; what it does not give is the
// scene's ("transfer", "material").
struct TagClass {
  std::string key;                      // where the scene gives it: "tags.classes[0]"
  std::optional<std::vector<ColorPoint>> color;
  std::optional<std::vector<ScalarPoint>> opacity;
  std::optional<Material> material;     // its exponent must be the scene's (one specular map)
};

struct TagSource {
  // Raw file, one unsigned byte per voxel, x fastest, the volume's size
  // (path as written; relative to the scene's folder when loaded).
  std::string file;
  std::vector<TagRule> label;            // applied after the file, in order: a later rule wins
  std::map<int, TagClass> classes;       // by tag
  bool given = false;                    // the scene has "tags"
};

// The geometry engine and the buffers that connect it to the pipelines, as
// Cube-5 §§4-6 assume them (docs/scene.md, "polygon_engine").
// How the slab images reach the pipelines in the system model's clocked
// runs (systemc/core/polygon_source.hpp): Cube-5's run-length buffer
// (§5), its dual-use DRAM buffer (§4), or at once (no polygon hardware's
// time modelled).
enum class PolygonConnection { Rle, Dual, Ideal };

struct PolygonEngine {
  PolygonConnection connection = PolygonConnection::Rle;
  double fill_rate = 180e6;       // fragments/s of the geometry engine (§6)
  double triangle_rate = 6e6;     // triangles/s of its set-up (§6)
  double dual_fill_rate = 357e6;  // pixels/s into the dual-use buffer (§4, §6)
  double rle_clock_hz = 200e6;    // the run-length buffer's flit clock (§5)
};

struct Scene {
  std::string file;  // where it was read from ("" = built in)
  VolumeSource volume;
  View view;
  int width = 256, height = 256;
  std::vector<ColorPoint> color;
  std::vector<ScalarPoint> opacity;
  std::vector<ScalarPoint> gm_lut;   // x: |g| / max |g| in [0,1]; y in [0,1]
  std::vector<Light> lights;
  Material material;
  bool shading = true;
  Blend blend = Blend::Composite;
  GradientModulation gm;
  int supersampling = 1;             // z only, 1..8
  ZGradient z_gradient = ZGradient::Abc;  // "z_gradient": "abc" | "voxel_differences"
  int xy_supersampling = 1;          // rays per base-plane pixel and axis, 1..4: n² frames blended on the host
  Cropping cropping;
  CutPlane cut;
  int pipelines = 4;
  // Sub-cubes (golden/blocks.hpp): blocks along object x, y, z, each
  // rendered by a machine of its own, merged by the composition network.
  std::array<int, 3> blocks{1, 1, 1};
  double clock_mhz = 125;
  Precision precision;
  std::vector<MeshSpec> polygons;   // docs/scene.md, "polygons"
  PolygonEngine polygon_engine;     // its rates, for the connections' times (golden/polygon_connections.hpp)
  TagSource tags;                   // used when precision.tag_bits > 0

  // Tags 0 .. tag_count() - 1 exist (one without tags).
  int tag_count() const { return 1 << precision.tag_bits; }
  const TagClass* tag_class(int tag) const {
    const auto it = tags.classes.find(tag);
    return precision.tag_bits > 0 && it != tags.classes.end() ? &it->second : nullptr;
  }
  // The transfer functions and material of samples with tag `tag`.
  const std::vector<ColorPoint>& color_of(int tag) const {
    const TagClass* c = tag_class(tag);
    return c && c->color ? *c->color : color;
  }
  const std::vector<ScalarPoint>& opacity_of(int tag) const {
    const TagClass* c = tag_class(tag);
    return c && c->opacity ? *c->opacity : opacity;
  }
  const Material& material_of(int tag) const {
    const TagClass* c = tag_class(tag);
    return c && c->material ? *c->material : material;
  }
};

// The effects a scene calls for: decides what is computed and simulated.
struct EffectSet {
  bool gradient = false;       // any use of the gradient
  bool magnitude = false;      // |g| and the GmLUT
  bool shading = false;        // reflectance maps and Phong combine
  bool specular = false;       // reflection vector and specular map
  bool cropping = false;
  bool cut_plane = false;
  bool supersampling = false;
  bool polygons = false;       // Cube-5: the Z test and the double composition (golden/polygons.hpp)
  bool tags = false;           // bela: voxel tags, {tag, value} classification, per-tag material
  Blend blend = Blend::Composite;
  std::vector<std::string> names() const;  // e.g. {"composite", "gradient", "shading", ...}
};

EffectSet effects_of(const Scene& s);

}  // namespace cube4::golden
