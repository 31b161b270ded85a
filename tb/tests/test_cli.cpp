// The cube4 command end to end: outputs, reports, exit codes and the
// messages of bad input (they must name the file, key and value).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include <sys/wait.h>

#include "tb/image_io.hpp"
#if CUBE4_TEST_RTL
#include <gtkwave/fstapi.h>  // the reader in Verilator's runtime
#endif
#include "tb/tests/cli_support.hpp"

namespace fs = std::filesystem;

namespace {

using cube4::test::Cli;
using cube4::test::CliResult;

const char* kSphere = R"({"volume": {"synthetic": "sphere", "size": [16, 16, 16]}, "view": {"rotate": [10, 20, 0]},
                          "output": {"width": 64, "height": 48}})";

}  // namespace

TEST_F(Cli, RendersEveryModelWithReportAndBasePlane) {
  const std::string scene = write("s.json", kSphere);
  for (const std::string model : {"fixed", "float", "reference", "splat"}) {
    const std::string out = path(model + ".png"), rep = path(model + ".json");
    const bool base_plane = model != "reference" && model != "splat";
    const std::string bp = base_plane ? " --baseplane " + path(model + "_bp.png") : "";
    const CliResult r = run("render " + scene + " --model " + model + " -q -o " + out + " --report " + rep + bp);
    ASSERT_EQ(r.code, 0) << r.err;
    const auto img = cube4::tb::read_image(out);
    EXPECT_EQ(img.width, 64);
    EXPECT_EQ(img.height, 48);
    nlohmann::json j;
    std::ifstream(rep) >> j;
    EXPECT_EQ(j["model"], model);
    EXPECT_EQ(j["samples"].get<uint64_t>() > 0, true);
    for (const char* key : {"volume", "view", "pipelines", "wall_seconds", "samples_per_second", "effects"})
      EXPECT_TRUE(j.contains(key)) << key;
    if (model == "splat") {
      EXPECT_EQ(j["splat"]["extent"].get<int>() % 2, 1);
    }
    if (model == "fixed") {
      EXPECT_EQ(j["samples"], 16 * 16 * 16);
      EXPECT_EQ(j["baseplane_hash_fnv1a64"].get<std::string>().size(), 16u);
    }
  }
}

TEST_F(Cli, BasePlanePngRoundTripsTheHardwareValues) {
  const std::string scene = write("s.json", kSphere);
  ASSERT_EQ(run("render " + scene + " -q -o " + path("a.png") + " --baseplane " + path("bp.png")).code, 0);
  const auto bp = cube4::tb::read_baseplane_png(path("bp.png"), 12);
  EXPECT_GT(bp.width, 16);
  int64_t alpha = 0;
  for (size_t i = 3; i < bp.rgba.size(); i += 4) {
    ASSERT_LE(bp.rgba[i], 4095);
    alpha += bp.rgba[i];
  }
  EXPECT_GT(alpha, 0);
}

TEST_F(Cli, InfoPrintsFactorisationRegistersAndEffects) {
  const std::string scene = write("s.json", kSphere);
  const std::string cmd = std::string(CUBE4_BINARY) + " info " + scene + " > " + path("info.json");
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  nlohmann::json j;
  std::ifstream(path("info.json")) >> j;
  EXPECT_TRUE(j["view"].contains("base_plane_axis"));
  EXPECT_TRUE(j["registers"].contains("dda"));
  EXPECT_EQ(j["effects"][0], "composite");
  EXPECT_EQ(j["view"]["zoom"], 1.0);
  EXPECT_EQ(j["view"]["look_at"], (std::vector<double>{7.5, 7.5, 7.5}));
  EXPECT_EQ(j["view"]["xy_supersampling"], 1);
  EXPECT_TRUE(j["polygons"].empty());
}

