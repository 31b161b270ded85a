// Frames allocate and free the same large buffers again and again (the
// base plane, ray stores, voxel and sample slices, polygon images): kept in
// the heap rather than mapped and returned to the kernel each time, they
// cost no page faults after the first frame (docs/performance.md, "What
// polygons cost the simulation"). Volumes above 32 MiB are still mapped.
// Called first thing by the programs that render frames: cube4 and the
// benchmarks that time it.
#pragma once
#include <malloc.h>

namespace cube4 {

inline void keep_frame_buffers_in_heap() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

}  // namespace cube4
