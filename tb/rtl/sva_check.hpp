// Helpers of the assertion tests (tb/rtl/test_*_sva.cpp): a verilated model
// on a context of its own, whose failed assertions (rtl/assert/) are
// recorded instead of aborting, and Verilator's messages captured.
//
// Every other RTL test runs on Verilator's default context, which aborts on
// a failed assertion: an assertion that fires in a normal run fails that
// test, with the assertion's message.
#pragma once
#include <gtest/gtest.h>
#include <verilated.h>

#include <cstdio>
#include <initializer_list>
#include <memory>
#include <sstream>
#include <string>

#include "systemc/rtl/vl_context.hpp"
#include "systemc/rtl/vl_coverage.hpp"

namespace cube4::rtl {

// Build with -DCUBE4_RTL_ASSERT=OFF: the checkers are not verilated, so
// there is nothing to fire.
#define CUBE4_SKIP_WITHOUT_ASSERTIONS() \
  if (!CUBE4_RTL_ASSERT) GTEST_SKIP() << "built with CUBE4_RTL_ASSERT=OFF: no assertions to fire"

template <class M>
class SvaBench {
 public:
  // Verilator's failed assertions call $stop on the thread's context:
  // the scoped context is the thread's while it lives.
  SvaBench() {
    ctx_->fatalOnError(false);
    ::testing::internal::CaptureStdout();
    capturing_ = true;
    m_ = std::make_unique<M>(ctx_.get(), "dut");
  }
  ~SvaBench() {
    if (m_) m_->final();
    write_coverage(*ctx_);
    if (capturing_) ::testing::internal::GetCapturedStdout();
  }
  SvaBench(const SvaBench&) = delete;
  SvaBench& operator=(const SvaBench&) = delete;

  M& operator*() { return *m_; }
  M* operator->() { return m_.get(); }
  VerilatedContext& context() { return *ctx_; }

  bool fired() { return ctx_->gotError(); }
  // Everything Verilator printed so far (the %Error lines); ends the capture.
  std::string output() {
    if (capturing_) {
      std::fflush(stdout);
      out_ += ::testing::internal::GetCapturedStdout();
      capturing_ = false;
    }
    return out_;
  }

 private:
  ScopedVerilatedContext ctx_;
  bool capturing_ = false;
  std::string out_;
  std::unique_ptr<M> m_;
};

// The assertion `label` fired, its message holds every one of `parts`
// (the cycle and the values at fault), and no other assertion fired.
template <class M>
void expect_fired(SvaBench<M>& b, const std::string& label, std::initializer_list<std::string> parts) {
  const std::string out = b.output();
  EXPECT_TRUE(b.fired()) << "assertion " << label << " did not fire; output:\n" << out;
  EXPECT_NE(out.find("." + label + ": "), std::string::npos) << "no message of " << label << " in:\n" << out;
  for (const std::string& p : parts) EXPECT_NE(out.find(p), std::string::npos) << "'" << p << "' missing from:\n" << out;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);)
    if (line.find("Assertion failed") != std::string::npos) {
      EXPECT_NE(line.find("." + label + ": "), std::string::npos) << "another assertion fired too: " << line;
    }
}

template <class M>
void expect_quiet(SvaBench<M>& b) {
  const std::string out = b.output();
  EXPECT_FALSE(b.fired()) << out;
  EXPECT_EQ(out.find("Assertion failed"), std::string::npos) << out;
}

// Runs `stream` on a fresh model M, reset first; expects assertion `label`
// with `parts` in its message, or (label empty) no assertion.
template <class M, class Stream>
void run_expecting(Stream&& stream, const std::string& label, std::initializer_list<std::string> parts) {
  SvaBench<M> b;
  reset(*b);
  stream(*b);
  if (label.empty())
    expect_quiet(b);
  else
    expect_fired(b, label, parts);
}

}  // namespace cube4::rtl
