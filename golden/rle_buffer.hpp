// The run-length-encoded frame buffer of translucent polygon slabs
// (Cube-5 §5, Fig. 13, Algorithm 1): the polygon side's store, which takes
// fragments in any order and hands each slab image, scanline by scanline,
// to the Cube pipelines' decoders (golden/units/rle_decode.hpp, where the
// format is defined).
//
// rle_insert() is the paper's RLE_AddPixelToScanline: the encoded line is
// copied flit by flit into a new one, the new pixel blended in at its
// position, a run of blank pixels split around it (rle_insert_into() makes
// the same line in place, without the copy: the flits the hardware copies
// are counted by rle_flits()). Read literally, the
// paper's pseudo-code has three faults at run ends, which ours does not
// share (the tests insert at every position of every kind of line):
//  - a fragment on the last pixel of a run longer than one is never
//    inserted (the split condition is `total + length > xPos`, with the
//    run word being the length less one);
//  - a fragment on a one-pixel run leaves a run of length zero (a run
//    word of -1) behind;
//  - after copying a whole run, `total` advances by the run word, one
//    pixel short.
// Every line the functions below make is canonical: no two run flits
// adjacent, no empty run, the pixels adding up to the line's width; the
// insert keeps a canonical line canonical (it only splits runs).
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "golden/precision.hpp"
#include "golden/units/composite_polygon.hpp"
#include "golden/units/rle_decode.hpp"

namespace cube4::golden {

using RleLine = std::vector<uint16_t>;

// A line's words where they are kept (an RleLine, or a slab image's store),
// valid while that line is not changed.
class RleWords {
 public:
  using value_type = uint16_t;
  using const_iterator = const uint16_t*;
  using iterator = const_iterator;
  RleWords() = default;
  RleWords(const uint16_t* words, size_t count) : words_(words), count_(count) {}
  RleWords(const RleLine& line) : words_(line.data()), count_(line.size()) {}  // NOLINT: a line is its words
  const uint16_t* data() const { return words_; }
  size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  const uint16_t* begin() const { return words_; }
  const uint16_t* end() const { return words_ + count_; }
  uint16_t operator[](size_t i) const { return words_[i]; }
  RleLine line() const { return RleLine(begin(), end()); }
  friend bool operator==(const RleWords& a, const RleWords& b) {
    return a.count_ == b.count_ && std::equal(a.begin(), a.end(), b.begin());
  }
  friend bool operator!=(const RleWords& a, const RleWords& b) { return !(a == b); }

