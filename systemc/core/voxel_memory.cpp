#include "systemc/core/voxel_memory.hpp"

#include <stdexcept>
#include <string>

namespace cube4::sysc {

VoxelMemory::VoxelMemory(const golden::Volume& v, int pipes) {
  if (pipes < 1 || pipes > golden::kMaxSkewPipes)
    throw std::invalid_argument("pipelines: " + std::to_string(pipes) + " (the voxel memory takes 1 .. " +
                                std::to_string(golden::kMaxSkewPipes) + ")");
  layout_.n = v.dim;
  layout_.p = pipes;
  modules_.assign(static_cast<size_t>(pipes), std::vector<uint16_t>(static_cast<size_t>(layout_.words_per_module()), 0));
  last_access_.assign(static_cast<size_t>(pipes), 0);
  // Lane by lane along each row: voxels x and x + p share a module and lie
  // in consecutive words of it (skew_address), so the address is worked out
  // once per lane instead of with its divisions per voxel.
  const bool tagged = !v.tags.empty();
  for (int z = 0; z < v.dim[2]; ++z)
    for (int y = 0; y < v.dim[1]; ++y)
      for (int k = 0; k < pipes && k < v.dim[0]; ++k) {
        const golden::SkewAddress a = golden::skew_address(layout_, k, y, z);
        uint16_t* word = modules_[static_cast<size_t>(a.module)].data() + a.index;
        for (int x = k; x < v.dim[0]; x += pipes)  // the word {tag, value} (docs/registers.md, "Tags")
          *word++ = static_cast<uint16_t>(v.at(x, y, z) | (tagged ? v.tag_at(x, y, z) << v.bits : 0));
      }
}

void VoxelMemory::write(int x, int y, int z, uint16_t value) {
  const golden::SkewAddress a = golden::skew_address(layout_, x, y, z);
  modules_[static_cast<size_t>(a.module)][static_cast<size_t>(a.index)] = value;
}

uint16_t VoxelMemory::read(int module, int64_t index) {
  uint64_t& last = last_access_[static_cast<size_t>(module)];
  if (last == cycle_)
    throw std::logic_error("voxel memory: module " + std::to_string(module) + " accessed twice in cycle " +
                           std::to_string(cycle_) + " (the skew is broken)");
  last = cycle_;
  ++reads_;
  return modules_[static_cast<size_t>(module)][static_cast<size_t>(index)];
}

}  // namespace cube4::sysc
