// cube4 explore: sweep files expand to the points they say and are refused
// with the file, key and value named; the Pareto front is the set of points
// nothing beats; a small sweep runs through GNU parallel into a table, fronts
// and plots, and resumes without recomputing what is done.
#include "tb/explore.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "golden/errors.hpp"
#include "golden/scene_io.hpp"
#include "tb/tests/one_node_slurm.hpp"

namespace cube4::tb {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("cube4_test_explore_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string read(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

int exit_code(const std::string& cmd) {
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A 24³ sphere, small enough for a sweep in the default suite.
constexpr const char* kScene = R"({"volume": {"synthetic": "sphere", "size": [24, 24, 24]},
  "view": {"rotate": [20, 30, 0]}, "output": {"width": 48, "height": 48}, "pipelines": 4, "clock_mhz": 125})";

std::string error_of(const fs::path& sweep) {
  try {
    load_sweep(sweep.string());
  } catch (const golden::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Explore, AxesMakeTheirProductThenThePointsListed) {
  const fs::path d = scratch("product");
  write(d / "scene.json", kScene);
  write(d / "s.json", R"({"scene": "scene.json", "axes": {"supersampling": [1, 2], "precision.alpha_bits": [12, 16]},
    "points": [{"pipelines": 8}]})");
  const Sweep s = load_sweep((d / "s.json").string());
  ASSERT_EQ(s.points.size(), 5u);
  EXPECT_EQ(s.points[0].scene["supersampling"], 1);
  EXPECT_EQ(s.points[0].scene["precision"]["alpha_bits"], 12);
  EXPECT_EQ(s.points[1].scene["precision"]["alpha_bits"], 16);  // the last axis varies fastest
  EXPECT_EQ(s.points[2].scene["supersampling"], 2);
  EXPECT_EQ(s.points[4].scene["pipelines"], 8);
  EXPECT_FALSE(s.points[4].scene.contains("supersampling"));
  EXPECT_EQ(s.model, "tlm");
}

TEST(Explore, RelativeFilesOfTheSceneBecomeAbsolute) {
  const fs::path d = scratch("files");
  fs::create_directories(d / "scenes");
  write(d / "scenes" / "s.json", R"({"volume": {"file": "head.den"}})");
  write(d / "sweep.json", R"({"scene": "scenes/s.json"})");
  // The volume file does not exist, but the scene parser does not open it.
  const Sweep s = load_sweep((d / "sweep.json").string());
  EXPECT_EQ(s.points.at(0).scene["volume"]["file"], (d / "scenes" / "head.den").string());
}

TEST(Explore, BadSweepsAreRefusedNamingFileKeyAndValue) {
  const fs::path d = scratch("bad");
  write(d / "scene.json", kScene);
  auto refused = [&](const std::string& sweep, const std::vector<std::string>& words) {
    write(d / "s.json", sweep);
    const std::string e = error_of(d / "s.json");
    ASSERT_FALSE(e.empty()) << sweep;
    EXPECT_NE(e.find((d / "s.json").string()), std::string::npos) << e;
    for (const std::string& w : words) EXPECT_NE(e.find(w), std::string::npos) << e << " lacks " << w;
  };
  refused(R"({"scene": "scene.json", "axes": {"transfer": [1]}})", {"transfer", "cannot be swept"});
  refused(R"({"scene": "scene.json", "axes": {"precision.no_such_bits": [1]}})", {"precision.no_such_bits"});
  refused(R"({"scene": "scene.json", "axes": {"precision.alpha_bits": [12, 40]}})",
          {"precision.alpha_bits = 40", "alpha_bits"});
  refused(R"({"scene": "scene.json", "axes": {"supersampling": [9]}})", {"supersampling = 9"});
  refused(R"({"scene": "scene.json", "axes": {"supersampling": []}})", {"supersampling", "non-empty"});
  refused(R"({"scene": "scene.json", "axes": {"z_gradient": ["abc", "sobel"]}})", {"z_gradient = sobel", "sobel"});
  refused(R"({"scene": "scene.json", "model": "gates"})", {"gates", "cannot be explored"});
  refused(R"({"scene": "scene.json", "frames": 3})", {"unknown key \"frames\""});
  refused(R"({"scene": "missing.json"})", {"missing.json"});
  refused(R"({"axes": {"supersampling": [1]}})", {"no \"scene\""});
  refused(R"({"scene": "scene.json", "roi": [0, 0, 0, 4]})", {"roi"});
  refused(R"({"scene": "scene.json", "points": [3]})", {"points[0]"});
  refused(R"({"scene": "scene.json", "check": "yes"})", {"\"check\"", "true or false"});
  refused(R"({"scene": "scene.json", "model": "fixed", "check": true})", {"\"check\"", "system model", "fixed"});
  refused("{", {"not JSON"});
}

TEST(Explore, ParetoFrontKeepsWhatNothingBeats) {
  // (psnr, cost): b beats a; c and d trade; e equals d.
  const std::vector<double> psnr{30, 31, 40, 35, 35}, cost{10, 9, 20, 12, 12};
  EXPECT_EQ(pareto_front(psnr, cost), (std::vector<bool>{false, true, true, true, true}));
  EXPECT_TRUE(pareto_front({}, {}).empty());
}

TEST(Explore, EachUnitIsSynthesisedWithTheParametersItDeclares) {
  golden::Scene s = golden::parse_scene(kScene, "scene");
  const auto d = declared_parameters(gate_config(s));
  ASSERT_EQ(d.size(), 6u);
  EXPECT_EQ(d.at("cube4_addr"), "NumPipes=4");
  EXPECT_NE(d.at("cube4_dda").find("FracBits=20"), std::string::npos) << d.at("cube4_dda");
  EXPECT_EQ(d.at("cube4_dda").find("NumPipes"), std::string::npos);
  // The weight generator's perspective divisions for perspective points only.
  EXPECT_NE(d.at("cube4_dda").find("HasPerspective=0"), std::string::npos) << d.at("cube4_dda");
  s.view.projection = golden::View::Projection::Perspective;
  EXPECT_NE(declared_parameters(gate_config(s)).at("cube4_dda").find("HasPerspective=1"), std::string::npos);
  EXPECT_NE(d.at("cube4_shade_unit").find("AlphaBits=16"), std::string::npos);
  EXPECT_EQ(d.at("cube4_shade_unit").find("NumPipes"), std::string::npos);
  EXPECT_NE(d.at("cube4_composite_unit").find("SliceDepth=16384"), std::string::npos);
  EXPECT_EQ(d.at("cube4_interp_unit").find("AlphaBits"), std::string::npos);
}

TEST(Explore, GateConfigurationFollowsWidthsAndPipelines) {
  golden::Scene s = golden::parse_scene(kScene, "scene");
  const std::string c4 = gate_config(s);
  EXPECT_NE(c4.find("AlphaBits=16"), std::string::npos) << c4;
  EXPECT_NE(c4.find("NumPipes=4,BeamDepth=64,SliceDepth=16384"), std::string::npos) << c4;
  EXPECT_NE(c4.find("FracBits=20"), std::string::npos) << "the weight generator's fraction: " << c4;
  s.pipelines = 5;
  EXPECT_NE(gate_config(s).find("NumPipes=5,BeamDepth=52,SliceDepth=13312"), std::string::npos);
}

// The whole flow, gates from a cache filled beforehand (yosys takes a
// minute or more per unit: scripts/explore.sh runs it for real).
TEST(Explore, SmallSweepRunsThroughParallelAndResumes) {
  if (exit_code("command -v parallel >/dev/null") != 0) GTEST_SKIP() << "GNU parallel not installed (apt-get install parallel)";
  const fs::path d = scratch("run");
  write(d / "scene.json", kScene);
  write(d / "s.json", R"({"scene": "scene.json", "model": "tlm", "reference_step": 0.5, "roi": [12, 12, 24, 24],
    "axes": {"supersampling": [1, 2], "pipelines": [2, 4]}})");
  const Sweep sweep = load_sweep((d / "s.json").string());
  // Made-up unit counts: the table must sum them per pipeline and chip.
  const fs::path cache = d / "gates";
  fs::create_directories(cache);
  for (const ExplorePoint& p : sweep.points) {
    const golden::Scene s = golden::parse_scene(p.scene.dump(), "point");
    for (const auto& [unit, params] : declared_parameters(gate_config(s))) {
      const nlohmann::json row = {{"nand2", unit == "cube4_addr" ? 50.0 : 100.0}, {"ram_bits", unit == "cube4_addr" ? 0.0 : 10.0}};
      write(gates_cache_file(cache.string(), unit, params),
            nlohmann::json{{"unit", unit}, {"parameters", params}, {"row", row}}.dump());
    }
  }
  const std::string cmd = std::string(CUBE4_BINARY) + " explore " + (d / "s.json").string() + " --out " +
                          (d / "out").string() + " -j 2 --gates-cache " + cache.string() + " 2> " +
                          (d / "log.txt").string();
  ASSERT_EQ(exit_code(cmd), 0) << read(d / "log.txt");
  const nlohmann::json r = nlohmann::json::parse(read(d / "out" / "results.json"));
  ASSERT_EQ(r["points"].size(), 4u);
  for (const auto& p : r["points"]) {
    ASSERT_EQ(p["status"], "ok") << p.dump();
    EXPECT_GT(p["error"]["psnr_db"].get<double>(), 10.0);
    EXPECT_LE(p["error_roi"]["max"].get<double>(), 1.0);
    EXPECT_GT(p["cycles_per_image"].get<double>(), 0.0);
    const int pipes = p["pipelines"];
    EXPECT_EQ(p["gates"]["nand2_pipeline"], 400.0);
    EXPECT_EQ(p["gates"]["nand2_chip"], 50.0 + 100.0 + pipes * 400.0);  // address and weight generators
    EXPECT_EQ(p["gates"]["ram_bits_chip"], 10.0 + pipes * 40.0);
  }
  // S = 2 costs twice the cycles of S = 1 at the same p.
  EXPECT_NEAR(r["points"][2]["cycles_per_image"].get<double>() / r["points"][0]["cycles_per_image"].get<double>(), 2.0,
              0.1);
  // p changes cycles and gates, not the image; S = 2 is the more accurate
  // here. Cycles: (S 1, p 4) is the cheapest, (S 2, p 4) beats (S 1, p 2).
  // Gates: (S 2, p 2) beats both p = 2 and p = 4 at S = 1.
  auto front = [&](const char* cost) {
    std::vector<bool> f;
    for (const auto& p : r["points"]) f.push_back(p["pareto"][cost].get<bool>());
    return f;
  };
  EXPECT_EQ(r["points"][0]["error"]["psnr_db"], r["points"][1]["error"]["psnr_db"]);
  EXPECT_EQ(front("cycles"), (std::vector<bool>{false, true, false, true}));
  EXPECT_EQ(front("gates"), (std::vector<bool>{false, false, true, false}));
  const std::string csv = read(d / "out" / "results.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  EXPECT_EQ(csv.rfind("index,supersampling,pipelines,status,psnr_db", 0), 0u) << csv;
  EXPECT_TRUE(fs::exists(d / "out" / "plots" / "fronts.png")) << read(d / "out" / "plots-log.txt");
  EXPECT_TRUE(fs::exists(d / "out" / "plots" / "fronts.svg"));
  EXPECT_EQ(read(d / "out" / "jobs.txt").find(" --point 3"), read(d / "out" / "jobs.txt").rfind(" --point 3"));

  // Resume: only the point whose result is gone runs again.
  const fs::path kept = d / "out" / "points" / "0000" / "result.json";
  const auto kept_time = fs::last_write_time(kept);
  fs::remove(d / "out" / "points" / "0002" / "result.json");
  ASSERT_EQ(exit_code(cmd), 0) << read(d / "log.txt");
  EXPECT_NE(read(d / "log.txt").find("1 to run"), std::string::npos) << read(d / "log.txt");
  EXPECT_EQ(fs::last_write_time(kept), kept_time);
  EXPECT_TRUE(fs::exists(d / "out" / "points" / "0002" / "result.json"));

  // --emit-jobs lists every point and runs none.
  ASSERT_EQ(exit_code(std::string(CUBE4_BINARY) + " explore " + (d / "s.json").string() + " --out " +
                      (d / "jobs").string() + " --emit-jobs -q"),
            0);
  const std::string jobs = read(d / "jobs" / "jobs.txt");
  EXPECT_EQ(std::count(jobs.begin(), jobs.end(), '\n'), 4);
  EXPECT_FALSE(fs::exists(d / "jobs" / "points"));
}

// The same sweep as a Slurm job array and a collect job after it
// (scripts/explore_slurm.sh --wait), on a one-node Slurm started here, gives
// the table GNU parallel gives (all but the simulation times); skipped,
// with the reason, where Slurm cannot run. Made-up gate counts in a cache
// the jobs find through XDG_CACHE_HOME (sbatch passes the environment on).
TEST(Explore, SlurmJobArrayGivesTheParallelTable) {
  const fs::path d = scratch("slurm");
  cube4::test::OneNodeSlurm slurm(d / "slurm");
  if (!slurm.why_not().empty()) GTEST_SKIP() << "no Slurm here: " << slurm.why_not();
  if (exit_code("command -v parallel >/dev/null") != 0) GTEST_SKIP() << "GNU parallel not installed";
  write(d / "scene.json", kScene);
  write(d / "s.json", R"({"scene": "scene.json", "model": "tlm", "reference_step": 0.5, "roi": [12, 12, 24, 24],
    "axes": {"pipelines": [2, 4]}})");
  const Sweep sweep = load_sweep((d / "s.json").string());
  const fs::path cache = d / "xdg" / "cube4" / "gates";
  fs::create_directories(cache);
  for (const ExplorePoint& p : sweep.points) {
    const golden::Scene s = golden::parse_scene(p.scene.dump(), "point");
    for (const auto& [unit, params] : declared_parameters(gate_config(s)))
      write(gates_cache_file(cache.string(), unit, params),
            nlohmann::json{{"unit", unit}, {"parameters", params}, {"row", {{"nand2", 100.0}, {"ram_bits", 10.0}}}}.dump());
  }
  ::setenv("XDG_CACHE_HOME", (d / "xdg").c_str(), 1);
  const std::string bin = CUBE4_BINARY, sweep_file = (d / "s.json").string();
  ASSERT_EQ(exit_code(bin + " explore " + sweep_file + " --out " + (d / "parallel").string() + " -j 2 -q 2> " +
                      (d / "parallel.log").string()),
            0)
      << read(d / "parallel.log");
  ASSERT_EQ(exit_code("timeout 300 " CUBE4_SOURCE_DIR "/scripts/explore_slurm.sh " + sweep_file + " --out " +
                      (d / "slurm-out").string() + " --cube4 " + bin + " --wait > " + (d / "slurm.log").string() +
                      " 2>&1"),
            0)
      << read(d / "slurm.log") << read(d / "slurm-out" / "slurm-collect.log");
  ::unsetenv("XDG_CACHE_HOME");
  const nlohmann::json a = nlohmann::json::parse(read(d / "parallel" / "results.json"));
  const nlohmann::json b = nlohmann::json::parse(read(d / "slurm-out" / "results.json"));
  ASSERT_EQ(a["points"].size(), 2u);
  ASSERT_EQ(b["points"].size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    nlohmann::json x = a["points"][i], y = b["points"][i];
    EXPECT_EQ(y["status"], "ok") << y.dump();
    for (nlohmann::json* p : {&x, &y}) {
      p->erase("sim_seconds");  // a simulation's own times: not the same twice
      p->erase("process_seconds");
      p->erase("pareto");       // partly by simulation time
    }
    EXPECT_EQ(x, y) << "point " << i;
  }
}

TEST(Explore, CommandRefusesABadSweepWithExitTwo) {
  const fs::path d = scratch("cli");
  write(d / "scene.json", kScene);
  write(d / "s.json", R"({"scene": "scene.json", "axes": {"blend": ["mip"]}})");
  EXPECT_EQ(exit_code(std::string(CUBE4_BINARY) + " explore " + (d / "s.json").string() + " --out " +
                      (d / "out").string() + " 2> " + (d / "err.txt").string()),
            2);
  EXPECT_NE(read(d / "err.txt").find("\"blend\" cannot be swept"), std::string::npos) << read(d / "err.txt");
}

}  // namespace
}  // namespace cube4::tb
