// Prints, as Markdown, how far the rings must reach for perspective frames
// (golden/perspective_dataflow.hpp; docs/perspective.md, "The dataflow"):
// over random viewing directions at several fields of view, the offsets of
// each operand from a sample's home, and the share of views whose rays'
// homes move by at most 1, 2 or 3 cells a slice (the compositor's reach).
// scripts/perspective_reach.sh puts the output into docs/perspective.md.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "golden/errors.hpp"
#include "golden/host_driver.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"

namespace {

using cube4::golden::CellRange;
using cube4::golden::PerspectiveReach;

constexpr int kViews = 200;

std::string scene_json(const std::string& size, int S, int fov, const std::array<int, 3>& rotate) {
  return R"({"volume": {"synthetic": "sphere", "size": )" + size + R"(}, "supersampling": )" + std::to_string(S) +
         R"(, "view": {"projection": "perspective", "fov": )" + std::to_string(fov) + R"(, "rotate": [)" +
         std::to_string(rotate[0]) + "," + std::to_string(rotate[1]) + "," + std::to_string(rotate[2]) + "]}}";
}

void join(CellRange& into, const CellRange& r) {
  if (r.empty()) return;
  into.add(r.lo);
  into.add(r.hi);
}

std::string show(const CellRange& r) { return "[" + std::to_string(r.lo) + ", " + std::to_string(r.hi) + "]"; }

}  // namespace

int main() {
  std::printf("| volume | S | fov | views | box | next ray | behind | ahead | move ≤ 1 | ≤ 2 | ≤ 3 | largest move |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string size : {"[64,64,64]", "[128,128,84]"}) {
    const cube4::golden::Scene probe = cube4::golden::parse_scene(scene_json(size, 1, 40, {0, 0, 0}), "reach.json");
    const cube4::golden::Volume vol = cube4::golden::load_volume(probe.volume, probe.precision.voxel_bits, ".");
    for (int S : {1, 2})
      for (int fov : {20, 40, 60, 80, 89}) {
        std::mt19937 rng(static_cast<unsigned>(fov * 10 + S));
        std::uniform_int_distribution<int> angle(-180, 179);
        CellRange box, next, behind, ahead;
        int views = 0, within[3] = {0, 0, 0};
        int64_t largest = 0;
        for (int i = 0; i < kViews; ++i) {
          const std::array<int, 3> rotate{angle(rng), angle(rng), angle(rng)};
          const cube4::golden::Scene s = cube4::golden::parse_scene(scene_json(size, S, fov, rotate), "reach.json");
          const PerspectiveReach r = cube4::golden::perspective_reach(cube4::golden::program_host(s, vol).regs);
          for (const auto* a : {&r.x, &r.y}) {
            join(box, a->box);
            join(next, a->next);
            join(behind, a->behind);
            join(ahead, a->ahead);
          }
          const int64_t move = cube4::golden::largest_home_move(r);
          largest = std::max(largest, move);
          for (int reach = 1; reach <= 3; ++reach) within[reach - 1] += move <= reach;
          ++views;
        }
        auto share = [&](int n) { return std::to_string(100 * n / views) + " %"; };
        std::printf("| %s | %d | %d° | %d | %s | %s | %s | %s | %s | %s | %s | %lld |\n", size.c_str(), S, fov, views,
                    show(box).c_str(), show(next).c_str(), show(behind).c_str(), show(ahead).c_str(),
                    share(within[0]).c_str(), share(within[1]).c_str(), share(within[2]).c_str(),
                    static_cast<long long>(largest));
      }
  }
  return EXIT_SUCCESS;
}
