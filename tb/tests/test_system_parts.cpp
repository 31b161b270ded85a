// The system model's pieces on their own (label unit): skewed voxel memory,
// the stream former's address generation and de-skew, the stream tag.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "golden/permuted_volume.hpp"
#include "golden/pipeline.hpp"
#include "golden/registers.hpp"
#include "golden/volume.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/stream_checker.hpp"
#include "systemc/core/stream_former.hpp"
#include "systemc/core/voxel_memory.hpp"
#include "systemc/tlm/beat_queue.hpp"
#include "systemc/tlm/tlm_addr.hpp"
#include "systemc/tlm/tlm_gradient.hpp"
#include "systemc/tlm/tlm_interp.hpp"
#include "golden/host_driver.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#if CUBE4_TEST_RTL
// verilated.h calls sc_time_stamp() unqualified once SystemC is included.
#include <systemc>
using sc_core::sc_time_stamp;
#include "systemc/core/trace_window.hpp"
#include "systemc/rtl/rtl_assertion.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/rtl/vl_context.hpp"
#endif

namespace {

using namespace cube4;

golden::Volume numbered(int nx, int ny, int nz) {
  golden::Volume v;
  v.dim = {nx, ny, nz};
  v.data.resize(v.size());
  for (size_t i = 0; i < v.data.size(); ++i) v.data[i] = static_cast<uint16_t>(1 + i % 4000);
  return v;
}

// The TLM units' output queue: first in, first out, through the compaction
// of a queue never drained; a slot handed out again keeps the beat it held,
// which is why the units write every field they drive (zeros included).
TEST(BeatQueue, HandsBeatsOutInOrderThroughCompaction) {
  struct Beat {
    int n = -1;
  };
  sysc::BeatQueue<Beat> q;
  Beat out;
  int next_in = 0, next_out = 0;
  // Push 3 for every 2 popped: the queue never drains, so it compacts.
  for (int round = 0; round < 6000; ++round) {
    for (int i = 0; i < 3; ++i) q.recycled_back().n = next_in++;
    for (int i = 0; i < 2; ++i) {
      ASSERT_FALSE(q.empty());
      q.pop_front(out);
      ASSERT_EQ(out.n, next_out++);
    }
  }
  while (!q.empty()) {
    q.pop_front(out);
    ASSERT_EQ(out.n, next_out++);
  }
  EXPECT_EQ(next_out, next_in);
}

TEST(BeatQueue, ARecycledSlotHoldsItsLastBeat) {
  struct Beat {
    int a = 0, b = 0;
  };
  sysc::BeatQueue<Beat> q;
  Beat& first = q.recycled_back();
  EXPECT_EQ(first.a, 0);  // a new slot is an idle beat
  first.a = 7;
  first.b = 9;
  Beat out;
  q.pop_front(out);
  EXPECT_TRUE(q.empty());
  Beat& again = q.recycled_back();  // the drained queue starts over in the same slot
  EXPECT_EQ(again.a, 7);
  EXPECT_EQ(again.b, 9);
  q.push_back(Beat{});  // a whole beat overwrites its slot
  q.pop_front(out);
  q.pop_front(out);
  EXPECT_EQ(out.a, 0);
  EXPECT_EQ(out.b, 0);
}

TEST(VoxelMemory, AModuleReadTwiceInACycleIsAnError) {
  sysc::VoxelMemory mem(numbered(4, 3, 2), 4);
  mem.begin_cycle();
  EXPECT_NO_THROW(mem.read(1, 0));
  EXPECT_NO_THROW(mem.read(2, 0));
  EXPECT_THROW(mem.read(1, 1), std::logic_error);
  mem.begin_cycle();
  EXPECT_NO_THROW(mem.read(1, 1));
}

TEST(VoxelMemory, RefusesPipelineCountsOutsideTheSkew) {
  EXPECT_THROW(sysc::VoxelMemory(numbered(2, 2, 2), 0), std::invalid_argument);
  EXPECT_THROW(sysc::VoxelMemory(numbered(2, 2, 2), golden::kMaxSkewPipes + 1), std::invalid_argument);
}

// Every traversal (6 permutations x 8 flips), p = 1 .. 8, sizes that p does
// not divide: each pass hands pipeline k exactly the voxel the golden
// PermutedVolume holds at (j*p + k, y, z), zero in the padding and the zero
// beam, and no module is read twice in a cycle (VoxelMemory would throw).
TEST(StreamFormer, DeskewedBeamsAreThePermutedVolume) {
  const golden::Volume vol = numbered(7, 5, 6);
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  int checked = 0;
  for (int p = 1; p <= 8; ++p)
    for (const auto& pm : perms)
      for (int f = 0; f < 8; ++f) {
        golden::Registers r;
        r.perm = {pm[0], pm[1], pm[2]};
        r.flip = {(f & 1) != 0, (f & 2) != 0, (f & 4) != 0};
        for (int i = 0; i < 3; ++i) r.dim[i] = vol.dim[r.perm[i]];
        r.supersampling = 1;
        r.classification.resize(4096);
        const golden::PermutedVolume pv(vol, r.perm, r.flip);
        const sysc::FramePlan plan(r, p);
        sysc::VoxelMemory mem(vol, p);
        sysc::TlmAddr addr(mem.layout(), {r.perm, r.flip});
        sysc::StreamFormer former(plan, mem, addr);
        for (int pass = 0; pass < plan.passes; ++pass)
          for (int y = 0; y < plan.beams(pass + 1 == plan.passes); ++y)
            for (int j = 0; j < plan.B; ++j) {
              const sysc::VoxelBeat b = former.next();
              ASSERT_TRUE(b.valid);
              ASSERT_EQ(b.f.beam_start, j == 0);
              ASSERT_EQ(b.f.slice_end, y == plan.ny - 1);
              ASSERT_EQ(b.f.flush, y == plan.ny);
              const int z = plan.pass_voxel_slice(pass);
              for (int k = 0; k < p; ++k) {
                const int x = j * p + k;
                const uint16_t want = y < plan.ny ? pv.at(x, y, z) : 0;
                ASSERT_EQ(b.voxel[static_cast<size_t>(k)], want)
                    << "p=" << p << " perm " << pm[0] << pm[1] << pm[2] << " flips " << f << " pass " << pass
                    << " (x, y, z) = (" << x << ", " << y << ", " << z << ")";
                ++checked;
              }
            }
        EXPECT_FALSE(former.next().valid);
        EXPECT_TRUE(former.done());
      }
  EXPECT_GT(checked, 100000);
}

// VolumePro's z gradient (docs/rtl-interp-zdiff.md): the stream former
// primes each frame with voxel slice 0 and then reads one slice ahead
// (z_voxel + 1 when wz = 0, z_voxel + 2 otherwise, zero past the volume),
// and the clocked TLM interpolation and gradient units fed that stream give
// every sample and gradient golden render_fixed() gives. In the unit label,
// so that the sanitizer build runs the TLM units' z-difference path.
struct GradientCollect : golden::SampleProbe {
  int nx, ny;
  std::vector<uint32_t> value;
  std::vector<golden::Gradient> gradient;
  GradientCollect(int x, int y, int K) : nx(x), ny(y), value(static_cast<size_t>(x) * y * K), gradient(value.size()) {}
  size_t index(int k, int y, int x) const { return (static_cast<size_t>(k) * ny + y) * nx + x; }
  void sample(int x, int y, const golden::SliceControl& c, uint32_t v, const golden::Gradient& g) override {
    value[index(c.k, y, x)] = v;
    gradient[index(c.k, y, x)] = g;
  }
};

TEST(StreamFormer, VoxelZGradientPrimesAndReadsOneSliceAheadForTheClockedTlmUnits) {
  for (int S : {1, 2, 3})
    for (int p : {1, 3, 4}) {
      SCOPED_TRACE("S = " + std::to_string(S) + ", p = " + std::to_string(p));
      const golden::Scene scene = golden::parse_scene(
          R"({"volume": {"synthetic": "noise", "size": [9, 7, 6], "seed": 5}, "view": {"direction": [0.3, -0.4, 1]},
              "supersampling": )" + std::to_string(S) + R"(, "z_gradient": "voxel_differences"})",
          "zdiff.json");
      const golden::Volume vol = golden::load_volume(scene.volume, scene.precision.voxel_bits, ".");
      golden::Registers r = golden::program_host(scene, vol).regs;
      r.gradient = true;
      const golden::PermutedVolume pv(vol, r.perm, r.flip);
      const sysc::FramePlan plan(r, p);
      ASSERT_TRUE(plan.zdiff);
      ASSERT_EQ(plan.first_pass(), -1);
      sysc::VoxelMemory mem(vol, p);
      sysc::TlmAddr addr(mem.layout(), {r.perm, r.flip});
      sysc::StreamFormer former(plan, mem, addr);
      sysc::TlmInterp interp(plan);
      sysc::TlmGradient grad(plan);
      GradientCollect want(plan.nx, plan.ny, plan.K);
      golden::FixedOptions o;
      o.probe = &want;
      golden::render_fixed(vol, r, o);
      std::vector<int> seen(want.value.size(), 0);
      auto collect = [&](const sysc::GradientBeat& g) {
        if (!g.valid) return;
        for (int k = 0; k < p; ++k) {
          const int x = g.x + k;
          if (x >= plan.nx) continue;
          const size_t i = want.index(static_cast<int>(g.slice), g.y, x);
          ++seen[i];
          ASSERT_EQ(g.sample[static_cast<size_t>(k)], want.value[i]) << "slice " << g.slice << " (" << x << ", " << g.y << ")";
          const golden::Gradient got{g.gx[static_cast<size_t>(k)], g.gy[static_cast<size_t>(k)], g.gz[static_cast<size_t>(k)]};
          ASSERT_EQ(got, want.gradient[i]) << "slice " << g.slice << " (" << x << ", " << g.y << ")";
        }
      };
      for (int pass = plan.first_pass(); pass < plan.passes; ++pass)
        for (int y = 0; y < plan.beams(pass + 1 == plan.passes); ++y)
          for (int j = 0; j < plan.B; ++j) {
            const sysc::VoxelBeat b = former.next();
            ASSERT_TRUE(b.valid);
            ASSERT_EQ(b.f.prime, pass == -1 && y < plan.ny);
            // Slice 0 first, then one ahead of the 12-neighbourhood's stream.
            int z = plan.nz;
            if (pass == -1) {
              z = 0;
            } else if (pass < plan.K) {
              const golden::SliceControl c = golden::slice_control(r, pass);
              z = std::min(plan.nz, c.z_voxel + (c.wz != 0 ? 2 : 1));
            }
            ASSERT_EQ(plan.pass_voxel_slice(pass), z);
            for (int k = 0; k < p; ++k)
              ASSERT_EQ(b.voxel[static_cast<size_t>(k)], y < plan.ny ? pv.at(j * p + k, y, z) : 0)
                  << "pass " << pass << " (" << j * p + k << ", " << y << ")";
            sysc::SampleBeat sb;
            interp.clock(b, sb);
            sysc::GradientBeat gb;
            grad.clock(sb, gb);
            collect(gb);
            if (::testing::Test::HasFatalFailure()) return;
          }
      EXPECT_FALSE(former.next().valid);
      // Drain the units' queues (their latency is a pass).
      for (int i = 0; i < 4 * plan.ny * plan.B; ++i) {
        sysc::SampleBeat sb;
        interp.clock(sysc::VoxelBeat{}, sb);
        sysc::GradientBeat gb;
        grad.clock(sb, gb);
        collect(gb);
        if (::testing::Test::HasFatalFailure()) return;
      }
      for (size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "sample " << i;
    }
}

