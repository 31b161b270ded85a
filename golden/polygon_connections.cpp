#include "golden/polygon_connections.hpp"

#include <algorithm>

namespace cube4::golden {

std::vector<SlabLoad> slab_loads(const PolygonFrame& f) {
  std::vector<SlabLoad> out(f.slabs.size());
  for (size_t k = 0; k < f.slabs.size(); ++k) {
    const SlabImage& s = f.slabs[k];
    SlabLoad& l = out[k];
    l.fragments = s.inserts();
    l.copied_flits = s.copied_flits();
    l.triangles = k < f.counts.slab_triangles.size() ? f.counts.slab_triangles[k] : 0;
    l.words = s.words();
    for (int lane = 0; lane < s.lanes(); ++lane) {
      l.flits += s.lane_flits(lane);
      l.read_flits = std::max(l.read_flits, s.lane_flits(lane));
    }
  }
  return out;
}

PolygonWork polygon_work(const PolygonFrame& f) { return {slab_loads(f), f.counts.opaque, f.counts.opaque_triangles}; }

double opaque_draw_seconds(uint64_t fragments, uint64_t triangles, double fill_rate, const PolygonEngine& e) {
  return std::max(static_cast<double>(fragments) / fill_rate, static_cast<double>(triangles) / e.triangle_rate);
}

double rle_draw_seconds(const SlabLoad& l, const PolygonEngine& e) {
  return std::max(opaque_draw_seconds(l.fragments, l.triangles, e.fill_rate, e),
                  static_cast<double>(l.copied_flits) / e.rle_clock_hz);
}

double dual_draw_seconds(const SlabLoad& l, const PolygonEngine& e) {
  return opaque_draw_seconds(l.fragments, l.triangles, e.dual_fill_rate, e);
}

ConnectionTimes connection_times(const std::vector<SlabLoad>& slabs, uint64_t slice_cycles, double clock_hz,
                                 uint64_t opaque_fragments, uint64_t opaque_triangles, const PolygonEngine& e) {
  ConnectionTimes t;
  const double slice_s = static_cast<double>(slice_cycles) / clock_hz;
  t.opaque_s = opaque_draw_seconds(opaque_fragments, opaque_triangles, e.fill_rate, e);
  const double opaque_dual_s = opaque_draw_seconds(opaque_fragments, opaque_triangles, e.dual_fill_rate, e);
  // RLE: slab k + 1 is drawn while slice k composites with slab k; slab 0
  // before any.
  std::vector<double> draw_s(slabs.size());
  for (size_t k = 0; k < slabs.size(); ++k) draw_s[k] = rle_draw_seconds(slabs[k], e);
  double rle = draw_s.empty() ? 0.0 : draw_s[0];
  for (size_t k = 0; k < slabs.size(); ++k) {
    const SlabLoad& l = slabs[k];
    const double composite_s = std::max(slice_s, static_cast<double>(l.read_flits) / clock_hz);
    const double step = std::max(composite_s, k + 1 < slabs.size() ? draw_s[k + 1] : 0.0);
    if (step > slice_s) ++t.rle_slabs_over_slice;
    rle += step;
    t.volume_s += slice_s;
    t.dual_s += slice_s + dual_draw_seconds(l, e);
  }
  // The opaque polygons overlap the previous frame's volume (RLE) or come
  // first (dual use).
  t.rle_s = std::max(rle, t.opaque_s);
  t.dual_s += opaque_dual_s;
  return t;
}

}  // namespace cube4::golden
