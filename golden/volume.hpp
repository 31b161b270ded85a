// Volumes as the hardware's voxel memory sees them: unsigned integers of the
// pipeline's voxel width, x fastest, with physical spacing per axis.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cube4::golden {

struct Volume {
  std::array<int, 3> dim{0, 0, 0};           // voxels along x, y, z
  std::array<double, 3> spacing{1, 1, 1};    // physical size of a voxel (any unit)
  int bits = 12;                             // voxel width; every value < 2^bits
  std::vector<uint16_t> data;                // dim[0]*dim[1]*dim[2] values, x fastest
  std::string source;                        // where it came from (file or generator)
  // Voxel tags (bela §III): one per voxel beside its value, x fastest, each
  // < 2^precision.tag_bits; empty: every tag is 0 (golden/volume_tags.cpp).
  std::vector<uint8_t> tags;
  std::string tag_source;                    // where the tags came from

  size_t index(int x, int y, int z) const {
    return (static_cast<size_t>(z) * dim[1] + y) * dim[0] + x;
  }
  uint16_t at(int x, int y, int z) const { return data[index(x, y, z)]; }
  uint8_t tag_at(int x, int y, int z) const { return tags.empty() ? 0 : tags[index(x, y, z)]; }
  size_t size() const { return static_cast<size_t>(dim[0]) * dim[1] * dim[2]; }
  uint32_t max_value() const { return (1u << bits) - 1u; }
};

}  // namespace cube4::golden
