// Scan conversion of one triangle on the base plane (Cube-5 §2: polygons
// drawn under the volume's permutation and shear, so that their footprints
// are pre-warped and their depth is measured along the processing axis).
// Host code, like the warp. One algorithm for two arithmetics: in integers
// (T = int64_t, vertices snapped to 1/`one` of a pixel) it is the golden
// rasteriser whose fragments the hardware consumes (golden/polygons.hpp);
// in doubles (T = double, one = 1) it is the float renderer's.
//
// Rules (docs/fixed-point.md, "Polygons"):
//  - Coverage: pixel (u, v) is the ray through the base-plane point (u, v);
//    the triangle covers it iff that point lies inside the triangle's
//    footprint (u, v) = the triangle's vertices in base-plane coordinates.
//    A triangle seen edge-on (zero footprint area) covers nothing. Both
//    faces are drawn: there is no culling (a translucent surface's far side
//    shows through it).
//  - Ties: a pixel centre on an edge or a vertex belongs to the triangle it
//    would lie in after an infinitesimal move towards -u (and an even
//    smaller one towards +v, for edges parallel to u). Triangles that share
//    edges therefore cover every pixel of their union exactly once.
//  - Depth: the plane of the triangle at the pixel centre, from its three
//    vertices' depths by barycentric weights (exact: the shear keeps planes
//    planar); in integers rounded half up to the vertices' depth unit.
//    In perspective each vertex also carries h = 1/w, w the rays' spacing
//    at its depth: the projection keeps d/w and 1/w affine on the footprint
//    (not d), so the depth is perspective-correct,
//    sum(e_i h_i d_i) / sum(e_i h_i) over the barycentric weights e_i. With
//    equal h (parallel projection: h = 1) that is the affine depth exactly.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace cube4::golden {

template <class T>
struct BaseVertex {
  T u = 0, v = 0, d = 0;  // base-plane position in 1/`one` pixels; depth
  T h = 1;                // 1/w in perspective (integers: a fixed-point value >= 1); 1 in parallel projection
};

namespace raster {

template <class T>
using Wide = std::conditional_t<std::is_integral_v<T>, __int128, double>;

inline __int128 floor_div(__int128 a, __int128 b) {  // b > 0
  __int128 q = a / b;
  if (a % b != 0 && a < 0) --q;
  return q;
}

// The first and last pixel centre within [lo, hi] (units of 1/one pixel),
// clamped to [0, n - 1]; first > last when there is none.
template <class T>
void centres(T lo, T hi, T one, int n, int& first, int& last) {
  double f, l;
  if constexpr (std::is_integral_v<T>) {
    f = static_cast<double>(-floor_div(-static_cast<__int128>(lo), one));
    l = static_cast<double>(floor_div(static_cast<__int128>(hi), one));
  } else {
    f = std::ceil(lo / one);
    l = std::floor(hi / one);
  }
  first = static_cast<int>(std::clamp(f, 0.0, static_cast<double>(n)));
  last = static_cast<int>(std::clamp(l, -1.0, static_cast<double>(n - 1)));
}

// Twice the signed area of (a, b, p): positive when p lies to the inside of
// edge a -> b of a positively oriented triangle.
template <class T>
Wide<T> edge(const BaseVertex<T>& a, const BaseVertex<T>& b, Wide<T> pu, Wide<T> pv) {
  return (Wide<T>(b.u) - a.u) * (pv - a.v) - (Wide<T>(b.v) - a.v) * (pu - a.u);
}

// The tie rule: on the edge (e == 0) the centre counts as inside iff moving
// it by (-1, +epsilon)·epsilon makes e positive.
template <class T, class E>
bool inside(E e, const BaseVertex<T>& a, const BaseVertex<T>& b) {
  if (e != 0) return e > 0;
  const T du = b.u - a.u, dv = b.v - a.v;
  return dv > 0 || (dv == 0 && du > 0);
}

}  // namespace raster

