#include "systemc/core/ray_gradients.hpp"

namespace cube4::sysc {
namespace {

std::string describe(const golden::Gradient& g) {
  return "gradient (" + std::to_string(g.x) + ", " + std::to_string(g.y) + ", " + std::to_string(g.z) + ")";
}

}  // namespace

RayGradients::RayGradients(const FramePlan& plan, const FrameRays& rays, int frames)
    : plan_(plan), rays_(rays), frames_(frames), slices_(static_cast<size_t>(rays.slices())) {
  for (int k = 0; k < rays.slices(); ++k) {
    Slice& out = slices_[static_cast<size_t>(k)];
    out.gx.assign(rays.count(k), 0);
    out.gy.assign(rays.count(k), 0);
    out.gz.assign(rays.count(k), 0);
    out.count.assign(rays.count(k), 0);
  }
}

golden::Gradient RayGradients::gradient(int k, int64_t u, int64_t v) const {
  const Slice& s = slices_[static_cast<size_t>(k)];
  const size_t i = rays_.index(k, u, v);
  return {s.gx[i], s.gy[i], s.gz[i]};
}

void RayGradients::take(uint32_t slice, int64_t u, int64_t v, const golden::Gradient& g) {
  ++taken_;
  const auto k = static_cast<int>(slice);
  if (!rays_.samples(k, u, v)) {
    fail(k, u, v, "no gradient (the ray does not sample the slice)", describe(g));
    return;
  }
  Slice& s = slices_[slice];
  const size_t i = rays_.index(k, u, v);
  if (++s.count[i] > frames_) {
    fail(k, u, v, "the ray's gradient " + std::to_string(frames_) + " time(s) a stream", "one more: " + describe(g));
    return;
  }
  if (s.count[i] > 1 && !(gradient(k, u, v) == g)) {
    fail(k, u, v, describe(gradient(k, u, v)) + " (the frame before's)", describe(g));
    return;
  }
  s.gx[i] = static_cast<int16_t>(g.x);
  s.gy[i] = static_cast<int16_t>(g.y);
  s.gz[i] = static_cast<int16_t>(g.z);
}

void RayGradients::finish(const golden::PerspectiveSamples& samples, bool check, const ZDifferences& z_difference) {
  auto from = [&](int slice) {
    return [&samples, this, slice](int64_t u, int64_t v) -> uint32_t {
      return rays_.samples(slice, u, v) ? samples.sample(slice, u, v) : 0;
    };
  };
  for (int k = 0; k < rays_.slices() && !first_; ++k) {
    const Slice& got = slices_[static_cast<size_t>(k)];
    for (size_t i = 0; i < got.count.size() && !first_; ++i) {
      const int64_t u = rays_.u_of(k, i), v = rays_.v_of(k, i);
      if (got.count[i] != frames_) {
        fail(k, u, v, "the ray's gradient " + std::to_string(frames_) + " time(s)",
             std::to_string(got.count[i]) + " time(s)");
      } else if (check) {
        const golden::PerspectiveSlice& s = rays_.slice(k);
        const golden::Gradient want =
            plan_.zdiff ? golden::perspective_gradient_voxel_z(plan_.r, s, u, v, from(k), z_difference(k, u, v))
                        : golden::perspective_gradient(plan_.r, s, u, v, from(k), from(k - 1), from(k + 1));
        if (!(want == gradient(k, u, v))) fail(k, u, v, describe(want), describe(gradient(k, u, v)));
      }
    }
  }
}

void RayGradients::fail(int k, int64_t u, int64_t v, const std::string& expected, const std::string& got) {
  if (!first_) first_ = Mismatch{Unit::Gradient, k, static_cast<int>(u), static_cast<int>(v), expected, got};
}

}  // namespace cube4::sysc
