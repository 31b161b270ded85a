// The bit-exact perspective renderer (Cube-4 §3): the parallel renderer's
// slice-by-slice traversal with rays that spread from the eye. Rays are
// kept by their base-plane pixel; on each sample slice the rays inside it
// (a rectangle of ray indices, perspective_slice()) are sampled by the box
// filter, their gradients taken from the neighbouring rays and the samples
// realigned straight behind and ahead, then shaded and composited with the
// parallel pipeline's unit functions, on a team of threads each taking
// every T-th row of rays.
// With polygons (golden/polygon_frame.hpp) a ray starts as its front pixel,
// each sample passes the Z test and the slice's slab pixel of the ray (its
// rank among the slice's rays, golden/polygons.hpp) follows it, and the
// back pixel goes behind the ray when the frame ends: the parallel
// compositor's steps (SliceCompositor) on the perspective rays.
#include <algorithm>
#include <exception>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "golden/perspective.hpp"
#include "golden/permuted_volume.hpp"
#include "golden/slice_steps.hpp"
#include "golden/team_barrier.hpp"

namespace cube4::golden {
namespace {

// Sample values (or tags) of one slice by base-plane pixel, with the slice
// that says which rays have one.
struct RayPlane {
  int width = 0, height = 0, origin_x = 0, origin_y = 0;
  PerspectiveSlice slice;
  bool valid = false;  // a slice of the volume (k in range)
  std::vector<uint32_t> v;
  std::vector<int32_t> z;  // with the voxel-difference z gradient: each ray's filtered z difference
  RayPlane(int w, int h, int ox, int oy, bool z_differences)
      : width(w), height(h), origin_x(ox), origin_y(oy), v(static_cast<size_t>(w) * h, 0),
        z(z_differences ? v.size() : 0, 0) {}
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
        lo_(r.dim[0], r.dim[1], kBoxPad), hi_(lo_), voxel_z_(r.gradient && r.z_gradient == ZGradient::VoxelDifferences),
        behind_(plane()), current_(plane()), ahead_(plane()), tag_(plane()), next_tag_(plane()),
        faces_(make_face_table(r)) {
    if (voxel_z_) below_ = above_ = d_lo_ = d_hi_ = lo_;
  }

  void run() {
    const bool may_skip = r_.blend == BlendMode::Composite && opt_.probe == nullptr;
    // Rays stop as in the parallel renderer (RayStop): at a settled pixel,
    // or at full α when the accumulators are asked for.
    stop_ = RayStopRule(!may_skip ? RayStop::never : opt_.accumulators ? RayStop::full_alpha : RayStop::settled_pixel,
                        r_.blend, r_.p);
    may_skip_ = may_skip;
    stopped_.assign(rays_.size(), 0);
    poly_ = opt_.polygons;
    if (poly_) start_polygons(*poly_);
    for (int first = 0; first < (r_.gradient ? 2 : 1); ++first) {
      RayPlane& out = first == 0 ? current_ : ahead_;
      RayPlane& tags = first == 0 ? tag_ : next_tag_;
      const int z = prepare_slice(first, out, tags);
      if (z >= 0) load_rows(z, 0, 1);
      sample_rows(out, tags, 0, 1);
    }
    // A team of threads, each taking every T-th row of rays (a ray's work
    // is its own: the image is the same for any T). Per slice: shade and
    // composite the rows' samples and slab pixels; then, once all have
    // (the barrier's completion, on one thread), move the planes on and
    // load the next slice's voxels; then sample the rows of the next slice.
    const int T = opt_.probe ? 1 : std::max(1, opt_.threads > 0 ? opt_.threads : default_threads());
    std::vector<uint64_t> counts(static_cast<size_t>(T), 0);
    std::vector<std::exception_ptr> failed(static_cast<size_t>(T));
    int k = 0;
    int load_z = -1;  // the voxel slices the next slice needs loaded, or -1
    auto advance = [&] {
      try {
        if (r_.gradient) {
          std::swap(behind_, current_);
          std::swap(current_, ahead_);
          std::swap(tag_, next_tag_);
          load_z = prepare_slice(k + 2, ahead_, next_tag_);
        } else {
          load_z = prepare_slice(k + 1, current_, tag_);
        }
      } catch (...) {
        failed[0] = std::current_exception();
      }
    };
    // A failure anywhere (a throwing progress callback, say) ends the frame
    // for the whole team at the same slice, so that no thread is left
    // waiting at a barrier.
    bool abandon = false;
    TeamBarrier after_shading(T, advance), after_loading(T), after_sampling(T, [&] {
      for (const std::exception_ptr& e : failed) abandon = abandon || e;
    });
    auto team = [&](int t) {
      auto guarded = [&](auto&& work) {
        try {
          work();
        } catch (...) {
          failed[static_cast<size_t>(t)] = std::current_exception();
        }
      };
      for (int slice = 0; slice < K_; ++slice) {
        guarded([&] { counts[static_cast<size_t>(t)] += shade_rows(slice, t, T); });
        after_shading.arrive_and_wait();
        if (load_z >= 0) {
          guarded([&] { load_rows(load_z, t, T); });
          after_loading.arrive_and_wait();
        }
        guarded([&] {
          if (r_.gradient) sample_rows(ahead_, next_tag_, t, T);
          else sample_rows(current_, tag_, t, T);
        });
        if (t == 0) {
          // The next slice's completion reads k after this barrier.
          ++k;
          if (opt_.progress) guarded([&] { opt_.progress(static_cast<double>(slice + 1) / K_); });
        }
        after_sampling.arrive_and_wait();
        if (abandon) break;
      }
    };
    std::vector<std::thread> workers;
    for (int t = 1; t < T; ++t) workers.emplace_back(team, t);
    team(0);
    for (std::thread& w : workers) w.join();
    for (const std::exception_ptr& e : failed)
      if (e) std::rethrow_exception(e);
    write_rays(bp_, rays_, r_.p, poly_);
    if (opt_.stats) {
      opt_.stats->samples = 0;
      for (uint64_t c : counts) opt_.stats->samples += c;
      opt_.stats->slices = K_;
    }
  }

