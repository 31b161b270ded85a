// --check: every unit's output stream against golden, sample by sample. The
// golden values come from render_fixed() (samples and gradients through its
// SampleProbe); shaded samples are golden shade_classified() of those. The
// first difference is kept with its unit, slice and position, so a wrong
// base plane is traced to the unit that first went wrong.
//
// The checking runs beside the simulation, on a thread of its own: the
// golden render, then every beat in the order the simulation handed them
// over (copied, in batches; the simulation waits only when the thread is
// far behind). A check costs the simulation the copies, not the golden
// work (docs/system.md, "Checks and reports"). Samples and gradients are
// handed over from one thread, shaded samples from one (the same or
// another: the units may run on two, systemc/core/schedules.hpp); each
// stream's beats keep their order.
#pragma once
#include <array>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <variant>
#include <vector>

#include "golden/volume.hpp"
#include "systemc/core/beats.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/system.hpp"

namespace cube4::sysc {

class StreamChecker {
 public:
  // Without the frame's polygons: they change no unit's stream (only the
  // compositing), and golden's rays would stop at opaque ones.
  StreamChecker(const FramePlan& plan, const golden::Volume& vol);
  ~StreamChecker();
  StreamChecker(const StreamChecker&) = delete;
  StreamChecker& operator=(const StreamChecker&) = delete;

  void samples(const SampleBeat& b) {
    if (b.valid) push(kFront, b);
  }
  void gradients(const GradientBeat& b) {
    if (b.valid && plan_.r.gradient) push(kFront, b);
  }
  void shaded(const ShadedBeat& b) {
    if (b.valid) push(kBack, b);
  }
  // Waits until every beat handed over so far is checked (rethrows what
  // the checking thread threw); more beats may follow.
  std::optional<Mismatch> first_mismatch();
  // Golden's base plane of the frame without polygons; waits for it.
  const golden::BasePlane& golden_plane();

 private:
  using Beat = std::variant<SampleBeat, GradientBeat, ShadedBeat>;
  static constexpr size_t kBatch = 4096, kMaxPending = 32;
  // The handing-over sides: samples and gradients, shaded samples.
  static constexpr size_t kFront = 0, kBack = 1;

  size_t index(int k, int x, int y) const {
    return (static_cast<size_t>(k) * plan_.ny + static_cast<size_t>(y)) * plan_.nx + static_cast<size_t>(x);
  }
  void push(size_t side, const Beat& b);
  void hand_over(size_t side);  // the side's batch being filled, if any (mutex_ held)
  void drain();      // hands it over and waits until every batch is checked
  void close();      // ends the thread
  void work(const golden::Volume& vol);
  void check(const SampleBeat& b);
  void check(const GradientBeat& b);
  void check(const ShadedBeat& b);
  void mismatch(Unit u, int k, int x, int y, const std::string& expected, const std::string& got);

  const FramePlan& plan_;
  // The checking thread's own (read by the caller only after close()).
  std::vector<uint16_t> sample_;
  std::vector<golden::Gradient> gradient_;
  std::vector<uint8_t> vtag_;  // each sample's voxel tag (all 0 without tags)
  golden::BasePlane plane_;
  std::array<std::optional<Mismatch>, kUnits> first_{};
  int sample_y_ = 0, sample_j_ = 0;

  // The hand-over.
  std::array<std::vector<Beat>, 2> filling_;  // the simulation's sides
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::vector<Beat>> pending_;
  std::vector<std::vector<Beat>> free_;  // checked batches' storage, for the simulation's side
  size_t handed_ = 0, checked_ = 0;  // batches
  bool closed_ = false, rendered_ = false;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace cube4::sysc
