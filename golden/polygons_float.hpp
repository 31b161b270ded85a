// The float renderers' polygons (render_float, render_float_perspective):
// the golden rasteriser's scan conversion in doubles (no snapping, exact
// depth), and per base-plane pixel the ray's translucent fragments in depth
// order and its nearest opaque one. Compositing them with the samples in
// depth order is what the fixed renderer's front, slab and back images
// arrange (golden/polygon_frame.hpp).
#pragma once
#include <cstddef>
#include <vector>

#include "golden/mesh.hpp"
#include "golden/polygons.hpp"
#include "golden/view.hpp"

namespace cube4::golden {

// A ray's accumulator in real arithmetic.
struct AccF {
  double r = 0, g = 0, b = 0, a = 0, value = 0;
  bool valid = false;
  // acc over a layer of colour c and opacity alpha behind it.
  void over(const Vec3& c, double alpha) {
    const double t = (1 - a) * alpha;
    r += t * c[0]; g += t * c[1]; b += t * c[2]; a += t;
  }
};

class PolygonsF {
 public:
  // The meshes drawn on a width x height base plane with the rays of `frame`.
  PolygonsF(const Scene& s, const std::vector<Mesh>& meshes, const ViewFactorisation& f, const BaseFrame& frame,
            int width, int height);
  // Before sample slice k of pixel i's ray: its fragments at depths up to
  // k; true if the sample lies in front of the opaque surface.
  bool before_sample(size_t i, int k, AccF& acc);
  // The ray leaves: the rest of its fragments, then the opaque surface.
  AccF leave(size_t i, AccF acc);
  bool done(size_t i) const { return done_[i]; }

 private:
  struct Hit {
    double d;
    Vec3 rgb;
    double alpha;
  };
  std::vector<std::vector<Hit>> hits_;
  std::vector<size_t> next_;
  std::vector<bool> done_;
  std::vector<double> z_;
  std::vector<Vec3> opaque_;
};

}  // namespace cube4::golden
