#include "systemc/host/polygon_buffer.hpp"

#include <algorithm>

#include "golden/units/composite_polygon.hpp"
#include "golden/units/rle_decode.hpp"

namespace cube4::sysc {
namespace rm = regmap;
using rm::ErrorCode;

std::vector<uint32_t> encode_slab_stream(const golden::SlabImage& slab) {
  std::vector<uint32_t> out;
  if (slab.empty()) return out;
  for (int y = 0; y < slab.beams(); ++y)
    for (int l = 0; l < slab.lanes(); ++l) {
      const golden::RleWords line = slab.line(y, l);
      out.push_back(static_cast<uint32_t>(line.size()));
      for (size_t i = 0; i < line.size(); i += 2)
        out.push_back(uint32_t{line[i]} | (i + 1 < line.size() ? uint32_t{line[i + 1]} << 16 : 0));
    }
  return out;
}

uint64_t slab_stream_words(const golden::SlabImage& slab) {
  if (slab.empty()) return 0;
  // encode_slab_stream()'s: per line a count word and its 16-bit words in pairs.
  const uint64_t lines = static_cast<uint64_t>(slab.beams()) * static_cast<uint64_t>(slab.lanes());
  return lines + (slab.words() + slab.odd_lines()) / 2;
}

void PolygonBuffer::map(const golden::PolygonFrame& f, const std::array<int, 3>& size) {
  size_ = size;
  mapped_ = &f;
}

void PolygonBuffer::take_mapped() {
  const golden::PolygonFrame& f = *mapped_;
  mapped_ = nullptr;
  const std::array<int, 3> size = size_;
  size_ = {0, 0, 0};
  fit(size);
  for (size_t i = 0; i < f.front.size(); ++i) {
    front_[2 * i] = uint32_t{f.front[i].r} | uint32_t{f.front[i].g} << 16;
    front_[2 * i + 1] = uint32_t{f.front[i].b} | uint32_t{f.front[i].a} << 16;
    back_[2 * i] = uint32_t{f.back[i].r} | uint32_t{f.back[i].g} << 16;
    back_[2 * i + 1] = uint32_t{f.back[i].b} | uint32_t{f.back[i].a} << 16;
  }
  std::copy(f.z.begin(), f.z.end(), z_.begin());
  for (size_t k = 0; k < f.slabs.size(); ++k) slabs_[k] = encode_slab_stream(f.slabs[k]);
}

void PolygonBuffer::fit(const std::array<int, 3>& size) {
  if (size == size_) return;
  size_ = size;
  const size_t pixels = static_cast<size_t>(size[0]) * size[1];
  front_.assign(2 * pixels, 0);
  back_.assign(2 * pixels, 0);
  z_.assign(pixels, golden::kZNone);
  slabs_.assign(static_cast<size_t>(size[2]), {});
}

std::optional<PolygonBuffer::Fault> PolygonBuffer::write(uint64_t addr, const uint32_t* words, unsigned n,
                                                         const std::array<int, 3>& size, const golden::Precision& p) {
  if (mapped_) take_mapped();
  const rm::Region r = rm::region_of(addr);
  const uint64_t pixels = uint64_t(size[0]) * size[1];
  auto at = [addr](unsigned i) { return addr + 4 * uint64_t{i}; };
  if (r == rm::Region::PolySlab) {
    const uint64_t k = (addr - rm::kPolySlabBase) / rm::kPolySlabStride;
    // Every word of a burst lies in the slice of its first (the window is
    // mapped slice by slice, and HostInterface refuses a burst leaving it).
    if (k >= uint64_t(size[2]) || (addr - rm::kPolySlabBase) % rm::kPolySlabStride + 4 * uint64_t{n} > rm::kPolySlabStride)
      return Fault{ErrorCode::PolygonSize, addr};
    fit(size);
    std::vector<uint32_t>& s = slabs_[k];
    const size_t first = (addr - rm::kPolySlabBase) % rm::kPolySlabStride / 4;
    if (s.size() < first + n) s.resize(first + n, 0);
    std::copy(words, words + n, s.begin() + static_cast<std::ptrdiff_t>(first));
    return std::nullopt;
  }
  const bool z = r == rm::Region::PolyZ;
  const uint64_t base = z ? rm::kPolyZBase : r == rm::Region::PolyFront ? rm::kPolyFrontBase : rm::kPolyBackBase;
  const uint64_t first = (addr - base) / 4;  // word index
  const uint32_t channel_max = (uint32_t{1} << p.alpha_bits) - 1;
  for (unsigned i = 0; i < n; ++i) {
    if ((first + i) / (z ? 1 : 2) >= pixels) return Fault{ErrorCode::PolygonSize, at(i)};
    const bool fits = z ? words[i] <= golden::kZNone
                        : (words[i] & 0xFFFF) <= channel_max && (words[i] >> 16) <= channel_max;
    if (!fits) return Fault{ErrorCode::FieldRange, at(i)};
  }
  fit(size);
  std::vector<uint32_t>& image = z ? z_ : r == rm::Region::PolyFront ? front_ : back_;
  std::copy(words, words + n, image.begin() + static_cast<std::ptrdiff_t>(first));
  return std::nullopt;
}

std::optional<PolygonBuffer::Fault> PolygonBuffer::frame(const std::array<int, 3>& size, int width, int height,
                                                         int slices, int dim_x, int dim_y, int lanes,
                                                         golden::PolygonFrame& out,
                                                         const golden::PolygonFrame*& result) const {
  result = nullptr;
  if (size[0] != width) return Fault{ErrorCode::PolygonSize, rm::kPolySize};
  if (size[1] != height) return Fault{ErrorCode::PolygonSize, rm::kPolySize + 4};
  if (size[2] != slices) return Fault{ErrorCode::PolygonSize, rm::kPolySize + 8};
  if (mapped_ && size_ == size) {
    // map() took the images' sizes; the slabs must have the beams' shape.
    for (int k = 0; k < slices; ++k) {
      const golden::SlabImage& s = mapped_->slabs[static_cast<size_t>(k)];
      if (s.width() != dim_x || s.beams() != dim_y || s.lanes() != lanes)
        return Fault{ErrorCode::PolygonImage, rm::kPolySlabBase + uint64_t(k) * rm::kPolySlabStride};
    }
    result = mapped_;
    return std::nullopt;
  }
  result = &out;
  const size_t pixels = static_cast<size_t>(width) * height;
  out = {};
  out.width = width;
  out.height = height;
  const bool blank = size_ != size;  // nothing written since the last frame
  auto pixel = [](const std::vector<uint32_t>& w, size_t i) {
    return golden::Pixel{static_cast<uint16_t>(w[2 * i]), static_cast<uint16_t>(w[2 * i] >> 16),
                         static_cast<uint16_t>(w[2 * i + 1]), static_cast<uint16_t>(w[2 * i + 1] >> 16)};
  };
  out.front.resize(pixels);
  out.back.resize(pixels);
  out.z.assign(pixels, golden::kZNone);
  if (!blank)
    for (size_t i = 0; i < pixels; ++i) {
      out.front[i] = pixel(front_, i);
      out.back[i] = pixel(back_, i);
      out.z[i] = z_[i];
    }
  // A slab without fragments is still the beams' shape: the decoders check it.
  const golden::SlabImage shape(dim_x, dim_y, lanes);
  out.slabs.assign(static_cast<size_t>(slices), shape);
  if (blank) return std::nullopt;
  for (int k = 0; k < slices; ++k) {
    const std::vector<uint32_t>& s = slabs_[static_cast<size_t>(k)];
    if (s.empty()) continue;
    const uint64_t base = rm::kPolySlabBase + uint64_t(k) * rm::kPolySlabStride;
    std::vector<golden::RleLine> lines;
    lines.reserve(static_cast<size_t>(dim_y) * lanes);
    size_t at = 0;
    golden::RleLine line;
    for (int y = 0; y < dim_y; ++y)
      for (int l = 0; l < lanes; ++l) {
        const uint64_t line_addr = base + 4 * uint64_t{at};
        if (at >= s.size()) return Fault{ErrorCode::PolygonImage, line_addr};
        const size_t count = s[at++];
        if ((count + 1) / 2 > s.size() - at) return Fault{ErrorCode::PolygonImage, line_addr};
        // Most lines of a slab are cleared (one run: words 0, 0, 0, 0,
        // width - 1): kept as the image keeps one never written.
        const int w = shape.lane_width(l);
        if (w > 0 && count == 5 && s[at] == 0 && s[at + 1] == 0 && s[at + 2] == static_cast<uint32_t>(w - 1)) {
          at += 3;
          lines.emplace_back();
          continue;
        }
        line.resize(count);
        for (size_t i = 0; i < count; ++i) line[i] = static_cast<uint16_t>(s[at + i / 2] >> (16 * (i % 2)));
        at += (count + 1) / 2;
        if (!golden::rle_for_each_pixel(line.data(), line.size(), shape.lane_width(l), [](int, const golden::Pixel&) {}))
          return Fault{ErrorCode::PolygonImage, line_addr};
        lines.push_back(line);
      }
    // Words past the last line: the stream is not this frame's shape.
    if (at != s.size()) return Fault{ErrorCode::PolygonImage, base + 4 * uint64_t{at}};
    out.slabs[static_cast<size_t>(k)] = golden::SlabImage(dim_x, dim_y, lanes, std::move(lines));
  }
  return std::nullopt;
}

}  // namespace cube4::sysc
