#include "golden/polygons.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "golden/errors.hpp"
#include "golden/polygon_connections.hpp"
#include "golden/rasterise.hpp"
#include "golden/shading_model.hpp"
#include "golden/units/composite_polygon.hpp"

namespace cube4::golden {
namespace {

// Pixels or sample slices from the origin the rasteriser takes: in
// parallel projection 2^30 (so 2^38 units, golden/rasterise.hpp); in
// perspective 2^24 pixels and 2^20 sample slices, so that with h < 2^24
// every sum e·h·d stays below 2^121 (docs/fixed-point.md, "Polygons").
constexpr double kRange = 1 << 30;
constexpr double kPerspectiveRange[3] = {1 << 24, 1 << 24, 1 << 20};

std::string scene_name(const Scene& s) { return s.file.empty() ? std::string("scene") : s.file; }

std::string fmt(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

// Rounded half up to `bits` fraction bits (exact in double within kRange).
int64_t snap(double x, int bits) { return static_cast<int64_t>(std::floor(std::ldexp(x, bits) + 0.5)); }

// The sample slices in which the ray of each base-plane pixel has a
// sample, and where that sample sits in slice k's slab image.
// Parallel: the ray of (u, v) is in slice k iff 0 <= u - origin_x + ix_k < nx
// and likewise in y, and its slab pixel is that column and row; the offsets
// grow by 0 or 1 a slice, so the slices form an interval.
// Perspective: ray u - origin_x is in slice k iff it lies in the slice's ray
// range [lo_k, hi_k) (Registers::rays_in_slice) on both axes, and its slab
// pixel is its rank in that range, (u - origin_x - lo_k); a ray enters and
// leaves once, so the slices form an interval here too.
// The interval is [first, last], empty when first > last; per axis it
// depends on the column (row) alone: one table entry each.
class RaySlices {
 public:
  RaySlices(const Registers& r, int width, int height) {
    const int K = r.sample_slices(), size[2] = {width, height}, origin[2] = {r.base_origin_x(), r.base_origin_y()};
    for (int axis = 0; axis < 2; ++axis) {
      Axis& a = axes_[axis];
      auto& to_slab = a.to_slab;
      if (!r.perspective) {
        std::vector<int> offsets;
        for (int k = 0; k < K; ++k) {
          offsets.push_back(axis == 0 ? r.x_offset(k).integer : r.y_offset(k).integer);
          to_slab.push_back(offsets.back() - origin[axis]);
        }
        for (int u = 0; u < size[axis]; ++u) a.slices.push_back(along(offsets, origin[axis] - u, r.dim[static_cast<size_t>(axis)]));
        continue;
      }
      a.slices.assign(static_cast<size_t>(size[axis]), {K, -1});
      for (int k = 0; k < K; ++k) {
        const RayRange rays = r.rays_in_slice(axis, k);
        to_slab.push_back(static_cast<int>(-origin[axis] - rays.lo));
        const int64_t lo = std::max<int64_t>(rays.lo + origin[axis], 0), hi = std::min<int64_t>(rays.hi + origin[axis], size[axis]);
        for (int64_t u = lo; u < hi; ++u) {
          auto& [first, last] = a.slices[static_cast<size_t>(u)];
          first = std::min(first, k);
          last = std::max(last, k);
        }
      }
    }
  }
  std::pair<int, int> of(int u, int v) const {
    const auto [x0, x1] = axes_[0].slices[static_cast<size_t>(u)];
    const auto [y0, y1] = axes_[1].slices[static_cast<size_t>(v)];
    return {std::max(x0, y0), std::min(x1, y1)};
  }
  // Slab k's pixel of the ray of base-plane pixel (u, v), which samples slice k.
  int slab_x(int u, int k) const { return u + axes_[0].to_slab[static_cast<size_t>(k)]; }
  int slab_y(int v, int k) const { return v + axes_[1].to_slab[static_cast<size_t>(k)]; }

 private:
  // Slices whose offset lies in [lo, lo + n - 1].
  static std::pair<int, int> along(const std::vector<int>& offsets, int lo, int n) {
    const auto first = std::lower_bound(offsets.begin(), offsets.end(), lo);
    const auto end = std::upper_bound(offsets.begin(), offsets.end(), lo + n - 1);
    return {static_cast<int>(first - offsets.begin()), static_cast<int>(end - offsets.begin()) - 1};
  }
  struct Axis {
    std::vector<std::pair<int, int>> slices;  // per column u (row v)
    std::vector<int> to_slab;                 // per slice k: slab column (row) less the pixel's
  };
  Axis axes_[2];
};

struct Fragment {
  int u, v;
  int64_t depth;  // 2^-kZFracBits sample slices
  Pixel px;
  uint32_t triangle;  // its triangle's index in the frame, for the triangle counts
};

// The fragments in depth order, equal depths in the order drawn: a least
// significant digit first radix sort (stable by construction) of the
// depths' offsets from the nearest, 11 bits a pass, as many passes as the
// depths' range needs (two for a volume of 2^14 sample slices), less those
// whose digit is the same for every fragment. (Shorter digits, e.g. two of
// 7 bits for 2^14 depths, or one of 14, measured slower on the sphere
// and box: 3 to 4 % of the frame.) The
// fragments themselves move, so that the walk in depth order reads them in
// sequence.
std::vector<Fragment> depth_order(std::vector<Fragment> order) {
  if (order.empty()) return order;
  int64_t nearest = order[0].depth, farthest = nearest;
  for (const Fragment& g : order) {
    nearest = std::min(nearest, g.depth);
    farthest = std::max(farthest, g.depth);
  }
  constexpr int kDigitBits = 11;
  constexpr uint64_t kDigitMask = (uint64_t{1} << kDigitBits) - 1;
  const auto range = static_cast<uint64_t>(farthest - nearest);
  int passes = 0;
  while (passes * kDigitBits < 64 && (range >> (passes * kDigitBits)) != 0) ++passes;
  // Every pass's digit counts in one read of the fragments; a pass whose
  // fragments all share one digit would leave the order as it is.
  using Counts = std::array<uint32_t, (size_t{1} << kDigitBits) + 1>;
  std::vector<Counts> start(static_cast<size_t>(passes), Counts{});
  for (const Fragment& g : order) {
    const auto offset = static_cast<uint64_t>(g.depth - nearest);
    for (int d = 0; d < passes; ++d) ++start[static_cast<size_t>(d)][(offset >> (d * kDigitBits) & kDigitMask) + 1];
  }
  std::vector<Fragment> next;
  for (int d = 0; d < passes; ++d) {
    Counts& c = start[static_cast<size_t>(d)];
    if (std::find(c.begin(), c.end(), static_cast<uint32_t>(order.size())) != c.end()) continue;
    for (size_t i = 1; i < c.size(); ++i) c[i] += c[i - 1];
    next.resize(order.size());
    const int shift = d * kDigitBits;
    for (const Fragment& g : order) next[c[static_cast<uint64_t>(g.depth - nearest) >> shift & kDigitMask]++] = g;
    order.swap(next);
  }
  return order;
}

}  // namespace

Vec3 BaseFrame::to_base(const Vec3& p) const {
  const double d = p[2] * S;
  if (ms == 0) return {p[0] - (x0 + d * sx) + origin_x, p[1] - (y0 + d * sy) + origin_y, d};
  const double m = w(d);
  return {(p[0] - (x0 + d * sx)) / m + origin_x, (p[1] - (y0 + d * sy)) / m + origin_y, d};
}

BaseFrame base_frame(const Registers& r) {
  const double one = std::ldexp(1.0, r.p.dda_frac_bits);
  if (r.perspective && r.scale_start != (int64_t{1} << r.p.dda_frac_bits))
    throw std::logic_error("base_frame: perspective registers with SCALE_START other than one");
  BaseFrame f;
  f.x0 = static_cast<double>(r.x_start) / one;
  f.sx = static_cast<double>(r.x_step) / one;
  f.y0 = static_cast<double>(r.y_start) / one;
  f.sy = static_cast<double>(r.y_step) / one;
  f.origin_x = r.base_origin_x();
  f.origin_y = r.base_origin_y();
  f.S = r.supersampling;
  if (r.perspective) f.ms = static_cast<double>(r.scale_step) / one;
  return f;
}

Margins polygon_margins(const std::vector<Mesh>& meshes, const ViewFactorisation& f, const BaseFrame& frame,
                        int width, int height) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lo[2] = {inf, inf}, hi[2] = {-inf, -inf};
  const auto extend = [&](const Vec3& b) {
    for (int i = 0; i < 2; ++i) {
      lo[i] = std::min(lo[i], b[i]);
      hi[i] = std::max(hi[i], b[i]);
    }
  };
  for (const Mesh& m : meshes) {
    if (!(m.opacity > 0)) continue;
    if (frame.ms == 0) {
      for (const Vec3& vertex : m.vertices) extend(frame.to_base(f.to_permuted(vertex)));
      continue;
    }
    // Perspective: only what lies beyond the near plane is drawn.
    for (const auto& t : m.triangles)
      project_triangle(frame, f.to_permuted(m.vertices[t[0]]), f.to_permuted(m.vertices[t[1]]),
                       f.to_permuted(m.vertices[t[2]]), [&](const BaseCorner(&c)[3]) {
                         for (const BaseCorner& k : c) extend(k.uvd);
                       });
  }
  // What the final image shows of the base plane's plane: its corners
  // through the warp's inverse (perspective: their rays' crossings).
  double seen_lo[2] = {inf, inf}, seen_hi[2] = {-inf, -inf};
  const double shift_x = frame.origin_x - frame.x0, shift_y = frame.origin_y - frame.y0;
  const Affine2 to_base = f.perspective ? Affine2{} : f.base_to_image(shift_x, shift_y).inverse();
  for (double X : {-0.5, f.image_width - 0.5})
    for (double Y : {-0.5, f.image_height - 0.5}) {
      std::array<double, 2> uv{};
      if (!f.perspective) {
        uv = to_base.apply(X, Y);
      } else if (const auto crossing = f.base_of_image(X, Y, shift_x, shift_y)) {
        uv = *crossing;
      } else {  // a corner ray that never reaches it: the seen part is unbounded
        for (int i = 0; i < 2; ++i) seen_lo[i] = -inf, seen_hi[i] = inf;
        continue;
      }
      for (int i = 0; i < 2; ++i) {
        seen_lo[i] = std::min(seen_lo[i], uv[static_cast<size_t>(i)]);
        seen_hi[i] = std::max(seen_hi[i], uv[static_cast<size_t>(i)]);
      }
    }
  Margins m;
  const int size[2] = {width, height};
  for (int i = 0; i < 2; ++i) {
    const double a = std::max(lo[i], seen_lo[i]), b = std::min(hi[i], seen_hi[i]);
    if (!(a <= b)) continue;
    // Pixel centres at integers: the first and last covered are ceil(a), floor(b).
    const double first = std::ceil(a), last = std::floor(b);
    m.lo[static_cast<size_t>(i)] = static_cast<int>(std::clamp(-first, 0.0, static_cast<double>(size[i])));
    m.hi[static_cast<size_t>(i)] =
        static_cast<int>(std::clamp(last - (size[i] - 1), 0.0, static_cast<double>(size[i])));
  }
  return m;
}

void check_polygon_scene(const Scene& s, const std::vector<Mesh>& meshes) {
  if (meshes.empty() || s.blend == Blend::Composite) return;
  throw InputError(scene_name(s) + ": \"blend\" = \"" + (s.blend == Blend::Mip ? "mip" : "minip") +
                   "\" cannot be combined with \"polygons\": polygons are composited in depth order with the "
                   "samples (Cube-5), which needs \"blend\": \"composite\"");
}

HostProgram program_host(const Scene& s, const Volume& vol, const std::vector<Mesh>& meshes) {
  check_polygon_scene(s, meshes);
  HostProgram h = program_host(s, vol);
  if (meshes.empty()) return h;
  const Margins m =
      polygon_margins(meshes, h.view, base_frame(h.regs), h.regs.base_width(), h.regs.base_height());
  h.regs.margin_lo = m.lo;
  h.regs.margin_hi = m.hi;
  return h;
}

PolygonFrame rasterise_polygons(const Scene& s, const std::vector<Mesh>& meshes, const HostProgram& h) {
  check_polygon_scene(s, meshes);
  const Registers& r = h.regs;
  const ViewFactorisation& f = h.view;
  const Precision& p = r.p;
  const int W = r.base_width(), H = r.base_height(), K = r.sample_slices(), nx = r.dim[0], ny = r.dim[1];
  if (nx > kRleRunMax) throw InputError(scene_name(s) + ": polygons need a base-plane x extent of at most " +
                                        std::to_string(kRleRunMax) + " voxels (the slab lines' run word)");
  const size_t pixels = static_cast<size_t>(W) * H;
  PolygonFrame out;
  out.width = W;
  out.height = H;
  out.front.assign(pixels, Pixel{});
  out.back.assign(pixels, Pixel{});
  out.z.assign(pixels, kZNone);
  out.slabs.assign(static_cast<size_t>(K), SlabImage(nx, ny, std::max(1, s.pipelines)));

  const BaseFrame frame = base_frame(r);
  const Lighting L = lighting_of(s, f);
  const uint32_t full = static_cast<uint32_t>(max_unsigned(p.alpha_bits));
  constexpr int64_t kNone = std::numeric_limits<int64_t>::max();
  std::vector<int64_t> opaque_depth(pixels, kNone);
  std::vector<Pixel> opaque_px(pixels);
  std::vector<Fragment> translucent;
  // A closed surface gives about two fragments a pixel it covers: room for
  // that over the base plane saves the copies of growing (what is not
  // written is not touched).
  translucent.reserve(2 * pixels);
  uint32_t triangle = 0, last_opaque = 0;  // triangles count from 1
  for (const Mesh& m : meshes) {
    const auto alpha = static_cast<uint32_t>(quantise_unit(m.opacity, p.alpha_bits));
    if (alpha == 0) continue;
    const bool opaque = alpha == full;
    for (const auto& t : m.triangles) {
      ++triangle;
      const Vec3 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
      const Vec3 rgb = polygon_color(s, L, f, a, b, c, m.color, m.lit);
      Rgb q{};
      for (int i = 0; i < 3; ++i) q[static_cast<size_t>(i)] = static_cast<uint32_t>(quantise_unit(rgb[i], p.alpha_bits));
      const Pixel px = polygon_pixel(q, alpha, p);
      const auto emit = [&](int u, int v, int64_t depth) {
        const size_t i = static_cast<size_t>(v) * W + u;
        if (!opaque) {
          translucent.push_back({u, v, depth, px, triangle});
          return;
        }
        if (last_opaque != triangle) ++out.counts.opaque_triangles;
        last_opaque = triangle;
        ++out.counts.opaque;
        // Nearer wins; on a tie the one drawn first.
        if (depth < opaque_depth[i]) {
          opaque_depth[i] = depth;
          opaque_px[i] = px;
        }
      };
      const auto draw = [&](const BaseCorner(&c)[3]) {
        // A pixel or more beside the base plane: no pixel centre, snapped or
        // not, whatever the vertices' range.
        bool beside = false;
        for (int axis = 0; axis < 2; ++axis) {
          const double size = axis == 0 ? W : H;
          beside = beside || std::max({c[0].uvd[axis], c[1].uvd[axis], c[2].uvd[axis]}) < -1 ||
                   std::min({c[0].uvd[axis], c[1].uvd[axis], c[2].uvd[axis]}) > size;
        }
        if (beside) return;
        BaseVertex<int64_t> corner[3];
        for (int i = 0; i < 3; ++i) {
          const Vec3& uvd = c[i].uvd;
          for (int axis = 0; axis < 3; ++axis)
            if (!(std::fabs(uvd[axis]) <= (frame.ms == 0 ? kRange : kPerspectiveRange[axis])))
              throw InputError(scene_name(s) + ": \"" + m.key + "\" has a vertex at base-plane (u, v, depth) = (" +
                               fmt(uvd[0]) + ", " + fmt(uvd[1]) + ", " + fmt(uvd[2]) + "), beyond the rasteriser's range of " +
                               (frame.ms == 0 ? "±2^30 pixels and sample slices"
                                              : "±2^24 pixels and ±2^20 sample slices in perspective"));
          corner[i] = {snap(uvd[0], kSubpixelBits), snap(uvd[1], kSubpixelBits), snap(uvd[2], kZFracBits),
                       std::max<int64_t>(1, snap(c[i].h, kInverseSpacingBits))};
        }
        scan_triangle<int64_t>(corner[0], corner[1], corner[2], int64_t{1} << kSubpixelBits, W, H, emit);
      };
      project_triangle(frame, f.to_permuted(a), f.to_permuted(b), f.to_permuted(c), draw);
    }
  }

  for (size_t i = 0; i < pixels; ++i)
    if (opaque_depth[i] != kNone)
      out.z[i] = static_cast<uint32_t>(std::clamp<int64_t>(opaque_depth[i], 0, kZNone));
  // Front to back, so that each image blends a pixel's fragments over one
  // another in depth order; equal depths in the order drawn.
  const std::vector<Fragment> order = depth_order(std::move(translucent));
  const RaySlices rays(r, W, H);
  const int64_t slice = int64_t{1} << kZFracBits;
  // Each slab's triangles, counted once: in depth order a triangle's
  // fragments come in slabs that never go back, so a slab is new to a
  // triangle exactly when it differs from the triangle's last one.
  out.counts.slab_triangles.assign(static_cast<size_t>(K), 0);
  std::vector<int> last_slab(static_cast<size_t>(triangle) + 1, -1);
  for (const Fragment& g : order) {
    const size_t i = static_cast<size_t>(g.v) * W + g.u;
    // At or behind the opaque surface: hidden (the unclamped depths, so that
    // this holds in front of the volume too).
    if (g.depth >= opaque_depth[i]) {
      ++out.counts.hidden;
      continue;
    }
    ++out.counts.translucent;
    const auto [first, last] = rays.of(g.u, g.v);
    if (first > last || g.depth > last * slice) {
      out.back[i] = pixel_over(out.back[i], g.px, p);
      ++out.counts.behind;
    } else if (g.depth <= first * slice) {
      out.front[i] = pixel_over(out.front[i], g.px, p);
      ++out.counts.in_front;
    } else {
      const int k = static_cast<int>((g.depth - 1) >> kZFracBits);  // k < depth <= k + 1
      out.slabs[static_cast<size_t>(k)].insert(rays.slab_x(g.u, k), rays.slab_y(g.v, k), g.px, p);
      ++out.counts.in_slabs;
      int& last = last_slab[g.triangle];
      if (last != k) ++out.counts.slab_triangles[static_cast<size_t>(k)];
      last = k;
    }
  }
  for (size_t i = 0; i < pixels; ++i)
    if (opaque_depth[i] != kNone) out.back[i] = pixel_over(out.back[i], opaque_px[i], p);
  return out;
}

PolygonTraffic polygon_traffic(const PolygonFrame& f, const Precision& p) { return polygon_traffic(f, slab_loads(f), p); }

PolygonTraffic polygon_traffic(const PolygonFrame& f, const std::vector<SlabLoad>& loads, const Precision& p) {
  PolygonTraffic t;
  const uint64_t channel = static_cast<uint64_t>((p.alpha_bits + 7) / 8);
  t.image_bytes = static_cast<uint64_t>(f.width) * static_cast<uint64_t>(f.height) * (8 * channel + (kZBits + 7) / 8);
  for (size_t k = 0; k < loads.size(); ++k) {
    const SlabImage& s = f.slabs[k];
    ++t.slabs;
    t.raw_bytes += static_cast<uint64_t>(s.width()) * static_cast<uint64_t>(s.beams()) * 4 * channel;
    t.slice_cycles = static_cast<uint64_t>(s.beams()) * static_cast<uint64_t>(s.lane_width(0));
    t.flits += loads[k].flits;
    t.rle_bytes += 2 * loads[k].words;
    t.rle_cycles += std::max(loads[k].read_flits, t.slice_cycles);
    if (loads[k].read_flits > t.slice_cycles) ++t.slabs_over_slice;
  }
  return t;
}

}  // namespace cube4::golden
