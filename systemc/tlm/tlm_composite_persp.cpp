#include "systemc/tlm/tlm_composite_persp.hpp"

#include <stdexcept>
#include <string>

#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/slice_steps.hpp"

namespace cube4::sysc {

TlmCompositePersp::TlmCompositePersp(const FramePlan& plan, bool accumulators)
    : plan_(plan),
      accumulators_(accumulators),
      origin_x_(plan.r.base_origin_x()),
      origin_y_(plan.r.base_origin_y()),
      per_frame_(golden::perspective_samples(plan.r)),
      plane_(golden::empty_base_plane(plan.r)) {
  rays_.assign(static_cast<size_t>(plane_.width) * plane_.height, golden::RayAcc{});
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
  golden::RayAcc& ray =
      rays_[static_cast<size_t>(v + origin_y_) * static_cast<size_t>(plane_.width) + static_cast<size_t>(u + origin_x_)];
  ray = golden::blend(plan_.r.blend, ray, out, plan_.r.p);
}

void TlmCompositePersp::end_frame() {
  plane_ = golden::empty_base_plane(plan_.r);
  if (accumulators_) plane_.acc.assign(rays_.size(), golden::RayAcc{});
  golden::write_rays(plane_, rays_, plan_.r.p);
  rays_.assign(rays_.size(), golden::RayAcc{});
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
