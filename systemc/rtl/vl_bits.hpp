// Bit access to verilated ports of any width: CData/SData/IData/QData or
// VlWide<N>, a field of `width` bits at bit `lsb`.
#pragma once
#include <verilated.h>

#include <cstdint>
#include <type_traits>

namespace cube4::rtl {

template <class T, std::enable_if_t<std::is_integral_v<T>, int> = 0>
inline void put_bits(T& port, int lsb, int width, uint64_t v) {
  const uint64_t mask = width >= 64 ? ~uint64_t{0} : (uint64_t{1} << width) - 1;
  uint64_t p = static_cast<uint64_t>(port);
  p = (p & ~(mask << lsb)) | ((v & mask) << lsb);
  port = static_cast<T>(p);
}
// Wide ports: a field of up to 64 bits spans at most three 32-bit words.
template <std::size_t N>
inline void put_bits(VlWide<N>& port, int lsb, int width, uint64_t v) {
  if (width < 64) v &= (uint64_t{1} << width) - 1;
  int word = lsb / 32, shift = lsb % 32, left = width;
  while (left > 0) {
    const int n = left < 32 - shift ? left : 32 - shift;
    const uint32_t mask = (n == 32 ? ~uint32_t{0} : ((uint32_t{1} << n) - 1)) << shift;
    port[word] = (port[word] & ~mask) | (static_cast<uint32_t>(v << shift) & mask);
    v >>= n;
    left -= n;
    shift = 0;
    ++word;
  }
}
template <class T, std::enable_if_t<std::is_integral_v<T>, int> = 0>
inline uint64_t get_bits(const T& port, int lsb, int width) {
  const uint64_t mask = width >= 64 ? ~uint64_t{0} : (uint64_t{1} << width) - 1;
  return static_cast<uint64_t>(port) >> lsb & mask;
}
template <std::size_t N>
inline uint64_t get_bits(const VlWide<N>& port, int lsb, int width) {
  uint64_t r = 0;
  int word = lsb / 32, shift = lsb % 32, got = 0;
  while (got < width) {
    const int n = width - got < 32 - shift ? width - got : 32 - shift;
    const uint64_t chunk = (port[word] >> shift) & (n == 32 ? ~uint32_t{0} : ((uint32_t{1} << n) - 1));
    r |= chunk << got;
    got += n;
    shift = 0;
    ++word;
  }
  return r;
}
inline int64_t sign_extend(uint64_t v, int bits) {
  const uint64_t m = uint64_t{1} << (bits - 1);
  v &= (m << 1) - 1;
  return static_cast<int64_t>(v ^ m) - static_cast<int64_t>(m);
}

}  // namespace cube4::rtl
