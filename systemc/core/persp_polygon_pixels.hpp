// What a perspective compositing unit reads of a frame's polygon images
// (Cube-5 in perspective, docs/perspective.md): a ray's start (its front
// pixel widened, or the empty accumulator without polygons) and the slab
// pixel behind a sample (the slab image of its slice at the ray's rank:
// pixel (x, y) lies behind the slice's ray (rays_x.lo + x, rays_y.lo + y)).
// TlmCompositePersp and RtlCompositePersp both read through it; the slab
// images are decoded as their slices are asked for (the last two kept, as
// a unit asks for slices in order with the next one overlapping).
#pragma once
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "golden/polygon_frame.hpp"
#include "golden/units/composite_polygon.hpp"
#include "systemc/core/frame_plan.hpp"

namespace cube4::sysc {

class PerspPolygonPixels {
 public:
  // `polygons` may be null (a frame without polygons); it must outlive this
  // and fit the registers' base plane, slices and blend.
  PerspPolygonPixels(const FramePlan& plan, const golden::PolygonFrame* polygons) : plan_(plan), polygons_(polygons) {
    if (polygons && (polygons->width != plan.r.base_width() || polygons->height != plan.r.base_height() ||
                     polygons->slabs.size() != static_cast<size_t>(plan.K) ||
                     plan.r.blend != golden::BlendMode::Composite))
      throw std::logic_error("perspective compositing: the polygon frame does not fit the registers' base plane, "
                             "slices and blend");
  }

  const golden::PolygonFrame* frame() const { return polygons_; }
  golden::RayAcc start(size_t pixel) const {
    return polygons_ ? golden::pixel_to_acc(polygons_->front[pixel], plan_.r.p) : golden::RayAcc{};
  }
  // The slab pixel behind ray (u, v)'s sample of slice k (with polygons).
  const golden::Pixel& behind(uint32_t k, int64_t u, int64_t v) {
    const golden::PerspectiveSlice& s = plan_.persp[k];
    const auto width = static_cast<size_t>(polygons_->slabs[k].width());
    return slab(k)[static_cast<size_t>(v - s.rays_y.lo) * width + static_cast<size_t>(u - s.rays_x.lo)];
  }

 private:
  const std::vector<golden::Pixel>& slab(uint32_t k) {
    for (auto& [slice, pixels] : slabs_)
      if (slice == k) return pixels;
    auto& [slice, pixels] = slabs_[0].first < slabs_[1].first ? slabs_[0] : slabs_[1];
    const golden::PerspectiveSlice& s = plan_.persp[k];
    const golden::SlabImage& image = polygons_->slabs[k];
    // Rays are at least a voxel apart: their ranks fit the volume's slice.
    if (s.rays_x.hi - s.rays_x.lo > image.width() || s.rays_y.hi - s.rays_y.lo > image.beams())
      throw std::logic_error("perspective compositing: slice " + std::to_string(k) + "'s slab image (" +
                             std::to_string(image.width()) + " x " + std::to_string(image.beams()) +
                             ") is smaller than its rays");
    const auto width = static_cast<size_t>(image.width());
    pixels.assign(width * static_cast<size_t>(image.beams()), golden::Pixel{});
    if (!image.empty())
      for (int y = 0; y < image.beams(); ++y) image.decode_beam(y, &pixels[static_cast<size_t>(y) * width]);
    slice = k;
    return pixels;
  }

  const FramePlan& plan_;
  const golden::PolygonFrame* polygons_;
  std::array<std::pair<int64_t, std::vector<golden::Pixel>>, 2> slabs_{{{-1, {}}, {-1, {}}}};
};

}  // namespace cube4::sysc
