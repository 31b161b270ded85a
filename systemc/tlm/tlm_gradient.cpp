#include "systemc/tlm/tlm_gradient.hpp"

namespace cube4::sysc {

TlmGradient::TlmGradient(const FramePlan& plan, bool skip_transparent, const TlmComposite* stops)
    : plan_(plan),
      skip_transparent_(skip_transparent),
      stops_(skip_transparent ? stops : nullptr),
      behind_(plan.nx, plan.ny, 1), current_(plan.nx, plan.ny, 1), ahead_(plan.nx, plan.ny, 1),
      zeros_(plan.nx, plan.ny, 1), tags_current_(plan.nx, plan.ny, 1), tags_ahead_(plan.nx, plan.ny, 1) {
  if (plan.zdiff) zdiff_current_ = zdiff_ahead_ = golden::Plane(plan.nx, plan.ny, 1);
}

void TlmGradient::emit_current(const golden::Plane& ahead) {
  const golden::SliceControl& c = plan_.slices[static_cast<size_t>(current_slice_)];
  golden::Neighbourhood n;
  if (current_slice_ == 0) ++frame_;
  for (int y = 0; y < plan_.ny; ++y)
    for (int j = 0; j < plan_.B; ++j) {
      GradientBeat& b = out_.recycled_back();
      b.valid = true;
      b.f = {j == 0, j == plan_.B - 1, y == 0, y == plan_.ny - 1};
      b.x = j * plan_.p;
      b.y = y;
      b.slice = static_cast<uint32_t>(current_slice_);
      for (int k = 0; k < plan_.p; ++k) {
        const int x = j * plan_.p + k;
        const auto i = static_cast<size_t>(k);
        // Padding columns: zero sample, zero gradient; a skipped sample: zero gradient.
        b.gx[i] = b.gy[i] = b.gz[i] = 0;
        if (x >= plan_.nx) {
          b.sample[i] = 0;
          b.vtag[i] = 0;
          continue;
        }
        const uint32_t centre = current_.at(x, y), tag = tags_current_.at(x, y);
        b.sample[i] = static_cast<uint16_t>(centre);
        b.vtag[i] = static_cast<uint8_t>(tag);
        if (skip_transparent_ && golden::sample_cannot_change_ray(plan_.r, centre, tag)) continue;
        if (stops_ && stops_->ray_stopped(frame_, static_cast<uint32_t>(current_slice_), x, y)) continue;
        golden::gather_neighbourhood(behind_, current_, ahead, c, x, y, n);
        if (plan_.zdiff) n.z_difference = zdiff_current_.row(y)[x];
        const golden::Gradient g = golden::sample_gradient(plan_.r, c, n);
        b.gx[i] = static_cast<int16_t>(g.x);
        b.gy[i] = static_cast<int16_t>(g.y);
        b.gz[i] = static_cast<int16_t>(g.z);
      }
    }
}

void TlmGradient::clock(const SampleBeat& in, GradientBeat& out) {
  if (in.valid) {
    if (in.f.slice_start && in.f.beam_start) y_ = 0;
    int32_t* row = ahead_.row(y_);
    for (int k = 0; k < plan_.p; ++k) {
      const int x = j_ * plan_.p + k;
      if (x >= plan_.nx) continue;
      row[x] = in.sample[static_cast<size_t>(k)];
      tags_ahead_.row(y_)[x] = in.vtag[static_cast<size_t>(k)];
      if (plan_.zdiff) zdiff_ahead_.row(y_)[x] = in.zdiff[static_cast<size_t>(k)];
    }
    ++j_;
    if (in.f.beam_end) {
      j_ = 0;
      ++y_;
    }
    if (in.f.slice_end && in.f.beam_end) {
      // The stream's zero slice, or a frame's first slice: the slice ahead
      // of the last one is zero.
      const bool zero = plan_.tag_zero_slice(in.tag), start = plan_.tag_frame_start(in.tag);
      if (zero) {
        ahead_.clear();
        tags_ahead_.clear();
        if (plan_.zdiff) zdiff_ahead_.clear();
      }
      if (current_slice_ >= 0) emit_current(start ? zeros_ : ahead_);
      if (start) current_.clear();  // behind the new frame's first slice
      std::swap(behind_, current_);
      std::swap(current_, ahead_);
      std::swap(tags_current_, tags_ahead_);
      std::swap(zdiff_current_, zdiff_ahead_);
      current_slice_ = static_cast<int>(plan_.tag_slice(in.tag));
      if (zero) {  // the frame's end: the next slice is the first of a frame
        current_slice_ = -1;
        behind_.clear();
        current_.clear();
        tags_current_.clear();
        if (plan_.zdiff) zdiff_current_.clear();
      }
    }
  }
  if (out_.empty()) {
    out = GradientBeat{};
  } else {
    out_.pop_front(out);
  }
}

}  // namespace cube4::sysc
