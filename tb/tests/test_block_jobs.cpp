// Blocks as independent jobs (tb/block_jobs.hpp): cube4 plan, one
// `cube4 render --plan --block --partial` process per block, cube4 compose;
// run by GNU parallel (scripts/render_blocks.sh) and by a Slurm job array
// on a one-node Slurm the test starts (scripts/render_blocks_slurm.sh).
// The composed base plane must equal one process's `cube4 render --blocks`
// bit for bit, and every bad plan or partial image must be refused by name.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <sys/wait.h>
#include <fstream>
#include <string>
#include <thread>

#include "tb/image_io.hpp"
#include "tb/tests/cli_support.hpp"
#include "tb/tests/one_node_slurm.hpp"

namespace fs = std::filesystem;

namespace {

using cube4::test::Cli;
using cube4::test::CliResult;

const char* kScene = R"({"volume": {"synthetic": "noise", "size": [20, 18, 16], "seed": 3},
                         "view": {"rotate": [25, -30, 10]}, "output": {"width": 48, "height": 48},
                         "transfer": {"opacity": [[0, 0], [0.3, 0.1], [1, 0.6]]}})";

class BlockJobs : public Cli {
 protected:
  std::string script(const std::string& name) const { return std::string(CUBE4_SOURCE_DIR) + "/scripts/" + name; }
  // The one-process partitioned base plane.
  std::vector<uint16_t> one_process(const std::string& scene, const std::string& counts, const std::string& model) {
    const CliResult r = run("render " + scene + " --blocks " + counts + " --model " + model + " -q -o " + path("one.png") +
                            " --baseplane " + path("one_bp.png"));
    EXPECT_EQ(r.code, 0) << r.err;
    return cube4::tb::read_baseplane_png(path("one_bp.png"), 16).rgba;
  }
  CliResult shell(const std::string& line) const {
    const std::string cmd = "bash -c '" + line + "' >" + path("sh.out") + " 2>" + path("sh.err");
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream e(path("sh.err")), o(path("sh.out"));
    r.err.assign(std::istreambuf_iterator<char>(e), {});
    r.out.assign(std::istreambuf_iterator<char>(o), {});
    return r;
  }
};

}  // namespace

TEST_F(BlockJobs, GnuParallelGivesTheOneProcessImage) {
  const std::string scene = write("s.json", kScene);
  std::vector<std::string> models = {"tlm"};
  if (CUBE4_TEST_RTL) models.push_back("rtl");
  for (const std::string& model : models) {
    const CliResult r = shell(script("render_blocks.sh") + " " + scene + " 2x2x2 " + path("jobs.png") + " --model " +
                              model + " -j 2 --cube4 " + CUBE4_BINARY + " --baseplane " + path("jobs_bp.png") +
                              " --work " + path("work_" + model));
    ASSERT_EQ(r.code, 0) << model << "\n" << r.err;
    EXPECT_EQ(cube4::tb::read_baseplane_png(path("jobs_bp.png"), 16).rgba, one_process(scene, "2x2x2", model)) << model;
    for (int i = 0; i < 8; ++i) EXPECT_TRUE(fs::exists(path("work_" + model + "/block" + std::to_string(i) + ".json")));
  }
}

