#include "systemc/tlm/tlm_composite_persp.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/slice_steps.hpp"

namespace cube4::sysc {

TlmCompositePersp::TlmCompositePersp(const FramePlan& plan, bool accumulators, const golden::PolygonFrame* polygons,
                                     int reach)
    : plan_(plan),
      accumulators_(accumulators),
      polygons_(polygons),
      polygon_pixels_(plan, polygons),
      reach_(reach),
      origin_x_(plan.r.base_origin_x()),
      origin_y_(plan.r.base_origin_y()),
      per_frame_(golden::perspective_samples(plan.r)),
      plane_(golden::empty_base_plane(plan.r)) {
  for (std::vector<Stored>& store : stores_) store.assign(static_cast<size_t>(plan.nx) * static_cast<size_t>(plan.ny), {});
  pending_.resize(static_cast<size_t>(2 * plan.p + reach));
  start_frame();
}

void TlmCompositePersp::start_frame() {
  frame_ = golden::empty_base_plane(plan_.r);
  if (accumulators_) frame_.acc.assign(static_cast<size_t>(frame_.width) * frame_.height, golden::RayAcc{});
  written_.assign(static_cast<size_t>(frame_.width) * frame_.height, 0);
}

void TlmCompositePersp::blend(const Sample& in, int64_t position, int64_t step) {
  const uint32_t k = in.k;
  const int64_t u = in.u, v = in.v;
  auto where = [&] {
    return "slice " + std::to_string(k) + ", ray (" + std::to_string(u) + ", " + std::to_string(v) +
           "), stream position " + std::to_string(position);
  };
  if (k >= static_cast<uint32_t>(plan_.K) || !golden::samples(plan_.persp[k], u, v))
    throw std::logic_error("TlmCompositePersp: a sample of no ray of its slice (" + where() + ")");
  const golden::PerspectiveSlice& s = plan_.persp[k];
  const int F = plan_.r.p.dda_frac_bits;
  const int64_t X = golden::ray_home(golden::axis_slice(s, 0), u, F), Y = golden::ray_home(golden::axis_slice(s, 1), v, F);
  const int64_t pass = static_cast<int64_t>(frames_done_) * plan_.K + k;
  const size_t pixel =
      static_cast<size_t>(v + origin_y_) * static_cast<size_t>(frame_.width) + static_cast<size_t>(u + origin_x_);
  // The ray's accumulator: of the slice before, at its home there, read by
  // that home's column stage `d` positions before this blend.
  golden::RayAcc ray = polygon_pixels_.start(pixel);
  if (k > 0 && golden::samples(plan_.persp[k - 1], u, v)) {
    const golden::PerspectiveSlice& before = plan_.persp[k - 1];
    const int64_t Xb = golden::ray_home(golden::axis_slice(before, 0), u, F);
    const int64_t Yb = golden::ray_home(golden::axis_slice(before, 1), v, F);
    if (std::abs(X - Xb) > reach_ || std::abs(Y - Yb) > reach_)
      throw std::logic_error("TlmCompositePersp: the ray moves from (" + std::to_string(Xb) + ", " +
                             std::to_string(Yb) + ") to (" + std::to_string(X) + ", " + std::to_string(Y) +
                             "), beyond the reach " + std::to_string(reach_) + " (" + where() + ")");
    const int64_t read = (position - (X - Xb + reach_)) / plan_.p;
    const Stored& e = stores_[static_cast<size_t>((pass - 1) & 1)][static_cast<size_t>(Yb * plan_.nx + Xb)];
    if (e.pass != pass - 1 || e.u != u || e.v != v)
      throw std::logic_error("TlmCompositePersp: the ray's accumulator of the slice before is not in its store (" +
                             where() + ")");
    if (e.ready > read)
      throw std::logic_error("TlmCompositePersp: the ray's accumulator of the slice before is stored at step " +
                             std::to_string(e.ready) + ", read at step " + std::to_string(read) + " (" + where() + ")");
    ray = e.acc;
  }
  golden::ShadedSample shaded;
  shaded.rgb = {in.red, in.green, in.blue};
  shaded.alpha = in.alpha;
  shaded.value = in.value;
  const golden::ShadedSample out = golden::perspective_crop_and_cut(plan_.r, s, u, v, shaded);
  if (!polygons_) {
    ray = golden::blend(plan_.r.blend, ray, out, plan_.r.p);
  } else {
    ray = golden::double_composite(ray, out, golden::sample_before_z(static_cast<int>(k), polygons_->z[pixel]),
                                   polygon_pixels_.behind(k, u, v), plan_.r.p);
  }
  stores_[static_cast<size_t>(pass & 1)][static_cast<size_t>(Y * plan_.nx + X)] = {ray, pass, u, v,
                                                                                 step + kLatency + reach_};
  // A ray that does not sample the next slice leaves: its pixel now.
  if (k + 1 == static_cast<uint32_t>(plan_.K) || !golden::samples(plan_.persp[k + 1], u, v)) {
    golden::write_ray(frame_, static_cast<int>(u + origin_x_), static_cast<int>(v + origin_y_), ray, plan_.r.p,
                      polygons_);
    written_[pixel] = 1;
  }
}

void TlmCompositePersp::end_frame() {
  // Rays that sampled nothing leave as they started.
  for (int y = 0; y < frame_.height; ++y)
    for (int x = 0; x < frame_.width; ++x) {
      const size_t i = static_cast<size_t>(y) * frame_.width + x;
      if (!written_[i]) golden::write_ray(frame_, x, y, polygon_pixels_.start(i), plan_.r.p, polygons_);
    }
  plane_ = std::move(frame_);
  start_frame();
  composited_ = 0;
  ++frames_done_;
}

void TlmCompositePersp::clock(const RayShadedBeat& in, CompositeOut& out) {
  out = CompositeOut{};
  out.frame_done = done_[head_];
  done_[head_] = false;
  if (in.step >= 0) {
    const auto size = static_cast<int64_t>(pending_.size());
    for (int k = 0; k < plan_.p; ++k) {
      if (!(in.valid >> k & 1)) continue;
      const auto i = static_cast<size_t>(k);
      const int64_t position = in.step * plan_.p + k + reach_;
      Pending& slot = pending_[static_cast<size_t>(position % size)];
      if (slot.position >= 0)
        throw std::logic_error("TlmCompositePersp: a sample due at stream position " + std::to_string(slot.position) +
                               " found no step there");
      slot = {position, {in.red[i], in.green[i], in.blue[i], in.alpha[i], in.value[i], in.u[i], in.v[i], in.tag[i]}};
    }
    // This step's positions blend, lane by lane.
    for (int64_t position = in.step * plan_.p; position < (in.step + 1) * plan_.p; ++position) {
      Pending& slot = pending_[static_cast<size_t>(position % size)];
      if (slot.position < 0) continue;
      if (slot.position != position)
        throw std::logic_error("TlmCompositePersp: a sample due at stream position " + std::to_string(slot.position) +
                               " found no step there");
      const Sample sample = slot.sample;
      slot.position = -1;
      blend(sample, position, in.step);
      if (++composited_ == per_frame_) {
        end_frame();
        done_[head_] = true;
      }
    }
  }
  head_ = (head_ + 1) % done_.size();
}

}  // namespace cube4::sysc
