// Times the golden renderers on one core, frame by frame (base plane plus
// warp, as a frame would be delivered), without the image-I/O libraries so
// that start-up does not blur the numbers. Prints one JSON object.
//   bench_golden [SCENE] [--model fixed|float|reference] [--frames N] [--warmup K]
//                [--supersampling S] [--reference-step H] [--threads N] [--no-skip]
//                [--ranges frame|volume]
// --threads: the fixed renderer's threads (default 1; 0: one per core).
// --ranges: where the fixed renderer's block ranges (empty-space skipping)
// are built: `frame` (default) inside every timed frame, as a renderer that
// cannot know the volume did not change would have to; `volume` once, after
// loading, outside the timing (FixedOptions::ranges), as VolPack's normals
// and VTK's gradients and min-max blocks are built once per volume.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "golden/errors.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "tb/heap_tuning.hpp"

using namespace cube4::golden;

int main(int argc, char** argv) {
  cube4::keep_frame_buffers_in_heap();  // as cube4 runs frames
  std::string scene_path, model = "fixed";
  int frames = 20, warmup = 3, supersampling = 0, threads = 1;
  bool skip = true;
  std::string ranges_at = "frame";
  double step = 0.25;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) { std::fprintf(stderr, "bench_golden: %s needs a value\n", a.c_str()); std::exit(2); }
      return argv[++i];
    };
    if (a == "--model") model = value();
    else if (a == "--frames") frames = std::atoi(value().c_str());
    else if (a == "--warmup") warmup = std::atoi(value().c_str());
    else if (a == "--supersampling") supersampling = std::atoi(value().c_str());
    else if (a == "--reference-step") step = std::atof(value().c_str());
    else if (a == "--threads") threads = std::atoi(value().c_str());
    else if (a == "--no-skip") skip = false;
    else if (a == "--ranges") ranges_at = value();
    else if (!a.empty() && a[0] != '-') scene_path = a;
    else { std::fprintf(stderr, "bench_golden: unknown option %s\n", a.c_str()); return 2; }
  }
  if (model != "fixed" && model != "float" && model != "reference") {
    std::fprintf(stderr, "bench_golden: --model %s: use fixed, float or reference\n", model.c_str());
    return 2;
  }
  if (ranges_at != "frame" && ranges_at != "volume") {
    std::fprintf(stderr, "bench_golden: --ranges %s: use frame or volume\n", ranges_at.c_str());
    return 2;
  }
  try {
    Scene s = scene_path.empty() ? default_scene() : load_scene(scene_path);
    if (supersampling > 0) s.supersampling = supersampling;
    finish_scene(s);
    const std::string dir = scene_path.empty() ? "." : std::filesystem::path(scene_path).parent_path().string();
    const auto load0 = std::chrono::steady_clock::now();
    const Volume vol = load_volume(s.volume, s.precision.voxel_bits, dir.empty() ? "." : dir);
    const double load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - load0).count();
    const HostProgram h = program_host(s, vol);
    BlockRanges volume_ranges;
    double ranges_ms = 0;
    if (model == "fixed" && skip && ranges_at == "volume") {
      const auto r0 = std::chrono::steady_clock::now();
      volume_ranges = block_ranges(vol);
      ranges_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - r0).count();
    }
    std::vector<double> ms;
    RenderStats stats;
    volatile float sink = 0;
    for (int f = 0; f < warmup + frames; ++f) {
      const auto t0 = std::chrono::steady_clock::now();
      ImageF img;
      if (model == "fixed") {
        FixedOptions opt;
        opt.stats = &stats;
        opt.threads = threads;
        opt.skip_empty = skip;
        if (ranges_at == "volume") opt.ranges = &volume_ranges;
        const BasePlane bp = render_fixed(vol, h.regs, opt);
        img = warp(bp.to_float(), bp.shift_x, bp.shift_y, h.view);
      } else if (model == "float") {
        const BasePlaneF bp = render_float(vol, s, h.view, &stats);
        img = warp(bp.image, bp.shift_x, bp.shift_y, h.view);
      } else {
        ReferenceOptions opt;
        opt.step = step;
        img = render_reference(vol, s, h.view, opt, &stats);
      }
      sink = sink + img.rgba[img.rgba.size() / 2];
      const double t = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      if (f >= warmup) ms.push_back(t);
    }
    std::sort(ms.begin(), ms.end());
    const double median = ms[ms.size() / 2];
    nlohmann::json j = {
        {"model", model},
        {"scene", scene_path.empty() ? "(default)" : scene_path},
        {"volume", vol.source},
        {"dim", vol.dim},
        {"volume_load_ms", load_ms},
        {"image", {s.width, s.height}},
        {"supersampling", s.supersampling},
        {"frames", frames},
        {"samples_per_frame", stats.samples},
        {"ms", {{"median", median}, {"min", ms.front()}, {"max", ms.back()}}},
        {"samples_per_second", stats.samples / (median * 1e-3)},
    };
    if (model == "reference") j["reference_step"] = step;
    if (model == "fixed") {
      j["threads"] = threads > 0 ? threads : default_threads();
      j["skip_empty"] = skip;
      j["ranges"] = ranges_at;
      if (ranges_at == "volume") j["block_ranges_ms"] = ranges_ms;
      j["shaded_per_frame"] = stats.shaded;
    }
    std::printf("%s\n", j.dump().c_str());
  } catch (const InputError& e) {
    std::fprintf(stderr, "bench_golden: %s\n", e.what());
    return 2;
  }
  return 0;
}
