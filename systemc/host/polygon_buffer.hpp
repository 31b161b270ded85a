// The composite buffer's polygon images as the host loads them (Cube-5 §5;
// docs/registers.md, "Polygons"): the front, back and Z images of the base
// plane and one run-length slab image per sample slice, written through the
// POLY_* windows, handed to the frame START runs as a golden::PolygonFrame
// and consumed by it.
//
// The bus format of a slab image (the POLY_SLAB window of slice k) is the
// run-length lines of golden/units/rle_decode.hpp, beam by beam and lane by
// lane (SlabImage's order): per line one word holding its count of 16-bit
// words, then those words two a word, low half first. A slice never written
// has no fragment (SlabImage's empty image). encode_slab_stream() is the
// host's side of that format, frame() the interface's.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "golden/polygon_frame.hpp"
#include "golden/precision.hpp"
#include "systemc/host/register_map.hpp"

namespace cube4::sysc {

std::vector<uint32_t> encode_slab_stream(const golden::SlabImage& slab);
// Its length in words, without making it.
uint64_t slab_stream_words(const golden::SlabImage& slab);

class PolygonBuffer {
 public:
  // A word the buffer refused, or whose frame it refused: the error and the
  // address of the word at fault.
  struct Fault {
    regmap::ErrorCode code;
    uint64_t addr;
  };

  // Checks the n words of a write at addr (a POLY_* window) against size =
  // {POLY_WIDTH, POLY_HEIGHT, POLY_SLICES} and the precision's pixel width;
  // nothing is stored unless every word is taken.
  std::optional<Fault> write(uint64_t addr, const uint32_t* words, unsigned n, const std::array<int, 3>& size,
                             const golden::Precision& p);
  // The frame the images make for a base plane of width x height pixels,
  // `slices` sample slices of dim_x x dim_y samples and `lanes` pipelines,
  // or the fault that refuses it: a size other than the images', a slab
  // line that does not hold its lane's pixels. `result` is the frame:
  // `storage`, decoded from the windows' words, or the mapped frame itself.
  std::optional<Fault> frame(const std::array<int, 3>& size, int width, int height, int slices, int dim_x, int dim_y,
                             int lanes, golden::PolygonFrame& storage, const golden::PolygonFrame*& result) const;
  // The DMI-style load: the windows hold f's images (of `size`, checked by
  // the caller) without their words; f must outlive the mapping, which a
  // window write (the buffer then takes f's words and the write), clear()
  // or the frame that consumes it ends.
  void map(const golden::PolygonFrame& f, const std::array<int, 3>& size);
  // After a frame: every image blank (front and back 0, Z kZNone, no slab).
  void clear() {
    size_ = {0, 0, 0};
    mapped_ = nullptr;
  }

 private:
  // Starts blank images of this size if the buffer holds another.
  void fit(const std::array<int, 3>& size);
  // A mapped frame becomes the windows' words.
  void take_mapped();

  std::array<int, 3> size_{0, 0, 0};
  std::vector<uint32_t> front_, back_, z_;  // front/back: two words a pixel, as BASE_PLANE
  std::vector<std::vector<uint32_t>> slabs_;
  const golden::PolygonFrame* mapped_ = nullptr;
};

}  // namespace cube4::sysc