// Calls emit(u, v, depth) for every pixel of [0, width) x [0, height) that
// the triangle covers, row by row. Integer vertices must keep every sum
// e_i·h_i·d_i within ±2^124 (the host refuses polygons beyond that: ±2^38
// units in u, v and d with h = 1; docs/fixed-point.md for perspective), so
// that every product fits 128 bits.
template <class T, class Emit>
void scan_triangle(BaseVertex<T> a, BaseVertex<T> b, BaseVertex<T> c, T one, int width, int height, Emit&& emit) {
  using W = raster::Wide<T>;
  W area = raster::edge(a, b, W(c.u), W(c.v));
  if (area == 0) return;
  if (area < 0) {
    std::swap(b, c);
    area = -area;
  }
  int u0, u1, v0, v1;
  raster::centres(std::min({a.u, b.u, c.u}), std::max({a.u, b.u, c.u}), one, width, u0, u1);
  raster::centres(std::min({a.v, b.v, c.v}), std::max({a.v, b.v, c.v}), one, height, v0, v1);
  // In integers each edge's test is monotonic along a row (its value is
  // exactly linear in u, its tie rule fixed per edge), so a row's covered
  // pixels are one run: the scan of a row ends at its first uncovered pixel
  // after a covered one. (Not so in floating point, whose rounded edge
  // values need not be monotonic: that scan reads the whole row.)
  const auto covered = [&](auto ea, auto eb, auto ec) {
    return raster::inside<T>(ea, b, c) && raster::inside<T>(eb, c, a) && raster::inside<T>(ec, a, b);
  };
  for (int v = v0; v <= v1; ++v) {
    const W pv = W(v) * one;
    if constexpr (std::is_integral_v<T>) {
      if (a.h != b.h || b.h != c.h) {
        // Perspective: numerator and denominator are both linear in u,
        // their quotient is not; one rounded division per covered pixel.
        const W pu = W(u0) * one;
        W ea = raster::edge(b, c, pu, pv), eb = raster::edge(c, a, pu, pv), ec = raster::edge(a, b, pu, pv);
        const W dea = -(W(c.v) - b.v) * one, deb = -(W(a.v) - c.v) * one, dec = -(W(b.v) - a.v) * one;
        const W ha = a.h, hb = b.h, hc = c.h, hda = ha * a.d, hdb = hb * b.d, hdc = hc * c.d;
        W N = ea * hda + eb * hdb + ec * hdc, D = ea * ha + eb * hb + ec * hc;
        const W dN = dea * hda + deb * hdb + dec * hdc, dD = dea * ha + deb * hb + dec * hc;
        for (int u = u0, in = 0; u <= u1; ++u) {
          if (covered(ea, eb, ec)) {
            emit(u, v, static_cast<T>(raster::floor_div(2 * N + D, 2 * D)));  // half up
            in = 1;
          } else if (in) {
            break;  // the row's pixels are contiguous (see covered)
          }
          ea += dea, eb += deb, ec += dec;
          N += dN, D += dD;
        }
        continue;
      }
      // The edges and the depth's numerator are linear in u: stepped along
      // the row exactly, the depth's rounded quotient with its remainder
      // (N = 2 num + area = q D + r, 0 <= r < D), so no division per pixel.
      const W pu = W(u0) * one;
      W ea = raster::edge(b, c, pu, pv), eb = raster::edge(c, a, pu, pv), ec = raster::edge(a, b, pu, pv);
      const W dea = -(W(c.v) - b.v) * one, deb = -(W(a.v) - c.v) * one, dec = -(W(b.v) - a.v) * one;
      const W D = 2 * area, dN = 2 * (dea * a.d + deb * b.d + dec * c.d);
      const W N = 2 * (ea * a.d + eb * b.d + ec * c.d) + area;
      const W q = raster::floor_div(N, D), r = N - q * D;
      const W dq = raster::floor_div(dN, D), dr = dN - dq * D;
      const auto row = [&](auto ea, auto eb, auto ec, auto dea, auto deb, auto dec, auto q, auto r, auto dq,
                           auto dr, auto D) {
        for (int u = u0, in = 0; u <= u1; ++u) {
          if (covered(ea, eb, ec)) {
            emit(u, v, static_cast<T>(q));  // rounded half up
            in = 1;
          } else if (in) {
            break;  // the row's pixels are contiguous (see covered)
          }
          ea += dea, eb += deb, ec += dec;
          q += dq, r += dr;
          if (r >= D) ++q, r -= D;
        }
      };
      // The same steps in 64 bits when no value of the row can leave them
      // (each is linear in u, so its ends bound it): the usual case, and
      // half the instructions of 128-bit steps.
      const W steps = W(u1 - u0 + 1), lim = W(1) << 61;
      const auto mag = [](W x) { return x < 0 ? -x : x; };
      const auto fits = [&](W at, W most_per_step) { return mag(at) + steps * most_per_step < lim; };
      // q moves by dq or dq + 1 a step; 0 <= r, dr < D.
      if (fits(ea, mag(dea)) && fits(eb, mag(deb)) && fits(ec, mag(dec)) && fits(q, mag(dq) + 1) && D < lim) {
        using I = int64_t;
        row(I(ea), I(eb), I(ec), I(dea), I(deb), I(dec), I(q), I(r), I(dq), I(dr), I(D));
      } else {
        row(ea, eb, ec, dea, deb, dec, q, r, dq, dr, D);
      }
    } else {
      for (int u = u0; u <= u1; ++u) {
        const W pu = W(u) * one;
        const W ea = raster::edge(b, c, pu, pv), eb = raster::edge(c, a, pu, pv), ec = raster::edge(a, b, pu, pv);
        if (!covered(ea, eb, ec)) continue;
        if (a.h == b.h && b.h == c.h)
          emit(u, v, (ea * a.d + eb * b.d + ec * c.d) / area);
        else
          emit(u, v, (ea * a.h * a.d + eb * b.h * b.d + ec * c.h * c.d) / (ea * a.h + eb * b.h + ec * c.h));
      }
    }
  }
}

}  // namespace cube4::golden
