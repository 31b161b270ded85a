// The schedules that clock a cycle-level frame (label unit, so the
// sanitizer build runs them): the hand-over between two threads
// (systemc/core/cycle_pipe.hpp), and run_units() on one thread and two
// under both kernels with the TLM units: the same frame, and a unit's
// error reported from the cycle a single thread would have stopped at.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "systemc/core/cycle_pipe.hpp"
#include "systemc/core/pixel_memory.hpp"
#include "systemc/core/schedules.hpp"
#include "systemc/core/voxel_memory.hpp"
#include "systemc/tlm/tlm_addr.hpp"
#include "systemc/tlm/tlm_composite.hpp"
#include "systemc/tlm/tlm_gradient.hpp"
#include "systemc/tlm/tlm_interp.hpp"
#include "systemc/tlm/tlm_shade.hpp"
#include "tb/tests/system_support.hpp"

namespace {

using namespace cube4;

TEST(CyclePipe, HandsEveryValueOverInOrderAcrossBatches) {
  sysc::CyclePipe<int> pipe(3, 2);
  std::thread producer([&] {
    for (int i = 0; i < 100; ++i) pipe.next() = i;
    pipe.next() = -1;
    pipe.discard();  // an unfinished cycle is not handed over
    pipe.close();
  });
  int want = 0;
  while (const int* v = pipe.pop()) EXPECT_EQ(*v, want++);
  producer.join();
  EXPECT_EQ(want, 100);
}

TEST(CyclePipe, AStoppedConsumerReleasesAWaitingProducer) {
  sysc::CyclePipe<int> pipe(2, 1);
  std::thread producer([&] {
    // Far more than the pipe holds: it waits until the consumer stops.
    for (int i = 0; i < 1000 && !pipe.stopped(); ++i) pipe.next() = i;
    pipe.close();
  });
  ASSERT_NE(pipe.pop(), nullptr);
  pipe.stop();
  producer.join();
  EXPECT_TRUE(pipe.stopped());
}

// A unit that throws in the cycle it is clocked for the n-th time.
template <class If, class In, class Out>
struct FailingUnit final : If {
  FailingUnit(std::unique_ptr<If> inner, uint64_t fail_at, std::string what)
      : inner_(std::move(inner)), fail_at_(fail_at), what_(std::move(what)) {}
  void clock(const In& in, Out& out) override {
    if (++clocks_ == fail_at_) throw std::runtime_error(what_);
    inner_->clock(in, out);
  }
  sysc::Level level() const override { return sysc::Level::Tlm; }
  std::unique_ptr<If> inner_;
  uint64_t fail_at_, clocks_ = 0;
  std::string what_;
};
using FailingGradient = FailingUnit<sysc::GradientIf, sysc::SampleBeat, sysc::GradientBeat>;
using FailingComposite = FailingUnit<sysc::CompositeIf, sysc::ShadedBeat, sysc::CompositeOut>;

struct Outcome {
  golden::BasePlane plane;
  uint64_t done_cycle = 0;
  std::vector<uint64_t> frames;
  std::array<uint64_t, 4> last{};
  uint64_t reads = 0;
  std::string error;
};

// One frame of the TLM units, the gradient unit failing in its
// gradient_fail-th clock and the compositing unit in its composite_fail-th
// (0: never).
Outcome run_tlm(bool threaded, sysc::Kernel kernel, uint64_t gradient_fail = 0, uint64_t composite_fail = 0) {
  const test::Programmed f = test::program(test::Case{});
  const sysc::FramePlan plan(f.regs, 4);
  sysc::VoxelMemory mem(f.vol, 4);
  sysc::PixelMemory pixels(f.regs);
  sysc::FrameUnits u;
  u.addr = std::make_unique<sysc::TlmAddr>(mem.layout(), golden::SkewTraversal{f.regs.perm, f.regs.flip});
  u.former = std::make_unique<sysc::StreamFormer>(plan, mem, *u.addr, 2);
  u.frames = 2;
  u.interp = std::make_unique<sysc::TlmInterp>(plan);
  u.gradient = std::make_unique<FailingGradient>(std::make_unique<sysc::TlmGradient>(plan), gradient_fail, "front");
  u.shade = std::make_unique<sysc::TlmShade>(plan);
  u.composite =
      std::make_unique<FailingComposite>(std::make_unique<sysc::TlmComposite>(plan, pixels), composite_fail, "back");
  u.threaded = threaded;
  u.p = 4;
  u.front_first_lane = 4;
  Outcome o;
  try {
    sysc::run_units(u, kernel);
  } catch (const std::exception& e) {
    o.error = e.what();
    return o;
  }
  o.plane = pixels.plane();
  o.done_cycle = u.done_cycle;
  o.frames = u.frame_done_cycles;
  o.last = {u.last_valid[0], u.last_valid[1], u.last_valid[2], u.last_shaded};
  o.reads = mem.reads();
  return o;
}

TEST(Schedules, TwoThreadsSimulateTheSameFrames) {
  for (sysc::Kernel kernel : {sysc::Kernel::PlainLoop, sysc::Kernel::SystemC}) {
    SCOPED_TRACE(kernel == sysc::Kernel::SystemC ? "SystemC" : "plain loop");
    const Outcome one = run_tlm(false, kernel), two = run_tlm(true, kernel);
    ASSERT_EQ(one.error, "");
    ASSERT_EQ(two.error, "");
    EXPECT_EQ(two.plane.rgba, one.plane.rgba);
    EXPECT_EQ(two.done_cycle, one.done_cycle);
    EXPECT_EQ(two.frames, one.frames);
    EXPECT_EQ(two.last, one.last);
    EXPECT_EQ(two.reads, one.reads);
    EXPECT_EQ(one.frames.size(), 2u);
  }
}

// The front runs ahead of the back, so of two errors the one from the
// earlier cycle is the frame's, as on one thread; an error of the front in
// a cycle after the frame's last pixel is no error of the frame.
TEST(Schedules, TheErrorOfTheEarlierCycleEndsTheFrame) {
  const uint64_t cycles = run_tlm(false, sysc::Kernel::PlainLoop).done_cycle;
  ASSERT_GT(cycles, 200u);
  for (sysc::Kernel kernel : {sysc::Kernel::PlainLoop, sysc::Kernel::SystemC})
    for (bool threaded : {false, true}) {
      SCOPED_TRACE(std::string(kernel == sysc::Kernel::SystemC ? "SystemC" : "plain loop") +
                   (threaded ? ", two threads" : ", one thread"));
      EXPECT_EQ(run_tlm(threaded, kernel, 120, 0).error, "front");
      EXPECT_EQ(run_tlm(threaded, kernel, 0, 80).error, "back");
      EXPECT_EQ(run_tlm(threaded, kernel, 150, 80).error, "back");
      EXPECT_EQ(run_tlm(threaded, kernel, 80, 150).error, "front");
      EXPECT_EQ(run_tlm(threaded, kernel, cycles + 10, 0).error, "");
    }
}

}  // namespace
