// What the host hands the hardware for a frame with polygons (Cube-5 §5),
// besides the registers: integers only, made by the host rasteriser
// (golden/polygons.hpp), consumed by the compositor (SliceCompositor,
// golden/units/composite_polygon.hpp).
//
// Every translucent fragment of a ray lies in exactly one of three places,
// by its depth D (sample slices) and the slices [k_in, k_out] in which the
// ray has samples:
//   front    D <= k_in                in front of the ray's first sample
//   slab k   k < D <= k + 1           between samples k and k + 1, k_in <= k < k_out
//   back     D > k_out                behind its last sample
// (a ray with no sample at all: all in back). The opaque polygons give the
// ray its Z and, behind everything else in back, their colour.
#pragma once
#include <cstdint>
#include <vector>

#include "golden/rle_buffer.hpp"
#include "golden/units/composite.hpp"

namespace cube4::golden {

struct PolygonFrame {
  int width = 0, height = 0;     // the base plane's, margins included
  // Per base-plane pixel, row by row; loaded into the composite buffer
  // before the frame. front: the ray's starting value. back: composited
  // behind the ray when it leaves. z: the Z test's depth (kZBits,
  // kZFracBits; kZNone where no opaque polygon covers the ray).
  std::vector<Pixel> front, back;
  std::vector<uint32_t> z;
  // Per sample slice k: the slab image composited with that slice's samples,
  // pixel (x, y) behind sample (x, y). An empty SlabImage has no fragment.
  std::vector<SlabImage> slabs;

  // What the rasteriser produced, for reports and tests.
  struct Counts {
    uint64_t opaque = 0;       // opaque fragments drawn (before the depth test)
    uint64_t translucent = 0;  // translucent fragments kept (in front of the opaque surface)
    uint64_t hidden = 0;       // translucent fragments at or behind the opaque surface, dropped
    uint64_t in_front = 0, in_slabs = 0, behind = 0;
    // Triangles that drew an opaque fragment; per slab, the triangles with
    // a fragment in it (what the geometry engine sets up for that slab).
    uint64_t opaque_triangles = 0;
    std::vector<uint32_t> slab_triangles;
  } counts;
};

}  // namespace cube4::golden
