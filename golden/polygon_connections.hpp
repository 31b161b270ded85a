// The frame time of Cube-5's two ways of connecting a polygon engine to the
// volume pipelines (Kreeger and Kaufman 1999, §§4-6), from what a frame's
// polygons load onto each slab:
//
//  - the run-length (RLE) frame buffer (§5, Fig. 15): the geometry engine
//    rasterises slab k + 1 into one half of a double-buffered run-length
//    buffer while the pipelines composite slice k with slab k from the
//    other, so a slab costs the longest of the slice, the slab's reading (a
//    flit per pipeline per clock) and the next slab's rasterisation. That
//    rasterisation is bounded by the engine's fill and triangle rates and by
//    Fig. 13's insert, which copies the fragment's whole line a flit per
//    clock of the buffer. Opaque polygons are drawn during the previous
//    frame's volume (§5) and cost nothing unless they take longer than it.
//  - the dual-use DRAM frame buffer (§4, Fig. 9): the two engines take
//    turns at one shared buffer ("either the geometry sub-system or the
//    Cube-5 sub-system is stalled"): the opaque polygons first, then each
//    slice and its slab one after the other. The volume keeps its rate
//    (§4: the buffer's bursts leave refresh its share and the pipelines
//    theirs); polygons fill at the buffer's random-access pixel rate.
//
// Rates are §6's assumptions (golden Scene::polygon_engine, scene keys
// under "polygon_engine": docs/scene.md). A performance model of the
// host-side connection, not a cycle-level one: the volume's time is its
// slices' beats, without the stream's zero pass and drain (docs/
// performance.md, "Cube-5: the two connections").
#pragma once
#include <cstdint>
#include <vector>

#include "golden/polygon_frame.hpp"
#include "golden/scene.hpp"

namespace cube4::golden {

// What one slab loads onto the connections.
struct SlabLoad {
  uint64_t fragments = 0;     // translucent fragments in the slab
  uint64_t triangles = 0;     // triangles with a fragment in it
  uint64_t copied_flits = 0;  // flits Fig. 13's inserts copied building it
  uint64_t read_flits = 0;    // the busiest pipeline's flits reading it
  uint64_t flits = 0;         // every pipeline's
  uint64_t words = 0;         // 16-bit words of its lines
};

// Per slab of the frame, from its run-length images and the rasteriser's
// counts (an empty slab: its cleared lines, a run flit each, to read).
std::vector<SlabLoad> slab_loads(const PolygonFrame& f);

struct ConnectionTimes {
  double volume_s = 0;  // the slices alone: volume-only frame
  double opaque_s = 0;  // the opaque polygons' drawing, once a frame
  double rle_s = 0;     // frame time through the run-length buffer
  double dual_s = 0;    // frame time through the dual-use buffer
  uint64_t rle_slabs_over_slice = 0;  // slabs that lengthen their slice (RLE)
};

// A frame's drawing work for the geometry engine: per slab, and its
// opaque polygons (the rasteriser's counts).
struct PolygonWork {
  std::vector<SlabLoad> slabs;
  uint64_t opaque_fragments = 0, opaque_triangles = 0;
};
PolygonWork polygon_work(const PolygonFrame& f);

// The geometry engine's time to draw what a slab holds: into the run-length
// buffer (fill and triangle rates, and Fig. 13's insert copying a flit per
// buffer clock), or into the dual-use buffer (its pixel rate); and the
// opaque polygons' time, at a given fill rate.
double rle_draw_seconds(const SlabLoad& l, const PolygonEngine& e);
double dual_draw_seconds(const SlabLoad& l, const PolygonEngine& e);
double opaque_draw_seconds(uint64_t fragments, uint64_t triangles, double fill_rate, const PolygonEngine& e);

// slice_cycles: one sample slice's cycles at clock_hz (every slice alike,
// as the cycle model streams them); slabs: one load per slice.
ConnectionTimes connection_times(const std::vector<SlabLoad>& slabs, uint64_t slice_cycles, double clock_hz,
                                 uint64_t opaque_fragments, uint64_t opaque_triangles, const PolygonEngine& e);

}  // namespace cube4::golden
