#include "golden/rle_buffer.hpp"

#include <algorithm>
#include <cstdint>
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
// Words written into a line in place.
struct InPlace {
  uint16_t* at;
  void push_back(uint16_t v) { *at++ = v; }
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

[[noreturn]] void malformed_at(size_t count, size_t at) {
  throw std::logic_error(at + 4 > count ? "malformed RLE line: it ends before its width"
                                        : "malformed RLE line: a run without its length");
}

// Room an insert may need beyond a line's words: a run's 5 words split into
// a run, a pixel and a run (14).
constexpr size_t kSplitGrowth = 9;

// Where Algorithm 1's walk stands after the flit that holds x.
struct Walk {
  size_t at = 0;      // the next flit's first word
  int64_t total = 0;  // pixels walked
  size_t flits = 0;   // flits of the line before the insert, walked so far
  int added = 0;      // flits the insert added to the line (a run split in up to three)
};

// Algorithm 1 up to and through the flit holding x: px blended in there,
// a run split around it. Stops there: the rest of the line is unchanged.
// The line is words[0, count), with room for kSplitGrowth more words;
// count becomes the changed line's. kWellFormed: the caller knows the
// line's flits hold exactly `width` pixels (a slab image's line), so the
// walk need not check that each flit lies within the line.
template <bool kWellFormed>
Walk insert_through(uint16_t* words, size_t& count, int width, int x, const Pixel& px, const Precision& p) {
  Walk w;
  if (x < 0 || x >= width) return w;  // no pixel of the line: nothing to insert
  uint32_t length = 1, size = 4;
  // The flit holding x: total <= x throughout, as x >= 0.
  for (;; w.at += size, w.total += length) {
    if (!kWellFormed && w.at + 4 > count) malformed_at(count, w.at);
    uint64_t four;  // a pixel flit's four words, all zero for a run
    std::memcpy(&four, words + w.at, sizeof four);
    if (four != 0) {
      length = 1, size = 4;
    } else {
      if (!kWellFormed && w.at + 5 > count) malformed_at(count, w.at);
      length = uint32_t{words[w.at + 4]} + 1, size = 5;
    }
    ++w.flits;
    if (x < w.total + length) break;
  }
  if (size == 4) {
    const Pixel b = pixel_over({words[w.at], words[w.at + 1], words[w.at + 2], words[w.at + 3]}, px, p);
    words[w.at] = b.r;
    words[w.at + 1] = b.g;
    words[w.at + 2] = b.b;
    words[w.at + 3] = b.a;
    w.at += 4;
  } else {  // split the run's 5 words around the new pixel: a run, the pixel, a run
    const int64_t before = x - w.total, after = w.total + length - x - 1;
    const size_t n = (before > 0 ? 5 : 0) + 4 + (after > 0 ? 5 : 0);
    // The run's 5 words make room for the split's n: the tail moves, and
    // the split is written in place (not staged: the copy of a staged
    // split's 16-bit words stalled on their stores).
    const size_t tail = w.at + 5;
    std::memmove(words + w.at + n, words + tail, (count - tail) * sizeof(uint16_t));
    InPlace split{words + w.at};
    put_run(split, before);
    put_pixel(split, pixel_over(Pixel{}, px, p));
    put_run(split, after);
    count = count + n - 5;
    w.at += n;
    w.added = (before > 0) + (after > 0);  // the runs left beside the pixel
  }
  w.total += length;
  return w;
}

}  // namespace

