#include "systemc/core/stream_checker.hpp"

#include <sstream>

#include "golden/pipeline.hpp"
#include "golden/renderers.hpp"

namespace cube4::sysc {
namespace {

struct Collector final : golden::SampleProbe {
  Collector(const FramePlan& p, std::vector<uint16_t>& s, std::vector<golden::Gradient>& g, std::vector<uint8_t>& t)
      : plan(p), samples(s), grads(g), tags(t) {}
  size_t index(int x, int y, const golden::SliceControl& c) const {
    return (static_cast<size_t>(c.k) * plan.ny + static_cast<size_t>(y)) * plan.nx + static_cast<size_t>(x);
  }
  void tagged(int x, int y, const golden::SliceControl& c, uint32_t tag) override {
    tags[index(x, y, c)] = static_cast<uint8_t>(tag);
  }
  void sample(int x, int y, const golden::SliceControl& c, uint32_t value, const golden::Gradient& g) override {
    const size_t i = index(x, y, c);
    samples[i] = static_cast<uint16_t>(value);
    grads[i] = g;
  }
  const FramePlan& plan;
  std::vector<uint16_t>& samples;
  std::vector<golden::Gradient>& grads;
  std::vector<uint8_t>& tags;
};

std::string str(std::initializer_list<int64_t> v) {
  std::ostringstream s;
  s << '(';
  bool first = true;
  for (int64_t x : v) {
    s << (first ? "" : ", ") << x;
    first = false;
  }
  s << ')';
  return s.str();
}

}  // namespace

StreamChecker::StreamChecker(const FramePlan& plan, const golden::Volume& vol)
    : plan_(plan), sample_(static_cast<size_t>(plan.nx) * plan.ny * plan.K),
      gradient_(sample_.size()), vtag_(sample_.size(), 0) {
  Collector c(plan, sample_, gradient_, vtag_);
  plane_ = golden::render_fixed(vol, plan.r, nullptr, {}, &c);
}

void StreamChecker::mismatch(Unit u, int k, int x, int y, const std::string& expected, const std::string& got) {
  auto& m = first_[static_cast<size_t>(u)];
  if (!m) m = Mismatch{u, k, x, y, expected, got};
}

void StreamChecker::samples(const SampleBeat& b) {
  if (!b.valid) return;
  if (b.f.slice_start && b.f.beam_start) sample_y_ = 0;
  const int k = static_cast<int>(plan_.tag_slice(b.tag));
  if (!plan_.tag_zero_slice(b.tag) && k < plan_.K) {
    for (int q = 0; q < plan_.p; ++q) {
      const int x = sample_j_ * plan_.p + q;
      if (x >= plan_.nx) continue;
      const size_t i = index(k, x, sample_y_);
      const auto l = static_cast<size_t>(q);
      if (b.sample[l] != sample_[i] || b.vtag[l] != vtag_[i])
        mismatch(Unit::Interp, k, x, sample_y_, str({sample_[i], vtag_[i]}), str({b.sample[l], b.vtag[l]}));
    }
  }
  ++sample_j_;
  if (b.f.beam_end) {
    sample_j_ = 0;
    ++sample_y_;
  }
}

void StreamChecker::gradients(const GradientBeat& b) {
  if (!b.valid || !plan_.r.gradient) return;
  for (int q = 0; q < plan_.p; ++q) {
    const int x = b.x + q;
    if (x >= plan_.nx || static_cast<int>(b.slice) >= plan_.K) continue;
    const size_t i = index(static_cast<int>(b.slice), x, b.y);
    const golden::Gradient& g = gradient_[i];
    const auto l = static_cast<size_t>(q);
    if (b.sample[l] != sample_[i] || b.gx[l] != g.x || b.gy[l] != g.y || b.gz[l] != g.z || b.vtag[l] != vtag_[i])
      mismatch(Unit::Gradient, static_cast<int>(b.slice), x, b.y, str({sample_[i], g.x, g.y, g.z, vtag_[i]}),
               str({b.sample[l], b.gx[l], b.gy[l], b.gz[l], b.vtag[l]}));
  }
}

void StreamChecker::shaded(const ShadedBeat& b) {
  if (!b.valid) return;
  for (int q = 0; q < plan_.p; ++q) {
    const int x = b.x + q;
    if (x >= plan_.nx || static_cast<int>(b.slice) >= plan_.K) continue;
    const size_t i = index(static_cast<int>(b.slice), x, b.y);
    const golden::ShadedSample s = golden::shade_classified(plan_.r, sample_[i], vtag_[i], gradient_[i]);
    const auto l = static_cast<size_t>(q);
    if (b.red[l] != s.rgb[0] || b.green[l] != s.rgb[1] || b.blue[l] != s.rgb[2] || b.alpha[l] != s.alpha ||
        b.value[l] != s.value)
      mismatch(Unit::Shade, static_cast<int>(b.slice), x, b.y, str({s.rgb[0], s.rgb[1], s.rgb[2], s.alpha, s.value}),
               str({b.red[l], b.green[l], b.blue[l], b.alpha[l], b.value[l]}));
  }
}

std::optional<Mismatch> StreamChecker::first_mismatch() const {
  for (const auto& m : first_)
    if (m) return m;
  return std::nullopt;
}

}  // namespace cube4::sysc
