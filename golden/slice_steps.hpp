// The fixed-point renderer's work on one sample slice, in the pieces the
// units do it in: interpolation of a slice, the gradient neighbourhood of a
// sample, ray alignment and compositing of a slice, and the rays that leave.
// render_fixed() is a loop over these; the system model's transaction-level
// units call the same pieces (systemc/tlm/), so there is one copy of each.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "golden/empty_space.hpp"
#include "golden/permuted_volume.hpp"
#include "golden/pipeline.hpp"
#include "golden/polygon_frame.hpp"
#include "golden/renderers.hpp"
#include "golden/units/composite_polygon.hpp"

namespace cube4::golden {

// A slice with a border of zeros: `pad` columns/rows before and after, so
// neighbours of edge samples read zero (the volume is surrounded by zeros).
struct Plane {
  int nx = 0, ny = 0, pad = 0, pitch = 0;
  std::vector<int32_t> v;
  Plane() = default;
  Plane(int nx_, int ny_, int pad_) : nx(nx_), ny(ny_), pad(pad_), pitch(nx_ + 2 * pad_),
      v(static_cast<size_t>(nx_ + 2 * pad_) * (ny_ + 2 * pad_), 0) {}
  int32_t* row(int y) { return &v[static_cast<size_t>(y + pad) * pitch + pad]; }
  const int32_t* row(int y) const { return &v[static_cast<size_t>(y + pad) * pitch + pad]; }
  uint32_t at(int x, int y) const { return static_cast<uint32_t>(row(y)[x]); }
  void clear() { std::fill(v.begin(), v.end(), 0); }
};

void load_voxel_slice(const PermutedVolume& pv, int z, Plane& out);
// VolumePro's voxel z differences of whole slices, borders included:
// out = voxel_z_difference(above, below) entry by entry.
inline void voxel_z_differences(const Plane& above, const Plane& below, Plane& out) {
  for (size_t i = 0; i < out.v.size(); ++i)
    out.v[i] = voxel_z_difference(static_cast<uint32_t>(above.v[i]), static_cast<uint32_t>(below.v[i]));
}
// Beams y0 .. y1-1 of voxel slice z, beam y only over spans[y] (the rest of
// the plane keeps what it held).
void load_voxel_slice(const PermutedVolume& pv, int z, Plane& out, int y0, int y1, const Span* spans);
// The same voxels' tags.
void load_tag_slice(const PermutedVolume& pv, int z, Plane& out, int y0, int y1, const Span* spans);

// Interpolation unit over a whole sample slice: trilinear() for every
// sample, computed stage by stage across the slice (x lerps of each voxel
// row once, then y, then z) with the same lerp, so the values are those of
// trilinear() on each sample's eight voxels (tested). A stage whose weight
// is zero returns its first operand exactly, so it is not computed.
// lo, hi: voxel slices z_voxel and z_voxel + 1 with a border of at least 1.
// The ranged form computes only beams y0 .. y1-1, beam y over spans[y]
// (which then reads voxel beams y and y + 1 over spans[y] and one voxel
// more); the rest of `out` keeps what it held.
class SliceInterp {
 public:
  SliceInterp(int nx, int ny, int weight_bits);
  void slice(const Plane& lo, const Plane& hi, const SliceControl& c, Plane& out);
  void slice(const Plane& lo, const Plane& hi, const SliceControl& c, Plane& out, int y0, int y1,
             const Span* spans);
  // The samples' tags from the voxels' tags lo, hi (same ranges): each the
  // tag of its nearest voxel, sample_tag() for every sample (tested).
  void tags(const Plane& lo, const Plane& hi, const SliceControl& c, Plane& out, int y0, int y1,
            const Span* spans) const;