size_t rle_insert_into(RleLine& line, int width, int x, const Pixel& px, const Precision& p) {
  if (blank(px)) return rle_flits(line);
  size_t count = line.size();
  // The room the insert may need, and back to the line's words after it,
  // whether it inserted or refused a malformed line.
  struct Room {
    RleLine& line;
    const size_t& count;
    ~Room() { line.resize(count); }
  } room{line, count};
  line.resize(count + kSplitGrowth);
  Walk w = insert_through<false>(line.data(), count, width, x, px, p);
  // On over the rest of the line, as Fig. 13's hardware copies it (so a
  // malformed tail is refused wherever the fragment falls).
  while (w.total < width) {
    const RleFlit f = rle_flit(line.data(), count, w.at);
    if (!f.ok) malformed_at(count, w.at);
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

size_t rle_flits(RleWords line) {
  size_t flits = 0;
  for (size_t at = 0; at + 4 <= line.size(); ++flits) {
    const RleFlit f = rle_flit(line.data(), line.size(), at);
    at += f.ok ? f.words : 5;  // a run cut short ends the line
  }
  return flits;
}

SlabImage::SlabImage(int width, int beams, int lanes) : width_(width), beams_(beams), lanes_(lanes) {
  if (lanes > 0 && (lanes & (lanes - 1)) == 0)
    for (lane_shift_ = 0; (1 << lane_shift_) < lanes; ++lane_shift_) {
    }
  for (int l = 0; l < lanes_; ++l) {
    lane_widths_.push_back(l < width_ ? (width_ - l + lanes_ - 1) / lanes_ : 0);
    RleLine c = rle_clear(lane_widths_.back());
    words_ += static_cast<uint64_t>(beams) * c.size();
    odd_lines_ += c.size() % 2 ? static_cast<uint64_t>(beams) : 0;
    lane_flits_.push_back(static_cast<uint64_t>(beams) * rle_flits(c));
    c.resize(5);  // a lane without pixels: no words (cleared() reads none)
    cleared_.insert(cleared_.end(), c.begin(), c.end());
  }
}

SlabImage::SlabImage(int width, int beams, int lanes, std::vector<RleLine> lines)
    : SlabImage(width, beams, lanes) {
  if (lines.size() != static_cast<size_t>(beams) * lanes)
    throw std::logic_error("slab image: " + std::to_string(lines.size()) + " lines for " + std::to_string(beams) +
                           " beams of " + std::to_string(lanes) + " lanes");
  slots_.resize(lines.size());
  for (size_t i = 0; i < lines.size(); ++i) {
    const auto y = static_cast<int>(i / lanes), l = static_cast<int>(i % lanes);
    const RleLine& words = lines[i];
    const RleWords checked = words.empty() ? cleared(l) : RleWords(words);
    if (!rle_for_each_pixel(checked.data(), checked.size(), lane_width(l), [](int, const Pixel&) {})) malformed(y, l);
    if (words.empty()) continue;
    Slot& s = slots_[i];
    s.at = static_cast<uint32_t>(pool_.size());
    s.size = s.cap = static_cast<uint32_t>(words.size());
    s.flits = static_cast<uint32_t>(rle_flits(words));
    pool_.insert(pool_.end(), words.begin(), words.end());
    const RleWords was = cleared(l);
    words_ += s.size - was.size();
    odd_lines_ += s.size % 2 - was.size() % 2;
    lane_flits_[static_cast<size_t>(l)] += s.flits - rle_flits(was);
  }
}

void SlabImage::move_to_end(Slot& s, int lane, uint32_t cap) {
  const size_t end = pool_.size();
  if (end + cap > UINT32_MAX) throw std::length_error("slab image: more than 2^32 words of lines");
  pool_.resize(end + cap);
  if (s.cap == 0) {
    const RleWords c = cleared(lane);
    std::copy(c.begin(), c.end(), pool_.begin() + static_cast<std::ptrdiff_t>(end));
    s.size = static_cast<uint32_t>(c.size());
    s.flits = lane < width_;  // one run, if the lane has pixels
  } else {
    std::copy_n(pool_.begin() + s.at, s.size, pool_.begin() + static_cast<std::ptrdiff_t>(end));
  }
  s.at = static_cast<uint32_t>(end);
  s.cap = cap;
}

void SlabImage::insert(int x, int y, const Pixel& px, const Precision& p) {
  if (slots_.empty()) {
    slots_.resize(static_cast<size_t>(beams_) * lanes_);
    pool_.reserve(1024);
  }
  // A shift, not a division per fragment, for the usual power-of-two
  // pipeline counts.
  const int lane = lane_shift_ >= 0 ? x & (lanes_ - 1) : x % lanes_;
  const int at = lane_shift_ >= 0 ? x >> lane_shift_ : x / lanes_;
  Slot& s = slots_[static_cast<size_t>(y) * lanes_ + lane];
  // Room for several fragments (a slab line of a surface seen obliquely
  // holds a few), and no more than the lane's longest line can use (a flit
  // of 4 words per pixel, a run of 5 for every other one, an insert's room).
  if (s.cap == 0) {
    const auto w = static_cast<uint32_t>(lane_width(lane));
    move_to_end(s, lane, std::min<uint32_t>(64, 4 * w + 5 * ((w + 1) / 2) + kSplitGrowth));
  }
  ++inserts_;
  // Fig. 13 copies the whole line, s.flits of them; the line is canonical
  // (made by inserts alone), so Algorithm 1 need not walk past the pixel to
  // refuse a malformed tail.
  copied_flits_ += s.flits;
  if (blank(px)) return;
  if (s.size + kSplitGrowth > s.cap) move_to_end(s, lane, 2 * s.cap);
  size_t count = s.size;
  const int added = insert_through<true>(pool_.data() + s.at, count, lane_width(lane), at, px, p).added;
  s.flits += static_cast<uint32_t>(added);
  lane_flits_[static_cast<size_t>(lane)] += static_cast<uint64_t>(added);
  words_ += count - s.size;  // modulo 2^64: right for a line that shrinks, too
  odd_lines_ += count % 2 - s.size % 2;
  s.size = static_cast<uint32_t>(count);
}

void SlabImage::decode_beam(int y, Pixel* out) const {
  for (int l = 0; l < lanes_ && l < width_; ++l) {
    if (empty()) {
      for (int x = l; x < width_; x += lanes_) out[x] = Pixel{};
      continue;
    }
    const RleWords words = line(y, l);
    if (!rle_decode_line(words.data(), words.size(), lane_width(l), out + l, lanes_)) malformed(y, l);
  }
}

void SlabImage::malformed(int y, int lane) {
  throw std::logic_error("malformed RLE line in a slab image (beam " + std::to_string(y) + ", lane " +
                         std::to_string(lane) + ")");
}

}  // namespace cube4::golden
