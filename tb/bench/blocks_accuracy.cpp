// What cutting a volume into blocks costs in accuracy and what it buys in
// cycles (golden/blocks.hpp): for a scene and a list of block counts, the
// partitioned fixed-point base plane against the one-pass base plane (in
// base-plane LSBs: the merges' rounding), both final images against the
// floating-point renderer's (the same algorithm in real arithmetic, one
// pass), and the modelled cycles: the slowest machine's frame (the cycle
// model, equal to the RTL's) plus the composition network's.
//
//   build/tb/bench/blocks_accuracy [--volumepro] SCENE AxBxC [AxBxC ...]
// --volumepro: at VolumePro's compositor widths (12-bit α, no guard bits:
// golden::volumepro_precision()), where each merge rounds at the pixel's
// own LSB.
// Prints one Markdown table row per count (scripts/accuracy_blocks.sh
// writes them into docs/accuracy.md). Deterministic.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "golden/blocks.hpp"
#include "golden/errors.hpp"
#include "golden/host_driver.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "systemc/core/compose_network.hpp"
#include "systemc/core/system.hpp"

namespace g = cube4::golden;
namespace sysc = cube4::sysc;

namespace {

struct Errors {
  double psnr = 0, mean = 0, max = 0;
};

// All four channels of two images (premultiplied, [0, 1]), as idiff -a.
Errors compare(const g::ImageF& a, const g::ImageF& b) {
  double sum = 0, sq = 0, worst = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) {
    const double d = std::fabs(static_cast<double>(a.rgba[i]) - b.rgba[i]);
    sum += d;
    sq += d * d;
    worst = std::max(worst, d);
  }
  const double n = static_cast<double>(a.rgba.size());
  return {sq > 0 ? 10 * std::log10(n / sq) : INFINITY, sum / n, worst};
}

std::array<int, 3> parse_counts(const char* s) {
  std::array<int, 3> c{};
  if (std::sscanf(s, "%dx%dx%d", &c[0], &c[1], &c[2]) != 3) throw g::InputError(std::string("bad counts ") + s);
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  const bool volumepro = argc > 1 && std::string(argv[1]) == "--volumepro";
  if (volumepro) {
    --argc;
    ++argv;
  }
  if (argc < 3) {
    std::fprintf(stderr, "usage: blocks_accuracy [--volumepro] SCENE AxBxC [AxBxC ...]\n");
    return 2;
  }
  try {
    g::Scene scene = g::load_scene(argv[1]);
    if (volumepro) {
      scene.precision = g::volumepro_precision();
      g::finish_scene(scene);
    }
    std::string dir = argv[1];
    dir = dir.find('/') == std::string::npos ? "." : dir.substr(0, dir.rfind('/'));
    const g::Volume vol = g::load_volume(scene.volume, scene.precision.voxel_bits, dir);
    const g::HostProgram host = g::program_host(scene, vol);
    const g::BasePlane one = g::render_fixed(vol, host.regs);
    const g::BasePlaneF fl = g::render_float(vol, scene, host.view);
    const g::ImageF float_image = g::warp(fl.image, fl.shift_x, fl.shift_y, host.view);
    const Errors one_vs_float = compare(g::warp(one.to_float(), one.shift_x, one.shift_y, host.view), float_image);
    const sysc::CycleCount one_cycles = sysc::frame_cycles(host.regs, scene.pipelines);
    for (int i = 2; i < argc; ++i) {
      const std::array<int, 3> counts = parse_counts(argv[i]);
      const g::BlockPlan plan = g::plan_blocks(host.regs, vol.dim, counts, argv[i]);
      const g::BasePlane bp = g::render_blocks_fixed(vol, plan, g::FixedOptions{});
      int worst = 0;
      double sum = 0;
      size_t differ = 0;
      for (size_t k = 0; k < bp.rgba.size(); ++k) {
        const int d = std::abs(int{bp.rgba[k]} - int{one.rgba[k]});
        worst = std::max(worst, d);
        sum += d;
        differ += d != 0;
      }
      const Errors e = compare(g::warp(bp.to_float(), bp.shift_x, bp.shift_y, host.view), float_image);
      uint64_t slowest = 0;
      for (const g::Block& b : plan.blocks) slowest = std::max(slowest, sysc::frame_cycles(b.regs, scene.pipelines).latency);
      const sysc::NetworkCycles nc = sysc::network_cycles(bp.width, bp.height, static_cast<int>(plan.blocks.size()));
      const uint64_t frame = plan.blocks.size() == 1 ? one_cycles.latency : slowest + nc.latency;
      std::printf("| %s | %zu | %d | %.4f | %.3f %% | %.2f | %.2e | %.4f | %.2f | %.2e | %.4f | %llu | %llu |\n",
                  argv[i], plan.blocks.size(), worst, sum / static_cast<double>(bp.rgba.size()),
                  100.0 * static_cast<double>(differ) / static_cast<double>(bp.rgba.size()), e.psnr, e.mean, e.max,
                  one_vs_float.psnr, one_vs_float.mean, one_vs_float.max, static_cast<unsigned long long>(frame),
                  static_cast<unsigned long long>(plan.blocks.size() == 1 ? 0 : nc.latency));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "blocks_accuracy: %s\n", e.what());
    return 2;
  }
  return 0;
}