 private:
  void bilinear(const Plane& v, int32_t wx, int32_t wy, std::vector<int32_t>& out, int y0, int y1,
                const Span* spans);
  int nx_, ny_, w_;
  std::vector<int32_t> tx_, ty_lo_, ty_hi_;
  std::vector<Span> whole_;  // every beam whole
};

// The 12-neighbourhood of sample (x, y) of slice c.k from the sample slices
// behind, current and ahead (borders of at least 1).
[[gnu::always_inline]] inline void gather_neighbourhood(const Plane& behind, const Plane& current, const Plane& ahead,
                                                         const SliceControl& c, int x, int y, Neighbourhood& n) {
  // Row pointers: one address computation a plane instead of one a voxel.
  // Always inlined, as the renderer's sample loop grew past GCC's budget.
  auto gather_2x2 = [x, y](const Plane& s, const Realign& rx, const Realign& ry, std::array<uint32_t, 4>& out) {
    const int32_t* a = s.row(y + ry.base) + x + rx.base;
    out = {static_cast<uint32_t>(a[0]), static_cast<uint32_t>(a[1]), static_cast<uint32_t>(a[s.pitch]),
           static_cast<uint32_t>(a[s.pitch + 1])};
  };
  const int32_t* row = current.row(y) + x;
  n.centre = static_cast<uint32_t>(row[0]);
  n.left = static_cast<uint32_t>(row[-1]);
  n.right = static_cast<uint32_t>(row[1]);
  n.up = static_cast<uint32_t>(row[-current.pitch]);
  n.down = static_cast<uint32_t>(row[current.pitch]);
  gather_2x2(behind, c.behind_x, c.behind_y, n.behind);
  gather_2x2(ahead, c.ahead_x, c.ahead_y, n.ahead);
}

inline void write_pixel(BasePlane& bp, int u, int v, const Pixel& a) {
  uint16_t* px = &bp.rgba[(static_cast<size_t>(v) * bp.width + u) * 4];
  px[0] = a.r; px[1] = a.g; px[2] = a.b; px[3] = a.a;
}

// The base plane of rays that have all left, one accumulator per pixel
// (row-major, the plane's size): each pixel the ray's (over the polygons'
// back image with a polygon frame), and with `bp.acc` the accumulators.
// A perspective frame ends so (render_perspective(), the clocked
// compositor of systemc/tlm/tlm_composite_persp.hpp).
// One ray's pixel (x, y) as it leaves: the compositing ring writes each
// ray so when it has blended its last sample.
inline void write_ray(BasePlane& bp, int x, int y, const RayAcc& ray, const Precision& p,
                      const PolygonFrame* polygons = nullptr) {
  const size_t i = static_cast<size_t>(y) * bp.width + x;
  write_pixel(bp, x, y, polygons ? leave_with_polygons(ray, polygons->back[i], p) : pixel_of(ray, p));
  if (!bp.acc.empty()) bp.acc[i] = ray;
}
inline void write_rays(BasePlane& bp, const std::vector<RayAcc>& rays, const Precision& p,
                       const PolygonFrame* polygons = nullptr) {
  for (int y = 0; y < bp.height; ++y)
    for (int x = 0; x < bp.width; ++x) write_ray(bp, x, y, rays[static_cast<size_t>(y) * bp.width + x], p, polygons);
}

// The compositing unit over whole slices: the ray store, ray alignment,
// blending, and the base-plane pixels of the rays that leave. Per slice,
// `shade(x, y, ray, out)` supplies the cropped and cut sample of (x, y) and
// returns false if it leaves `ray` exactly as it is (then `out` is not
// used), and `beams(y)` says which samples of beam y may change their ray:
// true or false for all or none, or a Span.
//
// Rays are stored by their base-plane pixel: the ray through sample (x, y)
// of slice k is pixel (x - ix_k + ix_last, y - iy_k + iy_last), which is
// ray_predecessor()'s alignment (the ray of (x, y) continues the one of
// (x - dx, y - dy)) without moving any ray. A ray enters the slice once and
// leaves it once (the offsets only grow), so a pixel not yet reached holds
// the empty ray a side-face entry starts with.
//
// `slice` and `finish` may be given a band of base-plane rows [v0, v1):
// they then touch only those rays and pixels, so bands run concurrently.
//
// With polygons (golden/polygon_frame.hpp) a ray starts as its front
// image's pixel, each of its samples passes the Z test first and its slab
// pixel follows it (double_composite(), in two passes over a beam that keep
// each ray's order), and the back image goes behind it when it leaves;
// pixels whose ray meets no sample are front over back from the start.
//
// With a RayStop other than `never` (front-to-back compositing only) the
// compositor stops offering a ray's samples to `shade` once they cannot
// change what is asked of the ray, and steps over stopped rays a word of
// bits at a time (most samples of a dense volume lie behind such rays):
// - `full_alpha`: the ray's α is full, so compose_over() adds mul_frac(0, ·)
//   = 0 to it: the accumulator itself is final (BasePlane::acc stays exact).
// - `settled_pixel`: the ray's base-plane pixel is final. Whatever is
//   composited behind the ray (samples, slab pixels, the back image) adds
//   to each colour channel at most what it adds to α (their premultiplied
//   colour is never above their α, and mul_frac() is monotonic), and α's
//   increments sum to at most t = full - α; so each channel ends in
//   [v, min(v + t, full)], and once acc_to_pixel() (monotonic) maps both
//   ends of that range to the same value for all four channels, no sample
//   can change the pixel, though it could still change the accumulator.
enum class RayStop { never, full_alpha, settled_pixel };

// RayStop's test on one ray, for every renderer that keeps rays. R: the
// registers' type; with DefaultPrecisionRegisters the widths are constants.
template <class R = Registers>
class BasicRayStopRule {
 public:
  BasicRayStopRule(RayStop stop, BlendMode blend, const Precision& p)
      : p_(p), stop_(blend == BlendMode::Composite ? stop : RayStop::never),
        full_(static_cast<uint32_t>(max_unsigned(acc_bits(p)))), settled_t_(settled_transparency()) {}
  bool active() const { return stop_ != RayStop::never; }
  bool can_stop(const RayAcc& a) const {
    if (a.a == full_) return true;
    const uint32_t t = full_ - a.a;
    if (t > settled_t_) return false;  // α's own pixel can still change
    auto settled = [&](uint32_t v) {
      return acc_to_pixel(v, precision()) == acc_to_pixel(v < full_ - t ? v + t : full_, precision());
    };
    return settled(a.r) && settled(a.g) && settled(a.b);
  }

