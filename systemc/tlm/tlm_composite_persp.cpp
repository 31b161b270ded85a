#include "systemc/tlm/tlm_composite_persp.hpp"

#include <stdexcept>
#include <string>

#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/slice_steps.hpp"

namespace cube4::sysc {

TlmCompositePersp::TlmCompositePersp(const FramePlan& plan, bool accumulators, const golden::PolygonFrame* polygons)
    : plan_(plan),
      accumulators_(accumulators),
      polygons_(polygons),
      origin_x_(plan.r.base_origin_x()),
      origin_y_(plan.r.base_origin_y()),
      per_frame_(golden::perspective_samples(plan.r)),
      plane_(golden::empty_base_plane(plan.r)) {
  if (polygons && (polygons->width != plane_.width || polygons->height != plane_.height ||
                   polygons->slabs.size() != static_cast<size_t>(plan.K) || plan.r.blend != golden::BlendMode::Composite))
    throw std::logic_error("TlmCompositePersp: the polygon frame does not fit the registers' base plane and blend");
  start_frame();
}

void TlmCompositePersp::start_frame() {
  rays_.assign(static_cast<size_t>(plane_.width) * plane_.height, golden::RayAcc{});
  if (polygons_)
    for (size_t i = 0; i < rays_.size(); ++i) rays_[i] = golden::pixel_to_acc(polygons_->front[i], plan_.r.p);
}

const std::vector<golden::Pixel>& TlmCompositePersp::slab(uint32_t k) {
  for (auto& [slice, pixels] : slabs_)
    if (slice == k) return pixels;
  auto& [slice, pixels] = slabs_[0].first < slabs_[1].first ? slabs_[0] : slabs_[1];
  const golden::PerspectiveSlice& s = plan_.persp[k];
  const golden::SlabImage& image = polygons_->slabs[k];
  // Rays are at least a voxel apart: their ranks fit the volume's slice.
  if (s.rays_x.hi - s.rays_x.lo > image.width() || s.rays_y.hi - s.rays_y.lo > image.beams())
    throw std::logic_error("TlmCompositePersp: slice " + std::to_string(k) + "'s slab image (" +
                           std::to_string(image.width()) + " x " + std::to_string(image.beams()) +
                           ") is smaller than its rays");
  const auto width = static_cast<size_t>(image.width());
  pixels.assign(width * static_cast<size_t>(image.beams()), golden::Pixel{});
  if (!image.empty())
    for (int y = 0; y < image.beams(); ++y) image.decode_beam(y, &pixels[static_cast<size_t>(y) * width]);
  slice = k;
  return pixels;
}

void TlmCompositePersp::composite(const RayShadedBeat& in, size_t lane) {
  const uint32_t k = in.tag[lane];
  const int64_t u = in.u[lane], v = in.v[lane];
  if (k >= static_cast<uint32_t>(plan_.K) || !golden::samples(plan_.persp[k], u, v))
    throw std::logic_error("TlmCompositePersp: a sample of no ray of its slice (slice " + std::to_string(k) +
                           ", ray (" + std::to_string(u) + ", " + std::to_string(v) + "))");
  const golden::PerspectiveSlice& s = plan_.persp[k];
  const golden::SamplePlace place = golden::sample_place(plan_.r, s, u, v);
  golden::SliceControl c;
  c.k = static_cast<int>(k);
  c.z_voxel = s.z_voxel;
  c.wz = s.wz;
  c.wx = place.wx;
  c.wy = place.wy;
  golden::ShadedSample shaded;
  shaded.rgb = {in.red[lane], in.green[lane], in.blue[lane]};
  shaded.alpha = in.alpha[lane];
  shaded.value = in.value[lane];
  const golden::ShadedSample out = golden::crop_and_cut(plan_.r, c, place.x, place.y, shaded);
  const size_t i =
      static_cast<size_t>(v + origin_y_) * static_cast<size_t>(plane_.width) + static_cast<size_t>(u + origin_x_);
  golden::RayAcc& ray = rays_[i];
  if (!polygons_) {
    ray = golden::blend(plan_.r.blend, ray, out, plan_.r.p);
    return;
  }
  // The slab's pixel (x, y) lies behind the slice's ray of rank (x, y).
  const auto width = static_cast<size_t>(polygons_->slabs[k].width());
  const golden::Pixel& behind = slab(k)[static_cast<size_t>(v - s.rays_y.lo) * width + static_cast<size_t>(u - s.rays_x.lo)];
  ray = golden::double_composite(ray, out, golden::sample_before_z(static_cast<int>(k), polygons_->z[i]), behind,
                                 plan_.r.p);
}

void TlmCompositePersp::end_frame() {
  plane_ = golden::empty_base_plane(plan_.r);
  if (accumulators_) plane_.acc.assign(rays_.size(), golden::RayAcc{});
  golden::write_rays(plane_, rays_, plan_.r.p, polygons_);
  start_frame();
  composited_ = 0;
  ++frames_done_;
}

void TlmCompositePersp::clock(const RayShadedBeat& in, CompositeOut& out) {
  out = CompositeOut{};
  out.frame_done = done_[head_];
  done_[head_] = false;
  for (int k = 0; in.valid && k < plan_.p; ++k) {
    if (!(in.valid >> k & 1)) continue;
    composite(in, static_cast<size_t>(k));
    if (++composited_ == per_frame_) {
      end_frame();
      done_[head_] = true;
    }
  }
  head_ = (head_ + 1) % done_.size();
}

}  // namespace cube4::sysc