 private:
  RayPlane plane() const { return RayPlane(bp_.width, bp_.height, ox_, oy_, voxel_z_); }

  // Slice k's samples of rows lo_y + t, lo_y + t + T, ...: shaded and
  // composited, then the slab pixels behind them. Returns the samples seen.
  uint64_t shade_rows(int k, int t, int T) {
    const PerspectiveSlice& s = current_.slice;
    uint64_t count = 0;
    for (int64_t v = s.rays_y.lo + t; v < s.rays_y.hi; v += T) {
      for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
        ++count;
        const size_t i = current_.index(u, v);
        if (stopped_[i] || (poly_ && !sample_before_z(k, poly_->z[i]))) continue;
        RayAcc& ray = rays_[i];
        const uint32_t centre = current_.at(u, v), tag = tagged_ ? tag_.at(u, v) : 0;
        if (may_skip_ && classify(r_.classification, tag, centre, r_.p).a == 0) continue;
        const Gradient g = !r_.gradient              ? Gradient{}
                           : opt_.given_gradients ? opt_.given_gradients->gradient(k, u, v)
                                                  : gradient(u, v);
        const SamplePlace place = sample_place(r_, s, u, v);
        const SliceControl c = placed_control(s, place);
        const ShadedSample out = crop_and_cut(r_, c, place.x, place.y,
                                              shade_classified(r_, centre, tag, g, faces_.get()));
        if (opt_.probe) {
          if (tagged_) opt_.probe->tagged(place.x, place.y, c, tag);
          opt_.probe->sample(place.x, place.y, c, centre, g);
          opt_.probe->shaded(place.x, place.y, c, out);
        }
        ray = blend(r_.blend, ray, out, r_.p);
        if (stop_.active() && stop_.can_stop(ray)) stopped_[i] = 1;
      }
      if (poly_) composite_slab(poly_->slabs[static_cast<size_t>(k)], s, static_cast<int>(v - s.rays_y.lo));
    }
    return count;
  }

  void start_polygons(const PolygonFrame& poly) {
    if (poly.width != bp_.width || poly.height != bp_.height || poly.front.size() != rays_.size() ||
        poly.back.size() != rays_.size() || poly.z.size() != rays_.size() ||
        poly.slabs.size() != static_cast<size_t>(K_) || r_.blend != BlendMode::Composite)
      throw std::logic_error("render_perspective: the polygon frame does not fit the registers' base plane and blend");
    for (size_t i = 0; i < rays_.size(); ++i) {
      rays_[i] = pixel_to_acc(poly.front[i], r_.p);
      if (stop_.active() && stop_.can_stop(rays_[i])) stopped_[i] = 1;
    }
  }

  // Line y of slice s.k's slab behind its samples: slab pixel (x, y) is the
  // slice's ray (rays_x.lo + x, rays_y.lo + y). Not on a stopped ray, whose
  // pixel it cannot change (RayStopRule).
  void composite_slab(const SlabImage& slab, const PerspectiveSlice& s, int y) {
    if (slab.empty()) return;
    slab.for_each_pixel(y, [&](int x, const Pixel& px) {
      const size_t i = current_.index(s.rays_x.lo + x, s.rays_y.lo + y);
      if (stopped_[i]) return;
      rays_[i] = ray_over_pixel(rays_[i], px, r_.p);
      if (stop_.active() && stop_.can_stop(rays_[i])) stopped_[i] = 1;
    });
  }

