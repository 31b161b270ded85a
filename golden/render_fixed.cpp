// The bit-exact fixed-point renderer: the hardware's traversal (slice by
// slice, beam by beam, in permuted order) built only from the unit functions,
// in the slice steps of golden/slice_steps.hpp.
//
// Threads each take a band of base-plane rows, i.e. a set of rays, and
// follow it through every slice (its beams move by the DDA's y offset). No
// ray is touched by two bands, so bands need no synchronisation, and each
// ray sees the same samples in the same order whatever the number of bands:
// the image is the same for every thread count. A band interpolates the
// beams its gradients read too, one beyond its own on each side.
#include <algorithm>
#include <array>
#include <exception>
#include <memory>
#include <thread>
#include <vector>

#include "golden/slice_steps.hpp"

namespace cube4::golden {

namespace {

template <class R>
struct Frame {
  const R& r;
  PermutedVolume access;
  const SkipMap& skip;
  BasicSliceCompositor<R>& compositor;
  const FacePositionTable* faces;
  SampleProbe* probe;
  bool may_skip;
};

// Beams [first, second) of slice k.
using Beams = std::pair<int, int>;

template <class R>
class Band {
 public:
  Band(const Frame<R>& f, int v0, int v1)
      : f_(f), r_(f.r), nx_(r_.dim[0]), ny_(r_.dim[1]), K_(r_.sample_slices()), reach_(r_.gradient ? 1 : 0),
        iy_last_(r_.base_origin_y()), v0_(v0), v1_(v1), tagged_(r_.p.tag_bits > 0),
        voxel_z_(r_.gradient && r_.z_gradient == ZGradient::VoxelDifferences), vox_lo_(nx_, ny_, 1),
        vox_hi_(nx_, ny_, 1), interp_(nx_, ny_, r_.p.weight_bits), spans_(static_cast<size_t>(ny_)),
        shading_(r_, f.faces) {
    if (tagged_) tag_lo_ = tag_hi_ = tag_current_ = tag_ahead_ = Plane(nx_, ny_, 1);
    if (voxel_z_) {
      for (Plane& v : zvox_) v = Plane(nx_, ny_, 1);
      zdiff_lo_ = zdiff_hi_ = zdiff_ = Plane(nx_, ny_, 1);
    }
  }

  void run(const Progress* progress) {
    const R& r = r_;
    int32_t first_visible = 0;
    while (first_visible < static_cast<int32_t>(r.class_values()) && !r.value_visible(first_visible)) ++first_visible;
    // Sample slices behind, current and ahead of the one being shaded.
    Plane behind(nx_, ny_, 1), current(nx_, ny_, 1), ahead(nx_, ny_, 1);
    samples_of(0, current, tag_current_);
    if (r.gradient) samples_of(1, ahead, tag_ahead_);
    Neighbourhood n;
    for (int k = 0; k < K_; ++k) {
      const SliceControl c = slice_control(r, k);
      // Which samples of beam y may change their ray: none outside the skip
      // map's span, nor those at its ends below the first value of non-zero α.
      auto beam = [&](int y) -> Span {
        Span s = f_.skip.visible(c.z_voxel, y);
        if (!f_.may_skip) return s;
        const int32_t* samples = current.row(y);
        while (s.begin < s.end && samples[s.begin] < first_visible) ++s.begin;
        while (s.end > s.begin && samples[s.end - 1] < first_visible) --s.end;
        return s;
      };
      // Neither gradient nor shading of a sample that cannot change its
      // ray (sample_cannot_change_ray) is computed, nor those of rays the
      // compositor has stopped (RayStop).
      auto shade = [&](int x, int y, const RayAcc&, ShadedSample& s) {
        const uint32_t centre = current.at(x, y);
        const uint32_t tag = tagged_ ? tag_current_.at(x, y) : 0;
        if (f_.may_skip && sample_cannot_change_ray(r, centre, tag)) return false;
        if (r.gradient) {
          gather_neighbourhood(behind, current, ahead, c, x, y, n);
          if (voxel_z_) n.z_difference = zdiff_.row(y)[x];
        } else {
          n.centre = centre;
        }
        n.tag = tag;
        ++shaded_;
        s = shade_sample_with(r, c, x, y, n, shading_);
        if (f_.probe) {
          if (tagged_) f_.probe->tagged(x, y, c, tag);
          f_.probe->sample(x, y, c, n.centre, r.gradient ? sample_gradient(r, c, n) : Gradient{});
          f_.probe->shaded(x, y, c, s);
        }
        return true;
      };
      if (voxel_z_) z_differences_of(c);
      f_.compositor.slice(c, shade, beam, v0_, v1_);
      if (r.gradient) {
        std::swap(behind, current);
        std::swap(current, ahead);
        std::swap(tag_current_, tag_ahead_);
        samples_of(k + 2, ahead, tag_ahead_);
      } else if (k + 1 < K_) {
        samples_of(k + 1, current, tag_current_);
      }
      if (progress && *progress) (*progress)(static_cast<double>(k + 1) / K_);
    }
    f_.compositor.finish(v0_, v1_);
  }
  uint64_t shaded() const { return shaded_; }