 private:
  // The largest t = full - α whose α still rounds to the full pixel (none
  // with full_alpha): acc_to_pixel() is monotonic, so a binary search.
  uint32_t settled_transparency() const {
    if (stop_ != RayStop::settled_pixel) return 0;
    const uint32_t top = acc_to_pixel(full_, precision());
    uint32_t lo = 0, hi = full_;  // acc_to_pixel(full_ - lo) == top, acc_to_pixel(full_ - hi) < top
    while (hi - lo > 1) {
      const uint32_t mid = lo + (hi - lo) / 2;
      (acc_to_pixel(full_ - mid, precision()) == top ? lo : hi) = mid;
    }
    return lo;
  }
  const Precision& precision() const {
    if constexpr (std::is_same_v<R, Registers>) return p_;
    else return R::p;
  }
  Precision p_;
  RayStop stop_;
  uint32_t full_, settled_t_;
};
using RayStopRule = BasicRayStopRule<Registers>;

// R: the registers' type (Registers, or DefaultPrecisionRegisters for widths
// known at compile time).
template <class R = Registers>
class BasicSliceCompositor {
 public:
  // `bp` as empty_base_plane() makes it: pixels no ray reaches stay 0.
  BasicSliceCompositor(const R& r, BasePlane& bp, const PolygonFrame* polygons = nullptr,
                  RayStop stop = RayStop::never)
      : r_(r), bp_(bp), nx_(r.dim[0]), ny_(r.dim[1]), K_(r.sample_slices()),
        ix_last_(r.base_origin_x()), iy_last_(r.base_origin_y()), width_(r.base_width()),
        stop_(stop, r.blend, r.p), words_(stop_.active() ? (r.base_width() + 63) / 64 : 0),
        rays_(static_cast<size_t>(r.base_width()) * r.base_height()),
        stopped_(static_cast<size_t>(words_) * r.base_height()), poly_(polygons) {
    if (poly_) start_polygons();
  }

  // Beams of slice c.k whose rays are base-plane rows [v0, v1).
  int first_beam(const SliceControl& c, int v0) const { return std::clamp(v0 + c.iy - iy_last_, 0, ny_); }
  int end_beam(const SliceControl& c, int v1) const { return std::clamp(v1 + c.iy - iy_last_, 0, ny_); }

