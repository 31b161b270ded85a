// Run-length decoder of slab images (Cube-5 §5): one per pipeline, turning
// its encoded scanline back into one polygon pixel per cycle, in the order
// the pipeline meets its samples.
//
// Format of a scanline (Cube-5 §5, "runs of blank pixels"): 16-bit words,
// flit by flit, each flit either
//   a pixel:  R, G, B, A          4 words, not all zero: one pixel
//   a run:    0, 0, 0, 0, L       5 words: L + 1 blank pixels (L = 0..65535)
// The four words of a pixel are a polygon pixel (golden/units/
// composite_polygon.hpp: premultiplied, alpha_bits each), so a flit whose
// first four words are zero can only be a run. The paper's run word holds
// the length less one (one byte covers its 256-pixel lines); ours covers
// lines of up to 65536 pixels. A line of width 0 has no flits.
//
// Per pipeline: the slab image of a beam is stored as p lines, line l
// holding the pixels x = l, l + p, l + 2p, ... (pipeline l's samples of the
// beam's partial beams, Cube-4 §5), so each pipeline's decoder reads its own
// line and outputs a pixel every cycle (golden/rle_buffer.hpp builds them).
#pragma once
#include <cstddef>
#include <cstdint>

#include "golden/units/composite.hpp"

namespace cube4::golden {

inline constexpr int kRleRunMax = 65536;  // pixels in one run flit

// The flit at words[at]: a pixel (one pixel, 4 words) or a run of blank
// pixels (5 words); ok is false if the line ends inside it. The one reading
// of the format, for the decoder below and every walk over a line.
struct RleFlit {
  Pixel px;             // blank for a run
  uint32_t length = 0;  // pixels
  uint32_t words = 0;
  bool ok = false;
};
constexpr RleFlit rle_flit(const uint16_t* w, size_t count, size_t at) {
  if (at + 4 > count) return {};
  const Pixel px{w[at], w[at + 1], w[at + 2], w[at + 3]};
  if ((px.r | px.g | px.b | px.a) != 0) return {px, 1, 4, true};
  if (at + 5 > count) return {};
  return {px, uint32_t{w[at + 4]} + 1, 5, true};
}

// The decoder's state: where it is in the line and how many blank pixels
// of the current run are still to come. next() is one cycle.
class RleDecoder {
 public:
  constexpr RleDecoder(const uint16_t* words, size_t count) : w_(words), count_(count) {}

  // The next pixel of the line. Reading past the line's words (a malformed
  // line) gives blank pixels and sets error().
  constexpr Pixel next() {
    if (run_left_ > 0) {
      --run_left_;
      return {};
    }
    const RleFlit f = rle_flit(w_, count_, at_);
    if (!f.ok) {
      error_ = true;
      return {};
    }
    at_ += f.words;
    run_left_ = f.length - 1;  // this cycle's pixel is the flit's first
    return f.px;
  }
  // Every word read and no run left over: the line had exactly the pixels
  // asked of it.
  constexpr bool finished() const { return !error_ && run_left_ == 0 && at_ == count_; }
  constexpr bool error() const { return error_; }

 private:
  const uint16_t* w_;
  size_t count_;
  size_t at_ = 0;
  uint32_t run_left_ = 0;
  bool error_ = false;
};

// Decodes a line of `pixels` pixels into out[0], out[stride], ...; true if
// the line held exactly that many.
constexpr bool rle_decode_line(const uint16_t* words, size_t count, int pixels, Pixel* out, int stride = 1) {
  RleDecoder d(words, count);
  for (int i = 0; i < pixels; ++i) out[static_cast<size_t>(i) * stride] = d.next();
  return d.finished();
}

// Calls visit(i, px) for each pixel i of the line that is not blank, a
// run at a time (the decoder's output without its blank cycles); true if
// the line held exactly `pixels` pixels, as rle_decode_line() would say.
template <class Visit>
constexpr bool rle_for_each_pixel(const uint16_t* words, size_t count, int pixels, Visit&& visit) {
  size_t at = 0;
  int64_t i = 0;
  while (i < pixels) {
    const RleFlit f = rle_flit(words, count, at);
    if (!f.ok) return false;
    if (f.words == 4) visit(static_cast<int>(i), f.px);
    at += f.words;
    i += f.length;
  }
  return i == pixels && at == count;
}

}  // namespace cube4::golden