 private:
  // The band's own beams of slice k.
  Beams beams(int k) const {
    const int iy = r_.y_offset(std::clamp(k, 0, K_ - 1)).integer;
    return {std::clamp(v0_ + iy - iy_last_, 0, ny_), std::clamp(v1_ + iy - iy_last_, 0, ny_)};
  }
  // The beams of slice k the band interpolates: its own, and those the
  // gradients of slices k - 1 .. k + 1 read (one beam further each way).
  Beams sample_beams(int k) const {
    return {std::max(beams(k - reach_).first - reach_, 0), std::min(beams(k + reach_).second + reach_, ny_)};
  }
  // The voxel beams of slice z that those read: sample beam y reads voxel
  // beams y and y + 1 of the voxel slices below and above it.
  Beams voxel_beams(int z) const {
    const int S = r_.supersampling;
    const int k0 = std::max(S * (z - 1), 0), k1 = std::min(S * (z + 1), K_) - 1;
    if (k0 > k1) return {0, 0};
    return {sample_beams(k0).first, std::min(sample_beams(k1).second + 1, ny_)};
  }
  void load(int z, Plane& out, Plane& tags) {
    const Beams b = voxel_beams(z);
    for (int y = b.first; y < b.second; ++y) spans_[static_cast<size_t>(y)] = f_.skip.voxels_needed(z, y);
    load_voxel_slice(f_.access, z, out, b.first, b.second, spans_.data());
    if (tagged_) load_tag_slice(f_.access, z, tags, b.first, b.second, spans_.data());
  }
  // Sample slice k's values into out and, with tags, its tags into tags.
  void samples_of(int k, Plane& out, Plane& tags) {
    if (k < 0 || k >= K_) {
      out.clear();
      if (tagged_) tags.clear();
      return;
    }
    const SliceControl c = slice_control(r_, k);
    if (c.z_voxel != loaded_z_) {
      if (c.z_voxel == loaded_z_ + 1 && loaded_z_ >= 0) {
        std::swap(vox_lo_, vox_hi_);
        std::swap(tag_lo_, tag_hi_);
      } else {
        load(c.z_voxel, vox_lo_, tag_lo_);
      }
      load(c.z_voxel + 1, vox_hi_, tag_hi_);
      loaded_z_ = c.z_voxel;
    }
    const Beams b = sample_beams(k);
    for (int y = b.first; y < b.second; ++y) spans_[static_cast<size_t>(y)] = f_.skip.samples_needed(k, y);
    interp_.slice(vox_lo_, vox_hi_, c, out, b.first, b.second, spans_.data());
    if (tagged_) interp_.tags(tag_lo_, tag_hi_, c, tags, b.first, b.second, spans_.data());
  }

  // VolumePro's z gradient: the voxel z differences D(z) = V(z+1) - V(z-1)
  // of voxel slices z_voxel and z_voxel + 1 interpolated to slice k's own
  // samples (those of the band's beams the compositor may shade). Whole
  // slices: D(z + 1) of one voxel slice is D(z) of the next.
  void z_differences_of(const SliceControl& c) {
    const int z = c.z_voxel;
    if (z != zvox_z_) {
      if (z == zvox_z_ + 1) {
        std::swap(zvox_[0], zvox_[1]);
        std::swap(zvox_[1], zvox_[2]);
        std::swap(zvox_[2], zvox_[3]);
        std::swap(zdiff_lo_, zdiff_hi_);
        load_voxel_slice(f_.access, z + 2, zvox_[3]);
      } else {
        for (int i = 0; i < 4; ++i) load_voxel_slice(f_.access, z - 1 + i, zvox_[static_cast<size_t>(i)]);
        voxel_z_differences(zvox_[2], zvox_[0], zdiff_lo_);
      }
      voxel_z_differences(zvox_[3], zvox_[1], zdiff_hi_);
      zvox_z_ = z;
    }
    const Beams b = beams(c.k);
    for (int y = b.first; y < b.second; ++y) spans_[static_cast<size_t>(y)] = f_.skip.samples_needed(c.k, y);
    interp_.slice(zdiff_lo_, zdiff_hi_, c, zdiff_, b.first, b.second, spans_.data());
  }

