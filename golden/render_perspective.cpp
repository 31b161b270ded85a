// The bit-exact perspective renderer (Cube-4 §3): the parallel renderer's
// slice-by-slice traversal with rays that spread from the eye. Rays are
// kept by their base-plane pixel; on each sample slice the rays inside it
// (a rectangle of ray indices, perspective_slice()) are sampled by the box
// filter, their gradients taken from the neighbouring rays and the samples
// realigned straight behind and ahead, then shaded and composited with the
// parallel pipeline's unit functions. One thread: the algorithm, not speed.
// With polygons (golden/polygon_frame.hpp) a ray starts as its front pixel,
// each sample passes the Z test and the slice's slab pixel of the ray (its
// rank among the slice's rays, golden/polygons.hpp) follows it, and the
// back pixel goes behind the ray when the frame ends: the parallel
// compositor's steps (SliceCompositor) on the perspective rays.
#include <algorithm>
#include <memory>
#include <stdexcept>
#include <vector>

#include "golden/perspective.hpp"
#include "golden/permuted_volume.hpp"
#include "golden/slice_steps.hpp"

namespace cube4::golden {
namespace {

// Sample values (or tags) of one slice by base-plane pixel, with the slice
// that says which rays have one.
struct RayPlane {
  int width = 0, height = 0, origin_x = 0, origin_y = 0;
  PerspectiveSlice slice;
  bool valid = false;  // a slice of the volume (k in range)
  std::vector<uint32_t> v;
  RayPlane(int w, int h, int ox, int oy)
      : width(w), height(h), origin_x(ox), origin_y(oy), v(static_cast<size_t>(w) * h, 0) {}
  size_t index(int64_t u, int64_t v_) const {
    return static_cast<size_t>(v_ + origin_y) * width + static_cast<size_t>(u + origin_x);
  }
  // Ray (u, v)'s sample; zero for rays that miss the slice, as the parallel
  // pipeline's samples beyond the volume are.
  uint32_t at(int64_t u, int64_t v_) const { return valid && samples(slice, u, v_) ? v[index(u, v_)] : 0; }
};

// Voxel slices with a border of zeros wide enough for the widest box.
constexpr int kBoxPad = 3;

class Traversal {
 public:
  Traversal(const Volume& vol, const Registers& r, const FixedOptions& opt, BasePlane& bp)
      : r_(r), opt_(opt), bp_(bp), pv_(vol, r.perm, r.flip), K_(r.sample_slices()), tagged_(r.p.tag_bits > 0),
        ox_(r.base_origin_x()), oy_(r.base_origin_y()), rays_(static_cast<size_t>(bp.width) * bp.height),
        lo_(r.dim[0], r.dim[1], kBoxPad), hi_(lo_), behind_(plane()), current_(plane()), ahead_(plane()),
        tag_(plane()), next_tag_(plane()), faces_(make_face_table(r)) {}

  void run() {
    const bool may_skip = r_.blend == BlendMode::Composite && opt_.probe == nullptr;
    // Rays stop as in the parallel renderer (RayStop): at a settled pixel,
    // or at full α when the accumulators are asked for.
    const RayStopRule stop(!may_skip ? RayStop::never : opt_.accumulators ? RayStop::full_alpha : RayStop::settled_pixel,
                           r_.blend, r_.p);
    std::vector<uint8_t> stopped(rays_.size(), 0);
    const PolygonFrame* poly = opt_.polygons;
    if (poly) start_polygons(*poly, stop, stopped);
    sample_slice(0, current_, tag_);
    if (r_.gradient) sample_slice(1, ahead_, next_tag_);
    uint64_t count = 0;
    for (int k = 0; k < K_; ++k) {
      const PerspectiveSlice& s = current_.slice;
      for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
        for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
          ++count;
          const size_t i = current_.index(u, v);
          if (stopped[i] || (poly && !sample_before_z(k, poly->z[i]))) continue;
          RayAcc& ray = rays_[i];
          const uint32_t centre = current_.at(u, v), tag = tagged_ ? tag_.at(u, v) : 0;
          if (may_skip && classify(r_.classification, tag, centre, r_.p).a == 0) continue;
          const Gradient g = r_.gradient ? gradient(u, v) : Gradient{};
          const SamplePlace place = sample_place(r_, s, u, v);
          SliceControl c;
          c.k = k;
          c.z_voxel = s.z_voxel;
          c.wz = s.wz;
          c.wx = place.wx;
          c.wy = place.wy;
          const ShadedSample out = crop_and_cut(r_, c, place.x, place.y,
                                                shade_classified(r_, centre, tag, g, faces_.get()));
          if (opt_.probe) {
            if (tagged_) opt_.probe->tagged(place.x, place.y, c, tag);
            opt_.probe->sample(place.x, place.y, c, centre, g);
            opt_.probe->shaded(place.x, place.y, c, out);
          }
          ray = blend(r_.blend, ray, out, r_.p);
          if (stop.active() && stop.can_stop(ray)) stopped[i] = 1;
        }
      if (poly) composite_slab(poly->slabs[static_cast<size_t>(k)], s, stop, stopped);
      if (r_.gradient) {
        std::swap(behind_, current_);
        std::swap(current_, ahead_);
        std::swap(tag_, next_tag_);
        sample_slice(k + 2, ahead_, next_tag_);
      } else if (k + 1 < K_) {
        sample_slice(k + 1, current_, tag_);
      }
      if (opt_.progress) opt_.progress(static_cast<double>(k + 1) / K_);
    }
    for (int y = 0; y < bp_.height; ++y)
      for (int x = 0; x < bp_.width; ++x) {
        const size_t i = static_cast<size_t>(y) * bp_.width + x;
        write_pixel(bp_, x, y, poly ? leave_with_polygons(rays_[i], poly->back[i], r_.p) : pixel_of(rays_[i], r_.p));
        if (!bp_.acc.empty()) bp_.acc[i] = rays_[i];
      }
    if (opt_.stats) {
      opt_.stats->samples = count;
      opt_.stats->slices = K_;
    }
  }

