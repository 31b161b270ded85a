// The scene's optical model in floating point: transfer functions, opacity
// correction, lights. The host driver samples it into tables; the float and
// reference renderers evaluate it directly. One definition for all three.
#pragma once
#include <utility>
#include <vector>

#include "golden/mesh.hpp"
#include "golden/scene.hpp"
#include "golden/view.hpp"

namespace cube4::golden {

double eval_piecewise(const std::vector<ScalarPoint>& pts, double x);  // clamped at the ends
Vec3 eval_color(const std::vector<ColorPoint>& pts, double x);

// Opacity of a segment `ratio` times the unit length: 1 - (1 - α)^ratio.
double correct_alpha(double alpha, double ratio);

// Ray step between sample slices relative to the unit length (the smallest voxel spacing).
double sample_step_ratio(const ViewFactorisation& f, int supersampling);

// Largest gradient magnitude the hardware can represent: the GmLUT's x = 1.
double max_gradient_magnitude(const Precision& p);

struct Lighting {
  std::vector<std::pair<Vec3, double>> lights;  // unit direction towards the light (object space), intensity
  double exponent = 20;
  // Σ I·max(0, n·l) for a unit outward normal n.
  double diffuse(const Vec3& n) const;
  // Σ I·max(0, r·l)^exponent for the unit mirror direction r of the eye.
  double specular(const Vec3& r) const;
};

Lighting lighting_of(const Scene& s, const ViewFactorisation& f);

// The colour of one triangle of a polygon mesh (Cube-5), flat over the
// triangle; a, b, c in object voxel coordinates. Unlit: `color`. Lit: the
// volume's Phong model with the scene's lights and material, at the
// triangle's normal turned towards the viewer (both faces are lit: the far
// side of a translucent surface shows through it):
//   RGB = clamp((ke + kd·Σ I·max(0, n·l))·color + ks·Σ I·max(0, r·l)^exponent·specular_color, 0, 1)
// One definition for the host rasteriser and the float and reference renderers.
Vec3 polygon_color(const Scene& s, const Lighting& L, const ViewFactorisation& f, const Vec3& a, const Vec3& b,
                   const Vec3& c, const Vec3& color, bool lit);

// The float and reference renderers' walk over the meshes: every triangle of
// a mesh that draws anything (opacity > 0), with its polygon_color():
// visit(mesh, a, b, c, rgb), corners in object voxel coordinates.
template <class Visit>
void for_each_drawn_triangle(const Scene& s, const ViewFactorisation& f, const std::vector<Mesh>& meshes,
                             Visit&& visit) {
  const Lighting L = lighting_of(s, f);
  for (const Mesh& m : meshes) {
    if (!(m.opacity > 0)) continue;
    for (const auto& t : m.triangles) {
      const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
      visit(m, a, b, c, polygon_color(s, L, f, a, b, c, m.color, m.lit));
    }
  }
}

// Unit outward normal (-gradient) in physical object space from a gradient
// in permuted voxel space; zero vector if the gradient is zero.
Vec3 normal_from_permuted_gradient(const ViewFactorisation& f, const Vec3& g_perm);
// Unit direction in object space from a direction in permuted voxel space.
Vec3 object_direction(const ViewFactorisation& f, const Vec3& d_perm);

// A sample's colour (not premultiplied) and opacity.
struct ShadedF {
  Vec3 rgb{};
  double alpha = 0;
};

// The pipeline's classification, gradient-magnitude modulation and Phong
// shading of one sample in real arithmetic, in the order the units apply
// them; the reflection vector is formed from the unnormalised gradient in
// permuted voxel space, as the shading unit forms it (docs/architecture.md,
// step 7). The float and splat renderers shade every sample with it, so that
// they differ from each other only in where their samples are.
class SampleShading {
 public:
  // vmax: the largest voxel value; ratio: the length of ray a sample stands
  // for, in unit lengths (its opacity is corrected to it).
  SampleShading(const Scene& s, const ViewFactorisation& f, double vmax, double ratio);
  // v: the sample's value; g: its gradient in permuted voxel space, scaled
  // as the gradient unit scales it (zero when the scene needs none).
  // tag: the sample's tag, choosing its transfer functions and material.
  ShadedF operator()(double v, const Vec3& g, int tag = 0) const;

 private:
  const Scene& s_;
  const ViewFactorisation& f_;
  EffectSet e_;
  Lighting lighting_;
  double vmax_, gmax_, ratio_;
};

}  // namespace cube4::golden
