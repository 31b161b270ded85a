#include "tb/explore.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <optional>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>

#include "golden/errors.hpp"
#include "golden/precision.hpp"
#include "golden/scene_io.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "tb/image_error.hpp"
#include "tb/image_io.hpp"
#include "tb/report.hpp"

namespace cube4::tb {
namespace fs = std::filesystem;
using golden::InputError;
using nlohmann::json;
using nlohmann::ordered_json;

namespace {

// Ring storage per axis the RTL is built for (rtl/cube4_pkg.sv, MaxDim):
// it sizes the units' beam and slice memories for the gate counts.
constexpr int kMaxDim = 256;
constexpr int kMaxPoints = 10000;

// The units one pipeline is made of, and those the chip has one of: the
// address generator and the weight generator (rtl/; docs/gates.md).
const std::vector<std::string> kPipelineUnits = {"cube4_interp_unit", "cube4_gradient_unit", "cube4_shade_unit",
                                                 "cube4_composite_unit"};
const std::vector<std::string> kChipUnits = {"cube4_addr", "cube4_dda"};

std::string read_text(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// Written whole or not at all: a reader (collect, a resumed sweep) never
// sees half a result.
void write_atomic(const fs::path& p, const std::string& text) {
  const fs::path tmp = p.string() + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream f(tmp);
    f << text;
    f.flush();
    if (!f) throw std::runtime_error("explore: cannot write " + tmp.string());
  }
  fs::rename(tmp, p);
}

std::string hex64(uint64_t v) {
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << v;
  return s.str();
}

std::string hash_text(const std::string& s) { return hex64(fnv1a64(s.data(), s.size())); }

// Relative "file" values of a scene are relative to the scene's folder;
// a point's scene lives elsewhere, so they become absolute.
void absolute_files(json& j, const fs::path& folder) {
  if (j.is_object()) {
    for (auto& [k, v] : j.items()) {
      if (k == "file" && v.is_string() && !v.get<std::string>().empty() && fs::path(v.get<std::string>()).is_relative())
        v = (folder / v.get<std::string>()).lexically_normal().string();
      else
        absolute_files(v, folder);
    }
  } else if (j.is_array()) {
    for (auto& v : j) absolute_files(v, folder);
  }
}

json load_scene_json(const fs::path& path, const std::string& who) {
  std::ifstream f(path);
  if (!f) throw InputError(who + ": cannot read the scene " + path.string());
  json j;
  try {
    j = json::parse(f);
  } catch (const json::exception& e) {
    throw InputError(who + ": the scene " + path.string() + " is not JSON: " + e.what());
  }
  if (!j.is_object()) throw InputError(who + ": the scene " + path.string() + " is not a JSON object");
  absolute_files(j, fs::absolute(path).parent_path());
  return j;
}

bool precision_key(const std::string& k) {
  if (k.rfind("precision.", 0) != 0) return false;
  const std::string f = k.substr(10);
  for (const golden::PrecisionField& p : golden::kPrecisionFields)
    if (f == p.key) return true;
  return false;
}

bool sweepable(const std::string& k) {
  const auto& keys = sweepable_keys();
  return precision_key(k) || std::find(keys.begin(), keys.end(), k) != keys.end();
}

std::string value_text(const ordered_json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

std::string values_text(const ordered_json& values) {
  std::string s;
  for (const auto& [k, v] : values.items()) s += (s.empty() ? "" : ", ") + k + " = " + value_text(v);
  return s.empty() ? "the base scene" : s;
}

// Sets a swept key in a scene ("a.b" is key b of object a).
void apply(json& scene, const std::string& key, const ordered_json& v) {
  const size_t dot = key.find('.');
  if (dot == std::string::npos) {
    scene[key] = json::parse(v.dump());
  } else {
    json& obj = scene[key.substr(0, dot)];
    if (!obj.is_object()) obj = json::object();
    obj[key.substr(dot + 1)] = json::parse(v.dump());
  }
}

// What the reference renderer sees: the scene without the keys that only
// the hardware models read, so the points that differ only in those share
// one reference image.
json reference_scene(json s) {
  for (const char* k : {"supersampling", "xy_supersampling", "z_gradient", "pipelines", "clock_mhz", "precision", "blocks"})
    s.erase(k);
  return s;
}

bool system_level(const std::string& m) { return m == "tlm" || m == "rtl" || m.rfind("mixed:", 0) == 0; }

struct ChildResult {
  int exit_code = -1;
  double seconds = 0;
  std::string last_error;  // the child's "cube4: error ..." line, if any
};

// Runs one command to completion, its output into `log`. One job's own
// steps, in order: the jobs themselves run through GNU parallel or Slurm.
ChildResult run_child(std::vector<std::string> args, const fs::path& log) {
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("explore: fork failed");
  if (pid == 0) {
    if (!freopen(log.c_str(), "w", stderr) || !freopen(log.c_str(), "a", stdout)) _exit(127);
    std::vector<char*> argv;
    for (std::string& s : args) argv.push_back(s.data());
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("explore: waitpid failed");
  ChildResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::istringstream lines(read_text(log));
  for (std::string line; std::getline(lines, line);)
    if (line.find("error") != std::string::npos || line.find("FAILED") != std::string::npos) r.last_error = line;
  return r;
}

// An exclusive lock on `path` while it lives: the jobs of one sweep that
// need the same reference image or gate count wait for the first.
class FileLock {
 public:
  explicit FileLock(const fs::path& path) : fd_(::open(path.c_str(), O_CREAT | O_RDWR, 0644)) {
    if (fd_ < 0) throw std::runtime_error("explore: cannot open the lock " + path.string());
    while (::flock(fd_, LOCK_EX) != 0)
      if (errno != EINTR) throw std::runtime_error("explore: cannot lock " + path.string());
  }
  ~FileLock() { ::close(fd_); }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

std::string source_dir() {
  const char* env = std::getenv("CUBE4_SOURCE_DIR");
  return env && *env ? env : CUBE4_SOURCE_DIR;
}

// Debian's python3, which has python3-matplotlib, unless CUBE4_PYTHON
// names another (a python3 first on PATH may lack it).
std::string python() {
  const char* env = std::getenv("CUBE4_PYTHON");
  if (env && *env) return env;
  return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

fs::path gates_cache_dir(const ExploreArgs& a) {
  if (!a.gates_cache.empty()) return a.gates_cache;
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg) return fs::path(xdg) / "cube4" / "gates";
  const char* home = std::getenv("HOME");
  return fs::path(home && *home ? home : "/tmp") / ".cache" / "cube4" / "gates";
}

// Whether the model runs some unit at RTL (a build verilated at the point's
// widths and p is then needed).
bool model_has_rtl(const std::string& m) { return m == "rtl" || m.rfind("mixed:", 0) == 0; }

// The cube4 that renders a point at RTL: this one, if its RTL was verilated
// at the point's widths and p; else one scripts/build_widths.sh builds (and
// keeps) for them. The jobs that need the same build wait for the first.
std::string rtl_renderer(const golden::Scene& scene, const std::string& self, const fs::path& log) {
  const golden::Precision built = sysc::rtl_precision();
  golden::Precision asked = scene.precision;
  asked.tag_bits = 0;
  const std::vector<int> pipes = sysc::rtl_pipes();
  const bool has_p = std::find(pipes.begin(), pipes.end(), scene.pipelines) != pipes.end();
  if (has_p && !golden::first_difference(asked, built, true)) return self;
  std::vector<std::string> args{"bash", source_dir() + "/scripts/build_widths.sh", "--pipes",
                                std::to_string(scene.pipelines)};
  for (const golden::PrecisionField& f : golden::kPrecisionFields)
    if (f.rtl_parameter && f.member != &golden::Precision::tag_bits &&
        asked.*f.member != golden::Precision{}.*f.member)
      args.push_back(std::string(f.rtl_parameter) + "=" + std::to_string(asked.*f.member));
  const char* root = std::getenv("CUBE4_WIDTH_BUILDS");
  const fs::path builds = root && *root ? fs::path(root) : fs::path(source_dir()) / "build-widths";
  fs::create_directories(builds);
  FileLock lock(builds / ".lock");
  const ChildResult r = run_child(args, log);
  if (r.exit_code != 0)
    throw std::runtime_error("explore: scripts/build_widths.sh could not build the RTL at this point's widths (" +
                             log.string() + ")");
  // The script's one stdout line, the program's path, ends the log.
  std::istringstream lines(read_text(log));
  std::string path;
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) path = line;
  if (!fs::exists(path)) throw std::runtime_error("explore: scripts/build_widths.sh named no program (" + log.string() + ")");
  return path;
}

}  // namespace

// The widths some unit is built with, p, and the memories p sizes.
std::string gate_config(const golden::Scene& s) {
  std::string c;
  for (const golden::PrecisionField& f : golden::kPrecisionFields)
    if (f.rtl_parameter) c += std::string(c.empty() ? "" : ",") + f.rtl_parameter + "=" + std::to_string(s.precision.*f.member);
  const int beam = (kMaxDim + s.pipelines - 1) / s.pipelines;
  c += ",NumPipes=" + std::to_string(s.pipelines) + ",BeamDepth=" + std::to_string(beam) +
       ",SliceDepth=" + std::to_string(kMaxDim * beam);
  // VolumePro's z gradient: the interpolation unit's outer voxels and
  // cube4_interp_zdiff, the gradient unit's difference path (their effect
  // parameters; a scene without it counts none of it).
  if (s.z_gradient == golden::ZGradient::VoxelDifferences) c += ",HasZDiff=1,HasVoxelZ=1";
  // The weight generator's perspective divisions, likewise (the pipelines
  // counted are parallel projection's: docs/explore.md says so).
  c += s.view.perspective() ? ",HasPerspective=1" : ",HasPerspective=0";
  return c;
}

// The RTL the gates are counted on: every rtl/*.sv (yosys reads them all),
// so that a change to a unit's source is a new cache entry.
std::string rtl_source_hash() {
  static const std::string h = [] {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(fs::path(source_dir()) / "rtl"))
      if (e.path().extension() == ".sv") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    std::string all;
    for (const fs::path& f : files) all += f.filename().string() + "\n" + read_text(f);
    return hash_text(all);
  }();
  return h;
}

std::string gates_cache_file(const std::string& cache_dir, const std::string& unit, const std::string& params) {
  return (fs::path(cache_dir) / (unit + "-" + hash_text(params + "|" + rtl_source_hash()) + ".json")).string();
}

std::map<std::string, std::string> declared_parameters(const std::string& config) {
  std::vector<std::string> args{"bash", source_dir() + "/scripts/gates.sh", "--declared", "--set", config};
  args.insert(args.end(), kChipUnits.begin(), kChipUnits.end());
  args.insert(args.end(), kPipelineUnits.begin(), kPipelineUnits.end());
  char tmpl[] = "/tmp/cube4-declared-XXXXXX";
  const int fd = ::mkstemp(tmpl);
  if (fd < 0) throw std::runtime_error("explore: cannot make a temporary file");
  ::close(fd);
  const ChildResult r = run_child(args, tmpl);
  const std::string text = read_text(tmpl);
  fs::remove(tmpl);
  if (r.exit_code != 0) throw std::runtime_error("explore: scripts/gates.sh --declared failed: " + text);
  std::map<std::string, std::string> out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const size_t sp = line.find(' ');
    if (sp != std::string::npos) out[line.substr(0, sp)] = line.substr(sp + 1);
  }
  if (out.size() != kPipelineUnits.size() + kChipUnits.size()) throw std::runtime_error("explore: scripts/gates.sh --declared said: " + text);
  return out;
}

namespace {

// yosys's count of each unit of a configuration (scripts/gates.sh --json),
// kept in the cache per unit and the parameters it declares: a sweep over
// alpha_bits synthesises the shading and compositing units again, not the
// others; one over p, the units p sizes.
json gates_of(const std::string& config, const ExploreArgs& a, const fs::path& log) {
  const fs::path dir = gates_cache_dir(a);
  fs::create_directories(dir);
  json j = {{"config", config}, {"units", json::object()}, {"synthesis_seconds", 0.0}};
  for (const auto& [unit, params] : declared_parameters(config)) {
    const fs::path file = gates_cache_file(dir.string(), unit, params);
    FileLock lock(file.string() + ".lock");
    json row;
    if (fs::exists(file)) {
      try {
        const json c = json::parse(read_text(file));
        if (c.value("unit", "") == unit && c.value("parameters", "") == params) row = c["row"];
      } catch (const json::exception&) {
      }
    }
    if (row.is_null()) {
      const fs::path out = file.string() + ".out";
      ::setenv("OUT", out.c_str(), 1);
      const ChildResult r = run_child({"bash", "-c", "exec \"$0\" --json --set \"$1\" \"$2\" > \"$OUT\"",
                                       source_dir() + "/scripts/gates.sh", params, unit},
                                      log);
      if (r.exit_code != 0)
        throw std::runtime_error("explore: yosys failed on " + unit + " " + params + " (" + log.string() + ")");
      const json rows = json::parse(read_text(out));
      fs::remove(out);
      if (!rows.is_array() || rows.size() != 1) throw std::runtime_error("explore: scripts/gates.sh gave " + rows.dump());
      row = rows[0];
      write_atomic(file, json{{"unit", unit}, {"parameters", params}, {"synthesis_seconds", r.seconds}, {"row", row}}.dump(1));
      j["synthesis_seconds"] = j["synthesis_seconds"].get<double>() + r.seconds;
    }
    j["units"][unit] = row;
  }
  return j;
}

fs::path point_dir(const fs::path& out, int i) {
  std::ostringstream s;
  s << std::setw(4) << std::setfill('0') << i;
  return out / "points" / s.str();
}

// What a point's result depends on: rerun it when any of these changes.
std::string point_hash(const Sweep& s, const ExplorePoint& p) {
  return hash_text(p.scene.dump() + "|" + s.model + "|" + std::to_string(s.reference_step) + "|" +
                   std::to_string(s.gates) + "|" + (s.check ? "check|" : "") + std::to_string(s.roi[0]) + "," + std::to_string(s.roi[1]) + "," +
                   std::to_string(s.roi[2]) + "," + std::to_string(s.roi[3]));
}

bool point_done(const Sweep& s, const ExplorePoint& p, const fs::path& out) {
  const fs::path f = point_dir(out, p.index) / "result.json";
  if (!fs::exists(f)) return false;
  try {
    const json r = json::parse(read_text(f));
    return r.value("hash", "") == point_hash(s, p) && r.value("status", "") == "ok";
  } catch (const json::exception&) {
    return false;
  }
}

// The reference image of a point's scene, rendered by the first job that
// needs it.
fs::path reference_image(const Sweep& s, const ExplorePoint& p, const fs::path& out, const std::string& self) {
  const std::string text = reference_scene(p.scene).dump(1);
  const std::string key = hash_text(text + "|" + std::to_string(s.reference_step));
  const fs::path dir = out / "references" / key;
  fs::create_directories(dir);
  FileLock lock(dir / "lock");
  const fs::path image = dir / "image.exr";
  if (fs::exists(image)) return image;
  write_atomic(dir / "scene.json", text);
  const ChildResult r = run_child({self, "render", (dir / "scene.json").string(), "--model", "reference",
                                   "--reference-step", std::to_string(s.reference_step), "-q", "-o", image.string()},
                                  dir / "log.txt");
  if (r.exit_code != 0)
    throw std::runtime_error("explore: the reference render failed (" + (dir / "log.txt").string() + "): " + r.last_error);
  return image;
}

json error_json(const ImageError& e) {
  return {{"psnr_db", std::isinf(e.psnr) ? json(nullptr) : json(e.psnr)},
          {"mean", e.mean_error},
          {"max", e.max_error}};
}

int run_point(const Sweep& s, const ExplorePoint& p, const ExploreArgs& a, const fs::path& out,
              const std::string& self) {
  const fs::path dir = point_dir(out, p.index);
  const std::string label = "explore: point " + std::to_string(p.index) + " (" + values_text(p.values) + ")";
  if (point_done(s, p, out)) {
    if (!a.quiet) std::fprintf(stderr, "%s: done before\n", label.c_str());
    return 0;
  }
  fs::create_directories(dir);
  write_atomic(dir / "scene.json", p.scene.dump(1));
  json result = {{"index", p.index}, {"values", p.values}, {"model", s.model}, {"hash", point_hash(s, p)}};
  auto fail = [&](const std::string& why) {
    result["status"] = "error";
    result["error"] = why;
    write_atomic(dir / "result.json", result.dump(1));
    std::fprintf(stderr, "%s: FAILED: %s\n", label.c_str(), why.c_str());
    return 1;
  };
  try {
    const fs::path ref = reference_image(s, p, out, self);
    const golden::Scene scene = golden::parse_scene(p.scene.dump(), (dir / "scene.json").string());
    const std::string renderer = model_has_rtl(s.model) ? rtl_renderer(scene, self, dir / "build-log.txt") : self;
    if (renderer != self) result["rtl_build"] = renderer;
    std::vector<std::string> args{renderer, "render", (dir / "scene.json").string(), "--model", s.model, "-q",
                                  "-o", (dir / "image.exr").string(), "--report", (dir / "report.json").string()};
    // Equivalence is cube4 regress's job, unless the sweep asks for it.
    if (system_level(s.model)) args.push_back(s.check ? "--check" : "--no-check");
    const ChildResult r = run_child(args, dir / "log.txt");
    if (r.exit_code != 0) return fail("cube4 render exited " + std::to_string(r.exit_code) + ": " + r.last_error);
    if (system_level(s.model) && s.check) result["check"] = "bit-exact";  // a mismatch fails the render
    const golden::ImageF img = read_image((dir / "image.exr").string());
    const golden::ImageF reference = read_image(ref.string());
    result["error"] = error_json(image_error(img, reference));
    if (s.roi[2] > 0) result["error_roi"] = error_json(image_error(img, reference, {s.roi[0], s.roi[1], s.roi[2], s.roi[3]}));

    const json rep = json::parse(read_text(dir / "report.json"));
    const double frames = rep.value("frames_per_image", 1.0);
    result["clock_mhz"] = scene.clock_mhz;
    result["pipelines"] = scene.pipelines;
    result["frames_per_image"] = frames;
    if (rep.contains("system")) {
      // An image costs its frames (xy_supersampling: n² of them), each at
      // the steady-state interval of back-to-back frames.
      const double cycles = rep["system"]["cycles_steady_state_interval"].get<double>() * frames;
      result["cycles_per_image"] = cycles;
      result["fps"] = scene.clock_mhz * 1e6 / cycles;
    } else {
      result["cycles_per_image"] = nullptr;  // the golden models count no cycles
      result["fps"] = nullptr;
    }
    result["sim_seconds"] = rep.value("wall_seconds", r.seconds);
    result["process_seconds"] = r.seconds;
    if (s.gates) {
      const json g = gates_of(gate_config(scene), a, dir / "gates-log.txt");
      double pipe_nand2 = 0, pipe_ram = 0;
      for (const std::string& u : kPipelineUnits) {
        pipe_nand2 += g["units"][u]["nand2"].get<double>();
        pipe_ram += g["units"][u]["ram_bits"].get<double>();
      }
      double chip_nand2 = 0, chip_ram = 0;
      for (const std::string& u : kChipUnits) {
        chip_nand2 += g["units"][u]["nand2"].get<double>();
        chip_ram += g["units"][u]["ram_bits"].get<double>();
      }
      result["gates"] = {{"config", g["config"]},
                         {"nand2_pipeline", pipe_nand2},
                         {"ram_bits_pipeline", pipe_ram},
                         {"nand2_chip", chip_nand2 + scene.pipelines * pipe_nand2},
                         {"ram_bits_chip", chip_ram + scene.pipelines * pipe_ram}};
    }
    result["status"] = "ok";
    write_atomic(dir / "result.json", result.dump(1));
    if (!a.quiet) {
      const json& e = result["error"];
      std::ostringstream m;
      m << std::fixed << std::setprecision(2) << label << ": ";
      if (e["psnr_db"].is_null()) m << "exact";
      else m << e["psnr_db"].get<double>() << " dB";
      m << ", mean error " << std::setprecision(4) << e["mean"].get<double>();
      if (!result["cycles_per_image"].is_null())
        m << ", " << static_cast<uint64_t>(result["cycles_per_image"].get<double>()) << " cycles/image";
      m << ", " << std::setprecision(2) << result["sim_seconds"].get<double>() << " s\n";
      std::fputs(m.str().c_str(), stderr);
    }
    return 0;
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}

std::string csv_cell(const json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) {
    std::string s = v.get<std::string>();
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  }
  if (v.is_array()) return "\"" + v.dump() + "\"";
  return v.dump();
}

// The table of every point, the Pareto fronts (per base scene: accuracy
// against cycles, gates and simulation time), and the plots.
int collect(const Sweep& s, const ExploreArgs& a, const fs::path& out) {
  std::vector<json> rows;
  int failed = 0, missing = 0;
  for (const ExplorePoint& p : s.points) {
    const fs::path f = point_dir(out, p.index) / "result.json";
    json r;
    if (fs::exists(f)) r = json::parse(read_text(f));
    if (r.is_null() || r.value("hash", "") != point_hash(s, p)) {
      ++missing;
      r = {{"index", p.index}, {"values", p.values}, {"status", "not run"}};
    } else if (r.value("status", "") != "ok") {
      ++failed;
    }
    r["scene_group"] = p.values.contains("scene") ? p.values["scene"] : ordered_json("base");
    rows.push_back(r);
  }
  // Fronts within each group of points that render the same scene.
  const std::vector<std::pair<std::string, std::string>> costs = {
      {"cycles", "cycles_per_image"}, {"gates", "nand2_chip"}, {"sim_time", "sim_seconds"}};
  std::set<std::string> groups;
  for (const json& r : rows) groups.insert(r["scene_group"].dump());
  for (const auto& [name, field] : costs) {
    for (const std::string& g : groups) {
      std::vector<size_t> idx;
      std::vector<double> psnr, cost;
      for (size_t i = 0; i < rows.size(); ++i) {
        const json& r = rows[i];
        if (r["scene_group"].dump() != g || r.value("status", "") != "ok") continue;
        const json& c = field == "nand2_chip" ? (r.contains("gates") ? r["gates"][field] : json(nullptr)) : r[field];
        if (c.is_null()) continue;
        idx.push_back(i);
        psnr.push_back(r["error"]["psnr_db"].is_null() ? INFINITY : r["error"]["psnr_db"].get<double>());
        cost.push_back(c.get<double>());
      }
      const std::vector<bool> front = pareto_front(psnr, cost);
      for (size_t k = 0; k < idx.size(); ++k) rows[idx[k]]["pareto"][name] = static_cast<bool>(front[k]);
    }
  }
  // The table: one column per swept key, then the measurements.
  std::vector<std::string> keys;
  for (const ExplorePoint& p : s.points)
    for (const auto& [k, v] : p.values.items())
      if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
  std::ostringstream csv;
  csv << "index";
  for (const std::string& k : keys) csv << "," << k;
  // The clock and p of every point, unless they are swept columns already.
  const bool clock_col = std::find(keys.begin(), keys.end(), "clock_mhz") == keys.end();
  const bool pipes_col = std::find(keys.begin(), keys.end(), "pipelines") == keys.end();
  csv << ",status,psnr_db,mean_error,max_error,roi_psnr_db,roi_mean_error,roi_max_error,cycles_per_image,fps"
      << (clock_col ? ",clock_mhz" : "") << (pipes_col ? ",pipelines" : "")
      << ",nand2_pipeline,ram_bits_pipeline,nand2_chip,ram_bits_chip,sim_seconds,front_cycles,front_gates,"
         "front_sim_time\n";
  for (const json& r : rows) {
    csv << r["index"].get<int>();
    for (const std::string& k : keys) csv << "," << (r["values"].contains(k) ? csv_cell(r["values"][k]) : "");
    const bool ok = r.value("status", "") == "ok";
    auto field = [&](const json& obj, const char* k) { return ok && obj.is_object() && obj.contains(k) ? csv_cell(obj[k]) : ""; };
    const json none;
    csv << "," << csv_cell(r["status"]) << "," << field(ok ? r["error"] : none, "psnr_db") << ","
        << field(ok ? r["error"] : none, "mean") << "," << field(ok ? r["error"] : none, "max") << ","
        << field(r.contains("error_roi") ? r["error_roi"] : none, "psnr_db") << ","
        << field(r.contains("error_roi") ? r["error_roi"] : none, "mean") << ","
        << field(r.contains("error_roi") ? r["error_roi"] : none, "max") << "," << field(r, "cycles_per_image") << ","
        << field(r, "fps") << (clock_col ? "," + field(r, "clock_mhz") : "")
        << (pipes_col ? "," + field(r, "pipelines") : "") << ","
        << field(r.contains("gates") ? r["gates"] : none, "nand2_pipeline") << ","
        << field(r.contains("gates") ? r["gates"] : none, "ram_bits_pipeline") << ","
        << field(r.contains("gates") ? r["gates"] : none, "nand2_chip") << ","
        << field(r.contains("gates") ? r["gates"] : none, "ram_bits_chip") << "," << field(r, "sim_seconds");
    for (const char* f : {"cycles", "gates", "sim_time"})
      csv << "," << (r.contains("pareto") && r["pareto"].contains(f) ? (r["pareto"][f].get<bool>() ? "1" : "0") : "");
    csv << "\n";
  }
  write_atomic(out / "results.csv", csv.str());
  const json doc = {{"sweep", fs::absolute(s.file).string()}, {"model", s.model}, {"reference_step", s.reference_step},
                    {"points", rows}};
  write_atomic(out / "results.json", doc.dump(1));
  if (!a.quiet)
    std::fprintf(stderr, "explore: %zu points, %d failed, %d not run -> %s\n", rows.size(), failed, missing,
                 (out / "results.csv").c_str());
  int status = failed || missing ? 1 : 0;
  if (a.plots) {
    const ChildResult r =
        run_child({python(), source_dir() + "/scripts/explore_plots.py", out.string()}, out / "plots-log.txt");
    if (r.exit_code != 0) {
      std::fprintf(stderr, "explore: the plots failed (%s): %s\n", (out / "plots-log.txt").c_str(), r.last_error.c_str());
      status = 1;
    } else if (!a.quiet) {
      std::fprintf(stderr, "explore: plots in %s\n", (out / "plots").c_str());
    }
  }
  return status;
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

const std::vector<std::string>& sweepable_keys() {
  static const std::vector<std::string> keys = {"scene",           "pipelines",   "clock_mhz", "supersampling",
                                                "xy_supersampling", "z_gradient", "view.rotate", "view.zoom",
                                                "precision.<width>"};
  return keys;
}

std::vector<bool> pareto_front(const std::vector<double>& psnr, const std::vector<double>& cost) {
  std::vector<bool> front(psnr.size(), true);
  for (size_t i = 0; i < psnr.size(); ++i)
    for (size_t j = 0; j < psnr.size() && front[i]; ++j)
      if (j != i && psnr[j] >= psnr[i] && cost[j] <= cost[i] && (psnr[j] > psnr[i] || cost[j] < cost[i]))
        front[i] = false;
  return front;
}

Sweep load_sweep(const std::string& path) {
  Sweep s;
  s.file = path;
  std::ifstream f(path);
  if (!f) throw InputError("explore: cannot read the sweep file " + path);
  ordered_json j;
  try {
    j = ordered_json::parse(f);
  } catch (const ordered_json::exception& e) {
    throw InputError(path + ": not JSON: " + e.what());
  }
  if (!j.is_object()) throw InputError(path + ": a sweep is a JSON object (docs/explore.md)");
  const fs::path folder = fs::absolute(path).parent_path();
  for (const auto& [k, v] : j.items())
    if (k != "scene" && k != "model" && k != "axes" && k != "points" && k != "reference_step" && k != "gates" &&
        k != "check" && k != "roi" && k != "description")
      throw InputError(path + ": unknown key \"" + k +
                       "\" (scene, model, axes, points, reference_step, gates, check, roi, description)");
  auto str = [&](const char* k) {
    if (!j[k].is_string()) throw InputError(path + ": \"" + k + "\" should be a string, not " + j[k].dump());
    return j[k].get<std::string>();
  };
  if (j.contains("model")) {
    s.model = str("model");
    if (s.model != "fixed" && s.model != "float" && !system_level(s.model))
      throw InputError(path + ": model \"" + s.model + "\" cannot be explored (fixed, float, tlm, rtl, mixed:UNIT,...)");
  }
  if (j.contains("reference_step")) {
    if (!j["reference_step"].is_number() || j["reference_step"].get<double>() <= 0 || j["reference_step"].get<double>() > 4)
      throw InputError(path + ": reference_step " + j["reference_step"].dump() + " is out of range (0, 4]");
    s.reference_step = j["reference_step"].get<double>();
  }
  if (j.contains("gates")) {
    if (!j["gates"].is_boolean()) throw InputError(path + ": \"gates\" should be true or false, not " + j["gates"].dump());
    s.gates = j["gates"].get<bool>();
  }
  if (j.contains("check")) {
    if (!j["check"].is_boolean()) throw InputError(path + ": \"check\" should be true or false, not " + j["check"].dump());
    s.check = j["check"].get<bool>();
    if (s.check && !system_level(s.model))
      throw InputError(path + ": \"check\" needs a system model (tlm, rtl, mixed:UNIT,...), not " + s.model);
  }
  if (j.contains("roi")) {
    const ordered_json& r = j["roi"];
    if (!r.is_array() || r.size() != 4 || !std::all_of(r.begin(), r.end(), [](const ordered_json& v) {
          return v.is_number_integer() && v.get<int64_t>() >= 0 && v.get<int64_t>() <= 8192;
        }) || r[2].get<int>() == 0 || r[3].get<int>() == 0)
      throw InputError(path + ": roi " + r.dump() + " should be [x, y, width, height] in output pixels, width and height > 0");
    for (int i = 0; i < 4; ++i) s.roi[i] = r[i].get<int>();
  }
  std::optional<json> base;
  if (j.contains("scene")) base = load_scene_json(folder / str("scene"), path);

  // The points: the product of the axes (the last varies fastest), then
  // the listed points.
  std::vector<ordered_json> values;
  auto check_key = [&](const std::string& where, const std::string& k) {
    if (!sweepable(k)) {
      std::string list;
      for (const std::string& key : sweepable_keys()) list += (list.empty() ? "" : ", ") + key;
      throw InputError(path + ": " + where + ": key \"" + k + "\" cannot be swept (" + list + ")");
    }
  };
  if (j.contains("axes")) {
    const ordered_json& axes = j["axes"];
    if (!axes.is_object() || axes.empty()) throw InputError(path + ": \"axes\" should be an object of key: [values]");
    values.push_back(ordered_json::object());
    for (const auto& [k, list] : axes.items()) {
      check_key("axes", k);
      if (!list.is_array() || list.empty())
        throw InputError(path + ": axes: \"" + k + "\" should be a non-empty list of values, not " + list.dump());
      std::vector<ordered_json> next;
      for (const ordered_json& v : values)
        for (const ordered_json& x : list) {
          ordered_json w = v;
          w[k] = x;
          next.push_back(w);
          if (next.size() > kMaxPoints)
            throw InputError(path + ": the axes make more than " + std::to_string(kMaxPoints) + " points");
        }
      values = std::move(next);
    }
  }
  if (j.contains("points")) {
    if (!j["points"].is_array()) throw InputError(path + ": \"points\" should be a list of objects");
    int n = 0;
    for (const ordered_json& p : j["points"]) {
      if (!p.is_object()) throw InputError(path + ": points[" + std::to_string(n) + "] should be an object, not " + p.dump());
      for (const auto& [k, v] : p.items()) check_key("points[" + std::to_string(n) + "]", k);
      values.push_back(p);
      ++n;
    }
  }
  if (values.empty()) values.push_back(ordered_json::object());
  if (values.size() > kMaxPoints) throw InputError(path + ": more than " + std::to_string(kMaxPoints) + " points");

  for (size_t i = 0; i < values.size(); ++i) {
    ExplorePoint p;
    p.index = static_cast<int>(i);
    p.values = values[i];
    const std::string where = path + ": point " + std::to_string(i) + " (" + values_text(p.values) + ")";
    if (p.values.contains("scene")) {
      if (!p.values["scene"].is_string()) throw InputError(where + ": \"scene\" should be a file name");
      p.scene = load_scene_json(folder / p.values["scene"].get<std::string>(), where);
    } else if (base) {
      p.scene = *base;
    } else {
      throw InputError(path + ": no \"scene\": give the base scene, or sweep \"scene\"");
    }
    for (const auto& [k, v] : p.values.items())
      if (k != "scene") apply(p.scene, k, v);
    // Every value is checked where the scene is: the scene parser names
    // the key and the range.
    try {
      golden::parse_scene(p.scene.dump(), "the point's scene");
    } catch (const InputError& e) {
      throw InputError(where + ": " + e.what());
    }
    s.points.push_back(std::move(p));
  }
  return s;
}

int run_explore(const ExploreArgs& a, const std::string& self) {
  Sweep s = load_sweep(a.sweep);
  if (a.no_gates) s.gates = false;
  const fs::path out = fs::absolute(a.out.empty() ? fs::path(fs::path(a.sweep).stem().string() + ".explore") : fs::path(a.out));
  fs::create_directories(out);
  if (a.point >= 0) {
    if (a.point >= static_cast<int>(s.points.size()))
      throw InputError(a.sweep + ": --point " + std::to_string(a.point) + ": the sweep has points 0.." +
                       std::to_string(s.points.size() - 1));
    return run_point(s, s.points[a.point], a, out, self);
  }
  if (a.collect) return collect(s, a, out);

  // The jobs: one command per point. jobs.txt lists all of them (what a
  // Slurm array runs, line by line: scripts/explore_slurm.sh); the points
  // not done yet go to GNU parallel.
  std::string all, pending;
  int n_pending = 0;
  for (const ExplorePoint& p : s.points) {
    std::string cmd = shell_quote(self) + " explore " + shell_quote(fs::absolute(a.sweep).string()) + " --out " +
                      shell_quote(out.string()) + " --point " + std::to_string(p.index);
    if (!a.gates_cache.empty()) cmd += " --gates-cache " + shell_quote(fs::absolute(a.gates_cache).string());
    if (a.no_gates) cmd += " --no-gates";
    all += cmd + "\n";
    if (!point_done(s, p, out)) pending += cmd + "\n", ++n_pending;
  }
  write_atomic(out / "jobs.txt", all);
  if (a.emit_jobs) {
    std::fprintf(stderr,
                 "explore: %zu jobs in %s (%d not done); run them (GNU parallel < jobs.txt, or "
                 "scripts/explore_slurm.sh), then cube4 explore %s --out %s --collect\n",
                 s.points.size(), (out / "jobs.txt").c_str(), n_pending, a.sweep.c_str(), out.c_str());
    return 0;
  }
  if (!a.quiet)
    std::fprintf(stderr, "explore: %zu points, %zu done before, %d to run at %s\n", s.points.size(),
                 s.points.size() - n_pending, n_pending, s.model.c_str());
  if (n_pending > 0) {
    write_atomic(out / "jobs-pending.txt", pending);
    const int jobs = a.jobs > 0 ? a.jobs : std::max(1, static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN)));
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("explore: fork failed");
    if (pid == 0) {
      const int in = ::open((out / "jobs-pending.txt").c_str(), O_RDONLY);
      if (in < 0 || ::dup2(in, 0) < 0) _exit(127);
      const std::string j = std::to_string(jobs);
      // --line-buffer: each job's progress line reaches stderr whole.
      execlp("parallel", "parallel", "-j", j.c_str(), "--line-buffer", "--halt", "never", "--joblog",
             (out / "parallel-joblog.txt").c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
      if (errno != EINTR) throw std::runtime_error("explore: waitpid failed");
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
      throw InputError("explore: GNU parallel could not be run (apt-get install parallel); or run " +
                       (out / "jobs.txt").string() + " another way and then cube4 explore --collect");
  }
  return collect(s, a, out);
}

}  // namespace cube4::tb
