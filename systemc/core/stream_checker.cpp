#include "systemc/core/stream_checker.hpp"

#include <sstream>
#include <utility>

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

StreamChecker::StreamChecker(const FramePlan& plan, const golden::Volume& vol) : plan_(plan) {
  for (auto& f : filling_) f.reserve(kBatch);
  thread_ = std::thread([this, &vol] { work(vol); });
}

StreamChecker::~StreamChecker() { close(); }

void StreamChecker::push(size_t side, const Beat& b) {
  std::vector<Beat>& filling = filling_[side];
  filling.push_back(b);
  if (filling.size() < kBatch) return;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return pending_.size() < kMaxPending; });
    hand_over(side);
  }
  changed_.notify_all();
}

void StreamChecker::hand_over(size_t side) {
  std::vector<Beat>& filling = filling_[side];
  if (filling.empty()) return;
  pending_.push_back(std::move(filling));
  ++handed_;
  // A checked batch's storage again, if one is back: no fresh pages.
  if (free_.empty()) {
    filling = {};
    filling.reserve(kBatch);
  } else {
    filling = std::move(free_.back());
    free_.pop_back();
  }
}

void StreamChecker::drain() {
  std::unique_lock<std::mutex> lock(mutex_);
  hand_over(kFront);
  hand_over(kBack);
  changed_.notify_all();
  changed_.wait(lock, [&] { return checked_ == handed_; });
}

void StreamChecker::close() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    hand_over(kFront);
    hand_over(kBack);
    closed_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void StreamChecker::work(const golden::Volume& vol) {
  try {
    sample_.assign(static_cast<size_t>(plan_.nx) * plan_.ny * plan_.K, 0);
    gradient_.assign(sample_.size(), golden::Gradient{});
    vtag_.assign(sample_.size(), 0);
    Collector c(plan_, sample_, gradient_, vtag_);
    plane_ = golden::render_fixed(vol, plan_.r, nullptr, {}, &c);
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex_);
    error_ = std::current_exception();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    rendered_ = true;
  }
  changed_.notify_all();
  for (;;) {
    std::vector<Beat> batch;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return !pending_.empty() || closed_; });
      if (pending_.empty()) return;
      batch = std::move(pending_.front());
      pending_.pop_front();
    }
    changed_.notify_all();
    if (!error_)  // else the render failed: nothing to compare with
      for (const Beat& b : batch) std::visit([this](const auto& beat) { check(beat); }, b);
    batch.clear();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++checked_;
      free_.push_back(std::move(batch));
    }
    changed_.notify_all();
  }
}

const golden::BasePlane& StreamChecker::golden_plane() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return rendered_; });
  if (error_) std::rethrow_exception(error_);
  return plane_;
}

void StreamChecker::mismatch(Unit u, int k, int x, int y, const std::string& expected, const std::string& got) {
  auto& m = first_[static_cast<size_t>(u)];
  if (!m) m = Mismatch{u, k, x, y, expected, got};
}

void StreamChecker::check(const SampleBeat& b) {
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

void StreamChecker::check(const GradientBeat& b) {
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

void StreamChecker::check(const ShadedBeat& b) {
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

std::optional<Mismatch> StreamChecker::first_mismatch() {
  drain();
  if (error_) std::rethrow_exception(error_);
  for (const auto& m : first_)
    if (m) return m;
  return std::nullopt;
}

}  // namespace cube4::sysc
