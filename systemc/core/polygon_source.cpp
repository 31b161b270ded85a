#include "systemc/core/polygon_source.hpp"

#include <algorithm>
#include <cmath>

namespace cube4::sysc {
namespace {

// Seconds of the engine as whole cycles of the pipelines' clock (a part
// cycle is a whole one: the slice cannot start mid-cycle).
uint64_t cycles(double seconds, double clock_hz) { return static_cast<uint64_t>(std::ceil(seconds * clock_hz)); }

}  // namespace

const char* polygon_connection_name(golden::PolygonConnection c) {
  switch (c) {
    case golden::PolygonConnection::Rle: return "rle";
    case golden::PolygonConnection::Dual: return "dual";
    case golden::PolygonConnection::Ideal: return "ideal";
  }
  return "?";
}

PolygonSource::PolygonSource(const FramePlan& plan, const golden::PolygonWork& work, const golden::PolygonEngine& e,
                             double clock_hz)
    : kind_(e.connection), slices_(plan.K), lag_(plan.passes > plan.K ? 1 : 0), first_pass_(plan.first_pass()) {
  for (const golden::SlabLoad& l : work.slabs)
    draw_.push_back(cycles(kind_ == golden::PolygonConnection::Dual ? golden::dual_draw_seconds(l, e)
                                                                    : golden::rle_draw_seconds(l, e),
                           clock_hz));
  draw_.resize(static_cast<size_t>(slices_), 0);
  opaque_ = cycles(golden::opaque_draw_seconds(work.opaque_fragments, work.opaque_triangles, e.dual_fill_rate, e),
                   clock_hz);
  drawn_.assign(static_cast<size_t>(slices_), 0);
}

uint64_t PolygonSource::release(int pass, uint64_t due) {
  uint64_t start = due;
  const int k = pass - lag_;  // the slice this pass composites
  const bool composites = k >= 0 && k < slices_;
  const auto at = [](int i) { return static_cast<size_t>(i); };
  switch (kind_) {
    case golden::PolygonConnection::Ideal:
      break;
    case golden::PolygonConnection::Rle:
      if (pass == 0 && slices_ > 0) {  // both halves free: slabs 0 and 1, one after the other
        drawn_[0] = due + draw_[0];
        if (slices_ > 1) drawn_[1] = drawn_[0] + draw_[1];
      }
      if (composites) {
        start = std::max(due, drawn_[at(k)]);
        // Slice k starts: slab k - 1's half is free for slab k + 1.
        if (k >= 1 && k + 1 < slices_) drawn_[at(k + 1)] = std::max(drawn_[at(k)], start) + draw_[at(k + 1)];
      }
      break;
    case golden::PolygonConnection::Dual:
      if (pass == 0) start += opaque_;
      if (composites) start += draw_[at(k)];
      break;
  }
  stalls_ += start - due;
  return start;
}

uint64_t PolygonSource::stalls_of_frame(uint64_t pass_cycles) {
  const uint64_t before = stalls_;
  const int passes = slices_ + lag_;
  uint64_t t = 0;
  for (int pass = first_pass_; pass < passes; ++pass) t = release(pass, t) + pass_cycles;
  return stalls_ - before;
}

}  // namespace cube4::sysc