  const Frame<R>& f_;
  const R& r_;
  int nx_, ny_, K_, reach_, iy_last_, v0_, v1_;
  bool tagged_, voxel_z_;
  std::array<Plane, 4> zvox_;  // voxel slices z_voxel - 1 .. z_voxel + 2
  Plane zdiff_lo_, zdiff_hi_;  // D(z_voxel), D(z_voxel + 1)
  Plane zdiff_;                // the shaded slice's interpolated z differences
  int zvox_z_ = -2;
  Plane vox_lo_, vox_hi_;  // voxel slices z_voxel and z_voxel + 1
  // With tags: the tags of those voxel slices and of the samples of the
  // slice being shaded and the one ahead (empty planes without tags).
  Plane tag_lo_, tag_hi_, tag_current_, tag_ahead_;
  SliceInterp interp_;
  std::vector<Span> spans_;
  int loaded_z_ = -1;
  uint64_t shaded_ = 0;
  BasicGradientShadingCache<R> shading_;
};

// Bands of base-plane rows with about equal work: a beam costs its
// interpolation and the samples that may change their ray.
std::vector<int> band_edges(const Registers& r, const SkipMap& skip, int bands) {
  const int height = r.base_height(), K = r.sample_slices(), ny = r.dim[1];
  const int iy_last = r.base_origin_y();
  std::vector<double> work(static_cast<size_t>(height), 0.0);
  for (int k = 0; k < K; ++k) {
    const int iy = r.y_offset(k).integer, z = z_voxel_slice(k, r.supersampling);
    for (int y = 0; y < ny; ++y)
      work[static_cast<size_t>(y - iy + iy_last)] += 0.25 * r.dim[0] + skip.visible(z, y).size();
  }
  double total = 0;
  for (double w : work) total += w;
  std::vector<int> edges{0};
  double sum = 0;
  for (int v = 0; v < height && static_cast<int>(edges.size()) < bands; ++v) {
    sum += work[static_cast<size_t>(v)];
    if (sum >= total * static_cast<double>(edges.size()) / bands) edges.push_back(v + 1);
  }
  edges.push_back(height);
  return edges;
}

}  // namespace

int default_threads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

namespace {

// The parallel-projection frame with registers of type R.
template <class R>
BasePlane render_parallel(const Volume& vol, const R& r, const FixedOptions& opt) {
  BasePlane bp = empty_base_plane(r);
  if (opt.accumulators) bp.acc.assign(static_cast<size_t>(bp.width) * bp.height, RayAcc{});
  const bool may_skip = r.blend == BlendMode::Composite && opt.probe == nullptr;
  BlockRanges own;
  const BlockRanges* ranges = nullptr;
  if (may_skip && opt.skip_empty) {
    if (!opt.ranges) own = block_ranges(vol);
    ranges = opt.ranges ? opt.ranges : &own;
  }
  const SkipMap skip(r, ranges);
  // Without accumulators asked for, only the base plane's pixels must be exact.
  const RayStop stop = !may_skip ? RayStop::never : opt.accumulators ? RayStop::full_alpha : RayStop::settled_pixel;
  BasicSliceCompositor<R> compositor(r, bp, opt.polygons, stop);
  const std::unique_ptr<FacePositionTable> faces = make_face_table(r);
  const Frame<R> frame{r, PermutedVolume(vol, r.perm, r.flip), skip, compositor, faces.get(), opt.probe, may_skip};
  const int threads = opt.probe ? 1 : std::clamp(opt.threads > 0 ? opt.threads : default_threads(), 1,
                                                 std::max(1, bp.height));
  const std::vector<int> edges = threads == 1 ? std::vector<int>{0, bp.height} : band_edges(r, skip, threads);
  std::vector<std::thread> workers;
  std::vector<std::exception_ptr> failed(edges.size() - 1);
  std::vector<uint64_t> shaded(edges.size() - 1, 0);
  auto run_band = [&](size_t b, const Progress* progress) {
    try {
      Band<R> band(frame, edges[b], edges[b + 1]);
      band.run(progress);
      shaded[b] = band.shaded();
    } catch (...) {
      failed[b] = std::current_exception();
    }
  };
  for (size_t b = 1; b + 1 < edges.size(); ++b) workers.emplace_back(run_band, b, nullptr);
  run_band(0, &opt.progress);
  for (std::thread& t : workers) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);

  if (opt.stats) {
    opt.stats->samples = static_cast<uint64_t>(r.dim[0]) * r.dim[1] * r.sample_slices();
    opt.stats->slices = r.sample_slices();
    opt.stats->shaded = 0;
    for (uint64_t n : shaded) opt.stats->shaded += n;
  }
  return bp;
}

}  // namespace

BasePlane render_fixed(const Volume& vol, const Registers& r, const FixedOptions& opt) {
  check_dda(r);
  if (r.perspective) return render_perspective(vol, r, opt);
  // Most frames run at the default widths: their loops with the widths as
  // constants (about a fifth fewer instructions, docs/performance.md).
  if (opt.constant_widths && DefaultPrecisionRegisters::has_default_precision(r))
    return render_parallel(vol, DefaultPrecisionRegisters(r), opt);
  return render_parallel(vol, r, opt);
}

BasePlane render_fixed(const Volume& vol, const Registers& r, RenderStats* stats, const Progress& progress,
                       SampleProbe* probe) {
  FixedOptions opt;
  opt.stats = stats;
  opt.progress = progress;
  opt.probe = probe;
  return render_fixed(vol, r, opt);
}

ImageF BasePlane::to_float() const {
  ImageF f;
  f.width = width;
  f.height = height;
  f.rgba.resize(rgba.size());
  const float scale = 1.0f / static_cast<float>((1u << bits) - 1u);
  for (size_t i = 0; i < rgba.size(); ++i) f.rgba[i] = rgba[i] * scale;
  return f;
}

}  // namespace cube4::golden