// The meshes as loaded: what they are, how many triangles, where.
TEST_F(Cli, InfoListsTheMeshes) {
  const std::string cmd = std::string(CUBE4_BINARY) + " info " + CUBE4_SOURCE_DIR + "/scenes/brain_probe.json > " +
                          path("info.json");
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  nlohmann::json j;
  std::ifstream(path("info.json")) >> j;
  ASSERT_EQ(j["polygons"].size(), 2u);
  EXPECT_NE(j["polygons"][0]["source"].get<std::string>().find("probe.obj"), std::string::npos);
  EXPECT_TRUE(j["polygons"][0]["closed"]);
  EXPECT_GT(j["polygons"][0]["triangles"].get<int>(), 0);
  const nlohmann::json& sphere = j["polygons"][1];
  EXPECT_EQ(sphere["source"], "sphere");
  EXPECT_EQ(sphere["triangles"], 2 * 24 * (12 - 1));  // docs/scene.md: 2·segments·(rings − 1)
  EXPECT_EQ(sphere["opacity"], 0.4);
  EXPECT_EQ(sphere["lit"], false);
  EXPECT_NEAR(sphere["bounds"][0][0].get<double>(), 64 - 6, 1e-9);
  EXPECT_NEAR(sphere["bounds"][1][2].get<double>(), 42 + 6, 1e-9);
}

TEST_F(Cli, BadInputExitsTwoNamingTheCulprit) {
  const std::string good = write("s.json", kSphere);
  struct Case { std::string args; std::string must_contain; };
  const std::vector<Case> cases = {
      {"render " + path("missing.json"), "missing.json"},
      {"render " + write("k.json", R"({"volume": {"synthetic": "sphere"}, "shadng": true})"), "shadng"},
      {"render " + write("r.json", R"({"volume": {"synthetic": "sphere"}, "supersampling": 9})"), "supersampling"},
      {"render " + write("v.json", R"({"volume": {"file": "nowhere.den"}})"), "nowhere.den"},
      {"render " + write("j.json", R"({"volume": )"), "j.json"},
      {"render " + good + " -o " + path("out.jpg"), "out.jpg"},
      {"render " + good + " --model bogus", "bogus"},
      {"render " + good + " --model reference --baseplane " + path("bp.png"), "baseplane"},
      {"render " + good + " --model mixed:interp,shader", "shader"},
      {"render " + good + " --model mixed:", "mixed:"},
      {"render " + good + " --model rtl --pipes 3", CUBE4_TEST_RTL ? "pipelines: 3" : "CUBE4_RTL=OFF"},
      {"render " + good + " --model tlm --trace " + path("t.fst"), "--trace"},
      {"render " + good + " --model rtl --trace " + path("t.vcd"), "t.vcd"},
      {"render " + good + " --model rtl --trace " + path("t.fst") + " --trace-window 9 3", "--trace-window"},
      {"render " + good + " --model rtl --pipes 0", "--pipes"},
      {"frobnicate", "frobnicate"},
  };
  for (const Case& c : cases) {
    const CliResult r = run(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.must_contain), std::string::npos) << c.args << "\n" << r.err;
  }
  // Nothing half-written for a rejected run.
  EXPECT_FALSE(fs::exists(path("out.jpg")));
  EXPECT_FALSE(fs::exists(path("bp.png")));
}

