// The cube4 command: render a scene with a chosen model, or describe what
// the host driver makes of it. Exit codes: 0 ok, 2 bad input, 1 internal error.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <sstream>
#include <chrono>
#include <vector>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "golden/blocks.hpp"
#include "golden/errors.hpp"
#include "golden/host_driver.hpp"
#include "golden/input_file.hpp"
#include "golden/mesh.hpp"
#include "golden/polygon_connections.hpp"
#include "golden/polygons.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "tb/block_jobs.hpp"
#include "tb/explore.hpp"
#include "tb/heap_tuning.hpp"
#include "tb/image_io.hpp"
#include "tb/output_files.hpp"
#include "tb/progress.hpp"
#include "tb/regress.hpp"
#include "tb/report.hpp"
#include "systemc/core/partitioned.hpp"
#include "systemc/core/system.hpp"
#include "systemc/host/host_program.hpp"
#include "systemc/host/register_map.hpp"
#include "systemc/rtl/rtl_assertion.hpp"
#include "tb/system_report.hpp"

namespace {

using namespace cube4;
using golden::InputError;

struct RenderArgs {
  std::string scene;
  std::string model = "fixed";
  std::string output = "cube4.png";
  std::string baseplane;
  std::string report;
  double reference_step = 0.25;
  golden::SplatKernel splat;
  int repeat = 1;
  bool quiet = false;
  int pipes = 0;           // 0: the scene's
  int check = -1;          // -1: on for models with RTL units
  bool simulate_all = false;
  bool no_assert = false;
  int frames = 1;
  std::string trace;       // FST file (RTL units)
  std::vector<int64_t> trace_window;  // first, last cycle
  uint64_t max_memory_mib = 0;  // 0: golden::kDefaultMemoryLimit
  std::optional<uint32_t> seed;        // default: CUBE4_SEED, else 1
  int threads = 0;              // golden renders (fixed, and --check's): 0 = one per core
  std::string blocks;           // --blocks AxBxC (default: the scene's "blocks")
  std::string plan;             // --plan PLAN.json: the scene and blocks of a plan (cube4 plan)
  int block = -1;               // --block I: render only block I of the plan ...
  std::string partial;          // ... into this partial image file
};

// Blocks along object x, y, z: --blocks AxBxC, else the scene's "blocks".
std::array<int, 3> block_counts(const RenderArgs& a, const golden::Scene& scene) {
  if (a.blocks.empty()) return scene.blocks;
  std::array<int, 3> c{};
  char x1 = 0, x2 = 0, rest = 0;
  if (std::sscanf(a.blocks.c_str(), "%d%c%d%c%d%c", &c[0], &x1, &c[1], &x2, &c[2], &rest) != 5 || x1 != 'x' ||
      x2 != 'x')
    throw InputError("--blocks " + a.blocks + ": give blocks along x, y and z as AxBxC, for example 2x2x1");
  for (int v : c)
    if (v < 1 || v > golden::kMaxBlocks)
      throw InputError("--blocks " + a.blocks + ": each count must lie in 1.." + std::to_string(golden::kMaxBlocks));
  return c;
}
bool partitioned(const std::array<int, 3>& c) { return c[0] * c[1] * c[2] > 1; }
std::string blocks_what(const RenderArgs& a, const golden::Scene& scene) {
  return a.blocks.empty() ? (scene.file.empty() ? "the default scene" : scene.file) + ": blocks" : "--blocks " + a.blocks;
}

// The RTL's random-reset seed: --seed, else the environment's CUBE4_SEED
// (what the RTL unit tests read), else 1.
uint32_t rtl_seed(const RenderArgs& a) {
  if (a.seed) return *a.seed;
  const char* env = std::getenv("CUBE4_SEED");
  if (!env || !*env) return 1;
  char* end = nullptr;
  const unsigned long v = std::strtoul(env, &end, 10);
  if (*end || v > 0xFFFFFFFFul) throw InputError(std::string("CUBE4_SEED = \"") + env + "\" is not a seed (0..4294967295)");
  return static_cast<uint32_t>(v);
}

bool is_system_model(const std::string& m) { return m == "tlm" || m == "rtl" || m.rfind("mixed:", 0) == 0; }

// --model tlm | rtl | mixed:UNIT,... (the listed units at RTL, the rest TLM).
std::array<sysc::Level, sysc::kUnits> parse_levels(const std::string& model) {
  std::array<sysc::Level, sysc::kUnits> l;
  l.fill(model == "rtl" ? sysc::Level::Rtl : sysc::Level::Tlm);
  if (model.rfind("mixed:", 0) != 0) return l;
  std::stringstream list(model.substr(6));
  std::string name;
  int count = 0;
  while (std::getline(list, name, ',')) {
    bool found = name == "compose";  // the composition network's (network_level())
    for (int u = 0; u < sysc::kUnits; ++u)
      if (name == sysc::unit_name(static_cast<sysc::Unit>(u))) {
        l[static_cast<size_t>(u)] = sysc::Level::Rtl;
        found = true;
      }
    if (!found)
      throw InputError("--model " + model + ": unknown unit '" + name +
                       "' (units: interp, gradient, shade, composite, addr, and compose: the composition network of --blocks)");
    ++count;
  }
  if (count == 0) throw InputError("--model " + model + ": name at least one unit after 'mixed:'");
  return l;
}

// The composition network of a partitioned render runs at RTL with
// --model rtl or mixed:...,compose,...; else at TLM.
sysc::Level network_level(const std::string& model) {
  if (model == "rtl") return sysc::Level::Rtl;
  if (model.rfind("mixed:", 0) != 0) return sysc::Level::Tlm;
  std::stringstream list(model.substr(6));
  std::string name;
  while (std::getline(list, name, ','))
    if (name == "compose") return sysc::Level::Rtl;
  return sysc::Level::Tlm;
}

// First pixel where two base planes differ, as text (empty if equal).
std::string first_pixel_difference(const golden::BasePlane& want, const golden::BasePlane& got) {
  if (want.width != got.width || want.height != got.height)
    return "base plane is " + std::to_string(got.width) + "x" + std::to_string(got.height) + ", golden's " +
           std::to_string(want.width) + "x" + std::to_string(want.height);
  for (size_t i = 0; i < want.rgba.size(); i += 4)
    if (!std::equal(&want.rgba[i], &want.rgba[i] + 4, &got.rgba[i])) {
      const size_t px = i / 4;
      std::ostringstream m;
      m << "pixel (" << px % static_cast<size_t>(want.width) << ", " << px / static_cast<size_t>(want.width)
        << "): expected RGBA (" << want.rgba[i] << ", " << want.rgba[i + 1] << ", " << want.rgba[i + 2] << ", "
        << want.rgba[i + 3] << "), got (" << got.rgba[i] << ", " << got.rgba[i + 1] << ", " << got.rgba[i + 2]
        << ", " << got.rgba[i + 3] << ")";
      return m.str();
    }
  return {};
}

struct Loaded {
  golden::Scene scene;
  golden::Volume volume;
  golden::HostProgram host;
  std::vector<golden::Mesh> meshes;  // the scene's "polygons", checked
};

// Relative paths in a scene are relative to its folder.
std::string scene_dir(const std::string& scene_path) {
  const std::string dir = scene_path.empty() ? "." : std::filesystem::path(scene_path).parent_path().string();
  return dir.empty() ? "." : dir;
}

void load_volume(Loaded& l, const std::string& scene_path, bool header_only) {
  l.volume = golden::load_volume(l.scene.volume, l.scene.precision.voxel_bits, scene_dir(scene_path), header_only);
  golden::load_tags(l.scene, l.volume, scene_dir(scene_path));
  // The meshes (once load() has them) widen the base plane: polygon margins.
  l.host = golden::program_host(l.scene, l.volume, l.meshes);
}

// With `header_only` the volume has no voxels yet: what every limit of a run
// depends on (dimensions, spacing, so the view and the registers) comes
// from the scene and the volume's header, so a run the limits refuse costs
// no load.
Loaded load(const std::string& scene_path, bool header_only = false) {
  Loaded l;
  l.scene = scene_path.empty() ? golden::default_scene() : golden::load_scene(scene_path);
  load_volume(l, scene_path, header_only);
  // A bad mesh is bad input (exit 2), whatever the model.
  l.meshes = golden::load_meshes(l.scene, scene_dir(scene_path));
  if (!l.meshes.empty()) l.host = golden::program_host(l.scene, l.volume, l.meshes);
  return l;
}


nlohmann::json effects_json(const golden::EffectSet& e) { return e.names(); }

// What a render holds besides the loaded volume, estimated before it starts
// so that an 8192x8192 image or a large volume through the system model is
// refused by name instead of ending in bad_alloc.
void check_render_memory(const Loaded& l, const std::string& model, int golden_threads,
                         const golden::BlockPlan* plan = nullptr) {
  const double voxels = static_cast<double>(l.volume.size());
  const double base = static_cast<double>(l.host.regs.base_width()) * l.host.regs.base_height();
  const double slice = static_cast<double>(l.host.regs.dim[0]) * l.host.regs.dim[1];
  const double image = static_cast<double>(l.scene.width) * l.scene.height;
  // The volume (2 bytes a voxel), the base plane (fixed and float: 16 bytes
  // a pixel at most), the final image (float RGBA, and 8-bit for PNG); the
  // system model keeps its own copy of the volume in voxel memory, and the
  // check's golden render another base plane. The fixed renderer's ray
  // store holds a ray per base-plane pixel, and each of its threads eight
  // slices of 4-byte samples and voxels. The splat model accumulates a slice
  // image and the image in double RGBA.
  const bool system = is_system_model(model);
  const bool fixed = model == "fixed" || system;
  // With polygons the fixed renderer also holds their front, back and Z
  // images (20 bytes a pixel), the float one its fragment lists.
  double bytes = voxels * 2 * (system ? 2 : 1) + base * 16 * (system ? 2 : 1) +
                 image * (20 + (model == "splat" ? 64 : 0)) +
                 (fixed ? base * sizeof(golden::RayAcc) * (system ? 2 : 1) + golden_threads * 8 * 4 * slice : 0) +
                 (l.meshes.empty() ? 0 : base * 20);
  // Partitioned: every block's partial image (pixels and accumulators) is
  // kept for the network, and one block's volume is copied at a time.
  if (plan)
    for (const golden::Block& b : plan->blocks) {
      const double part = static_cast<double>(b.base_width()) * b.base_height();
      bytes += part * (8 + sizeof(golden::RayAcc)) * (system ? 2 : 1);
    }
  if (plan && !plan->blocks.empty()) {
    const auto& d = plan->blocks.front().object_dim;
    bytes += static_cast<double>(d[0]) * d[1] * d[2] * 2 * (system ? 2 : 1);
  }
  golden::check_memory(l.scene.file.empty() ? std::string("the default scene") : l.scene.file,
                       "the " + model + " render", bytes,
                       golden::dims_text(l.volume.dim[0], l.volume.dim[1], l.volume.dim[2]) + " voxels, " +
                           std::to_string(l.scene.width) + "x" + std::to_string(l.scene.height) + " image");
}

// The built system's limits, from the registers of the volume's header
// (before any voxel is loaded): the host interface's volume window, then
// what sysc::check_system_limits() holds.
// With a block plan, each block's machine is held to them instead of the
// whole volume's: a volume beyond one machine renders as blocks.
void check_system_limits(const Loaded& l, const sysc::SystemConfig& cfg, const golden::BlockPlan* plan) {
  // `who`: "" for the whole volume, else the block.
  auto one = [&](const std::array<int, 3>& dim, const golden::Registers& regs, const std::string& who) {
    for (int i = 0; i < 3; ++i)
      if (dim[i] > sysc::regmap::kMaxDimLimit)
        throw InputError(l.volume.source + ": " + (who.empty() ? "volume " : who + ", stored voxels ") +
                         golden::dims_text(dim[0], dim[1], dim[2]) + ", has more than the host interface's " +
                         std::to_string(sysc::regmap::kMaxDimLimit) +
                         " voxels per axis (its volume window, docs/registers.md); render it with --model fixed, " +
                         "or in more blocks (--blocks AxBxC)");
    try {
      sysc::check_system_limits(regs, cfg);
    } catch (const sysc::VolumeTooLarge& e) {
      throw InputError(who.empty() ? std::string(e.what()) : l.volume.source + ": " + who + ": " + e.what() + "; use more blocks");
    } catch (const std::invalid_argument& e) {
      throw InputError(who.empty() ? std::string(e.what()) : l.volume.source + ": " + who + ": " + e.what());
    }
  };
  if (!plan) return one(l.volume.dim, l.host.regs, "");
  for (const golden::Block& b : plan->blocks) one(b.object_dim, b.regs, "block " + std::to_string(b.index));
}

// The FST files the RTL units write (systemc/rtl/: one per unit, the
// shading unit's from pipeline 0).
const std::vector<std::string> kTraceUnits = {"addr", "interp", "gradient", "shade0", "composite"};

void apply_memory_limit(uint64_t mib) {
  if (mib > 0) golden::set_memory_limit(mib << 20);
}

// cube4 render --plan P --block I --partial F: one block of a plan, by the
// chosen model, into a partial image file (tb/block_jobs.hpp).
int render_plan_block(const RenderArgs& a, const tb::PlanFile& pf, const Loaded& l, const std::array<int, 3>& counts,
                      const std::string& what, sysc::SystemConfig cfg, bool system, tb::OutputSet& outputs,
                      const std::string& partial_temp, const std::string& report_temp,
                      tb::ProgressPrinter& progress) {
  if (l.scene.xy_supersampling != 1)
    throw InputError(pf.path + ": a plan renders one frame, but the scene asks for xy_supersampling " +
                     std::to_string(l.scene.xy_supersampling));
  const golden::BlockPlan plan = golden::plan_blocks(l.host.regs, l.volume.dim, counts, what);
  const std::string id = tb::plan_id(plan, l.volume);
  if (id != pf.id)
    throw InputError(pf.path + ": plan_id " + pf.id + ", but its scene and volume give " + id +
                     " now: the scene, the volume or cube4 changed since the plan was made; make the plan again");
  const golden::Block& b = plan.blocks[static_cast<size_t>(a.block)];
  const golden::Volume bv = golden::block_volume(l.volume, b);
  auto cb = [&](double f) { progress(f); };
  const auto t0 = std::chrono::steady_clock::now();
  golden::BasePlane part;
  std::optional<sysc::SystemResult> sys;
  std::string check_failure;
  double bus_seconds = 0;
  if (system) {
    cfg.accumulators = true;
    try {
      sys = sysc::render_through_host(b.regs, bv, cfg, cb, &bus_seconds);
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());
    } catch (const sysc::HostError& e) {
      throw InputError(e.what());
    }
    part = sys->plane;
    if (cfg.check) {
      golden::FixedOptions opt;
      opt.threads = a.threads;
      const std::string diff = sysc::partial_difference(golden::render_block_fixed(bv, b, opt), part);
      if (!diff.empty()) check_failure = "block " + std::to_string(a.block) + ": " + diff;
      else if (sys->mismatch) check_failure = "first unit output that differs: " + sys->mismatch->describe();
    }
  } else {
    golden::FixedOptions opt;
    opt.threads = a.threads;
    opt.progress = cb;
    part = golden::render_block_fixed(bv, b, opt);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  tb::write_partial(partial_temp, part, l.host.regs.p, id, a.block, static_cast<int>(plan.blocks.size()), a.model);
  if (!a.report.empty()) {
    nlohmann::json r = {{"model", a.model},
                        {"plan", a.plan},
                        {"plan_id", id},
                        {"scene", a.scene.empty() ? "(default)" : a.scene},
                        {"block", tb::describe_blocks(plan)["per_block"][static_cast<size_t>(a.block)]},
                        {"partial", a.partial},
                        {"wall_seconds", seconds}};
    if (sys) {
      r["system"] = tb::describe_system(*sys, cfg, l.scene.clock_mhz, seconds, check_failure);
      r["system"]["host_bus_ms"] = bus_seconds * 1e3;
    }
    tb::write_json(report_temp, r, a.report);
  }
  outputs.commit();
  if (!a.quiet)
    std::fprintf(stderr, "cube4: block %d of %zu (%s model) in %.3f s -> %s\n", a.block, plan.blocks.size(),
                 a.model.c_str(), seconds, a.partial.c_str());
  if (!check_failure.empty()) {
    std::fprintf(stderr, "cube4: check FAILED against the golden model: %s\n", check_failure.c_str());
    return 3;
  }
  return 0;
}

int run_render(const RenderArgs& args) {
  apply_memory_limit(args.max_memory_mib);
  RenderArgs a = args;
  // One block of a plan (cube4 plan): its scene and cut come from the plan.
  std::optional<tb::PlanFile> plan_file;
  if (!a.plan.empty()) {
    if (!a.scene.empty()) throw InputError("--plan: the plan names the scene; give no scene file as well");
    if (!a.blocks.empty()) throw InputError("--plan: the plan gives the blocks; give no --blocks as well");
    if (a.block < 0 || a.partial.empty())
      throw InputError("--plan: give the block to render and its partial image file: --block I --partial F.cpart");
    plan_file = tb::read_plan(a.plan);
    a.scene = plan_file->scene;
    a.blocks = std::to_string(plan_file->counts[0]) + "x" + std::to_string(plan_file->counts[1]) + "x" +
               std::to_string(plan_file->counts[2]);
    if (a.block >= plan_file->blocks)
      throw InputError("--block " + std::to_string(a.block) + ": the plan " + a.plan + " has blocks 0.." +
                       std::to_string(plan_file->blocks - 1));
  } else if (a.block >= 0 || !a.partial.empty()) {
    throw InputError("--block and --partial render one block of a plan: give --plan PLAN.json (cube4 plan)");
  }
  if (plan_file && (a.model == "float" || a.model == "reference"))
    throw InputError("--plan: the " + a.model + " model renders in one pass and has no blocks");
  // Outputs are checked before the (possibly long) render, so a typo costs nothing.
  for (const std::string* p : {&a.output, &a.baseplane}) {
    if (p->empty()) continue;
    const std::string ext = std::filesystem::path(*p).extension().string();
    if (ext != ".png" && ext != ".exr" && ext != ".PNG" && ext != ".EXR")
      throw InputError("output file '" + *p + "': unsupported extension '" + ext + "' (use .png or .exr)");
  }
  if ((a.model == "reference" || a.model == "splat") && !a.baseplane.empty())
    throw InputError("--baseplane: the " + a.model + " model renders the final image directly and has no base plane");
  if (!(a.reference_step > 0 && a.reference_step <= 4))
    throw InputError("--reference-step " + std::to_string(a.reference_step) + " is out of range (0, 4]");
  if (!(a.splat.sigma >= 0.05 && a.splat.sigma <= 4) || !(a.splat.width >= 0.25 && a.splat.width <= 8))
    throw InputError("--splat-kernel " + std::to_string(a.splat.sigma) + " " + std::to_string(a.splat.width) +
                     " is out of range (SIGMA 0.05..4, WIDTH 0.25..8 voxel spacings)");
  const bool system = is_system_model(a.model);
  if (!system && a.model != "fixed" && a.model != "float" && a.model != "reference" && a.model != "splat")
    throw InputError("--model " + a.model + ": unknown model (fixed, float, reference, splat, tlm, rtl, mixed:UNIT,...)");
  if (!a.trace_window.empty() &&
      (a.trace_window.size() != 2 || a.trace_window[0] < 0 || a.trace_window[0] > a.trace_window[1]))
    throw InputError("--trace-window: give FIRST LAST cycles, 0 <= FIRST <= LAST");
  if (!a.trace.empty() && std::filesystem::path(a.trace).extension() != ".fst")
    throw InputError("--trace '" + a.trace + "': the file must end in .fst");
  if (!a.trace.empty() && (!system || parse_levels(a.model) == parse_levels("tlm")))
    throw InputError("--trace: the " + a.model + " model has no RTL unit to trace");
  if (!a.trace_window.empty() && a.trace.empty()) throw InputError("--trace-window: give --trace FILE.fst as well");
  if (system) parse_levels(a.model);  // a wrong unit name costs no load
  // Every output is checked, and its temporary made, before any work.
  tb::OutputSet outputs;
  const std::string partial_temp = plan_file ? outputs.add(a.partial, "--partial") : "";
  const std::string output_temp = plan_file ? "" : outputs.add(a.output, "--output");
  const std::string baseplane_temp = a.baseplane.empty() ? "" : outputs.add(a.baseplane, "--baseplane");
  const std::string report_temp = a.report.empty() ? "" : outputs.add(a.report, "--report");
  const std::string trace_temp = a.trace.empty() ? "" : outputs.add_trace(a.trace, kTraceUnits);
  if (!a.scene.empty()) outputs.check_not_output(a.scene, "the scene");
  Loaded l = load(a.scene, true);
  if (system && !l.meshes.empty()) {
    sysc::SystemConfig levels;
    levels.levels = parse_levels(a.model);
    levels.p = a.pipes > 0 ? a.pipes : l.scene.pipelines;
    try {
      sysc::check_polygon_levels(levels, l.scene.view.perspective());
    } catch (const std::invalid_argument& e) {
      throw InputError((a.scene.empty() ? std::string("the scene") : a.scene) + ": \"polygons\" (" +
                       std::to_string(l.meshes.size()) + (l.meshes.size() == 1 ? " mesh" : " meshes") + "), --model " +
                       a.model + ": " + e.what() + "; or render with --model fixed, float or reference");
    }
  }
  if (l.scene.volume.kind == "den" || l.scene.volume.kind == "raw" || l.scene.volume.kind == "nifti")
    outputs.check_not_output(l.volume.source, "the volume");
  const int golden_threads = a.threads > 0 ? a.threads : golden::default_threads();
  // Sub-cubes: the plan from the volume's header already, so that its
  // limits, and each block's, cost no load. The float and reference
  // renderers have no machines to partition: they render in one pass.
  const std::array<int, 3> counts = block_counts(a, l.scene);
  const bool blocked = partitioned(counts) && (system || a.model == "fixed");
  const std::string what_blocks = blocks_what(a, l.scene);
  std::optional<golden::BlockPlan> header_plan;
  if (l.scene.view.perspective() && a.model == "splat")
    throw InputError((a.scene.empty() ? std::string("the scene") : a.scene) +
                     ": \"view.projection\": \"perspective\": the splat model projects voxels in parallel only "
                     "(bela's splatting); render with --model fixed, float, reference, tlm or mixed:interp");
  if (a.model == "splat" && !l.meshes.empty())
    throw InputError((a.scene.empty() ? std::string("the scene") : a.scene) +
                     ": \"polygons\": the splat model draws the volume only (bela's voxel projection)");
  if (blocked && !l.meshes.empty())
    throw InputError(what_blocks + ": a scene with \"polygons\" renders in one pass so far (Cube-5's polygon images "
                     "are not cut into blocks yet)");
  if (blocked) {
    header_plan = golden::plan_blocks(l.host.regs, l.volume.dim, counts, what_blocks);
    if (a.frames > 1)
      throw InputError("--frames: a partitioned render (" + what_blocks +
                       ") does not stream frames; its report gives the steady-state interval of machines and network");
    if (!a.trace.empty())
      throw InputError("--trace: a partitioned render (" + what_blocks + ") runs one machine per block; trace a "
                       "volume of one block's size instead");
  }
  check_render_memory(l, a.model, golden_threads, header_plan ? &*header_plan : nullptr);
  sysc::SystemConfig cfg;
  sysc::NetworkConfig net;
  std::optional<sysc::SystemResult> sys;
  std::optional<sysc::PartitionedResult> part;
  double bus_seconds = 0;  // host-bus time of programming the frame and reading it back
  std::string check_failure;
  if (system) {
    cfg.p = a.pipes > 0 ? a.pipes : l.scene.pipelines;
    cfg.levels = parse_levels(a.model);
    net.level = network_level(a.model);
    cfg.check = a.check < 0 ? !cfg.all_tlm() || (blocked && net.level == sysc::Level::Rtl) : a.check == 1;
    cfg.simulate_unneeded = a.simulate_all;
    cfg.frames = a.frames;
    cfg.seed = rtl_seed(a);
    cfg.polygon_engine = l.scene.polygon_engine;
    cfg.clock_hz = l.scene.clock_mhz * 1e6;
    cfg.assertions = !a.no_assert;
    cfg.threads = a.threads;  // 1: one thread; else two where the machine has them
    net.assertions = cfg.assertions;
    if (a.frames > 1 && cfg.all_tlm())
      throw InputError("--frames: the tlm model has no clock to stream frames on (its interval is the cycle model's)");
    if (!a.trace.empty()) {
      cfg.trace.file = trace_temp;
      if (a.trace_window.size() == 2) {
        cfg.trace.first = static_cast<uint64_t>(a.trace_window[0]);
        cfg.trace.last = static_cast<uint64_t>(a.trace_window[1]);
      }
    }
    net.cycle_level = !cfg.all_tlm();  // clocked with the machines, or loosely timed with them
    net.seed = cfg.seed;
    check_system_limits(l, cfg, header_plan ? &*header_plan : nullptr);
  }
  load_volume(l, a.scene, false);
  tb::ProgressPrinter progress("render " + a.model, !a.quiet);
  auto cb = [&](double f) { progress(f); };
  if (plan_file) return render_plan_block(a, *plan_file, l, counts, what_blocks, cfg, system, outputs, partial_temp,
                                          report_temp, progress);
  golden::RenderStats stats;
  golden::ImageF image;
  std::optional<uint64_t> hash;
  // x/y supersampling (VolumePro §4.1): n² frames whose rays start 1/n of a
  // pixel apart, each warped, then blended on the host; for n = 1 the one
  // frame of the scene. The reference ray caster casts a ray per output
  // pixel already and renders once; so does the splat model, which has no rays.
  const std::vector<golden::Scene> sub_scenes =
      a.model == "reference" || a.model == "splat" ? std::vector<golden::Scene>{l.scene}
                                                   : golden::xy_subframes(l.scene);
  std::vector<golden::HostProgram> sub_hosts;
  for (const golden::Scene& s : sub_scenes)
    sub_hosts.push_back(sub_scenes.size() == 1 ? l.host : golden::program_host(s, l.volume, l.meshes));
  auto sub_frame_name = [&](size_t i) {
    if (sub_scenes.size() == 1) return std::string();
    const auto& o = sub_scenes[i].view.ray_offset;
    return "frame " + std::to_string(i + 1) + " of " + std::to_string(sub_scenes.size()) + " (ray offset " +
           std::to_string(o[0]) + ", " + std::to_string(o[1]) + "): ";
  };
  // Each repetition renders the base plane(s) (or the reference image) and
  // warps them: an image as the hardware plus companion card would deliver it.
  std::vector<double> frame_seconds;
  std::optional<golden::BlockRanges> ranges;
  std::optional<golden::PolygonFrame::Counts> polygon_counts;  // the fixed and system models' first frame's
  std::optional<golden::PolygonTraffic> polygon_traffic;       // and what moving its images costs
  std::optional<golden::ConnectionTimes> polygon_connections;  // and Cube-5's two connections' frame times
  for (int rep = 0; rep < a.repeat; ++rep) {
    const bool last = rep + 1 == a.repeat;
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<golden::ImageF> frames;
    std::vector<uint16_t> planes;  // every frame's base plane, in order: the hash
    uint64_t samples = 0;
    auto keep_plane = [&](const golden::BasePlane& bp, size_t i) {
      if (!last) return;
      planes.insert(planes.end(), bp.rgba.begin(), bp.rgba.end());
      if (i == 0 && !a.baseplane.empty()) tb::write_baseplane(baseplane_temp, bp, a.baseplane);
    };
    for (size_t i = 0; i < sub_scenes.size(); ++i) {
      const golden::HostProgram& host = sub_hosts[i];
      if (blocked) {
        const golden::BlockPlan plan = golden::plan_blocks(host.regs, l.volume.dim, counts, what_blocks);
        golden::BasePlane bp;
        if (system) {
          try {
            part = sysc::render_partitioned(plan, l.volume, cfg, net, cb);
          } catch (const std::invalid_argument& e) {
            throw InputError(e.what());
          } catch (const sysc::HostError& e) {
            throw InputError(e.what());
          }
          bp = part->network.plane;
          samples += part->samples;
          bus_seconds += part->bus_seconds;
          if (last && cfg.check && check_failure.empty() && part->mismatch)
            check_failure = sub_frame_name(i) + *part->mismatch;
        } else {
          golden::RenderStats frame_stats;
          golden::FixedOptions opt;
          opt.stats = &frame_stats;
          opt.progress = cb;
          opt.threads = a.threads;
          bp = golden::render_blocks_fixed(l.volume, plan, opt);
          samples += frame_stats.samples;
        }
        frames.push_back(golden::warp(bp.to_float(), bp.shift_x, bp.shift_y, host.view));
        keep_plane(bp, i);
        continue;
      }
      // The polygons are host work of every frame, like its registers.
      std::optional<golden::PolygonFrame> polygons;
      if (!l.meshes.empty() && (system || a.model == "fixed")) {
        // Slab images are laid out for the pipelines that decode them.
        golden::Scene lanes = sub_scenes[i];
        if (system) lanes.pipelines = cfg.p;
        polygons = golden::rasterise_polygons(lanes, l.meshes, host);
        // The host's drawing work, for the polygon source's time (the
        // images cross the host bus as pixels only) and the report.
        cfg.polygon_work = golden::polygon_work(*polygons);
        if (i == 0) {
          polygon_counts = polygons->counts;
          polygon_traffic = golden::polygon_traffic(*polygons, cfg.polygon_work->slabs, lanes.precision);
          polygon_connections = golden::connection_times(
              cfg.polygon_work->slabs, polygon_traffic->slice_cycles, lanes.clock_mhz * 1e6,
              polygons->counts.opaque, polygons->counts.opaque_triangles, lanes.polygon_engine);
        }
      }
      const golden::PolygonFrame* frame_polygons = polygons ? &*polygons : nullptr;
      if (system) {
        try {
          // Mapped: the voxel memory uses the loaded volume in place (same bus time, no copy).
          sys = sysc::render_through_host(host.regs, l.volume, cfg, cb, &bus_seconds, frame_polygons,
                                          sysc::VolumeLoad::Mapped);
        } catch (const std::invalid_argument& e) {
          throw InputError(e.what());
        } catch (const sysc::HostError& e) {  // registers the built hardware cannot take
          throw InputError(e.what());
        }
        const golden::BasePlane& bp = sys->plane;
        samples += sys->samples;
        frames.push_back(golden::warp(bp.to_float(), bp.shift_x, bp.shift_y, host.view));
        keep_plane(bp, i);
        if (last && cfg.check && check_failure.empty()) {
          golden::FixedOptions opt;
          opt.threads = a.threads;
          opt.polygons = frame_polygons;
          const std::string diff = first_pixel_difference(golden::render_fixed(l.volume, host.regs, opt), bp);
          if (!diff.empty() || sys->mismatch) {
            check_failure = sub_frame_name(i) + (diff.empty() ? "base plane equal, but " : diff + "; ");
            check_failure += sys->mismatch ? "first unit output that differs: " + sys->mismatch->describe()
                                           : "every unit stream matched: the compositing unit or pixel memory differs";
          }
        }
      } else if (a.model == "fixed") {
        golden::RenderStats frame_stats;
        golden::FixedOptions opt;
        opt.stats = &frame_stats;
        opt.progress = cb;
        opt.threads = a.threads;
        // Built once: the volume is the same for every repetition and frame.
        if (!ranges) ranges = golden::block_ranges(l.volume);
        opt.ranges = &*ranges;
        opt.polygons = frame_polygons;
        const golden::BasePlane bp = golden::render_fixed(l.volume, host.regs, opt);
        samples += frame_stats.samples;
        frames.push_back(golden::warp(bp.to_float(), bp.shift_x, bp.shift_y, host.view));
        keep_plane(bp, i);
      } else if (a.model == "float") {
        golden::RenderStats frame_stats;
        const golden::BasePlaneF bp =
            golden::render_float(l.volume, sub_scenes[i], host.view, &frame_stats, cb, l.meshes);
        samples += frame_stats.samples;
        frames.push_back(golden::warp(bp.image, bp.shift_x, bp.shift_y, host.view));
        if (last && i == 0 && !a.baseplane.empty()) tb::write_baseplane(baseplane_temp, bp.image, a.baseplane);
      } else if (a.model == "splat") {
        golden::RenderStats frame_stats;
        frames.push_back(golden::render_splat(l.volume, l.scene, l.host.view, a.splat, &frame_stats, cb));
        samples += frame_stats.samples;
      } else {
        golden::ReferenceOptions opt;
        opt.step = a.reference_step;
        opt.meshes = &l.meshes;
        golden::RenderStats frame_stats;
        frames.push_back(golden::render_reference(l.volume, l.scene, l.host.view, opt, &frame_stats, cb));
        samples += frame_stats.samples;
      }
    }
    image = frames.size() == 1 ? std::move(frames.front()) : golden::blend_frames(frames);
    stats.samples = samples;
    frame_seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (last && !planes.empty()) hash = tb::fnv1a64(planes.data(), planes.size() * sizeof(uint16_t));
  }
  std::vector<double> sorted = frame_seconds;
  std::sort(sorted.begin(), sorted.end());
  const double seconds = sorted[sorted.size() / 2];
  tb::write_image(output_temp, image, a.output);
  if (!a.report.empty()) {
    nlohmann::json r = {
        {"model", a.model},
        {"scene", a.scene.empty() ? "(default)" : a.scene},
        {"volume", tb::describe_volume(l.volume)},
        {"view", tb::describe_view(l.scene, l.host)},
        {"pipelines", l.scene.pipelines},
        {"clock_mhz", l.scene.clock_mhz},
        {"supersampling", l.scene.supersampling},
        {"xy_supersampling", l.scene.xy_supersampling},
        {"frames_per_image", sub_scenes.size()},
        {"samples", stats.samples},
        {"wall_seconds", seconds},
        {"frames", a.repeat},
        {"frame_ms", {{"min", sorted.front() * 1e3}, {"median", seconds * 1e3}, {"max", sorted.back() * 1e3}}},
        {"samples_per_second", seconds > 0 ? stats.samples / seconds : 0.0},
        {"effects", effects_json(l.host.effects)},
        {"output", a.output},
    };
    if (a.model == "reference") r["reference_step"] = a.reference_step;
    if (a.model == "splat") {
      const golden::FootprintTables t = golden::footprint_tables(l.host.view, a.splat);
      r["splat"] = {{"kernel", "gaussian"}, {"sigma", a.splat.sigma}, {"distribution_width", a.splat.width},
                    {"extent", t.extent}, {"cell_area_pixels", t.cell_area}};
    }
    if (a.model == "fixed") r["threads"] = a.threads > 0 ? a.threads : golden::default_threads();
    if (polygon_counts)
      r["polygon_fragments"] = {{"opaque", polygon_counts->opaque},      {"translucent", polygon_counts->translucent},
                                {"hidden", polygon_counts->hidden},      {"in_front", polygon_counts->in_front},
                                {"in_slabs", polygon_counts->in_slabs},  {"behind", polygon_counts->behind}};
    if (polygon_traffic)  // Cube-5 §5-6: the run-length connection against plain images (golden/polygons.hpp)
      r["polygon_traffic"] = {{"slabs", polygon_traffic->slabs},
                              {"flits", polygon_traffic->flits},
                              {"rle_bytes", polygon_traffic->rle_bytes},
                              {"raw_bytes", polygon_traffic->raw_bytes},
                              {"image_bytes", polygon_traffic->image_bytes},
                              {"slice_cycles", polygon_traffic->slice_cycles},
                              {"rle_cycles", polygon_traffic->rle_cycles},
                              {"slabs_over_slice", polygon_traffic->slabs_over_slice}};
    if (polygon_connections)  // Cube-5 §§4-6: the frame time through each connection (golden/polygon_connections.hpp)
      r["polygon_connections"] = {{"volume_s", polygon_connections->volume_s},
                                  {"opaque_s", polygon_connections->opaque_s},
                                  {"rle_s", polygon_connections->rle_s},
                                  {"dual_s", polygon_connections->dual_s},
                                  {"rle_slabs_over_slice", polygon_connections->rle_slabs_over_slice}};
    if (header_plan) {
      r["blocks"] = tb::describe_blocks(*header_plan);
    } else if (partitioned(counts)) {
      r["blocks"] = "not applicable: the " + a.model + " model renders in one pass";
    }
    if (part) {
      r["system"] = tb::describe_partitioned(*part, cfg, l.scene.clock_mhz, seconds, check_failure);
      r["system"]["host_bus_ms"] = bus_seconds * 1e3;
      r["system"]["image_fps_steady_state"] =
          r["system"]["fps_steady_state"].get<double>() / static_cast<double>(sub_scenes.size());
    } else if (sys) {
      r["system"] = tb::describe_system(*sys, cfg, l.scene.clock_mhz, seconds, check_failure);
      r["system"]["host_bus_ms"] = bus_seconds * 1e3;
      // The cycle figures are one frame's; an image of x/y supersampling is
      // frames_per_image of them.
      r["system"]["image_fps_steady_state"] =
          r["system"]["fps_steady_state"].get<double>() / static_cast<double>(sub_scenes.size());
    }
    if (!a.baseplane.empty()) r["baseplane"] = a.baseplane;
    if (hash) r["baseplane_hash_fnv1a64"] = tb::hex64(*hash);
    tb::write_json(report_temp, r, a.report);
  }
  // A failed check (exit 3) still delivers its outputs: the image and the
  // report's description of the mismatch are what one debugs it with.
  outputs.commit();
  if (progress.shown() || !a.quiet)
    std::fprintf(stderr, "cube4: %s model, %llu samples in %.3f s -> %s\n", a.model.c_str(),
                 static_cast<unsigned long long>(stats.samples), seconds, a.output.c_str());
  if (!check_failure.empty()) {
    std::fprintf(stderr, "cube4: check FAILED against the golden model: %s\n", check_failure.c_str());
    return 3;
  }
  if (part && !a.quiet) tb::print_partitioned_summary(*part, cfg, l.scene.clock_mhz);
  if (sys && !a.quiet) tb::print_system_summary(*sys, cfg, l.scene.clock_mhz);
  return 0;
}

struct PlanArgs {
  std::string scene, blocks, output = "plan.json";
  uint64_t max_memory_mib = 0;
};

// cube4 plan: the block plan of a scene, for jobs run one block each.
int run_plan(const PlanArgs& a) {
  apply_memory_limit(a.max_memory_mib);
  tb::OutputSet outputs;
  const std::string temp = outputs.add(a.output, "--output");
  if (!a.scene.empty()) outputs.check_not_output(a.scene, "the scene");
  const Loaded l = load(a.scene);
  if (l.scene.xy_supersampling != 1)
    throw InputError((a.scene.empty() ? std::string("the default scene") : a.scene) +
                     ": a plan renders one frame, but the scene asks for xy_supersampling " +
                     std::to_string(l.scene.xy_supersampling));
  RenderArgs ra;
  ra.blocks = a.blocks;
  const std::array<int, 3> counts = block_counts(ra, l.scene);
  const golden::BlockPlan plan = golden::plan_blocks(l.host.regs, l.volume.dim, counts, blocks_what(ra, l.scene));
  const std::string scene = a.scene.empty() ? "" : std::filesystem::absolute(a.scene).string();
  tb::write_json(temp, tb::plan_json(plan, scene, tb::plan_id(plan, l.volume)), a.output);
  outputs.commit();
  std::printf("%zu\n", plan.blocks.size());  // the job count, for scripts
  return 0;
}

struct ComposeArgs {
  std::string plan;
  std::vector<std::string> partials;
  std::string output = "cube4.png", baseplane, report, model = "tlm";
  int check = -1;  // -1: on at RTL
  bool quiet = false;
  bool no_assert = false;
  std::optional<uint32_t> seed;
  uint64_t max_memory_mib = 0;
};

// cube4 compose: the partial images of a plan through the composition
// network, then the warp: the image `cube4 render --blocks` makes.
int run_compose(const ComposeArgs& a) {
  apply_memory_limit(a.max_memory_mib);
  if (a.model != "tlm" && a.model != "rtl")
    throw InputError("--model " + a.model + ": the composition network runs at tlm or rtl");
  tb::OutputSet outputs;
  const std::string output_temp = outputs.add(a.output, "--output");
  const std::string baseplane_temp = a.baseplane.empty() ? "" : outputs.add(a.baseplane, "--baseplane");
  const std::string report_temp = a.report.empty() ? "" : outputs.add(a.report, "--report");
  const tb::PlanFile pf = tb::read_plan(a.plan);
  for (const std::string& f : a.partials) outputs.check_not_output(f, "a partial image");
  const Loaded l = load(pf.scene);
  RenderArgs ra;
  ra.blocks = std::to_string(pf.counts[0]) + "x" + std::to_string(pf.counts[1]) + "x" + std::to_string(pf.counts[2]);
  const golden::BlockPlan plan = golden::plan_blocks(l.host.regs, l.volume.dim, pf.counts, pf.path + ": counts");
  const std::string id = tb::plan_id(plan, l.volume);
  if (id != pf.id)
    throw InputError(pf.path + ": plan_id " + pf.id + ", but its scene and volume give " + id +
                     " now: the scene, the volume or cube4 changed since the plan was made; make the plan again");
  const std::vector<tb::Partial> parts = tb::order_partials(plan, id, a.partials);
  std::vector<const golden::BasePlane*> ptrs;
  for (const tb::Partial& p : parts) ptrs.push_back(&p.plane);
  sysc::NetworkConfig net;
  net.level = a.model == "rtl" ? sysc::Level::Rtl : sysc::Level::Tlm;
  net.cycle_level = net.level == sysc::Level::Rtl;
  net.check = a.check < 0 ? net.level == sysc::Level::Rtl : a.check == 1;
  net.assertions = !a.no_assert;
  RenderArgs seeded;
  seeded.seed = a.seed;
  net.seed = rtl_seed(seeded);
  tb::ProgressPrinter progress("compose " + a.model, !a.quiet);
  sysc::NetworkResult res;
  try {
    res = sysc::run_network(plan, ptrs, net, [&](double f) { progress(f); });
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  const golden::BasePlane& bp = res.plane;
  tb::write_image(output_temp, golden::warp(bp.to_float(), bp.shift_x, bp.shift_y, l.host.view), a.output);
  if (!a.baseplane.empty()) tb::write_baseplane(baseplane_temp, bp, a.baseplane);
  const uint64_t hash = tb::fnv1a64(bp.rgba.data(), bp.rgba.size() * sizeof(uint16_t));
  if (!a.report.empty()) {
    const double hz = l.scene.clock_mhz * 1e6;
    nlohmann::json r = {{"model", a.model},
                        {"plan", a.plan},
                        {"plan_id", id},
                        {"scene", pf.scene.empty() ? "(default)" : pf.scene},
                        {"blocks", tb::describe_blocks(plan)},
                        {"network",
                         {{"level", sysc::level_name(res.level)},
                          {"nodes", res.nodes},
                          {"depth", res.depth},
                          {"cycles", res.cycles},
                          {"cycles_steady_state_interval", res.stream_cycles},
                          {"images_per_second_steady_state", hz / static_cast<double>(res.stream_cycles)},
                          {"wall_seconds", res.wall_seconds},
                          {"seed", net.seed},
                          {"check", net.check ? (res.mismatch ? *res.mismatch : std::string("passed: bit-exact"))
                                              : std::string("off")}}},
                        {"output", a.output},
                        {"baseplane_hash_fnv1a64", tb::hex64(hash)}};
    if (!a.baseplane.empty()) r["baseplane"] = a.baseplane;
    tb::write_json(report_temp, r, a.report);
  }
  outputs.commit();
  if (!a.quiet)
    std::fprintf(stderr, "cube4: %zu partial images through %d nodes (depth %d, %s) in %llu cycles -> %s\n",
                 parts.size(), res.nodes, res.depth, sysc::level_name(res.level),
                 static_cast<unsigned long long>(res.cycles), a.output.c_str());
  if (res.mismatch) {
    std::fprintf(stderr, "cube4: check FAILED against the golden model: %s\n", res.mismatch->c_str());
    return 3;
  }
  return 0;
}

int run_info(const std::string& scene, uint64_t max_memory_mib) {
  apply_memory_limit(max_memory_mib);
  const Loaded l = load(scene);
  nlohmann::json j = {
      {"scene", scene.empty() ? "(default)" : scene},
      {"volume", tb::describe_volume(l.volume)},
      {"view", tb::describe_view(l.scene, l.host)},
      {"effects", effects_json(l.host.effects)},
      {"registers", tb::describe_registers(l.host.regs)},
      {"pipelines", l.scene.pipelines},
      {"clock_mhz", l.scene.clock_mhz},
      {"polygons", nlohmann::json::array()},
  };
  // The meshes as loaded and checked: what a user wants to see before
  // trusting a mesh file's units and transform.
  for (const golden::Mesh& m : l.meshes) {
    const auto box = golden::bounds(m);
    j["polygons"].push_back({{"source", m.source},
                             {"triangles", m.triangles.size()},
                             {"vertices", m.vertices.size()},
                             {"dropped_degenerate", m.dropped_degenerate},
                             {"closed", golden::is_closed(m)},
                             {"bounds", {box[0], box[1]}},
                             {"color", m.color},
                             {"opacity", m.opacity},
                             {"lit", m.lit}});
  }
  std::cout << j.dump(2) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  cube4::keep_frame_buffers_in_heap();
  CLI::App app{"cube4: cycle-level model of the Cube-4 / VolumePro volume rendering architecture"};
  app.require_subcommand(1);
  RenderArgs ra;
  CLI::App* render = app.add_subcommand("render", "render a scene (default: shaded composite of brainsmall)");
  render->add_option("scene", ra.scene, "scene JSON file (docs/scene.md)");
  render->add_option("--model", ra.model,
                     "fixed (bit-exact golden), float, reference (image-order), splat (bela's energy projection), "
                     "or the system model: tlm, rtl, "
                     "mixed:UNIT,... (units interp, gradient, shade, composite, addr at RTL, the rest TLM)")
      ;
  render->add_option("-o,--output", ra.output, "final image, .png or .exr")->capture_default_str();
  render->add_option("--baseplane", ra.baseplane, "also write the base-plane image (.png: 16-bit, bit-exact; with xy_supersampling, the first frame's)");
  render->add_option("--report", ra.report, "write a JSON report");
  render->add_option("--reference-step", ra.reference_step, "reference model: ray step in voxels")->capture_default_str();
  render->add_option_function<std::vector<double>>(
            "--splat-kernel", [&ra](const std::vector<double>& v) { ra.splat = {v[0], v[1]}; },
            "splat model: SIGMA WIDTH of the Gaussian kernel in voxel spacings (default 0.5 1.25)")
      ->expected(2);
  render->add_option("--repeat", ra.repeat, "render N times (benchmarking): the report gives min and median")
      ->check(CLI::Range(1, 100000));
  render->add_flag("-q,--quiet", ra.quiet, "no progress or summary on stderr");
  render->add_option("--pipes", ra.pipes, "system model: pipelines p (default: the scene's)")
      ->check(CLI::Range(1, 256));
  render->add_flag_callback("--check", [&ra] { ra.check = 1; },
                            "system model: compare the base plane and every unit's stream with golden, bit-exact "
                            "(default: on when a unit runs at RTL; exit 3 on a mismatch)");
  render->add_flag_callback("--no-check", [&ra] { ra.check = 0; }, "system model: no comparison with golden");
  render->add_option("--frames", ra.frames,
                     "system model: stream N frames of the view back to back and measure the steady-state interval")
      ->check(CLI::Range(1, 1000));
  render->add_flag("--simulate-all", ra.simulate_all,
                   "system model: simulate every unit and all RTL hardware, needed or not (to measure what skipping saves)");
  render->add_option("--trace", ra.trace, "system model: FST waveforms of the RTL units (FILE.fst -> FILE.UNIT.fst)");
  render->add_option("--trace-window", ra.trace_window, "FIRST LAST: trace only these cycles")->expected(2);
  render->add_option("--threads", ra.threads,
                     "fixed model and --check: threads, each rendering a band of rays; clocked system models: 1 "
                     "runs the units on one thread, more on two (the shading and compositing units on a thread "
                     "of their own; default: two when one of them is at RTL) (default 0: one per core; the "
                     "image and cycles are the same for any number)")
      ->check(CLI::Range(0, 1024));
  render->add_option("--blocks", ra.blocks,
                     "AxBxC: render the volume as blocks along x, y, z, each by a machine of its own, merged by the "
                     "composition network (fixed and system models; default: the scene's \"blocks\", 1x1x1)");
  render->add_option("--plan", ra.plan, "with --block and --partial: render one block of a plan (cube4 plan)");
  render->add_option("--block", ra.block, "the plan's block to render (0 .. blocks-1)")->check(CLI::Range(0, golden::kMaxBlocks - 1));
  render->add_option("--partial", ra.partial, "the block's partial image file (.cpart) for cube4 compose");
  render->add_flag("--no-assert", ra.no_assert,
                   "system model: do not evaluate the RTL units' assertions (by default a failed one stops the run, exit 4)");
  render->add_option("--seed", ra.seed, "system model: Verilator random-reset seed of the RTL units (default: CUBE4_SEED, else 1)");
  const std::string memory_help = "refuse volumes and renders estimated to need more than MiB of memory (default " +
                                  std::to_string(golden::kDefaultMemoryLimit >> 20) + ")";
  render->add_option("--max-memory", ra.max_memory_mib, memory_help)->check(CLI::Range(uint64_t{1}, uint64_t{1} << 30));
  std::string info_scene;
  uint64_t info_max_memory = 0;
  CLI::App* info = app.add_subcommand("info", "print the view factorisation, register summary and effect set");
  info->add_option("scene", info_scene, "scene JSON file (default: the default scene)");
  info->add_option("--max-memory", info_max_memory, memory_help)->check(CLI::Range(uint64_t{1}, uint64_t{1} << 30));
  PlanArgs pa;
  CLI::App* plan = app.add_subcommand("plan", "cut a scene's volume into blocks for jobs of one block each: a plan file");
  plan->add_option("scene", pa.scene, "scene JSON file (default: the default scene)");
  plan->add_option("--blocks", pa.blocks, "AxBxC: blocks along x, y, z (default: the scene's \"blocks\")");
  plan->add_option("-o,--output", pa.output, "the plan file")->capture_default_str();
  plan->add_option("--max-memory", pa.max_memory_mib, memory_help)->check(CLI::Range(uint64_t{1}, uint64_t{1} << 30));
  ComposeArgs ca;
  CLI::App* compose = app.add_subcommand(
      "compose", "merge a plan's partial images through the composition network into the image");
  compose->add_option("plan", ca.plan, "the plan file (cube4 plan)")->required();
  compose->add_option("partials", ca.partials, "every block's partial image (cube4 render --plan --block --partial)")
      ->required();
  compose->add_option("-o,--output", ca.output, "final image, .png or .exr")->capture_default_str();
  compose->add_option("--baseplane", ca.baseplane, "also write the composed base plane (.png: 16-bit)");
  compose->add_option("--report", ca.report, "write a JSON report");
  compose->add_option("--model", ca.model, "the network's level: tlm (loosely timed) or rtl (verilated nodes)")
      ->capture_default_str();
  compose->add_flag_callback("--check", [&ca] { ca.check = 1; }, "compare with golden (default: on at rtl; exit 3)");
  compose->add_flag_callback("--no-check", [&ca] { ca.check = 0; }, "no comparison with golden");
  compose->add_option("--seed", ca.seed, "Verilator random-reset seed (default: CUBE4_SEED, else 1)");
  compose->add_flag("--no-assert", ca.no_assert, "rtl: do not evaluate the nodes' assertions (a failed one: exit 4)");
  compose->add_flag("-q,--quiet", ca.quiet, "no progress or summary on stderr");
  compose->add_option("--max-memory", ca.max_memory_mib, memory_help)->check(CLI::Range(uint64_t{1}, uint64_t{1} << 30));
  tb::RegressArgs rg;
  CLI::App* regress = app.add_subcommand(
      "regress", "render scenes at several model levels with --check, in parallel; JUnit XML and a summary");
  regress->add_option("scenes", rg.inputs, "scene files, folders of *.json scenes, or lists of scenes (.txt)")->required();
  regress->add_option("--levels", rg.levels, "model levels (fixed, float, tlm, rtl, mixed:UNIT,...)")
      ->delimiter(' ')->capture_default_str();
  regress->add_option("-j,--jobs", rg.jobs, "parallel renders (default: one per core)")->check(CLI::Range(1, 256));
  regress->add_option("--pipes", rg.pipes, "system levels: pipelines p (default: each scene's)")->check(CLI::Range(1, 256));
  regress->add_option("--junit", rg.junit, "JUnit XML output (each case's files in <name>.cases/ beside it)")
      ->capture_default_str();
  regress->add_option("--summary", rg.summary, "Markdown summary output");
  regress->add_flag("-q,--quiet", rg.quiet, "no progress on stderr");
  tb::ExploreArgs ea;
  CLI::App* explore = app.add_subcommand(
      "explore", "sweep widths, p, S, clock and scenes: error, cycles, gates and simulation time per point, the "
                 "Pareto fronts and plots (docs/explore.md)");
  explore->add_option("sweep", ea.sweep, "sweep file (JSON, docs/explore.md)")->required();
  explore->add_option("--out", ea.out, "results folder (default: the sweep's name + .explore, here)");
  explore->add_option("-j,--jobs", ea.jobs, "GNU parallel's jobs at a time (default: one per core)")
      ->check(CLI::Range(1, 256));
  explore->add_flag("--emit-jobs", ea.emit_jobs, "write the job list (jobs.txt, one cube4 command per point) and stop");
  explore->add_flag("--collect", ea.collect, "collect the results there are into the table, fronts and plots");
  explore->add_option("--point", ea.point, "run one point (what each job does)")->check(CLI::Range(0, 9999));
  explore->add_flag_callback("--no-plots", [&ea] { ea.plots = false; }, "no plots (they need python3-matplotlib)");
  explore->add_flag("--no-gates", ea.no_gates, "no gate counts (yosys), whatever the sweep says");
  explore->add_option("--gates-cache", ea.gates_cache,
                      "folder of yosys results per width configuration (default: ~/.cache/cube4/gates)");
  explore->add_flag("-q,--quiet", ea.quiet, "no progress on stderr");
  const std::string cmd = argc > 1 ? argv[1] : "";
  if (argc > 1 && argv[1][0] != '-' && cmd != "render" && cmd != "info" && cmd != "regress" && cmd != "plan" &&
      cmd != "compose" && cmd != "explore") {
    std::fprintf(stderr,
                 "cube4: error: unknown command '%s' (commands: render, info, regress, plan, compose, explore; see --help)\n",
                 argv[1]);
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    if (*render) return run_render(ra);
    if (*regress) return tb::run_regress(rg, std::filesystem::canonical("/proc/self/exe").string());
    if (*plan) return run_plan(pa);
    if (*compose) return run_compose(ca);
    if (*explore) return tb::run_explore(ea, std::filesystem::canonical("/proc/self/exe").string());
    return run_info(info_scene, info_max_memory);
  } catch (const InputError& e) {
    std::fprintf(stderr, "cube4: error: %s\n", e.what());
    return 2;
  } catch (const sysc::RtlAssertionError& e) {
    std::fprintf(stderr, "cube4: RTL assertion failed: %s\n", e.what());
    return sysc::kExitRtlAssertion;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cube4: internal error: %s\n", e.what());
    return 1;
  }
}
