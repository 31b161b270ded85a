// Gradient estimators compared in Towards-scalable §3 (its Fig. 2), for a
// study, not for the pipeline: ABC gradients from 6, 10, 12 and 26 samples
// of the sheared sample slices, and zero-order central differences of the
// voxels. Each is written once over an arithmetic M: FixedGradientMath
// rounds and saturates as gradient_component() does, RealGradientMath is
// the float model's exact arithmetic. Definitions: docs/fixed-point.md,
// "Gradient neighbourhoods (study)".
#pragma once
#include <array>
#include <cmath>
#include <cstdint>

#include "golden/precision.hpp"
#include "golden/units/gradient.hpp"
#include "golden/units/interp.hpp"

namespace cube4::golden {

struct FixedGradientMath {
  using Value = int64_t;
  using Weight = uint32_t;
  using Component = int32_t;
  Precision p;
  Value lerp(Value a, Value b, Weight w) const { return golden::lerp(a, b, w, p.weight_bits); }
  bool upper(Weight w) const { return upper_corner(w, p.weight_bits) == 1; }
  Weight one() const { return Weight{1} << p.weight_bits; }
  // a + u·(b − a) + v·(c − a) with u + v <= 1, rounded once, half up, as
  // lerp() rounds; a convex combination, so it needs no saturation.
  Value triangle(Value a, Value b, Value c, Weight u, Weight v) const {
    const int w = p.weight_bits;
    return a + (((b - a) * u + (c - a) * v + (Value{1} << (w - 1))) >> w);
  }
  // A full difference summed over 2^extra_shift weights: one rounding.
  Component component(int64_t full, int extra_shift = 0) const {
    Precision q = p;
    q.gradient_shift += extra_shift;
    return gradient_component(full, q);
  }
};

struct RealGradientMath {
  using Value = double;
  using Weight = double;
  using Component = double;
  Precision p;
  Value lerp(Value a, Value b, Weight w) const { return a + w * (b - a); }
  bool upper(Weight w) const { return w >= 0.5; }  // ties up, as upper_corner()
  Weight one() const { return 1.0; }
  Value triangle(Value a, Value b, Value c, Weight u, Weight v) const { return a + u * (b - a) + v * (c - a); }
  Component component(double full, int extra_shift = 0) const {
    return std::ldexp(full, -(p.gradient_shift + extra_shift));
  }
};

// Where the point straight behind (or ahead of) a sample lies in the
// neighbouring slice's grid: x + base + weight (realign() for fixed point).
template <class Weight>
struct Alignment {
  int32_t base = 0;
  Weight weight{};
};
inline Alignment<double> realign_real(double frac_here, double frac_there) {
  const double d = frac_here - frac_there, base = std::floor(d);
  return {static_cast<int32_t>(base), d - base};
}

template <class Weight>
struct SliceAlignment {
  Alignment<Weight> behind_x, behind_y, ahead_x, ahead_y;
  int supersampling = 1;
};

template <class M>
using GradientOf = std::array<typename M::Component, 3>;

// The three ways of reading the value straight behind/ahead from the 2x2
// samples around it: nearest (6-neighbourhood), the triangle of the three
// nearest (10), bilinear (12, abc_sample()'s order: x, then y).
struct StraightNearest {
  template <class M, class Plane>
  typename M::Value operator()(const M& m, const Plane& s, int x, int y, const Alignment<typename M::Weight>& ax,
                               const Alignment<typename M::Weight>& ay) const {
    return s.at(x + ax.base + m.upper(ax.weight), y + ay.base + m.upper(ay.weight));
  }
};

struct StraightTriangle {
  // The corner nearest the point, and its neighbours across x and y: the
  // point lies in their triangle (the square's other half holds the corner
  // opposite), at local coordinates u, v from the nearest corner.
  template <class M, class Plane>
  typename M::Value operator()(const M& m, const Plane& s, int x, int y, const Alignment<typename M::Weight>& ax,
                               const Alignment<typename M::Weight>& ay) const {
    const bool ux = m.upper(ax.weight), uy = m.upper(ay.weight);
    const int nx = x + ax.base + ux, ny = y + ay.base + uy;
    const int sx = ux ? -1 : 1, sy = uy ? -1 : 1;
    const auto u = ux ? m.one() - ax.weight : ax.weight, v = uy ? m.one() - ay.weight : ay.weight;
    return m.triangle(s.at(nx, ny), s.at(nx + sx, ny), s.at(nx, ny + sy), u, v);
  }
};

struct StraightBilinear {
  template <class M, class Plane>
  typename M::Value operator()(const M& m, const Plane& s, int x, int y, const Alignment<typename M::Weight>& ax,
                               const Alignment<typename M::Weight>& ay) const {
    const int bx = x + ax.base, by = y + ay.base;
    return m.lerp(m.lerp(s.at(bx, by), s.at(bx + 1, by), ax.weight),
                  m.lerp(s.at(bx, by + 1), s.at(bx + 1, by + 1), ax.weight), ay.weight);
  }
};

// ABC gradient of sample (x, y) of the current slice: x and y central
// differences in it, z the difference of the values straight ahead and
// behind (scaled by S, as gradient_12n()). With StraightBilinear it is
// gradient_12n() on abc_sample()'s values.
template <class Straight, class M, class Plane>
GradientOf<M> abc_gradient(const M& m, const Plane& behind, const Plane& current, const Plane& ahead, int x, int y,
                           const SliceAlignment<typename M::Weight>& a) {
  using V = typename M::Value;
  const Straight straight;
  const V b = straight(m, behind, x, y, a.behind_x, a.behind_y);
  const V f = straight(m, ahead, x, y, a.ahead_x, a.ahead_y);
  return {m.component(V(current.at(x + 1, y)) - V(current.at(x - 1, y))),
          m.component(V(current.at(x, y + 1)) - V(current.at(x, y - 1))), m.component((f - b) * a.supersampling)};
}

// 26-neighbourhood: the 3x3x3 block of samples around the sample; in the
// slices behind and ahead the 3x3 around the point straight behind/ahead,
// each read with `Straight`. With StraightNearest that is the 3x3 centred on
// the sample nearest the point, 8 + 9 + 9 samples; StraightBilinear reads
// 4x4 per slice (8 + 16 + 16 = 40 samples). Each axis: a 3D Sobel
// difference, weights (2 − |i|)(2 − |j|) across it, 16 in all, rounded once.
template <class Straight, class M, class Plane>
GradientOf<M> gradient_3x3x3(const M& m, const Plane& behind, const Plane& current, const Plane& ahead, int x, int y,
                             const SliceAlignment<typename M::Weight>& a) {
  using V = typename M::Value;
  const Straight straight;
  auto at = [&](int i, int j, int k) -> V {  // offsets in x, y, slice
    if (k < 0) return straight(m, behind, x + i, y + j, a.behind_x, a.behind_y);
    if (k > 0) return straight(m, ahead, x + i, y + j, a.ahead_x, a.ahead_y);
    return current.at(x + i, y + j);
  };
  V gx = 0, gy = 0, gz = 0;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j) {
      const int w = (2 - std::abs(i)) * (2 - std::abs(j));
      gx += w * (at(1, i, j) - at(-1, i, j));
      gy += w * (at(i, 1, j) - at(i, -1, j));
      gz += w * (at(i, j, 1) - at(i, j, -1));
    }
  return {m.component(gx, 4), m.component(gy, 4), m.component(gz * a.supersampling, 4)};
}

// Zero-order central differences: of the voxels around the voxel nearest to
// the sample at (x + wx, y + wy, z + wz); no interpolation at all.
template <class M, class Voxels>
GradientOf<M> gradient_zero_order(const M& m, const Voxels& v, int x, int y, int z, typename M::Weight wx,
                                  typename M::Weight wy, typename M::Weight wz) {
  using V = typename M::Value;
  const int X = x + m.upper(wx), Y = y + m.upper(wy), Z = z + m.upper(wz);
  return {m.component(V(v.at(X + 1, Y, Z)) - V(v.at(X - 1, Y, Z))),
          m.component(V(v.at(X, Y + 1, Z)) - V(v.at(X, Y - 1, Z))),
          m.component(V(v.at(X, Y, Z + 1)) - V(v.at(X, Y, Z - 1)))};
}

}  // namespace cube4::golden
