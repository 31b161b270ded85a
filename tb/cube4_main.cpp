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

#include "golden/errors.hpp"
#include "golden/host_driver.hpp"
#include "golden/input_file.hpp"
#include "golden/mesh.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "tb/image_io.hpp"
#include "tb/output_files.hpp"
#include "tb/progress.hpp"
#include "tb/regress.hpp"
#include "tb/report.hpp"
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
};

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
    bool found = false;
    for (int u = 0; u < sysc::kUnits; ++u)
      if (name == sysc::unit_name(static_cast<sysc::Unit>(u))) {
        l[static_cast<size_t>(u)] = sysc::Level::Rtl;
        found = true;
      }
    if (!found)
      throw InputError("--model " + model + ": unknown unit '" + name + "' (units: interp, gradient, shade, composite, addr)");
    ++count;
  }
  if (count == 0) throw InputError("--model " + model + ": name at least one unit after 'mixed:'");
  return l;
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
  std::vector<golden::Mesh> meshes;  // the scene's "polygons", checked; not rendered yet
};

// Relative paths in a scene are relative to its folder.
std::string scene_dir(const std::string& scene_path) {
  const std::string dir = scene_path.empty() ? "." : std::filesystem::path(scene_path).parent_path().string();
  return dir.empty() ? "." : dir;
}

void load_volume(Loaded& l, const std::string& scene_path, bool header_only) {
  l.volume = golden::load_volume(l.scene.volume, l.scene.precision.voxel_bits, scene_dir(scene_path), header_only);
  l.host = golden::program_host(l.scene, l.volume);
}

// With `header_only` the volume has no voxels yet: what every limit of a run
// depends on (dimensions, spacing, so the view and the registers) comes
// from the scene and the volume's header, so a run the limits refuse costs
// no load.
Loaded load(const std::string& scene_path, bool header_only = false) {
  Loaded l;
  l.scene = scene_path.empty() ? golden::default_scene() : golden::load_scene(scene_path);
  load_volume(l, scene_path, header_only);
  // A bad mesh is bad input (exit 2) even while the renderers ignore meshes.
  l.meshes = golden::load_meshes(l.scene, scene_dir(scene_path));
  return l;
}


nlohmann::json effects_json(const golden::EffectSet& e) { return e.names(); }

// What a render holds besides the loaded volume, estimated before it starts
// so that an 8192x8192 image or a large volume through the system model is
// refused by name instead of ending in bad_alloc.
void check_render_memory(const Loaded& l, const std::string& model, int golden_threads) {
  const double voxels = static_cast<double>(l.volume.size());
  const double base = static_cast<double>(l.host.regs.base_width()) * l.host.regs.base_height();
  const double slice = static_cast<double>(l.host.regs.dim[0]) * l.host.regs.dim[1];
  const double image = static_cast<double>(l.scene.width) * l.scene.height;
  // The volume (2 bytes a voxel), the base plane (fixed and float: 16 bytes
  // a pixel at most), the final image (float RGBA, and 8-bit for PNG); the
  // system model keeps its own copy of the volume in voxel memory, and the
  // check's golden render another base plane. The fixed renderer's ray
  // store holds a ray per base-plane pixel, and each of its threads eight
  // slices of 4-byte samples and voxels.
  const bool system = is_system_model(model);
  const bool fixed = model == "fixed" || system;
  const double bytes = voxels * 2 * (system ? 2 : 1) + base * 16 * (system ? 2 : 1) + image * 20 +
                       (fixed ? base * sizeof(golden::RayAcc) * (system ? 2 : 1) + golden_threads * 8 * 4 * slice : 0);
  golden::check_memory(l.scene.file.empty() ? std::string("the default scene") : l.scene.file,
                       "the " + model + " render", bytes,
                       golden::dims_text(l.volume.dim[0], l.volume.dim[1], l.volume.dim[2]) + " voxels, " +
                           std::to_string(l.scene.width) + "x" + std::to_string(l.scene.height) + " image");
}

