#include "golden/rle_buffer.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace cube4::golden {
namespace {

void put_pixel(RleLine& out, const Pixel& px) { out.insert(out.end(), {px.r, px.g, px.b, px.a}); }

void put_run(RleLine& out, int length) {
  if (length > 0) out.insert(out.end(), {0, 0, 0, 0, static_cast<uint16_t>(length - 1)});
}

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

RleLine rle_insert(const RleLine& in, int width, int x, const Pixel& px, const Precision& p) {
  if (blank(px)) return in;
  RleLine out;
  out.reserve(in.size() + 10);
  size_t at = 0;
  int total = 0;  // pixels copied so far
  // One flit per step, as Fig. 13's hardware copies one per cycle.
  while (total < width) {
    if (at + 4 > in.size()) throw std::logic_error("malformed RLE line: it ends before its width");
    const Pixel old{in[at], in[at + 1], in[at + 2], in[at + 3]};
    if (!blank(old)) {
      put_pixel(out, total == x ? pixel_over(old, px, p) : old);
      at += 4;
      total += 1;
      continue;
    }
    if (at + 5 > in.size()) throw std::logic_error("malformed RLE line: a run without its length");
    const int length = in[at + 4] + 1;
    if (total <= x && x < total + length) {
      put_run(out, x - total);
      put_pixel(out, pixel_over(old, px, p));
      put_run(out, total + length - x - 1);
    } else {
      put_run(out, length);
    }
    at += 5;
    total += length;
  }
  return out;
}

size_t rle_flits(const RleLine& line) {
  size_t flits = 0;
  for (size_t at = 0; at + 4 <= line.size(); ++flits)
    at += (line[at] | line[at + 1] | line[at + 2] | line[at + 3]) ? 4 : 5;
  return flits;
}

SlabImage::SlabImage(int width, int beams, int lanes, std::vector<RleLine> lines)
    : width_(width), beams_(beams), lanes_(lanes), lines_(std::move(lines)) {
  if (lines_.size() != static_cast<size_t>(beams) * lanes)
    throw std::logic_error("slab image: " + std::to_string(lines_.size()) + " lines for " + std::to_string(beams) +
                           " beams of " + std::to_string(lanes) + " lanes");
  for (size_t i = 0; i < lines_.size(); ++i) rle_decode(lines_[i], lane_width(static_cast<int>(i % lanes)));
}

void SlabImage::insert(int x, int y, const Pixel& px, const Precision& p) {
  if (lines_.empty()) {
    lines_.resize(static_cast<size_t>(beams_) * lanes_);
    for (int yy = 0; yy < beams_; ++yy)
      for (int l = 0; l < lanes_; ++l) lines_[static_cast<size_t>(yy) * lanes_ + l] = rle_clear(lane_width(l));
  }
  const int lane = x % lanes_;
  RleLine& l = lines_[static_cast<size_t>(y) * lanes_ + lane];
  ++inserts_;
  copied_flits_ += rle_flits(l);
  l = rle_insert(l, lane_width(lane), x / lanes_, px, p);
}

void SlabImage::decode_beam(int y, Pixel* out) const {
  for (int l = 0; l < lanes_ && l < width_; ++l) {
    if (empty()) {
      for (int x = l; x < width_; x += lanes_) out[x] = Pixel{};
      continue;
    }
    const RleLine& words = line(y, l);
    if (!rle_decode_line(words.data(), words.size(), lane_width(l), out + l, lanes_))
      throw std::logic_error("malformed RLE line in a slab image (beam " + std::to_string(y) + ", lane " +
                             std::to_string(l) + ")");
  }
}

size_t SlabImage::flits() const {
  size_t n = 0;
  for (const RleLine& l : lines_) n += rle_flits(l);
  return n;
}

}  // namespace cube4::golden