TEST_F(BlockJobs, BadPlansAndPartialImagesAreRefusedByName) {
  const std::string scene = write("s.json", kScene);
  const CliResult plan = run("plan " + scene + " --blocks 2x1x2 -o " + path("plan.json"));
  ASSERT_EQ(plan.code, 0) << plan.err;
  EXPECT_EQ(plan.out, "4\n");
  std::string parts;
  for (int i = 0; i < 4; ++i) {
    const std::string part = path("p" + std::to_string(i) + ".cpart");
    const CliResult r = run("render --plan " + path("plan.json") + " --block " + std::to_string(i) + " --partial " +
                            part + " -q");
    ASSERT_EQ(r.code, 0) << r.err;
    parts += " " + part;
  }
  auto compose = [&](const std::string& files) {
    return run("compose " + path("plan.json") + " " + files + " -q -o " + path("c.png"));
  };
  ASSERT_EQ(compose(parts).code, 0);
  fs::remove(path("c.png"));
  const std::string p0 = path("p0.cpart"), p1 = path("p1.cpart"), p2 = path("p2.cpart"), p3 = path("p3.cpart");
  struct Bad {
    std::string files, message;
  };
  // A corrupt byte, a cut file, and a file that is no partial image.
  fs::copy_file(p1, path("bad.cpart"));
  {
    std::fstream f(path("bad.cpart"), std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(400);
    f.put('\x5a');
  }
  fs::copy_file(p1, path("cut.cpart"));
  fs::resize_file(path("cut.cpart"), fs::file_size(p1) - 7);
  write("text.cpart", "hello");
  // Partial images of another plan: another cut of the same scene.
  ASSERT_EQ(run("plan " + scene + " --blocks 4x1x1 -o " + path("other.json")).code, 0);
  ASSERT_EQ(run("render --plan " + path("other.json") + " --block 0 --partial " + path("o0.cpart") + " -q").code, 0);
  const Bad cases[] = {
      {p0 + " " + p1 + " " + p3, "block 2 of 4 missing"},
      {parts + " " + p2, "block 2 again"},
      {p0 + " " + path("bad.cpart") + " " + p2 + " " + p3, "bad.cpart: corrupt (CRC-32 mismatch)"},
      {p0 + " " + path("cut.cpart") + " " + p2 + " " + p3, "cut.cpart: truncated"},
      {p0 + " " + path("text.cpart") + " " + p2 + " " + p3, "text.cpart: not a cube4 partial image"},
      {path("o0.cpart") + " " + p1 + " " + p2 + " " + p3, "o0.cpart: a partial image of another plan"},
      {p0 + " " + p1 + " " + p2 + " " + path("missing.cpart"), "missing.cpart"},
  };
  for (const Bad& c : cases) {
    const CliResult r = compose(c.files);
    EXPECT_EQ(r.code, 2) << c.message;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("c.png"))) << c.message << ": an image was written";
  }
  // The scene changed after the plan was made: its blocks would not fit.
  std::string changed = kScene;
  changed.insert(changed.rfind('}'), R"(, "shading": false)");
  write("s.json", changed);
  const CliResult stale = run("render --plan " + path("plan.json") + " --block 0 --partial " + path("x.cpart") + " -q");
  EXPECT_EQ(stale.code, 2);
  EXPECT_NE(stale.err.find("changed since the plan was made"), std::string::npos) << stale.err;
  EXPECT_NE(compose(parts).err.find("changed since the plan was made"), std::string::npos);
  // Options that make no sense together.
  EXPECT_EQ(run("render --plan " + path("plan.json") + " --block 7 --partial " + path("x.cpart")).code, 2);
  EXPECT_EQ(run("render " + scene + " --block 1 --partial " + path("x.cpart")).code, 2);
  EXPECT_EQ(run("render --plan " + path("plan.json") + " --block 1").code, 2);
  write("notplan.json", "{\"scene\": 3}");
  const CliResult np = run("compose " + path("notplan.json") + parts + " -q -o " + path("c.png"));
  EXPECT_EQ(np.code, 2);
  EXPECT_NE(np.err.find("notplan.json: not a plan"), std::string::npos) << np.err;
}

using cube4::test::OneNodeSlurm;

// The same blocks as a Slurm job array and a compose job that waits for it
// (scripts/render_blocks_slurm.sh --wait), on a one-node Slurm started here;
// skipped, with the reason, where Slurm cannot run.
TEST_F(BlockJobs, SlurmJobArrayGivesTheOneProcessImage) {
  const std::string scene = write("s.json", kScene);
  OneNodeSlurm slurm(dir / "slurm");
  if (!slurm.why_not().empty()) GTEST_SKIP() << "no Slurm here: " << slurm.why_not();
  const CliResult r = shell("timeout 300 " + script("render_blocks_slurm.sh") + " " + scene + " 2x1x2 " +
                            path("slurm.png") + " --work " + path("work") + " --cube4 " + CUBE4_BINARY + " --wait");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const CliResult bp = run("compose " + path("work/plan.json") + " " + path("work/block0.cpart") + " " +
                           path("work/block1.cpart") + " " + path("work/block2.cpart") + " " +
                           path("work/block3.cpart") + " -q -o " + path("again.png") + " --baseplane " +
                           path("slurm_bp.png"));
  ASSERT_EQ(bp.code, 0) << bp.err;
  EXPECT_TRUE(fs::exists(path("slurm.png")));
  EXPECT_EQ(cube4::tb::read_baseplane_png(path("slurm_bp.png"), 16).rgba, one_process(scene, "2x1x2", "tlm"));
}
