// Progress on stderr for runs longer than a second: silent before, then at
// most a few updates per second, and a final line.
#pragma once
#include <chrono>
#include <cstdio>
#include <string>

namespace cube4::tb {

class ProgressPrinter {
 public:
  explicit ProgressPrinter(std::string what, bool enabled = true) : what_(std::move(what)), enabled_(enabled) {}
  void operator()(double fraction) {
    if (!enabled_) return;
    const double t = elapsed();
    if (t < 1.0 || (t - last_ < 0.5 && fraction < 1.0)) return;
    last_ = t;
    shown_ = true;
    std::fprintf(stderr, "%s: %3.0f%% (%.1f s)\n", what_.c_str(), fraction * 100.0, t);
  }
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  bool shown() const { return shown_; }

 private:
  std::string what_;
  bool enabled_;
  bool shown_ = false;
  double last_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace cube4::tb
