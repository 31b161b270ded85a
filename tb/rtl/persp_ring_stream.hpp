// What the perspective gradient and compositing rings' testbenches share
// (test_gradient_persp_ring.cpp, test_composite_persp_ring.cpp): the
// stream as the system streams frames into the rings behind the
// interpolation ring (the frames' passes back to back, the zero pass, six
// flush beams), with random idle cycles, and the pass constants both rings
// take at a pass's first step (random words at every other step, which the
// rings must not take).
#pragma once
#include <cstdint>
#include <map>
#include <vector>

#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "systemc/rtl/unit_streams.hpp"
#include "tb/rtl/rtl_check.hpp"

namespace cube4::rtl {

// One stream step: its index, pass (`passes`: the zero pass), whether it
// flushes, and at a pass's first step that pass's slice (else null).
struct PerspStep {
  int64_t step = 0;
  int pass = 0;
  bool zero = false, flush = false;
  const golden::PerspectiveSlice* slice = nullptr;
};

// Drives the steps of `passes` passes of `slices` (frames back to back) and
// the zero pass (ny beams of B partial beams, six flush beams after the
// zero pass) into m's stream ports, with idle cycles between them
// (probability 0.15 each; the p lanes' sample_valid_i random then, which
// the rings must ignore), calling `step(s)` to drive the rest of a step's
// inputs and `clock()` for every cycle. Stops early once `ok()` is false.
template <class M, class Step, class Clock, class Ok>
void stream_persp_passes(M& m, const std::vector<golden::PerspectiveSlice>& slices, int passes, int ny, int B, int p,
                         Random& rng, Step&& step, Clock&& clock, Ok&& ok) {
  constexpr int kFlushBeams = 6;
  const int K = static_cast<int>(slices.size());
  int64_t index = 0;
  for (int pass = 0; pass <= passes && ok(); ++pass) {
    const bool zero = pass == passes;
    for (int b = 0; b < ny + (zero ? kFlushBeams : 0) && ok(); ++b)
      for (int j = 0; j < B && ok(); ++j, ++index) {
        while (rng.chance(0.15)) {
          m.valid_i = 0;
          m.sample_valid_i = static_cast<uint32_t>(rng.bits(p));
          clock();
        }
        const bool flush = b >= ny;
        m.valid_i = 1;
        m.beam_start_i = j == 0;
        m.beam_end_i = j == B - 1;
        m.slice_start_i = !flush && b == 0;
        m.slice_end_i = !flush && b == ny - 1;
        m.flush_i = flush;
        const bool first = !flush && b == 0 && j == 0;
        step(PerspStep{index, pass, zero, flush, first ? &slices[static_cast<size_t>(zero ? 0 : pass % K)] : nullptr});
        clock();
      }
  }
}

// The pass constants both rings take (sysc::drive_persp_rays(): spacing,
// ray 0's positions and the rays per axis, none in the zero pass), first
// and last slice of the frame (K slices), and the tag (the pass). `s`: the
// pass's slice at its first step, else null (random words).
template <class M>
void drive_persp_pass_constants(M& m, const golden::PerspectiveSlice* s, int pass, bool zero, int K, Random& rng,
                                int tag_bits) {
  if (s) {
    sysc::drive_persp_rays(m, *s, zero);
  } else {
    m.spacing_i = rng.bits(sysc::kPerspPosBits);
    m.ray0_x_i = rng.bits(sysc::kPerspPosBits);
    m.ray0_y_i = rng.bits(sysc::kPerspPosBits);
    m.rays_x_lo_i = static_cast<uint16_t>(rng.bits(sysc::kPerspRayBits));
    m.rays_x_hi_i = static_cast<uint16_t>(rng.bits(sysc::kPerspRayBits));
    m.rays_y_lo_i = static_cast<uint16_t>(rng.bits(sysc::kPerspRayBits));
    m.rays_y_hi_i = static_cast<uint16_t>(rng.bits(sysc::kPerspRayBits));
  }
  const int k = pass % K;
  m.first_i = s ? (!zero && k == 0) : rng.bits(1);
  m.last_i = s ? (!zero && k == K - 1) : rng.bits(1);
  put_bits(m.tag_i, 0, tag_bits, s ? static_cast<uint64_t>(pass) : rng.bits(tag_bits));
}

// The ray homed at cell `fc` of a stream of frames back to back (the
// frames' K slices each, `passes` passes before the zero pass), if any: the
// ray whose sample (or gradient) a ring forms at that cell's position.
struct HomedRay {
  bool valid = false;
  int k = 0;
  int64_t u = 0, v = 0;
};
inline HomedRay ray_homed_at(const std::vector<golden::PerspectiveSlice>& slices, const golden::FormedCell& fc,
                             int passes, int frac_bits, int weight_bits) {
  const int K = static_cast<int>(slices.size());
  if (!fc.valid || fc.pass >= passes) return {};
  const int k = static_cast<int>(fc.pass % K);
  const golden::PerspectiveSlice& s = slices[static_cast<size_t>(k)];
  const golden::HomeLane hu = golden::home_lane(s.ray0_x, s.spacing, s.rays_x, fc.x, frac_bits, weight_bits);
  const golden::HomeLane hv = golden::home_lane(s.ray0_y, s.spacing, s.rays_y, fc.y, frac_bits, weight_bits);
  if (!hu.valid || !hv.valid) return {};
  return {true, k, hu.ray, hv.ray};
}

// What a ring owes, cycle by cycle: each driven step's expected outputs by
// lane (`want`: step -> lane -> Expect), due `latency` cycles after the
// step's cycle. take(cycle) finds the step due then (-1: none), lane(k)
// what lane k owes in it (nullptr: nothing).
template <class Expect>
class DueLanes {
 public:
  DueLanes(std::map<int64_t, std::map<int, Expect>>& want, uint64_t latency) : want_(want), latency_(latency) {}
  void driven(uint64_t cycle, int64_t step) { due_[cycle + latency_] = step; }
  int64_t take(uint64_t cycle) {
    lanes_ = nullptr;
    const auto d = due_.find(cycle);
    if (d == due_.end()) return -1;
    const int64_t step = d->second;
    due_.erase(d);
    if (const auto w = want_.find(step); w != want_.end()) lanes_ = &w->second;
    return step;
  }
  Expect* lane(int k) const {
    if (!lanes_) return nullptr;
    const auto it = lanes_->find(k);
    return it == lanes_->end() ? nullptr : &it->second;
  }
  // After the stream: every ray due must have left (Expect::seen), else
  // the first that did not is the checker's failure.
  template <class Checker>
  void check_every_ray_left(Checker& c, uint64_t cycle) const {
    for (const auto& [at, lanes] : want_)
      for (const auto& [lane, e] : lanes)
        if (!e.seen && c.ok())
          c.check(cycle, {{"pass", e.pass}, {"u", e.u}, {"v", e.v}, {"due at step", at}, {"lane", lane}},
                  {{"left", 1}}, {{"left", 0}});
  }

 private:
  std::map<int64_t, std::map<int, Expect>>& want_;
  uint64_t latency_;
  std::map<uint64_t, int64_t> due_;
  std::map<int, Expect>* lanes_ = nullptr;
};

}  // namespace cube4::rtl