 private:
  const uint16_t* words_ = nullptr;
  size_t count_ = 0;
};

// A cleared line: one run of `width` blank pixels (no flit for width 0).
RleLine rle_clear(int width);
RleLine rle_encode(const Pixel* pixels, int width);
// Throws std::logic_error if the line does not hold exactly `width` pixels.
std::vector<Pixel> rle_decode(const RleLine& line, int width);
// Algorithm 1: the line with `px` blended in at x, behind what the line
// holds there (fragments are inserted front to back: pixel_over(old, px)).
// A blank px changes nothing.
RleLine rle_insert(const RleLine& line, int width, int x, const Pixel& px, const Precision& p);
// The same insert on the line itself; returns the flits of the line
// before it (rle_flits(): what the hardware copies). Throws
// std::logic_error, as rle_insert() does, on a line that does not hold
// `width` pixels.
size_t rle_insert_into(RleLine& line, int width, int x, const Pixel& px, const Precision& p);
// Flits in a line: the cycles Fig. 13's hardware spends copying it.
size_t rle_flits(RleWords line);

// One slab image: the fragments of one thin slab, for every beam y of the
// sample slice and every pipeline lane (golden/units/rle_decode.hpp).
class SlabImage {
 public:
  SlabImage() : SlabImage(0, 0, 1) {}
  SlabImage(int width, int beams, int lanes);
  // An image from its beams x lanes lines, beam by beam (as line() orders
  // them), e.g. as a bus delivered them; an empty line stands for its
  // lane's cleared line. Throws std::logic_error unless every line holds
  // exactly its lane's pixels.
  SlabImage(int width, int beams, int lanes, std::vector<RleLine> lines);
  int width() const { return width_; }
  int beams() const { return beams_; }
  int lanes() const { return lanes_; }
  // Pixels of lane l of a beam: x = l, l + lanes, ... < width.
  int lane_width(int lane) const { return lane_widths_[static_cast<size_t>(lane)]; }
  // No fragment at all: the lines are not even stored (every one cleared).
  bool empty() const { return slots_.empty(); }
  // Valid until the next insert.
  RleWords line(int y, int lane) const {
    if (slots_.empty()) return cleared(lane);
    const Slot& s = slots_[static_cast<size_t>(y) * lanes_ + lane];
    return s.cap == 0 ? cleared(lane) : RleWords(pool_.data() + s.at, s.size);
  }
  // Inserts a fragment at (x, y) with rle_insert on its lane's line.
  void insert(int x, int y, const Pixel& px, const Precision& p);
  // Beam y as the p decoders deliver it: out[x] for x in [0, width).
  // Throws std::logic_error on a malformed line.
  void decode_beam(int y, Pixel* out) const;
  // visit(x, px) for each pixel of beam y that is not blank, lane by lane
  // (decode_beam() without the blank pixels). Throws std::logic_error on a
  // malformed line.
  template <class Visit>
  void for_each_pixel(int y, Visit&& visit) const {
    if (empty()) return;
    for (int l = 0; l < lanes_ && l < width_; ++l) {
      const Slot& s = slots_[static_cast<size_t>(y) * lanes_ + l];
      if (s.cap == 0) continue;  // never inserted into: its lane's cleared line, all blank
      if (!rle_for_each_pixel(pool_.data() + s.at, s.size, lane_width(l),
                              [&](int i, const Pixel& px) { visit(l + i * lanes_, px); }))
        malformed(y, l);
    }
  }
  // Flits in a line (rle_flits(line(y, lane))), kept as the line is built.
  uint32_t line_flits(int y, int lane) const {
    if (slots_.empty()) return lane < width_;
    const Slot& s = slots_[static_cast<size_t>(y) * lanes_ + lane];
    return s.cap == 0 ? lane < width_ : s.flits;
  }
  // Over all its lines (cleared ones too), kept as the lines change: the
  // words, the lines of an odd number of words, and each lane's flits
  // (the sum of line_flits(y, lane) over the beams).
  uint64_t words() const { return words_; }
  uint64_t odd_lines() const { return odd_lines_; }
  uint64_t lane_flits(int lane) const { return lane_flits_[static_cast<size_t>(lane)]; }
  // What building it cost Fig. 13's hardware: the fragments inserted and
  // the flits copied doing so (each insert copies its line, a flit a clock).
  uint64_t inserts() const { return inserts_; }
  uint64_t copied_flits() const { return copied_flits_; }

 private:
  // Where a line's words lie in pool_, and its flits (rle_flits()). A line
  // never inserted into has no room (cap 0) and reads as its lane's
  // cleared line, so that an image with a few fragments stores only the
  // lines they fall in.
  struct Slot {
    uint32_t at = 0, size = 0, cap = 0, flits = 0;
  };
  [[noreturn]] static void malformed(int y, int lane);
  RleWords cleared(int lane) const {
    return {cleared_.data() + 5 * static_cast<size_t>(lane), lane_widths_[static_cast<size_t>(lane)] > 0 ? 5u : 0u};
  }
  // Slot s's line (its lane's cleared line if it has none yet) moved to
  // the end of the pool, with room for `cap` words.
  void move_to_end(Slot& s, int lane, uint32_t cap);

  int width_ = 0, beams_ = 0, lanes_ = 1;
  int lane_shift_ = -1;  // log2(lanes_) if lanes_ is a power of two
  // Beam by beam, lane by lane.
  std::vector<Slot> slots_;
  // Every stored line's words, one allocation for the image: a line that
  // outgrows its room moves to the end with twice the room (its old words
  // stay behind, unused).
  std::vector<uint16_t> pool_;
  // Per lane, its cleared line (rle_clear()): 5 words, none for a lane
  // without pixels.
  std::vector<uint16_t> cleared_;
  // Per lane, its pixels: kept rather than divided out per fragment.
  std::vector<int> lane_widths_;
  uint64_t inserts_ = 0, copied_flits_ = 0;
  uint64_t words_ = 0, odd_lines_ = 0;
  std::vector<uint64_t> lane_flits_;
};

}  // namespace cube4::golden