TEST(FramePlan, TagCarriesSliceZeroFlagAndRealignFields) {
  golden::Registers r;
  r.dim = {9, 8, 7};
  r.supersampling = 3;
  r.gradient = true;
  r.x_step = 300000;  // moving weights: realign fields change per slice
  r.y_step = -200000;
  r.y_start = 10 << 20;
  const sysc::FramePlan plan(r, 4);
  ASSERT_EQ(plan.passes, 7 * 3 + 1);
  for (int pass = 0; pass < plan.passes; ++pass) {
    const uint64_t t = plan.pass_tag(pass);
    EXPECT_EQ(plan.tag_slice(t), static_cast<uint32_t>(pass));
    EXPECT_EQ(plan.tag_zero_slice(t), pass == plan.K);
    EXPECT_LT(t, uint64_t{1} << plan.tag_bits());
    if (pass == plan.K) continue;
    const golden::SliceControl c = golden::slice_control(r, pass);
    const int w = r.p.weight_bits;
    EXPECT_EQ(t & ((1u << w) - 1), c.behind_x.weight);
    EXPECT_EQ(t >> w & 1, c.behind_x.base < 0 ? 1u : 0u);
    EXPECT_EQ(t >> (4 * (w + 1)) & 15, 3u) << "S";
  }
}