 private:
  RayPlane plane() const { return RayPlane(bp_.width, bp_.height, ox_, oy_); }

  void start_polygons(const PolygonFrame& poly, const RayStopRule& stop, std::vector<uint8_t>& stopped) {
    if (poly.width != bp_.width || poly.height != bp_.height || poly.front.size() != rays_.size() ||
        poly.back.size() != rays_.size() || poly.z.size() != rays_.size() ||
        poly.slabs.size() != static_cast<size_t>(K_) || r_.blend != BlendMode::Composite)
      throw std::logic_error("render_perspective: the polygon frame does not fit the registers' base plane and blend");
    for (size_t i = 0; i < rays_.size(); ++i) {
      rays_[i] = pixel_to_acc(poly.front[i], r_.p);
      if (stop.active() && stop.can_stop(rays_[i])) stopped[i] = 1;
    }
  }

  // Slice s.k's slab behind its samples: slab pixel (x, y) is the slice's
  // ray (rays_x.lo + x, rays_y.lo + y). Not on a stopped ray, whose pixel it
  // cannot change (RayStopRule).
  void composite_slab(const SlabImage& slab, const PerspectiveSlice& s, const RayStopRule& stop,
                      std::vector<uint8_t>& stopped) {
    if (slab.empty()) return;
    for (int y = 0; y < s.rays_y.hi - s.rays_y.lo; ++y)
      slab.for_each_pixel(y, [&](int x, const Pixel& px) {
        const size_t i = current_.index(s.rays_x.lo + x, s.rays_y.lo + y);
        if (stopped[i]) return;
        rays_[i] = ray_over_pixel(rays_[i], px, r_.p);
        if (stop.active() && stop.can_stop(rays_[i])) stopped[i] = 1;
      });
  }

  Gradient gradient(int64_t u, int64_t v) const {
    const PerspectiveSlice& s = current_.slice;
    auto behind = [&](int64_t a, int64_t b) { return behind_.at(a, b); };
    auto ahead = [&](int64_t a, int64_t b) { return ahead_.at(a, b); };
    return gradient_perspective(current_.at(u - 1, v), current_.at(u + 1, v), current_.at(u, v - 1),
                                current_.at(u, v + 1), realigned_sample(r_, s.behind_x, s.behind_y, u, v, behind),
                                realigned_sample(r_, s.ahead_x, s.ahead_y, u, v, ahead), r_.supersampling,
                                s.lateral_reciprocal, r_.p);
  }

  // Slice k's samples (and tags) of every ray that has one.
  void sample_slice(int k, RayPlane& out, RayPlane& tags) {
    out.valid = tags.valid = k >= 0 && k < K_;
    if (!out.valid) return;
    out.slice = tags.slice = perspective_slice(r_, k);
    const PerspectiveSlice& s = out.slice;
    if (s.z_voxel != loaded_z_) {
      load_voxel_slice(pv_, s.z_voxel, lo_);
      load_voxel_slice(pv_, s.z_voxel + 1, hi_);
      loaded_z_ = s.z_voxel;
    }
    auto voxel = [&](int x, int y, int dz) { return (dz == 0 ? lo_ : hi_).at(x, y); };
    const int F = r_.p.dda_frac_bits;
    const int dz_tag = upper_corner(s.wz, r_.p.weight_bits);
    for (int64_t v = s.rays_y.lo; v < s.rays_y.hi; ++v)
      for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
        out.v[out.index(u, v)] = perspective_sample(r_, s, u, v, voxel);
        if (tagged_)
          tags.v[tags.index(u, v)] = pv_.tag_at(nearest_voxel(ray_position(s.ray0_x, s.spacing, u), F),
                                                nearest_voxel(ray_position(s.ray0_y, s.spacing, v), F),
                                                s.z_voxel + dz_tag);
      }
  }

  const Registers& r_;
  const FixedOptions& opt_;
  BasePlane& bp_;
  PermutedVolume pv_;
  int K_;
  bool tagged_;
  int ox_, oy_;
  std::vector<RayAcc> rays_;
  Plane lo_, hi_;
  RayPlane behind_, current_, ahead_, tag_, next_tag_;
  std::unique_ptr<FacePositionTable> faces_;
  int loaded_z_ = -1;
};

}  // namespace

BasePlane render_perspective(const Volume& vol, const Registers& r, const FixedOptions& opt) {
  BasePlane bp = empty_base_plane(r);
  if (opt.accumulators) bp.acc.assign(static_cast<size_t>(bp.width) * bp.height, RayAcc{});
  Traversal(vol, r, opt, bp).run();
  return bp;
}

}  // namespace cube4::golden