// The scene's meshes are loaded and checked by every command, drawn by the
// golden models and the system model at TLM and RTL, and refused by name
// where the RTL has no polygon hardware; an empty list is no list.
TEST_F(Cli, MeshesAreCheckedAndDrawnAtEveryLevel) {
  const std::string plain(kSphere);
  const std::string with_mesh =
      plain.substr(0, plain.rfind('}')) +
      R"(, "polygons": [{"shape": "box", "size": [4, 4, 30], "transform": {"translate": [7.5, 7.5, 7.5]},
                         "color": [1, 0, 0], "opacity": 0.5}]})";
  const std::string empty_list = plain.substr(0, plain.rfind('}')) + R"(, "polygons": []})";
  ASSERT_EQ(run("render " + write("a.json", plain) + " --model fixed -q -o " + path("a.exr")).code, 0);
  ASSERT_EQ(run("render " + write("e.json", empty_list) + " --model fixed -q -o " + path("e.exr")).code, 0);
  const auto ia = cube4::tb::read_image(path("a.exr")), ie = cube4::tb::read_image(path("e.exr"));
  ASSERT_EQ(ia.rgba.size(), 64u * 48 * 4);
  EXPECT_TRUE(ia.rgba == ie.rgba) << "an empty polygon list changed the image";
  const std::string scene = write("b.json", with_mesh);
  for (const std::string model : {"fixed", "float", "reference"}) {
    ASSERT_EQ(run("render " + scene + " --model " + model + " -q -o " + path(model + ".exr")).code, 0) << model;
    const auto ib = cube4::tb::read_image(path(model + ".exr"));
    // A red box through the sphere's middle: red beats green and blue there.
    const float* centre = &ib.rgba[(static_cast<size_t>(24) * 64 + 32) * 4];
    EXPECT_GT(centre[0], centre[1] + 0.05f) << model;
  }
  // At TLM the system model draws them, bit-exact with fixed (--check).
  const CliResult tlm = run("render " + scene + " --model tlm --check -q -o " + path("tlm.exr"));
  EXPECT_EQ(tlm.code, 0) << tlm.err;
  EXPECT_TRUE(cube4::tb::read_image(path("tlm.exr")).rgba == cube4::tb::read_image(path("fixed.exr")).rgba)
      << "the tlm image differs from the fixed one";
  if (CUBE4_TEST_RTL) {
    // At RTL the compositing ring with polygon hardware draws them (p = 4),
    // bit-exact too; p = 2 has no such ring and is refused by name.
    for (const std::string model : {"rtl", "mixed:composite"}) {
      const CliResult r = run("render " + scene + " --model " + model + " --check -q -o " + path("sys.exr"));
      EXPECT_EQ(r.code, 0) << model << ": " << r.err;
      EXPECT_TRUE(cube4::tb::read_image(path("sys.exr")).rgba == cube4::tb::read_image(path("fixed.exr")).rgba)
          << model;
    }
    const CliResult r = run("render " + scene + " --model mixed:composite --pipes 2 -q -o " + path("sys.png"));
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("\"polygons\" (1 mesh), --model mixed:composite: pipelines: 2 has no RTL compositing "
                         "unit with polygon hardware"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(path("sys.png")));
  }

  const std::string bad = plain.substr(0, plain.rfind('}')) + R"(, "polygons": [{"file": "nowhere.obj"}]})";
  for (const char* command : {"render ", "info "}) {
    const CliResult r = run(command + write("c.json", bad) + (command[0] == 'r' ? " -o " + path("c.png") : ""));
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("\"polygons[0].file\" = \"nowhere.obj\" cannot be loaded"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(path("nowhere.obj")), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(path("c.png")));
}

// Cube-5's scene through the system model at transaction level: the base
// plane checked against golden fixed with its polygons (exit 0, and the
// same image as fixed).
TEST_F(Cli, BrainProbeRendersThroughTheSystemModelAtTlm) {
  const std::string scene = std::string(CUBE4_SOURCE_DIR) + "/scenes/brain_probe.json";
  const CliResult tlm = run("render " + scene + " --model tlm --check -q -o " + path("tlm.exr") + " --report " +
                            path("tlm.json"));
  ASSERT_EQ(tlm.code, 0) << tlm.err;
  ASSERT_EQ(run("render " + scene + " --model fixed -q -o " + path("fixed.exr")).code, 0);
  EXPECT_TRUE(cube4::tb::read_image(path("tlm.exr")).rgba == cube4::tb::read_image(path("fixed.exr")).rgba);
  std::ifstream report(path("tlm.json"));
  const nlohmann::json j = nlohmann::json::parse(report);
  EXPECT_GT(j["polygon_fragments"]["opaque"].get<uint64_t>(), 0u);
}

