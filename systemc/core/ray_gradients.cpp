#include "systemc/core/ray_gradients.hpp"

namespace cube4::sysc {
namespace {

std::string describe(const golden::Gradient& g) {
  return "gradient (" + std::to_string(g.x) + ", " + std::to_string(g.y) + ", " + std::to_string(g.z) + ")";
}

}  // namespace

RayGradients::RayGradients(const FramePlan& plan, int frames)
    : plan_(plan), frames_(frames), slices_(static_cast<size_t>(plan.K)) {
  for (int k = 0; k < plan.K; ++k) {
    const golden::PerspectiveSlice& s = plan.persp[static_cast<size_t>(k)];
    Slice& out = slices_[static_cast<size_t>(k)];
    out.width = s.rays_x.empty() ? 0 : s.rays_x.hi - s.rays_x.lo;
    const int64_t height = s.rays_y.empty() ? 0 : s.rays_y.hi - s.rays_y.lo;
    const auto n = static_cast<size_t>(out.width * height);
    out.gx.assign(n, 0);
    out.gy.assign(n, 0);
    out.gz.assign(n, 0);
    out.count.assign(n, 0);
  }
}

size_t RayGradients::index(uint32_t k, int64_t u, int64_t v) const {
  const golden::PerspectiveSlice& s = plan_.persp[k];
  return static_cast<size_t>((v - s.rays_y.lo) * slices_[k].width + (u - s.rays_x.lo));
}

golden::Gradient RayGradients::gradient(int k, int64_t u, int64_t v) const {
  const Slice& s = slices_[static_cast<size_t>(k)];
  const size_t i = index(static_cast<uint32_t>(k), u, v);
  return {s.gx[i], s.gy[i], s.gz[i]};
}

void RayGradients::take(uint32_t k, int64_t u, int64_t v, const golden::Gradient& g) {
  ++taken_;
  if (k >= static_cast<uint32_t>(plan_.K) || !golden::samples(plan_.persp[k], u, v)) {
    fail(static_cast<int>(k), u, v, "no gradient (the ray does not sample the slice)", describe(g));
    return;
  }
  Slice& s = slices_[k];
  const size_t i = index(k, u, v);
  if (++s.count[i] > frames_) {
    fail(static_cast<int>(k), u, v, "the ray's gradient " + std::to_string(frames_) + " time(s) a stream",
         "one more: " + describe(g));
    return;
  }
  if (s.count[i] > 1 && !(gradient(static_cast<int>(k), u, v) == g)) {
    fail(static_cast<int>(k), u, v, describe(gradient(static_cast<int>(k), u, v)) + " (the frame before's)",
         describe(g));
    return;
  }
  s.gx[i] = static_cast<int16_t>(g.x);
  s.gy[i] = static_cast<int16_t>(g.y);
  s.gz[i] = static_cast<int16_t>(g.z);
}

void RayGradients::finish(const golden::PerspectiveSamples& samples, bool check) {
  for (int k = 0; k < plan_.K && !first_; ++k) {
    const golden::PerspectiveSlice& s = plan_.persp[static_cast<size_t>(k)];
    const Slice& got = slices_[static_cast<size_t>(k)];
    auto from = [&](int slice) {
      return [&samples, this, slice](int64_t u, int64_t v) -> uint32_t {
        if (slice < 0 || slice >= plan_.K || !golden::samples(plan_.persp[static_cast<size_t>(slice)], u, v)) return 0;
        return samples.sample(slice, u, v);
      };
    };
    for (size_t i = 0; i < got.count.size() && !first_; ++i) {
      const int64_t u = s.rays_x.lo + static_cast<int64_t>(i) % got.width;
      const int64_t v = s.rays_y.lo + static_cast<int64_t>(i) / got.width;
      if (got.count[i] != frames_) {
        fail(k, u, v, "the ray's gradient " + std::to_string(frames_) + " time(s)",
             std::to_string(got.count[i]) + " time(s)");
      } else if (check) {
        const golden::Gradient want = golden::perspective_gradient(plan_.r, s, u, v, from(k), from(k - 1), from(k + 1));
        if (!(want == gradient(k, u, v))) fail(k, u, v, describe(want), describe(gradient(k, u, v)));
      }
    }
  }
}

void RayGradients::fail(int k, int64_t u, int64_t v, const std::string& expected, const std::string& got) {
  if (!first_) first_ = Mismatch{Unit::Gradient, k, static_cast<int>(u), static_cast<int>(v), expected, got};
}

}  // namespace cube4::sysc
