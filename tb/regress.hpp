// cube4 regress: a set of scenes rendered at several model levels, each run
// a child `cube4 render ... --check` process, in parallel; the results as
// JUnit XML (one test case per scene and level, the first mismatch in the
// failure message) and a Markdown summary, for CI servers to read.
#pragma once
#include <string>
#include <vector>

namespace cube4::tb {

struct RegressArgs {
  std::vector<std::string> inputs;        // scene files, folders of *.json, or list files (.txt)
  std::vector<std::string> levels{"fixed", "tlm", "rtl"};
  int jobs = 0;                           // 0: one per core
  int pipes = 0;                          // 0: each scene's
  std::string junit = "regress.xml";
  std::string summary;                    // Markdown; empty: none
  bool quiet = false;
};

// Expands the inputs to scene paths (sorted within a folder); throws
// golden::InputError naming a path that is missing or has no scene.
std::vector<std::string> regress_scenes(const std::vector<std::string>& inputs);

// Runs the regression with `self` as the cube4 binary; returns 0 when every
// case passed, 3 when one failed or differed, 2 for bad input.
int run_regress(const RegressArgs& a, const std::string& self);

}  // namespace cube4::tb