  Gradient gradient(int64_t u, int64_t v) const {
    const PerspectiveSlice& s = current_.slice;
    auto at = [](const RayPlane& plane) { return [&plane](int64_t a, int64_t b) { return plane.at(a, b); }; };
    if (voxel_z_) return perspective_gradient_voxel_z(r_, s, u, v, at(current_), current_.z[current_.index(u, v)]);
    return perspective_gradient(r_, s, u, v, at(current_), at(behind_), at(ahead_));
  }

  // Slice k's constants into the planes. Returns the voxel slice z whose
  // voxel slices z and z + 1 the samples need loaded first (load_rows), or
  // -1 when they are loaded already or the slice has no samples.
  int prepare_slice(int k, RayPlane& out, RayPlane& tags) {
    out.valid = tags.valid = k >= 0 && k < K_;
    if (!out.valid) return -1;
    out.slice = tags.slice = perspective_slice(r_, k);
    // Given samples need no voxels, but for VolumePro's z gradient.
    if (out.slice.z_voxel == loaded_z_ || (opt_.given_samples && !voxel_z_)) return -1;
    loaded_z_ = out.slice.z_voxel;
    return loaded_z_;
  }

  // Beams t, t + T, ... of voxel slices z and z + 1 (a beam per pipeline:
  // the permuted reads are strided, the costliest loads of the frame).
  void load_rows(int z, int t, int T) {
    const int nx = r_.dim[0];
    for (int y = t; y < r_.dim[1]; y += T) {
      pv_.load_beam(y, z, lo_.row(y));
      pv_.load_beam(y, z + 1, hi_.row(y));
      if (!voxel_z_) continue;
      // The voxel z differences D(z) and D(z + 1), as the parallel renderer's.
      pv_.load_beam(y, z - 1, below_.row(y));
      pv_.load_beam(y, z + 2, above_.row(y));
      for (int x = 0; x < nx; ++x) {
        d_lo_.row(y)[x] = voxel_z_difference(static_cast<uint32_t>(hi_.row(y)[x]), static_cast<uint32_t>(below_.row(y)[x]));
        d_hi_.row(y)[x] = voxel_z_difference(static_cast<uint32_t>(above_.row(y)[x]), static_cast<uint32_t>(lo_.row(y)[x]));
      }
    }
  }

  // The samples (and tags) of the prepared slice's rays in rows lo_y + t,
  // lo_y + t + T, ...
  void sample_rows(RayPlane& out, RayPlane& tags, int t, int T) {
    if (!out.valid) return;
    const PerspectiveSlice& s = out.slice;
    auto voxel = [&](int x, int y, int dz) { return (dz == 0 ? lo_ : hi_).at(x, y); };
    const PerspectiveSamples* given = opt_.given_samples;
    for (int64_t v = s.rays_y.lo + t; v < s.rays_y.hi; v += T)
      for (int64_t u = s.rays_x.lo; u < s.rays_x.hi; ++u) {
        if (given) {
          out.v[out.index(u, v)] = given->sample(s.k, u, v);
          if (tagged_) tags.v[tags.index(u, v)] = given->vtag(s.k, u, v);
          if (!voxel_z_) continue;
        } else {
          out.v[out.index(u, v)] = perspective_sample(r_, s, u, v, voxel);
        }
        if (voxel_z_)
          out.z[out.index(u, v)] = perspective_z_difference(
              r_, s, u, v, [&](int x, int y, int dz) { return (dz == 0 ? d_lo_ : d_hi_).at(x, y); });
        if (tagged_ && !given) {
          const TagVoxel t = perspective_tag_voxel(r_, s, u, v);
          tags.v[tags.index(u, v)] = pv_.tag_at(t.x, t.y, s.z_voxel + t.dz);
        }
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
  bool voxel_z_;
  Plane below_, above_, d_lo_, d_hi_;  // voxel-difference z gradient: V(z - 1), V(z + 2), D(z), D(z + 1)
  RayPlane behind_, current_, ahead_, tag_, next_tag_;
  std::unique_ptr<FacePositionTable> faces_;
  int loaded_z_ = -1;
  RayStopRule stop_{RayStop::never, BlendMode::Composite, Precision{}};
  bool may_skip_ = false;
  std::vector<uint8_t> stopped_;
  const PolygonFrame* poly_ = nullptr;
};

}  // namespace

BasePlane render_perspective(const Volume& vol, const Registers& r, const FixedOptions& opt) {
  BasePlane bp = empty_base_plane(r);
  if (opt.accumulators) bp.acc.assign(static_cast<size_t>(bp.width) * bp.height, RayAcc{});
  Traversal(vol, r, opt, bp).run();
  return bp;
}

}  // namespace cube4::golden
