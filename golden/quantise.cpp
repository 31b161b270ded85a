#include "golden/quantise.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "golden/errors.hpp"

namespace cube4::golden {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string voxel_name(size_t i, std::array<int, 3> dim) {
  const size_t nx = static_cast<size_t>(dim[0]), ny = static_cast<size_t>(dim[1]);
  return "voxel " + std::to_string(i) + " (x=" + std::to_string(i % nx) +
         ", y=" + std::to_string(i / nx % ny) + ", z=" + std::to_string(i / (nx * ny)) + ")";
}

// Samples may sit at any byte offset in a file buffer, so read through memcpy.
template <class T>
T sample_at(const unsigned char* p, size_t i) {
  T v;
  std::memcpy(&v, p + i * sizeof(T), sizeof(T));
  return v;
}

template <class T>
void check_sample(T v, SampleType t, size_t i, std::array<int, 3> dim, const std::string& origin) {
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(v))
      throw InputError(origin + ": " + voxel_name(i, dim) + " is " +
                       (std::isnan(v) ? "NaN" : "infinite") +
                       "; only finite values can be quantised");
  } else if (t == SampleType::UInt12 && static_cast<uint32_t>(v) > 4095u) {
    throw InputError(origin + ": " + voxel_name(i, dim) + " has value " +
                     std::to_string(static_cast<uint32_t>(v)) + ", above the uint12 maximum 4095");
  }
}

ValueRange scaled(ValueRange r, Scaling s) {
  ValueRange out{r.lo * s.slope + s.inter, r.hi * s.slope + s.inter};
  if (out.lo > out.hi) std::swap(out.lo, out.hi);  // a negative slope reverses the range
  return out;
}

template <class T>
std::vector<uint16_t> quantise_typed(const unsigned char* p, SampleType t, std::array<int, 3> dim,
                                     const Quantisation& q, int voxel_bits,
                                     const std::string& origin, Scaling s) {
  const size_t n = static_cast<size_t>(dim[0]) * dim[1] * dim[2];
  // One pass validates and finds the data range (MinMax needs it; it is cheap).
  T mn = std::numeric_limits<T>::max(), mx = std::numeric_limits<T>::lowest();
  for (size_t i = 0; i < n; ++i) {
    const T v = sample_at<T>(p, i);
    check_sample(v, t, i, dim, origin);
    if (v < mn) mn = v;
    if (v > mx) mx = v;
  }
  if (n == 0) mn = mx = 0;
  std::optional<ValueRange> tr = type_range(t);
  if (tr) tr = scaled(*tr, s);
  const ValueRange r =
      quantisation_range(q, tr, scaled({static_cast<double>(mn), static_cast<double>(mx)}, s));
  std::vector<uint16_t> out(n);
  for (size_t i = 0; i < n; ++i)
    out[i] =
        quantise_value(static_cast<double>(sample_at<T>(p, i)) * s.slope + s.inter, r, voxel_bits);
  return out;
}

}  // namespace

const char* sample_type_name(SampleType t) {
  switch (t) {
    case SampleType::UInt8: return "uint8";
    case SampleType::Int8: return "int8";
    case SampleType::UInt12: return "uint12";
    case SampleType::UInt16: return "uint16";
    case SampleType::Int16: return "int16";
    case SampleType::UInt32: return "uint32";
    case SampleType::Int32: return "int32";
    case SampleType::Float32: return "float32";
    case SampleType::Float64: return "float64";
  }
  return "?";
}

size_t sample_bytes(SampleType t) {
  switch (t) {
    case SampleType::UInt8:
    case SampleType::Int8: return 1;
    case SampleType::UInt12:
    case SampleType::UInt16:
    case SampleType::Int16: return 2;
    case SampleType::UInt32:
    case SampleType::Int32:
    case SampleType::Float32: return 4;
    case SampleType::Float64: return 8;
  }
  return 0;
}

bool is_float(SampleType t) { return t == SampleType::Float32 || t == SampleType::Float64; }

std::optional<ValueRange> type_range(SampleType t) {
  switch (t) {
    case SampleType::UInt8: return ValueRange{0, 255};
    case SampleType::Int8: return ValueRange{-128, 127};
    case SampleType::UInt12: return ValueRange{0, 4095};
    case SampleType::UInt16: return ValueRange{0, 65535};
    case SampleType::Int16: return ValueRange{-32768, 32767};
    case SampleType::UInt32: return ValueRange{0, 4294967295.0};
    case SampleType::Int32: return ValueRange{-2147483648.0, 2147483647.0};
    case SampleType::Float32:
    case SampleType::Float64: return std::nullopt;
  }
  return std::nullopt;
}

void check_voxel_bits(int voxel_bits) {
  // Voxels are stored in 16 bits; below 8 the classification LUTs lose meaning.
  if (voxel_bits < 8 || voxel_bits > 16)
    throw InputError("precision.voxel_bits: " + std::to_string(voxel_bits) +
                     " is outside the supported 8..16");
}

uint16_t quantise_value(double v, ValueRange r, int voxel_bits) {
  const double maxv = static_cast<double>((1u << voxel_bits) - 1u);
  if (!(r.hi > r.lo)) return 0;  // constant data: nothing to spread out
  const double x = std::floor((v - r.lo) * maxv / (r.hi - r.lo) + 0.5);
  if (!(x > 0)) return 0;  // also catches NaN
  if (x >= maxv) return static_cast<uint16_t>(maxv);
  return static_cast<uint16_t>(x);
}

ValueRange quantisation_range(const Quantisation& q, std::optional<ValueRange> type,
                              ValueRange data) {
  switch (q.mode) {
    case Quantisation::Mode::Full: return type ? *type : data;
    case Quantisation::Mode::MinMax: return data;
    case Quantisation::Mode::Window:
      if (!std::isfinite(q.lo) || !std::isfinite(q.hi) || !(q.hi > q.lo))
        throw InputError("volume.map: window needs finite lo < hi, got lo=" + num(q.lo) +
                         " hi=" + num(q.hi));
      return {q.lo, q.hi};
  }
  return data;
}

std::vector<uint16_t> quantise(const void* samples, SampleType t, std::array<int, 3> dim,
                               const Quantisation& q, int voxel_bits, const std::string& origin,
                               Scaling s) {
  check_voxel_bits(voxel_bits);
  const auto* p = static_cast<const unsigned char*>(samples);
  switch (t) {
    case SampleType::UInt8: return quantise_typed<uint8_t>(p, t, dim, q, voxel_bits, origin, s);
    case SampleType::Int8: return quantise_typed<int8_t>(p, t, dim, q, voxel_bits, origin, s);
    case SampleType::UInt12:
    case SampleType::UInt16: return quantise_typed<uint16_t>(p, t, dim, q, voxel_bits, origin, s);
    case SampleType::Int16: return quantise_typed<int16_t>(p, t, dim, q, voxel_bits, origin, s);
    case SampleType::UInt32: return quantise_typed<uint32_t>(p, t, dim, q, voxel_bits, origin, s);
    case SampleType::Int32: return quantise_typed<int32_t>(p, t, dim, q, voxel_bits, origin, s);
    case SampleType::Float32: return quantise_typed<float>(p, t, dim, q, voxel_bits, origin, s);
    case SampleType::Float64: return quantise_typed<double>(p, t, dim, q, voxel_bits, origin, s);
  }
  return {};
}

}  // namespace cube4::golden
