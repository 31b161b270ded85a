// The one mapping from input sample values to voxel values, shared by every
// loader and the synthetic volumes so that a volume quantises identically
// whatever file format it arrived in (docs/volumes.md, "Quantisation").
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "golden/scene.hpp"

namespace cube4::golden {

// Sample types the loaders hand over. UInt12 is stored in 16 bits but its
// full range is 0..4095, which is what CT scanners write.
enum class SampleType { UInt8, Int8, UInt12, UInt16, Int16, UInt32, Int32, Float32, Float64 };

struct ValueRange {
  double lo = 0, hi = 0;
};

// NIfTI's scl_slope/scl_inter; the identity for formats without one.
struct Scaling {
  double slope = 1, inter = 0;
};

const char* sample_type_name(SampleType t);
size_t sample_bytes(SampleType t);
bool is_float(SampleType t);
// The type's own value range; nullopt for floating-point types.
std::optional<ValueRange> type_range(SampleType t);

// Voxel widths the pipeline supports; throws InputError naming the key.
void check_voxel_bits(int voxel_bits);

// out = floor((v - r.lo) * (2^bits - 1) / (r.hi - r.lo) + 0.5), clamped to
// [0, 2^bits - 1], in double. An empty range (hi == lo) maps everything to 0.
uint16_t quantise_value(double v, ValueRange r, int voxel_bits);

// The input range a mode selects. `type` is the (scaled) type range, nullopt
// for floats; `data` is the (scaled) data min..max.
ValueRange quantisation_range(const Quantisation& q, std::optional<ValueRange> type,
                              ValueRange data);

// Quantises dim[0]*dim[1]*dim[2] samples of type t, native byte order, at
// `samples` (no alignment needed). Values a type cannot hold (uint12 above
// 4095, NaN, infinities) are an InputError naming `origin` and the voxel.
std::vector<uint16_t> quantise(const void* samples, SampleType t, std::array<int, 3> dim,
                               const Quantisation& q, int voxel_bits, const std::string& origin,
                               Scaling s = {});

}  // namespace cube4::golden
