#include "tb/regress.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "golden/errors.hpp"
#include "systemc/rtl/rtl_assertion.hpp"
#include "tb/output_files.hpp"
#include "tb/report.hpp"

namespace cube4::tb {
namespace fs = std::filesystem;
using golden::InputError;

namespace {

struct Case {
  std::string scene, level;
  fs::path dir;            // the case's outputs: image, report, log
  pid_t pid = 0;
  int exit_code = -1;
  double seconds = 0;
  std::chrono::steady_clock::time_point start;
  std::string hash, failure, log;
  // A failed check: a difference from golden (exit 3) or a failed RTL
  // assertion (exit 4); any other non-zero exit is an error.
  bool failed() const { return exit_code == 3 || exit_code == sysc::kExitRtlAssertion; }
};

std::string read_file(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string xml_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default:
        // XML 1.0 admits no other control characters than tab and newline.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') o += ' ';
        else o += c;
    }
  }
  return o;
}

std::string level_slug(const std::string& level) {
  std::string s = level;
  std::replace(s.begin(), s.end(), ':', '-');
  std::replace(s.begin(), s.end(), ',', '+');
  return s;
}

void start(Case& c, const std::string& self, int pipes) {
  fs::create_directories(c.dir);
  std::vector<std::string> args{self, "render", c.scene, "--model", c.level, "-q",
                                "-o", (c.dir / "image.png").string(), "--report", (c.dir / "report.json").string()};
  if (c.level != "fixed" && c.level != "float" && c.level != "reference") args.push_back("--check");
  if (pipes > 0 && c.level != "fixed") args.insert(args.end(), {"--pipes", std::to_string(pipes)});
  const std::string log = (c.dir / "log.txt").string();
  c.start = std::chrono::steady_clock::now();
  c.pid = fork();
  if (c.pid < 0) throw std::runtime_error("regress: fork failed");
  if (c.pid == 0) {
    if (!freopen(log.c_str(), "w", stderr) || !freopen(log.c_str(), "a", stdout)) _exit(1);
    std::vector<char*> argv;
    for (std::string& s : args) argv.push_back(s.data());
    argv.push_back(nullptr);
    execv(self.c_str(), argv.data());
    _exit(127);
  }
}

void finish(Case& c, int status) {
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - c.start).count();
  c.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  c.log = read_file(c.dir / "log.txt");
  if (fs::exists(c.dir / "report.json")) {
    try {
      const nlohmann::json r = nlohmann::json::parse(read_file(c.dir / "report.json"));
      if (r.contains("baseplane_hash_fnv1a64")) c.hash = r["baseplane_hash_fnv1a64"];
    } catch (const nlohmann::json::exception&) {
    }
  }
  // The child names the first differing pixel, unit, slice and sample on
  // its last error line (exit 3), or the bad input (exit 2); a failed RTL
  // assertion (exit 4) is Verilator's line, which names the assertion and
  // the values at fault.
  std::istringstream lines(c.log);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("cube4: check FAILED", 0) == 0 || line.rfind("cube4: error", 0) == 0 ||
        line.rfind("cube4: internal error", 0) == 0)
      c.failure = line;
    if (c.exit_code == sysc::kExitRtlAssertion && c.failure.empty() && line.find("Assertion failed in") != std::string::npos)
      c.failure = line;
  }
}

}  // namespace

std::vector<std::string> regress_scenes(const std::vector<std::string>& inputs) {
  std::vector<std::string> scenes;
  for (const std::string& in : inputs) {
    const fs::path p(in);
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<std::string> found;
      for (const auto& e : fs::directory_iterator(p))
        if (e.path().extension() == ".json") found.push_back(e.path().string());
      if (found.empty()) throw InputError("regress: folder " + in + " holds no .json scene");
      std::sort(found.begin(), found.end());
      scenes.insert(scenes.end(), found.begin(), found.end());
    } else if (p.extension() == ".json" && fs::is_regular_file(p, ec)) {
      scenes.push_back(in);
    } else if (fs::is_regular_file(p, ec)) {  // a list: one scene per line, relative to the list's folder
      std::ifstream f(p);
      int n = 0;
      for (std::string line; std::getline(f, line);) {
        line.erase(0, line.find_first_not_of(" \t"));
        line.erase(line.find_last_not_of(" \t\r") + 1);
        if (line.empty() || line[0] == '#') continue;
        const fs::path s = fs::path(line).is_absolute() ? fs::path(line) : p.parent_path() / line;
        if (!fs::is_regular_file(s, ec)) throw InputError("regress: " + in + ": scene " + line + " does not exist");
        scenes.push_back(s.string());
        ++n;
      }
      if (n == 0) throw InputError("regress: list " + in + " names no scene");
    } else {
      throw InputError("regress: " + in + " is neither a scene, a folder of scenes nor a list of scenes");
    }
  }
  return scenes;
}

