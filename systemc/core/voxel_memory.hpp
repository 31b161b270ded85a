// Voxel memory: p modules with the Cube-4 linear skew (golden/units/addr.hpp),
// one read port each. The model counts the accesses of every module in
// every cycle and throws if one is accessed twice: the skew's promise, which
// the traversal must keep for any view.
#pragma once
#include <cstdint>
#include <vector>

#include "golden/units/addr.hpp"
#include "golden/volume.hpp"

namespace cube4::sysc {

class VoxelMemory {
 public:
  VoxelMemory(const golden::Volume& v, int pipes);

  const golden::SkewLayout& layout() const { return layout_; }
  // Host write of voxel (x, y, z) in object coordinates.
  void write(int x, int y, int z, uint16_t value);
  // One cycle's reads: module m at index[m]; every module at most once.
  void begin_cycle() { ++cycle_; }
  uint16_t read(int module, int64_t index);
  // A read expected at a later cycle, for the host's cache only: the
  // traversal strides through the modules (a cache line per voxel on many
  // views), and one cycle of the rest of the machine hides the miss.
  void prefetch(int module, int64_t index) const {
    __builtin_prefetch(modules_[static_cast<size_t>(module)].data() + index);
  }
  uint64_t reads() const { return reads_; }

 private:
  golden::SkewLayout layout_;
  std::vector<std::vector<uint16_t>> modules_;
  std::vector<uint64_t> last_access_;  // cycle of each module's last read (+1; 0 = never)
  uint64_t cycle_ = 0, reads_ = 0;
};

}  // namespace cube4::sysc