TEST(FramePlan, RefusesWhatTheStreamCannotCarry) {
  golden::Registers r;
  r.dim = {4, 4, 4};
  r.supersampling = 16;
  EXPECT_THROW(sysc::FramePlan(r, 4), std::invalid_argument);
  r.supersampling = 1;
  EXPECT_THROW(sysc::FramePlan(r, 0), std::invalid_argument);
}

}  // namespace

// --check's stream checker names the unit, slice and sample of the first
// difference (and takes golden's own values without complaint).
namespace {
// A 6 x 5 x 4 volume of numbered voxels and its frame, with gradients.
struct CheckedFrame {
  golden::Volume vol;
  golden::Registers r;
  CheckedFrame() : vol(numbered(6, 5, 4)) {
    for (auto& v : vol.data) v = static_cast<uint16_t>(v % 4096);
    r.dim = {6, 5, 4};
    r.classification.resize(4096);
    r.gradient = true;
  }
};

TEST(StreamChecker, NamesTheFirstDifferingUnitSliceAndSample) {
  const CheckedFrame f;
  const golden::Volume& vol = f.vol;
  const golden::Registers& r = f.r;
  const sysc::FramePlan plan(r, 4);
  sysc::StreamChecker checker(plan, vol);
  const golden::PermutedVolume pv(vol, r.perm, r.flip);
  // Slice 0, beam 0: the samples are the voxels (zero weights): correct.
  sysc::SampleBeat b;
  b.valid = true;
  b.f = {true, false, true, false};
  b.tag = plan.pass_tag(0);
  for (int k = 0; k < 4; ++k) b.sample[static_cast<size_t>(k)] = pv.at(k, 0, 0);
  checker.samples(b);
  EXPECT_FALSE(checker.first_mismatch());
  // Second partial beam, x = 4, 5: one wrong value at x = 5.
  b.f = {false, true, true, false};
  b.sample = {};
  b.sample[0] = pv.at(4, 0, 0);
  b.sample[1] = static_cast<uint16_t>(pv.at(5, 0, 0) + 1);
  checker.samples(b);
  ASSERT_TRUE(checker.first_mismatch());
  const sysc::Mismatch m = *checker.first_mismatch();
  EXPECT_EQ(m.unit, sysc::Unit::Interp);
  EXPECT_EQ(m.slice, 0);
  EXPECT_EQ(m.x, 5);
  EXPECT_EQ(m.y, 0);
  EXPECT_NE(m.describe().find("interp unit, slice 0, sample (5, 0)"), std::string::npos) << m.describe();
  // A wrong gradient later does not replace the earlier unit's report.
  sysc::GradientBeat g;
  g.valid = true;
  g.slice = 2;
  g.x = 0;
  g.y = 3;
  g.gx[0] = 99;
  checker.gradients(g);
  EXPECT_EQ(checker.first_mismatch()->unit, sysc::Unit::Interp);
}

// The checking thread takes the beats in batches: a difference after
// several batches' worth of beats is found when the caller asks, and the
// beats before it (here all beyond the volume's x, so compared with
// nothing) do not count as differences.
TEST(StreamChecker, FindsADifferenceManyBatchesIntoTheStream) {
  const CheckedFrame f;
  const sysc::FramePlan plan(f.r, 4);
  sysc::StreamChecker checker(plan, f.vol);
  sysc::GradientBeat g;
  g.valid = true;
  g.slice = 1;
  g.x = 8;  // beyond nx = 6
  g.gx[0] = 99;
  for (int i = 0; i < 3 * 4096 + 17; ++i) checker.gradients(g);
  EXPECT_FALSE(checker.first_mismatch());
  g.x = 4;
  g.y = 2;
  checker.gradients(g);
  ASSERT_TRUE(checker.first_mismatch());
  EXPECT_EQ(checker.first_mismatch()->unit, sysc::Unit::Gradient);
  EXPECT_EQ(checker.first_mismatch()->x, 4);
  EXPECT_EQ(checker.first_mismatch()->y, 2);
}
// A failed RTL assertion stops the unit's clock() with RtlAssertionError,
// naming the unit and the system's cycle (the checker's message on stdout
// names the assertion and the same cycle); with the context's assertions
// off (cube4 render --no-assert) the same stream runs on. The stream: the
// zero slice of the gradient ring, ny = 2 beams of B = 2 partial beams
// (nx = 6, p = 4), then a sample in the unit's zero beam, which must be idle.
// No scene makes the system send such a stream, so this is the wrapper
// level's test of the path cube4 render takes to its exit code 4.
TEST(RtlAssertion, StopsTheFrameNamingUnitAndCycle) {
  if (!CUBE4_TEST_RTL) GTEST_SKIP() << "built without RTL";
#if CUBE4_TEST_RTL
  golden::Registers r;
  r.dim = {6, 2, 3};
  r.gradient = true;
  const sysc::FramePlan plan(r, 4);
  for (const bool assertions : {true, false}) {
    rtl::ScopedVerilatedContext ctx;
    ctx->fatalOnError(false);
    ctx->assertOn(assertions);
    auto gradient = sysc::make_rtl_gradient(plan, *ctx, sysc::TraceWindow{});
    sysc::SampleBeat in;
    sysc::GradientBeat out;
    in.tag = plan.pass_tag(plan.K);  // the zero slice, which the unit's zero beam follows
    testing::internal::CaptureStdout();
    int failed_cycle = 0;
    std::string unit;
    for (int cycle = 1; cycle <= 8; ++cycle) {
      const int step = cycle - 1;  // 0 .. 3: the slice; 4: the zero beam's first cycle
      in.valid = step <= 4;
      in.f.beam_start = step % 2 == 0;
      in.f.beam_end = step % 2 == 1;
      in.f.slice_start = step < 2;
      in.f.slice_end = step == 2 || step == 3;
      try {
        gradient->clock(in, out);
      } catch (const sysc::RtlAssertionError& e) {
        failed_cycle = cycle;
        unit = e.unit();
        EXPECT_EQ(e.cycle(), 5u);
        EXPECT_NE(std::string(e.what()).find("gradient unit (RTL) failed in cycle 5"), std::string::npos) << e.what();
        break;
      }
    }
    std::fflush(stdout);
    const std::string printed = testing::internal::GetCapturedStdout();
    if (assertions) {
      EXPECT_EQ(failed_cycle, 5);
      EXPECT_EQ(unit, "gradient");
      EXPECT_NE(printed.find("a_zero_beam_idle: cube4_gradient_unit: cycle 5: valid_i high in a zero-beam cycle"),
                std::string::npos)
          << printed;
    } else {
      EXPECT_EQ(failed_cycle, 0);
      EXPECT_EQ(printed, "");
    }
  }
#endif
}

}  // namespace