  template <class Shade, class Beams>
  void slice(const SliceControl& c, Shade&& shade, Beams&& beams, int v0 = 0, int v1 = kAllRows) {
    const int y0 = first_beam(c, v0), y1 = end_beam(c, v1);
    // With rays that stop: up to kBatch samples of a beam are shaded, then
    // blended together (each ray takes one sample a slice, so the order
    // changes no bit). Shading and blending in separate loops took 0.91×
    // the time of one loop doing both, on brainsmall and brainsmall ×2
    // (docs/performance.md). On the stack: bands of rays share a
    // compositor from threads of their own.
    std::array<ShadedSample, kBatch> batch;
    std::array<int, kBatch> batch_x;
    for (int y = y0; y < y1; ++y) {
      Span span;
      if constexpr (std::is_same_v<decltype(beams(y)), bool>) {
        if (beams(y)) span = {0, nx_};
      } else {
        span = beams(y);
      }
      if (span.empty() && !poly_) continue;
      const int v = y - c.iy + iy_last_, shift = ix_last_ - c.ix;  // ray (u, v) = sample (u - shift, y)
      const size_t row = static_cast<size_t>(v) * width_ + shift;
      RayAcc* ray = &rays_[row];
      ShadedSample s;
      if (words_ > 0) {
        uint64_t* stopped = &stopped_[static_cast<size_t>(v) * words_];
        const uint32_t* z = poly_ ? &poly_->z[row] : nullptr;
        int n = 0;
        auto blend_batch = [&] {
          for (int i = 0; i < n; ++i) {
            const int x = batch_x[static_cast<size_t>(i)];
            // The stop test reads the blended ray from registers: reading
            // it back from the store just made stalled on store forwarding.
            const RayAcc blended = blend_front_to_back(ray[x], batch[static_cast<size_t>(i)], r_.p);
            ray[x] = blended;
            const int u = x + shift;
            if (stop_.can_stop(blended)) stopped[u >> 6] |= uint64_t{1} << (u & 63);
          }
          n = 0;
        };
        for (int x = span.begin; x < span.end; ++x) {
          const uint64_t live = ~stopped[(x + shift) >> 6] >> ((x + shift) & 63);
          if (live == 0) {  // the rest of this word's rays are stopped
            x += 63 - ((x + shift) & 63);
            continue;
          }
          x += __builtin_ctzll(live);
          if (x >= span.end) break;
          if ((z && !sample_before_z(c.k, z[x])) || !shade(x, y, ray[x], batch[static_cast<size_t>(n)])) continue;
          batch_x[static_cast<size_t>(n)] = x;
          if (++n == kBatch) blend_batch();
        }
        blend_batch();
      } else if (!poly_) {
        for (int x = span.begin; x < span.end; ++x)
          if (shade(x, y, ray[x], s)) ray[x] = blend(r_.blend, ray[x], s, r_.p);
        continue;
      } else {
        const uint32_t* z = &poly_->z[row];
        for (int x = span.begin; x < span.end; ++x)
          if (sample_before_z(c.k, z[x]) && shade(x, y, ray[x], s)) ray[x] = blend(r_.blend, ray[x], s, r_.p);
      }
      if (poly_) composite_slab(c, y, ray);
    }
    // Rays of slice k-1 with no successor in slice k left through a side
    // face; only the last dy beams and the last dx rays of a beam can.
    if (c.k > 0 && (c.dx | c.dy)) {
      const SliceControl pc = slice_control(r_, c.k - 1);
      for (int y = first_beam(pc, v0); y < end_beam(pc, v1); ++y)
        for (int x = y >= ny_ - c.dy ? 0 : nx_ - c.dx; x < nx_; ++x)
          if (ray_leaves(x, y, c.dx, c.dy, nx_, ny_)) leave(pc, x, y);
    }
  }

  // Whether sample (x, y) of slice c lies on a ray that has stopped
  // (RayStop): no later sample of it is composited.
  bool ray_stopped(const SliceControl& c, int x, int y) const {
    if (words_ == 0) return false;
    const int u = x + ix_last_ - c.ix, v = y - c.iy + iy_last_;
    return stopped_[static_cast<size_t>(v) * words_ + static_cast<size_t>(u >> 6)] >> (u & 63) & 1;
  }

  // After the last slice: the rays still inside leave through the back face.
  void finish(int v0 = 0, int v1 = kAllRows) {
    const SliceControl last = slice_control(r_, K_ - 1);
    for (int y = first_beam(last, v0); y < end_beam(last, v1); ++y)
      for (int x = 0; x < nx_; ++x) leave(last, x, y);
  }

  static constexpr int kAllRows = 1 << 30;

 private:
  static constexpr int kBatch = 64;  // samples shaded before they are blended (slice())
  void leave(const SliceControl& c, int x, int y) {
    const int u = x - c.ix + ix_last_, v = y - c.iy + iy_last_;
    const size_t i = static_cast<size_t>(v) * width_ + u;
    write_pixel(bp_, u, v, poly_ ? leave_with_polygons(rays_[i], poly_->back[i], r_.p) : pixel_of(rays_[i], r_.p));
    if (!bp_.acc.empty()) bp_.acc[i] = rays_[i];
  }
  void start_polygons();
  // Slab c.k's pixels of beam y behind the beam's rays (those already holding sample c.k).
  void composite_slab(const SliceControl& c, int y, RayAcc* ray);
  void mark_if_stopped(int u, int v) {
    if (words_ > 0 && stop_.can_stop(rays_[static_cast<size_t>(v) * width_ + u]))
      stopped_[static_cast<size_t>(v) * words_ + (u >> 6)] |= uint64_t{1} << (u & 63);
  }
  const R& r_;
  BasePlane& bp_;
  int nx_, ny_, K_, ix_last_, iy_last_, width_;
  BasicRayStopRule<R> stop_;
  int words_;
  std::vector<RayAcc> rays_;
  std::vector<uint64_t> stopped_;  // words_ per base-plane row, bit u: ray u is stopped
  const PolygonFrame* poly_;
};
using SliceCompositor = BasicSliceCompositor<Registers>;
extern template class BasicSliceCompositor<Registers>;
extern template class BasicSliceCompositor<DefaultPrecisionRegisters>;

// An empty base plane of the frame's size, with the warp's shift.
BasePlane empty_base_plane(const Registers& r);
// The warp's shift of the frame's base plane (BasePlane::shift_x, shift_y):
// where ray (0, 0) enters, for either projection, margins included.
void set_base_plane_shift(BasePlane& bp, const Registers& r);

}  // namespace cube4::golden
