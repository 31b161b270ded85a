#include "golden/rle_buffer.hpp"

#include <algorithm>
#include <cstring>
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

namespace {

[[noreturn]] void malformed_at(const RleLine& line, size_t at) {
  throw std::logic_error(at + 4 > line.size() ? "malformed RLE line: it ends before its width"
                                              : "malformed RLE line: a run without its length");
}

// Where Algorithm 1's walk stands after the flit that holds x.
struct Walk {
  size_t at = 0;      // the next flit's first word
  int64_t total = 0;  // pixels walked
  size_t flits = 0;   // flits of the line before the insert, walked so far
  int added = 0;      // flits the insert added to the line (a run split in up to three)
};

// Algorithm 1 up to and through the flit holding x: px blended in there,
// a run split around it. Stops there: the rest of the line is unchanged.
Walk insert_through(RleLine& line, int width, int x, const Pixel& px, const Precision& p) {
  Walk w;
  if (x < 0 || x >= width) return w;  // no pixel of the line: nothing to insert
  const uint16_t* words = line.data();
  const size_t count = line.size();
  uint32_t length = 1, size = 4;
  // The flit holding x: total <= x throughout, as x >= 0.
  for (;; w.at += size, w.total += length) {
    if (w.at + 4 > count) malformed_at(line, w.at);
    uint64_t four;  // a pixel flit's four words, all zero for a run
    std::memcpy(&four, words + w.at, sizeof four);
    if (four != 0) {
      length = 1, size = 4;
    } else {
      if (w.at + 5 > count) malformed_at(line, w.at);
      length = uint32_t{words[w.at + 4]} + 1, size = 5;
    }
    ++w.flits;
    if (x < w.total + length) break;
  }
  if (size == 4) {
    const Pixel b = pixel_over({words[w.at], words[w.at + 1], words[w.at + 2], words[w.at + 3]}, px, p);
    line[w.at] = b.r;
    line[w.at + 1] = b.g;
    line[w.at + 2] = b.b;
    line[w.at + 3] = b.a;
    w.at += 4;
  } else {  // split the run's 5 words around the new pixel
    SplitRun split;
    put_run(split, x - w.total);
    put_pixel(split, pixel_over(Pixel{}, px, p));
    put_run(split, w.total + length - x - 1);
    // The run's 5 words make room for the split's n: the tail moves.
    const size_t tail = w.at + 5, end = line.size();
    if (split.n > 5) line.resize(end + split.n - 5);
    std::memmove(line.data() + w.at + split.n, line.data() + tail, (end - tail) * sizeof(uint16_t));
    if (split.n < 5) line.resize(end + split.n - 5);
    std::copy(split.w, split.w + split.n, line.begin() + static_cast<std::ptrdiff_t>(w.at));
    w.at += split.n;
    w.added = (x > w.total) + (x < w.total + length - 1);  // the runs left beside the pixel
  }
  w.total += length;
  return w;
}

}  // namespace

size_t rle_insert_into(RleLine& line, int width, int x, const Pixel& px, const Precision& p) {
  if (blank(px)) return rle_flits(line);
  Walk w = insert_through(line, width, x, px, p);
  // On over the rest of the line, as Fig. 13's hardware copies it (so a
  // malformed tail is refused wherever the fragment falls).
  while (w.total < width) {
    const RleFlit f = rle_flit(line.data(), line.size(), w.at);
    if (!f.ok) malformed_at(line, w.at);
    w.at += f.words;
    w.total += f.length;
    ++w.flits;
  }
  return w.flits;
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
  for (int l = 0; l < lanes_; ++l) {
    lane_widths_.push_back(l < width_ ? (width_ - l + lanes_ - 1) / lanes_ : 0);
    cleared_.push_back(rle_clear(lane_widths_.back()));
  }
}


SlabImage::SlabImage(int width, int beams, int lanes, std::vector<RleLine> lines)
    : SlabImage(width, beams, lanes) {
  lines_ = std::move(lines);
  if (lines_.size() != static_cast<size_t>(beams) * lanes)
    throw std::logic_error("slab image: " + std::to_string(lines_.size()) + " lines for " + std::to_string(beams) +
                           " beams of " + std::to_string(lanes) + " lanes");
  flits_.resize(lines_.size());
  for (size_t i = 0; i < lines_.size(); ++i) {
    const auto y = static_cast<int>(i / lanes), l = static_cast<int>(i % lanes);
    const RleLine& words = line(y, l);
    if (!rle_for_each_pixel(words.data(), words.size(), lane_width(l), [](int, const Pixel&) {})) malformed(y, l);
    flits_[i] = static_cast<uint32_t>(rle_flits(words));
  }
}

void SlabImage::insert(int x, int y, const Pixel& px, const Precision& p) {
  if (lines_.empty()) {
    lines_.resize(static_cast<size_t>(beams_) * lanes_);
    flits_.resize(lines_.size());
  }
  const int lane = x % lanes_, at = x / lanes_;  // one division
  const size_t i = static_cast<size_t>(y) * lanes_ + lane;
  RleLine& l = lines_[i];
  if (l.empty()) {
    l.reserve(32);  // room for a few fragments without growing
    l = cleared_[static_cast<size_t>(lane)];
    flits_[i] = lane < width_;  // one run, if the lane has pixels
  }
  ++inserts_;
  // Fig. 13 copies the whole line, flits_[i] of them; the line is canonical
  // (made by inserts alone), so Algorithm 1 need not walk past the pixel to
  // refuse a malformed tail.
  copied_flits_ += flits_[i];
  if (!blank(px)) flits_[i] += static_cast<uint32_t>(insert_through(l, lane_width(lane), at, px, p).added);
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

}  // namespace cube4::golden