TEST_F(Cli, TruncatedVolumeFileIsReportedWithItsName) {
  std::ofstream(path("cut.den"), std::ios::binary) << std::string(30, '\0');
  const CliResult r = run("render " + write("t.json", R"({"volume": {"file": "cut.den"}})") + " -o " + path("x.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("cut.den"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("x.png")));
}

// The system model from the command line: a checked RTL run and a TLM run
// give the golden base plane (same hash) and report the system's figures.
TEST_F(Cli, SystemModelsReportCyclesAndMatchGolden) {
  const std::string scene = write("s.json", kSphere);
  std::string golden_hash;
  std::vector<std::string> models = {"fixed", "tlm"};
  if (CUBE4_TEST_RTL) models.insert(models.end(), {"rtl", "mixed:gradient,composite"});
  for (const std::string& model : models) {
    const std::string rep = path("r.json");
    const CliResult r = run("render " + scene + " --model " + model + " -q -o " + path("o.png") + " --report " + rep);
    ASSERT_EQ(r.code, 0) << model << "\n" << r.err;
    nlohmann::json j;
    std::ifstream(rep) >> j;
    if (model == "fixed") {
      golden_hash = j["baseplane_hash_fnv1a64"];
      continue;
    }
    EXPECT_EQ(j["baseplane_hash_fnv1a64"], golden_hash) << model;
    const nlohmann::json& s = j["system"];
    for (const char* key : {"cycles_per_frame", "cycles_steady_state_interval", "fps_steady_state", "samples_per_cycle",
                            "simulated_cycles_per_wall_second", "units", "skipped", "check", "host_bus_ms"})
      EXPECT_TRUE(s.contains(key)) << model << ": " << key;
    EXPECT_EQ(s["units"]["interp"], model == "rtl" ? "rtl" : "tlm") << model;
    EXPECT_EQ(s["units"]["weight_generator"], model == "rtl" ? "rtl" : "tlm") << model;
    EXPECT_EQ(s["units"]["composite"], model == "tlm" ? "tlm" : "rtl") << model;
    if (model != "tlm") {
      EXPECT_EQ(s["check"].get<std::string>().rfind("passed", 0), 0u) << model;
    }
  }
}

// --trace: one FST per RTL unit, quietly, each holding the frame's cycles
// under the system's numbers. Before, reset and the shading unit's table
// load were dumped, the cycle counter restarted, Verilator printed a
// "previous dump" warning on stdout for each backward time, and the
// shading unit's trace held the table load instead of the frame.
TEST_F(Cli, TracesHoldTheFrameQuietly) {
  if (!CUBE4_TEST_RTL) GTEST_SKIP() << "built without RTL";
#if CUBE4_TEST_RTL
  const std::string scene = write("s.json", kSphere);
  const CliResult r = run("render " + scene + " --model rtl --pipes 4 -q -o " + path("o.png") + " --report " +
                          path("r.json") + " --trace " + path("t.fst"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
  nlohmann::json j;
  std::ifstream(path("r.json")) >> j;
  const uint64_t cycles = j["system"]["simulated_cycles"];
  for (const char* unit : {"addr", "interp", "gradient", "shade0", "composite"}) {
    const std::string f = path(std::string("t.") + unit + ".fst");
    void* fst = fstReaderOpen(f.c_str());
    ASSERT_NE(fst, nullptr) << f;
    // Dump times are 2 * cycle (+1 for the rising edge), cycles from 1; the
    // simulation stops on the clock after the one that wrote the last pixel.
    EXPECT_GE(fstReaderGetStartTime(fst), 2u) << unit;
    EXPECT_LE(fstReaderGetEndTime(fst), 2 * (cycles + 1) + 1) << unit;
    EXPECT_GE(fstReaderGetEndTime(fst), cycles) << unit << ": the trace ends before the frame's second half";
    fstReaderClose(fst);
  }
#endif
}

// --no-assert turns the RTL assertions off (the report says so; they never
// fire on a frame the system forms: the same image, exit 0, nothing from
// Verilator on stdout); the help names the flag and exit code 4 of a failed
// assertion.
TEST_F(Cli, NoAssertRendersTheSameFrame) {
  const CliResult help = run("render --help");
  ASSERT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("--no-assert"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("exit 4"), std::string::npos) << help.out;
  if (!CUBE4_TEST_RTL) GTEST_SKIP() << "built without RTL";
  const std::string scene = write("s.json", kSphere);
  std::string hash;
  for (const std::string flag : {"", " --no-assert"}) {
    const std::string rep = path("r.json");
    const CliResult r = run("render " + scene + " --model rtl --pipes 4 -q -o " + path("o.png") + " --report " + rep + flag);
    ASSERT_EQ(r.code, 0) << flag << ": " << r.err;
    EXPECT_EQ(r.out, "") << flag;
    nlohmann::json j;
    std::ifstream(rep) >> j;
    if (hash.empty()) hash = j["baseplane_hash_fnv1a64"];
    EXPECT_EQ(j["baseplane_hash_fnv1a64"], hash) << flag;
    EXPECT_EQ(j["system"]["rtl_assertions"], flag.empty() ? "on" : "off (--no-assert)");
  }
}

TEST_F(Cli, EveryThreadCountGivesTheSameBasePlane) {
  const std::string scene = write("s.json", kSphere);
  std::string first;
  for (const std::string threads : {"1", "2", "5", "0"}) {
    const std::string rep = path("r" + threads + ".json");
    const CliResult r = run("render " + scene + " -q --threads " + threads + " -o " + path("o.png") + " --report " + rep);
    ASSERT_EQ(r.code, 0) << r.err;
    nlohmann::json j;
    std::ifstream(rep) >> j;
    if (threads != "0") {
      EXPECT_EQ(j["threads"], std::stoi(threads));
    }
    EXPECT_GE(j["threads"].get<int>(), 1);
    if (first.empty()) first = j["baseplane_hash_fnv1a64"];
    EXPECT_EQ(j["baseplane_hash_fnv1a64"], first) << threads << " threads";
  }
  EXPECT_EQ(run("render " + scene + " -q --threads -1 -o " + path("o.png")).code, 2);
}

// x/y supersampling: n² frames, each an ordinary frame the system model
// renders bit-exactly; the image is their blend, the same from every model
// level; n = 1 is the scene without the key.
TEST_F(Cli, XySupersamplingRendersCheckedFramesAndBlendsThem) {
  const std::string plain = write("p.json", kSphere);
  std::string with_key = kSphere;
  with_key.insert(with_key.rfind('}'), R"(, "xy_supersampling": 2)");
  const std::string scene = write("s.json", with_key);
  auto render = [&](const std::string& s, const std::string& model, const std::string& out) {
    const std::string rep = path("r.json");
    const CliResult r = run("render " + s + " --model " + model + " -q -o " + path(out) + " --report " + rep);
    EXPECT_EQ(r.code, 0) << model << "\n" << r.err;
    nlohmann::json j;
    std::ifstream(rep) >> j;
    return j;
  };
  const nlohmann::json one = render(plain, "fixed", "one.exr");
  const nlohmann::json four = render(scene, "fixed", "four.exr");
  EXPECT_EQ(one["frames_per_image"], 1);
  EXPECT_EQ(four["frames_per_image"], 4);
  EXPECT_EQ(four["xy_supersampling"], 2);
  EXPECT_NE(one["baseplane_hash_fnv1a64"], four["baseplane_hash_fnv1a64"]);
  EXPECT_NE(cube4::tb::read_image(path("one.exr")).rgba, cube4::tb::read_image(path("four.exr")).rgba);
  std::string xy1 = kSphere;
  xy1.insert(xy1.rfind('}'), R"(, "xy_supersampling": 1)");
  EXPECT_EQ(render(write("one.json", xy1), "fixed", "xy1.exr")["baseplane_hash_fnv1a64"], one["baseplane_hash_fnv1a64"]);
  std::vector<std::string> models = {"tlm"};
  if (CUBE4_TEST_RTL) models.push_back("rtl");
  for (const std::string& model : models) {
    const nlohmann::json j = render(scene, model, model + ".exr");
    EXPECT_EQ(j["baseplane_hash_fnv1a64"], four["baseplane_hash_fnv1a64"]) << model;
    EXPECT_EQ(cube4::tb::read_image(path(model + ".exr")).rgba, cube4::tb::read_image(path("four.exr")).rgba) << model;
    EXPECT_DOUBLE_EQ(j["system"]["image_fps_steady_state"].get<double>(),
                     j["system"]["fps_steady_state"].get<double>() / 4) << model;
    if (model == "rtl") {
      EXPECT_EQ(j["system"]["check"].get<std::string>().rfind("passed", 0), 0u);
    }
  }
}

// Sub-cubes (--blocks, or the scene's "blocks"): the partitioned image is
// the same at every level (fixed, tlm, rtl, the network alone at RTL) and
// differs from the one pass image only by the merges' rounding; MIP's is
// the one pass image. The report says how the volume was cut and what
// the machines and the network cost.
TEST_F(Cli, BlocksRenderTheSameImageAtEveryLevel) {
  const std::string plain = write("p.json", kSphere);
  std::string with_key = kSphere;
  with_key.insert(with_key.rfind('}'), R"(, "blocks": [2, 1, 2])");
  const std::string scene = write("s.json", with_key);
  auto render = [&](const std::string& s, const std::string& args) {
    const std::string rep = path("r.json");
    const CliResult r = run("render " + s + " " + args + " -q -o " + path("o.png") + " --report " + rep);
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    nlohmann::json j;
    std::ifstream(rep) >> j;
    return j;
  };
  const nlohmann::json one = render(plain, "--model fixed");
  const nlohmann::json fixed = render(scene, "--model fixed");
  EXPECT_EQ(fixed["blocks"]["machines"], 4);
  EXPECT_EQ(fixed["blocks"]["counts"], nlohmann::json::array({2, 1, 2}));
  EXPECT_EQ(render(plain, "--model fixed --blocks 2x1x2")["baseplane_hash_fnv1a64"], fixed["baseplane_hash_fnv1a64"]);
  EXPECT_EQ(render(scene, "--model fixed --blocks 1x1x1")["baseplane_hash_fnv1a64"], one["baseplane_hash_fnv1a64"]);
  std::vector<std::string> models = {"tlm"};
  if (CUBE4_TEST_RTL) models.insert(models.end(), {"rtl", "mixed:compose"});
  for (const std::string& model : models) {
    const nlohmann::json j = render(scene, "--model " + model);
    EXPECT_EQ(j["baseplane_hash_fnv1a64"], fixed["baseplane_hash_fnv1a64"]) << model;
    const nlohmann::json& s = j["system"];
    EXPECT_EQ(s["machines"], 4) << model;
    EXPECT_EQ(s["network"]["nodes"], 3) << model;
    EXPECT_EQ(s["network"]["depth"], 2) << model;
    EXPECT_EQ(s["network"]["level"], model == "tlm" ? "tlm" : "rtl") << model;
    EXPECT_EQ(s["per_machine"].size(), 4u) << model;
    EXPECT_GT(s["cycles_per_frame"].get<uint64_t>(), s["network"]["cycles"].get<uint64_t>()) << model;
    if (model != "tlm") {
      EXPECT_EQ(s["check"].get<std::string>().rfind("passed", 0), 0u) << model << ": " << s["check"];
    }
  }
  // The float and reference renderers have no machines: one pass, said so.
  EXPECT_NE(render(scene, "--model float")["blocks"].get<std::string>().find("one pass"), std::string::npos);
  std::string mip = kSphere;
  mip.insert(mip.rfind('}'), R"(, "blend": "mip", "shading": false)");
  const std::string mip_scene = write("m.json", mip);
  EXPECT_EQ(render(mip_scene, "--model tlm --blocks 3x2x1")["baseplane_hash_fnv1a64"],
            render(mip_scene, "--model fixed")["baseplane_hash_fnv1a64"]);
}

TEST_F(Cli, BlocksThatDoNotDivideSensiblyExitTwo) {
  const std::string scene = write("s.json", kSphere);
  const CliResult thin = run("render " + scene + " --blocks 1x5x1 -q -o " + path("o.png"));
  EXPECT_EQ(thin.code, 2);
  EXPECT_NE(thin.err.find("--blocks 1x5x1: y 5 blocks of a volume 16 voxels long"), std::string::npos) << thin.err;
  EXPECT_NE(thin.err.find("at most 4 blocks along y"), std::string::npos) << thin.err;
  for (const char* bad : {"2x2", "2x2x0", "axbxc", "2x2x2x2", "-1x1x1"}) {
    const CliResult r = run("render " + scene + " --blocks " + bad + " -q -o " + path("o.png"));
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find(std::string("--blocks ") + bad), std::string::npos) << r.err;
  }
  std::string key = kSphere;
  key.insert(key.rfind('}'), R"(, "blocks": [1, 1, 9])");
  const CliResult k = run("render " + write("k.json", key) + " -q -o " + path("o.png"));
  EXPECT_EQ(k.code, 2);
  EXPECT_NE(k.err.find("k.json: blocks: z 9 blocks"), std::string::npos) << k.err;
  EXPECT_FALSE(fs::exists(path("o.png")));
}
