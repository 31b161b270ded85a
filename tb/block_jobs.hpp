// Blocks as independent jobs (bela's object-space processors, past one
// process or one machine): a plan file says how a scene's volume is cut;
// each block renders in a process of its own into a partial image file; a
// last job composes the partial images through the composition network.
// Any job engine can run them (GNU parallel, a Slurm job array:
// scripts/render_blocks.sh, scripts/render_blocks_slurm.sh); the composed
// image equals the one-process `cube4 render --blocks` bit for bit.
//
// The plan's identity (plan_id) is a hash of everything a block's image
// depends on: the volume's registers (every register and table the host
// writes), the block counts and the volume's voxels. A partial image
// carries it, so one rendered from another scene, view, volume or cut is
// refused by name, as is a missing, repeated, truncated or corrupt one.
//
// Partial image file (.cpart), little-endian:
//   8 bytes  "C4PART\r\n"
//   u32      format version (1)
//   u32      header length L, then L bytes of JSON: plan_id, block, blocks,
//            width, height, alpha_bits, acc_guard_bits, voxel_bits, model
//   W·H × 20 bytes: each ray's accumulator (golden RayAcc) in raster order:
//            r, g, b, a (u32), value (u16), selected (u8), 0 (u8)
//   u32      CRC-32 (zlib) of every byte before it
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "golden/blocks.hpp"
#include "golden/volume.hpp"

namespace cube4::tb {

// The identity of a plan of `vol`, as 16 hex digits.
std::string plan_id(const golden::BlockPlan& plan, const golden::Volume& vol);

// The plan file's JSON: scene (an absolute path, or "" for the default
// scene), counts, plan_id, and the blocks as `cube4 render --report`
// describes them.
nlohmann::json plan_json(const golden::BlockPlan& plan, const std::string& scene_path, const std::string& id);

struct PlanFile {
  std::string path;
  std::string scene;  // "" = the default scene
  std::array<int, 3> counts{1, 1, 1};
  std::string id;
  int blocks = 0;
};
// Reads and checks a plan file (InputError naming the file and the key).
PlanFile read_plan(const std::string& path);

struct Partial {
  std::string path;
  std::string plan_id;
  int block = -1, blocks = 0;
  std::string model;
  golden::BasePlane plane;  // width, height and acc (rgba unused)
};

void write_partial(const std::string& path, const golden::BasePlane& partial, const golden::Precision& p,
                   const std::string& id, int block, int blocks, const std::string& model);
// Reads and checks a partial image file (InputError naming the file and
// the fault: not a partial image, truncated, corrupt, another format).
Partial read_partial(const std::string& path);

// The partial images of `plan` in plan order from `files` (any order):
// each must belong to the plan (id), fit its block (size, widths) and
// appear once; every block must have one. InputError otherwise.
std::vector<Partial> order_partials(const golden::BlockPlan& plan, const std::string& id,
                                    const std::vector<std::string>& files);

}  // namespace cube4::tb
