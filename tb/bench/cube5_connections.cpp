// Cube-5's Fig. 16 and 17 in our model: the frame rate of a volume alone
// and mixed with translucent polygons of depth complexity 1, 3 and 5,
// through the run-length buffer and through the dual-use buffer
// (golden/polygon_connections.hpp), for an n³ volume on four pipelines at
// 133 MHz and the paper's frame-buffer sizes.
//
// The paper's scenes (a ghost ship, a tank) are not available; in their
// place each slab gets its share of d·W·H fragments at uniformly random
// pixels (seeded), built in a real run-length slab image with the golden
// insert (so the copied and read flits are counted, not estimated), and
// one triangle per 50 fragments (§6's "50-pixel triangles").
//   cube5_connections [--seed S]   (Markdown on stdout)
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "golden/polygon_connections.hpp"

namespace {

using namespace cube4::golden;

constexpr int kPipes = 4;
constexpr double kClockHz = 133e6;
constexpr double kFragmentsPerTriangle = 50;

ConnectionTimes frame(int n, int width, int height, int depth_complexity, std::mt19937_64& rng) {
  const Precision p;
  PolygonFrame f;
  f.width = width;
  f.height = height;
  f.slabs.assign(static_cast<size_t>(n), SlabImage(width, height, kPipes));
  f.counts.slab_triangles.assign(static_cast<size_t>(n), 0);
  const uint64_t total = static_cast<uint64_t>(depth_complexity) * width * height;
  Pixel px{};
  px.r = px.g = px.b = px.a = 1u << 12;  // any translucent colour: the cost does not depend on it
  std::uniform_int_distribution<int> ux(0, width - 1), uy(0, height - 1);
  for (int k = 0; k < n; ++k) {
    // Slab k's share, spread so that the slabs add up to the total exactly.
    const uint64_t count = total * (k + 1) / n - total * k / n;
    for (uint64_t i = 0; i < count; ++i) f.slabs[static_cast<size_t>(k)].insert(ux(rng), uy(rng), px, p);
    f.counts.slab_triangles[static_cast<size_t>(k)] =
        static_cast<uint32_t>((static_cast<double>(count) + kFragmentsPerTriangle - 1) / kFragmentsPerTriangle);
  }
  // The volume's slice on p pipelines, passes back to back (as
  // golden::polygon_traffic counts it; the stream's zero pass and drain not).
  const uint64_t slice_cycles = static_cast<uint64_t>(n) * ((n + kPipes - 1) / kPipes);
  return connection_times(slab_loads(f), slice_cycles, kClockHz, 0, 0, PolygonEngine{});
}

}  // namespace

int main(int argc, char** argv) {
  unsigned seed = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--seed") == 0 && i + 1 < argc) {
      seed = static_cast<unsigned>(std::stoul(argv[++i]));
    } else {
      std::fprintf(stderr, "usage: cube5_connections [--seed S]\n");
      return 2;
    }
  }
  std::mt19937_64 rng(seed);
  std::printf("| volume | frame buffer | depth complexity | fragments/slab | RLE Hz | dual-use Hz | RLE slabs over their slice |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|\n");
  const int sizes[][2] = {{256, 256}, {640, 480}, {1280, 1024}};
  for (int n : {256, 512}) {
    for (const auto& wh : sizes) {
      for (int d : {0, 1, 3, 5}) {
        std::fprintf(stderr, "cube5_connections: %d^3, %dx%d, depth complexity %d...\n", n, wh[0], wh[1], d);
        const ConnectionTimes t = frame(n, wh[0], wh[1], d, rng);
        std::printf("| %d³ | %d × %d | %s | %.0f | %.1f | %.1f | %llu |\n", n, wh[0], wh[1],
                    d == 0 ? "volume only" : std::to_string(d).c_str(),
                    static_cast<double>(d) * wh[0] * wh[1] / n, 1 / t.rle_s, 1 / t.dual_s,
                    static_cast<unsigned long long>(t.rle_slabs_over_slice));
      }
    }
  }
  return 0;
}
