#include "golden/rle_buffer.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace cube4::golden {
namespace {

// Flits appended to a line, or to the few words an insert splits a run
// into.
template <class Words>
void put_pixel(Words& out, const Pixel& px) {
  for (const uint16_t w : {px.r, px.g, px.b, px.a}) out.push_back(w);
}
template <class Words>
void put_run(Words& out, int64_t length) {
  if (length <= 0) return;
  for (int i = 0; i < 4; ++i) out.push_back(0);
  out.push_back(static_cast<uint16_t>(length - 1));
}
// A run split around one pixel: at most a run, a pixel and a run.
struct SplitRun {
  uint16_t w[14];
  size_t n = 0;
  void push_back(uint16_t v) { w[n++] = v; }
};

void check_width(int width) {
  if (width < 0 || width > kRleRunMax)
    throw std::logic_error("RLE line of " + std::to_string(width) + " pixels (at most " +
                           std::to_string(kRleRunMax) + ")");
}

}  // namespace

RleLine rle_clear(int width) {
  check_width(width);
  RleLine out;
  put_run(out, width);
  return out;
}

RleLine rle_encode(const Pixel* pixels, int width) {
  check_width(width);
  RleLine out;
  int run = 0;
  for (int x = 0; x < width; ++x) {
    if (blank(pixels[x])) {
      ++run;
      continue;
    }
    put_run(out, run);
    run = 0;
    put_pixel(out, pixels[x]);
  }
  put_run(out, run);
  return out;
}

std::vector<Pixel> rle_decode(const RleLine& line, int width) {
  std::vector<Pixel> out(static_cast<size_t>(width));
  if (!rle_decode_line(line.data(), line.size(), width, out.data()))
    throw std::logic_error("malformed RLE line: it does not hold exactly " + std::to_string(width) + " pixels");
  return out;
}

size_t rle_insert_into(RleLine& line, int width, int x, const Pixel& px, const Precision& p) {
  if (blank(px)) return rle_flits(line);
  size_t at = 0, flits = 0;
  int64_t total = 0;  // pixels walked so far
  // Flit by flit over the whole line, as Fig. 13's hardware copies it (so
  // a malformed tail is refused wherever the fragment falls).
  while (total < width) {
    const RleFlit f = rle_flit(line.data(), line.size(), at);
    if (!f.ok)
      throw std::logic_error(at + 4 > line.size() ? "malformed RLE line: it ends before its width"
                                                  : "malformed RLE line: a run without its length");
    if (total <= x && x < total + f.length) {
      if (f.words == 4) {
        const Pixel b = pixel_over(f.px, px, p);
        line[at] = b.r;
        line[at + 1] = b.g;
        line[at + 2] = b.b;
        line[at + 3] = b.a;
      } else {  // split the run's 5 words around the new pixel
        SplitRun split;
        put_run(split, x - total);
        put_pixel(split, pixel_over(f.px, px, p));
        put_run(split, total + f.length - x - 1);
        const auto pos = line.begin() + static_cast<std::ptrdiff_t>(at);
        if (split.n > 5)
          line.insert(pos + 5, split.n - 5, 0);
        else
          line.erase(pos + static_cast<std::ptrdiff_t>(split.n), pos + 5);
        std::copy(split.w, split.w + split.n, line.begin() + static_cast<std::ptrdiff_t>(at));
        at += split.n;
        total += f.length;
        ++flits;
        continue;
      }
    }
    at += f.words;
    total += f.length;
    ++flits;
  }
  return flits;
}

RleLine rle_insert(const RleLine& in, int width, int x, const Pixel& px, const Precision& p) {
  RleLine out = in;
  rle_insert_into(out, width, x, px, p);
  return out;
}

size_t rle_flits(const RleLine& line) {
  size_t flits = 0;
  for (size_t at = 0; at + 4 <= line.size(); ++flits) {
    const RleFlit f = rle_flit(line.data(), line.size(), at);
    at += f.ok ? f.words : 5;  // a run cut short ends the line
  }
  return flits;
}

SlabImage::SlabImage(int width, int beams, int lanes) : width_(width), beams_(beams), lanes_(lanes) {
  for (int l = 0; l < lanes_; ++l) cleared_.push_back(rle_clear(lane_width(l)));
}

SlabImage::SlabImage(int width, int beams, int lanes, std::vector<RleLine> lines)
    : SlabImage(width, beams, lanes) {
  lines_ = std::move(lines);
  if (lines_.size() != static_cast<size_t>(beams) * lanes)
    throw std::logic_error("slab image: " + std::to_string(lines_.size()) + " lines for " + std::to_string(beams) +
                           " beams of " + std::to_string(lanes) + " lanes");
  for (size_t i = 0; i < lines_.size(); ++i) {
    const auto y = static_cast<int>(i / lanes), l = static_cast<int>(i % lanes);
    const RleLine& words = line(y, l);
    if (!rle_for_each_pixel(words.data(), words.size(), lane_width(l), [](int, const Pixel&) {})) malformed(y, l);
  }
}

void SlabImage::insert(int x, int y, const Pixel& px, const Precision& p) {
  if (lines_.empty()) lines_.resize(static_cast<size_t>(beams_) * lanes_);
  const int lane = x % lanes_;
  RleLine& l = lines_[static_cast<size_t>(y) * lanes_ + lane];
  if (l.empty()) {
    l.reserve(32);  // room for a few fragments without growing
    l = cleared_[static_cast<size_t>(lane)];
  }
  ++inserts_;
  copied_flits_ += rle_insert_into(l, lane_width(lane), x / lanes_, px, p);
}

void SlabImage::decode_beam(int y, Pixel* out) const {
  for (int l = 0; l < lanes_ && l < width_; ++l) {
    if (empty()) {
      for (int x = l; x < width_; x += lanes_) out[x] = Pixel{};
      continue;
    }
    const RleLine& words = line(y, l);
    if (!rle_decode_line(words.data(), words.size(), lane_width(l), out + l, lanes_)) malformed(y, l);
  }
}

void SlabImage::malformed(int y, int lane) {
  throw std::logic_error("malformed RLE line in a slab image (beam " + std::to_string(y) + ", lane " +
                         std::to_string(lane) + ")");
}

size_t SlabImage::flits() const {
  size_t n = 0;
  for (const RleLine& l : lines_) n += rle_flits(l);
  return n;
}

}  // namespace cube4::golden
