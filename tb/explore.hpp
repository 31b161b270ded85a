// cube4 explore: a design-space sweep (docs/explore.md). A sweep file names
// a base scene, a model level and the keys to vary; every point of it is an
// independent `cube4 explore SWEEP --point I` job that renders the point,
// measures its error against the reference renderer, its modelled cycles,
// its gates (yosys, cached per width configuration) and its simulation
// time, and writes one result file. The jobs run through GNU parallel (or a
// Slurm job array, scripts/explore_slurm.sh); `cube4 explore` then collects
// the results into one table, the Pareto fronts and plots. A point whose
// result exists is not run again, so an interrupted sweep resumes.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "golden/scene.hpp"

namespace cube4::tb {

struct ExploreArgs {
  std::string sweep;         // the sweep file (JSON)
  std::string out;           // results folder; empty: SWEEP's name with .explore, in the current folder
  int jobs = 0;              // GNU parallel's -j; 0: one per core
  bool emit_jobs = false;    // plan, write jobs.txt, stop
  bool collect = false;      // only collect the results there are
  int point = -1;            // >= 0: run this one point (what a job does)
  bool plots = true;
  bool no_gates = false;     // no yosys, whatever the sweep says
  bool quiet = false;
  std::string gates_cache;   // empty: $XDG_CACHE_HOME/cube4/gates or ~/.cache/cube4/gates
};

// One point: the swept keys' values and the scene they make.
struct ExplorePoint {
  int index = 0;
  nlohmann::ordered_json values;  // key -> value, in the sweep's order
  nlohmann::json scene;           // the base scene with the values applied, file paths absolute
};

struct Sweep {
  std::string file;
  std::string model = "tlm";
  double reference_step = 0.25;
  bool gates = true;
  bool check = false;         // render with --check: every point bit-exact against golden
  int roi[4] = {0, 0, 0, 0};  // x, y, width, height in output pixels; width 0: none
  std::vector<ExplorePoint> points;
};

// Reads and checks the sweep: every key sweepable, every value in range
// (each point's scene goes through the scene parser). Throws
// golden::InputError naming the sweep file, the key and the value.
Sweep load_sweep(const std::string& path);

// The keys a sweep may vary, for messages and docs.
const std::vector<std::string>& sweepable_keys();

// Pareto front of (error, cost) pairs: lower cost and higher psnr are
// better; on_front[i] is true when no other point is at least as good in
// both and better in one.
std::vector<bool> pareto_front(const std::vector<double>& psnr, const std::vector<double>& cost);

// The RTL parameters a point's chip is synthesised with (its widths, p and
// the memories p sizes); those of them each unit declares
// (scripts/gates.sh --declared); and the cache file of yosys's result for
// a unit at its parameters.
std::string gate_config(const golden::Scene& s);
std::map<std::string, std::string> declared_parameters(const std::string& config);
std::string gates_cache_file(const std::string& cache_dir, const std::string& unit, const std::string& params);

// Returns the exit code: 0 all points done, 2 bad input, 1 a point failed.
int run_explore(const ExploreArgs& a, const std::string& self);

}  // namespace cube4::tb
