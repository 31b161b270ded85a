#include "systemc/tlm/tlm_composite.hpp"

#include <algorithm>

namespace cube4::sysc {

TlmComposite::TlmComposite(const FramePlan& plan, PixelMemory& pixels, const golden::PolygonFrame* polygons)
    : plan_(plan), pixels_(pixels), polygons_(polygons), slice_(static_cast<size_t>(plan.nx) * plan.ny),
      changing_(static_cast<size_t>(plan.ny), golden::Span{plan.nx, 0}) {}

void TlmComposite::clock(const ShadedBeat& in, CompositeOut& out) {
  // It writes pixel memory directly: its pixel ports stay idle.
  out.pixel_valid = 0;
  out.frame_done = false;
  if (!in.valid) return;
  for (int k = 0; k < plan_.p; ++k) {
    const int x = in.x + k;
    if (x >= plan_.nx) continue;
    const auto i = static_cast<size_t>(k);
    golden::ShadedSample& s = slice_[static_cast<size_t>(in.y) * plan_.nx + x];
    s.rgb = {in.red[i], in.green[i], in.blue[i]};
    s.alpha = in.alpha[i];
    s.value = in.value[i];
    s.visible = true;
    if (golden::blend_changes_ray(plan_.r.blend, s)) {
      golden::Span& c = changing_[static_cast<size_t>(in.y)];
      c.begin = std::min(c.begin, x);
      c.end = std::max(c.end, x + 1);
    }
  }
  if (!(in.f.slice_end && in.f.beam_end)) return;
  // A frame's compositor starts with its first slice: with polygons it
  // writes every pixel's front-over-back value then, which must not
  // overwrite the previous frame's plane before that frame is done.
  // Rays stop as the golden renderer's do: a sample on a ray it can no
  // longer change (its pixel, or for a block's partial image the
  // accumulator kept with it) is not composited.
  if (!compositor_) {
    compositor_.emplace(plan_.r, pixels_.plane(), polygons_,
                        pixels_.keeps_accumulators() ? golden::RayStop::full_alpha : golden::RayStop::settled_pixel);
    ++frames_;
  }
  const golden::SliceControl& c = plan_.slices[in.slice];
  auto shade = [&](int x, int y, const golden::RayAcc&, golden::ShadedSample& s) {
    s = golden::crop_and_cut(plan_.r, c, x, y, slice_[static_cast<size_t>(y) * plan_.nx + x]);
    return golden::blend_changes_ray(plan_.r.blend, s);
  };
  compositor_->slice(c, shade, [&](int y) { return changing_[static_cast<size_t>(y)]; });
  std::fill(changing_.begin(), changing_.end(), golden::Span{plan_.nx, 0});
  if (in.slice + 1 == static_cast<uint32_t>(plan_.K)) {
    compositor_->finish();
    out.frame_done = true;
    compositor_.reset();
  }
}

}  // namespace cube4::sysc