// The built system's limits, from the registers of the volume's header
// (before any voxel is loaded): the host interface's volume window, then
// what sysc::check_system_limits() holds.
void check_system_limits(const Loaded& l, const sysc::SystemConfig& cfg) {
  for (int i = 0; i < 3; ++i)
    if (l.volume.dim[i] > sysc::regmap::kMaxDimLimit)
      throw InputError(l.volume.source + ": volume " +
                       golden::dims_text(l.volume.dim[0], l.volume.dim[1], l.volume.dim[2]) +
                       " has more than the host interface's " + std::to_string(sysc::regmap::kMaxDimLimit) +
                       " voxels per axis (its volume window, docs/registers.md); render it with --model fixed");
  try {
    sysc::check_system_limits(l.host.regs, cfg);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

// The FST files the RTL units write (systemc/rtl/: one per unit, the
// shading unit's from pipeline 0).
const std::vector<std::string> kTraceUnits = {"addr", "interp", "gradient", "shade0", "composite"};

void apply_memory_limit(uint64_t mib) {
  if (mib > 0) golden::set_memory_limit(mib << 20);
}

int run_render(const RenderArgs& a) {
  apply_memory_limit(a.max_memory_mib);
  // Outputs are checked before the (possibly long) render, so a typo costs nothing.
  for (const std::string* p : {&a.output, &a.baseplane}) {
    if (p->empty()) continue;
    const std::string ext = std::filesystem::path(*p).extension().string();
    if (ext != ".png" && ext != ".exr" && ext != ".PNG" && ext != ".EXR")
      throw InputError("output file '" + *p + "': unsupported extension '" + ext + "' (use .png or .exr)");
  }
  if (a.model == "reference" && !a.baseplane.empty())
    throw InputError("--baseplane: the reference model casts rays from image pixels and has no base plane");
  if (!(a.reference_step > 0 && a.reference_step <= 4))
    throw InputError("--reference-step " + std::to_string(a.reference_step) + " is out of range (0, 4]");
  const bool system = is_system_model(a.model);
  if (!system && a.model != "fixed" && a.model != "float" && a.model != "reference")
    throw InputError("--model " + a.model + ": unknown model (fixed, float, reference, tlm, rtl, mixed:UNIT,...)");
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
  const std::string output_temp = outputs.add(a.output, "--output");
  const std::string baseplane_temp = a.baseplane.empty() ? "" : outputs.add(a.baseplane, "--baseplane");
  const std::string report_temp = a.report.empty() ? "" : outputs.add(a.report, "--report");
  const std::string trace_temp = a.trace.empty() ? "" : outputs.add_trace(a.trace, kTraceUnits);
  if (!a.scene.empty()) outputs.check_not_output(a.scene, "the scene");
  Loaded l = load(a.scene, true);
  if (l.scene.volume.kind == "den" || l.scene.volume.kind == "raw" || l.scene.volume.kind == "nifti")
    outputs.check_not_output(l.volume.source, "the volume");
  const int golden_threads = a.threads > 0 ? a.threads : golden::default_threads();
  check_render_memory(l, a.model, golden_threads);
  sysc::SystemConfig cfg;
  std::optional<sysc::SystemResult> sys;
  double bus_seconds = 0;  // host-bus time of programming the frame and reading it back
  std::string check_failure;
  if (system) {
    cfg.p = a.pipes > 0 ? a.pipes : l.scene.pipelines;
    cfg.levels = parse_levels(a.model);
    cfg.check = a.check < 0 ? !cfg.all_tlm() : a.check == 1;
    cfg.simulate_unneeded = a.simulate_all;
    cfg.frames = a.frames;
    cfg.seed = rtl_seed(a);
    cfg.assertions = !a.no_assert;
    if (a.frames > 1 && cfg.all_tlm())
      throw InputError("--frames: the tlm model has no clock to stream frames on (its interval is the cycle model's)");
    if (!a.trace.empty()) {
      cfg.trace.file = trace_temp;
      if (a.trace_window.size() == 2) {
        cfg.trace.first = static_cast<uint64_t>(a.trace_window[0]);
        cfg.trace.last = static_cast<uint64_t>(a.trace_window[1]);
      }
    }
    check_system_limits(l, cfg);
  }
  load_volume(l, a.scene, false);
  tb::ProgressPrinter progress("render " + a.model, !a.quiet);
  auto cb = [&](double f) { progress(f); };
  golden::RenderStats stats;
  golden::ImageF image;
  std::optional<uint64_t> hash;
  // x/y supersampling (VolumePro §4.1): n² frames whose rays start 1/n of a
  // pixel apart, each warped, then blended on the host; for n = 1 the one
  // frame of the scene. The reference ray caster casts a ray per output
  // pixel already and renders once.
  const std::vector<golden::Scene> sub_scenes =
      a.model == "reference" ? std::vector<golden::Scene>{l.scene} : golden::xy_subframes(l.scene);
  std::vector<golden::HostProgram> sub_hosts;
  for (const golden::Scene& s : sub_scenes)
    sub_hosts.push_back(sub_scenes.size() == 1 ? l.host : golden::program_host(s, l.volume));
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
      if (system) {
        try {
          sys = sysc::render_through_host(host.regs, l.volume, cfg, cb, &bus_seconds);
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
        const golden::BasePlane bp = golden::render_fixed(l.volume, host.regs, opt);
        samples += frame_stats.samples;
        frames.push_back(golden::warp(bp.to_float(), bp.shift_x, bp.shift_y, host.view));
        keep_plane(bp, i);
      } else if (a.model == "float") {
        golden::RenderStats frame_stats;
        const golden::BasePlaneF bp = golden::render_float(l.volume, sub_scenes[i], host.view, &frame_stats, cb);
        samples += frame_stats.samples;
        frames.push_back(golden::warp(bp.image, bp.shift_x, bp.shift_y, host.view));
        if (last && i == 0 && !a.baseplane.empty()) tb::write_baseplane(baseplane_temp, bp.image, a.baseplane);
      } else {
        golden::ReferenceOptions opt;
        opt.step = a.reference_step;
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
    if (a.model == "fixed") r["threads"] = a.threads > 0 ? a.threads : golden::default_threads();
    if (sys) {
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
  if (sys && !a.quiet) tb::print_system_summary(*sys, cfg, l.scene.clock_mhz);
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
  // The meshes as loaded and checked (not rendered yet): what a user wants
  // to see before trusting a mesh file's units and transform.
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
  CLI::App app{"cube4: cycle-level model of the Cube-4 / VolumePro volume rendering architecture"};
  app.require_subcommand(1);
  RenderArgs ra;
  CLI::App* render = app.add_subcommand("render", "render a scene (default: shaded composite of brainsmall)");
  render->add_option("scene", ra.scene, "scene JSON file (docs/scene.md)");
  render->add_option("--model", ra.model,
                     "fixed (bit-exact golden), float, reference (image-order), or the system model: tlm, rtl, "
                     "mixed:UNIT,... (units interp, gradient, shade, composite, addr at RTL, the rest TLM)")
      ;
  render->add_option("-o,--output", ra.output, "final image, .png or .exr")->capture_default_str();
  render->add_option("--baseplane", ra.baseplane, "also write the base-plane image (.png: 16-bit, bit-exact; with xy_supersampling, the first frame's)");
  render->add_option("--report", ra.report, "write a JSON report");
  render->add_option("--reference-step", ra.reference_step, "reference model: ray step in voxels")->capture_default_str();
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
                     "fixed model and --check: threads, each rendering a band of rays (default 0: one per core; "
                     "the image is the same for any number)")
      ->check(CLI::Range(0, 1024));
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
  const std::string cmd = argc > 1 ? argv[1] : "";
  if (argc > 1 && argv[1][0] != '-' && cmd != "render" && cmd != "info" && cmd != "regress") {
    std::fprintf(stderr, "cube4: error: unknown command '%s' (commands: render, info, regress; see --help)\n", argv[1]);
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