int run_regress(const RegressArgs& a, const std::string& self) {
  if (a.levels.empty()) throw InputError("regress: --levels is empty");
  for (const std::string& l : a.levels)
    if (l != "fixed" && l != "float" && l != "tlm" && l != "rtl" && l.rfind("mixed:", 0) != 0)
      throw InputError("regress: --levels: unknown level '" + l + "' (fixed, float, tlm, rtl, mixed:UNIT,...)");
  const std::vector<std::string> scenes = regress_scenes(a.inputs);
  // All outputs or none (docs/reliability.md): checked before any work.
  OutputSet outputs;
  const std::string junit_temp = outputs.add(a.junit, "--junit");
  const std::string summary_temp = a.summary.empty() ? "" : outputs.add(a.summary, "--summary");
  // Outputs go beside the JUnit file, one folder per case, kept for a look.
  const fs::path work = fs::path(a.junit).parent_path() / (fs::path(a.junit).stem().string() + ".cases");
  fs::remove_all(work);
  std::vector<Case> cases;
  for (const std::string& s : scenes)
    for (const std::string& l : a.levels) {
      Case c;
      c.scene = s;
      c.level = l;
      c.dir = work / (fs::path(s).stem().string() + "." + level_slug(l));
      cases.push_back(std::move(c));
    }
  const int jobs = a.jobs > 0 ? a.jobs : std::max(1, static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN)));

  const auto t0 = std::chrono::steady_clock::now();
  std::map<pid_t, Case*> running;
  size_t next = 0, done = 0;
  while (done < cases.size()) {
    while (running.size() < static_cast<size_t>(jobs) && next < cases.size()) {
      start(cases[next], self, a.pipes);
      running[cases[next].pid] = &cases[next];
      ++next;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) throw std::runtime_error("regress: waitpid failed");
    auto it = running.find(pid);
    if (it == running.end()) continue;
    finish(*it->second, status);
    running.erase(it);
    ++done;
    if (!a.quiet)
      std::fprintf(stderr, "regress: [%zu/%zu] %s at %s: %s\n", done, cases.size(), it->second->scene.c_str(),
                   it->second->level.c_str(), it->second->exit_code == 0 ? "passed" : "FAILED");
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // Every level's base plane must equal the fixed model's (the golden one)
  // bit for bit: hashes of one scene compared across levels.
  std::map<std::string, std::string> golden_hash;
  for (const Case& c : cases)
    if (c.level == "fixed" && c.exit_code == 0) golden_hash[c.scene] = c.hash;
  for (Case& c : cases)
    if (c.exit_code == 0 && c.level != "fixed" && c.level != "float" && golden_hash.count(c.scene) &&
        c.hash != golden_hash[c.scene]) {
      c.exit_code = 3;
      c.failure = "base-plane hash " + c.hash + " differs from the fixed model's " + golden_hash[c.scene];
    }

  int failures = 0, errors = 0;
  for (const Case& c : cases) {
    failures += c.failed();
    errors += c.exit_code != 0 && !c.failed();
  }
  std::ostringstream x;
  x << std::fixed << std::setprecision(3);  // xs:decimal, never 1e-05
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<testsuites name=\"cube4 regress\" tests=\"" << cases.size() << "\" failures=\"" << failures
    << "\" errors=\"" << errors << "\" time=\"" << total << "\">\n";
  for (const std::string& l : a.levels) {
    int n = 0, f = 0, e = 0;
    double t = 0;
    for (const Case& c : cases)
      if (c.level == l) ++n, f += c.failed(), e += c.exit_code != 0 && !c.failed(), t += c.seconds;
    x << "  <testsuite name=\"" << xml_escape(l) << "\" tests=\"" << n << "\" failures=\"" << f << "\" errors=\""
      << e << "\" skipped=\"0\" time=\"" << t << "\">\n";
    for (const Case& c : cases) {
      if (c.level != l) continue;
      x << "    <testcase classname=\"cube4." << xml_escape(level_slug(l)) << "\" name=\"" << xml_escape(c.scene)
        << "\" time=\"" << c.seconds << "\">\n";
      if (c.failed())
        x << "      <failure type=\"" << (c.exit_code == 3 ? "mismatch" : "assertion") << "\" message=\""
          << xml_escape(c.failure) << "\"/>\n";
      else if (c.exit_code != 0)
        x << "      <error type=\"exit " << c.exit_code << "\" message=\""
          << xml_escape(c.failure.empty() ? "exit code " + std::to_string(c.exit_code) : c.failure) << "\"/>\n";
      if (!c.log.empty()) x << "      <system-err>" << xml_escape(c.log) << "</system-err>\n";
      x << "    </testcase>\n";
    }
    x << "  </testsuite>\n";
  }
  x << "</testsuites>\n";
  write_text(junit_temp, x.str(), a.junit);

  if (!a.summary.empty()) {
    std::ostringstream m;
    m << "# cube4 regress\n\n" << cases.size() << " cases (" << scenes.size() << " scenes × " << a.levels.size()
      << " levels), " << failures << " failed, " << errors << " errors, " << total << " s with " << jobs
      << " jobs.\n\n| scene |";
    for (const std::string& l : a.levels) m << " " << l << " |";
    m << "\n|---|";
    for (size_t i = 0; i < a.levels.size(); ++i) m << "---|";
    m << "\n";
    for (const std::string& s : scenes) {
      m << "| " << s << " |";
      for (const Case& c : cases)
        if (c.scene == s) m << " " << (c.exit_code == 0 ? "pass" : c.failed() ? "**FAIL**" : "**error**") << " |";
      m << "\n";
    }
    for (const Case& c : cases)
      if (c.exit_code != 0) m << "\n- " << c.scene << " at " << c.level << ": " << c.failure;
    m << "\n";
    write_text(summary_temp, m.str(), a.summary);
  }
  outputs.commit();
  if (!a.quiet)
    std::fprintf(stderr, "regress: %zu cases, %d failed, %d errors -> %s\n", cases.size(), failures, errors,
                 a.junit.c_str());
  return errors ? 2 : failures ? 3 : 0;
}

}  // namespace cube4::tb
