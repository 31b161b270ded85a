#include "systemc/core/stream_former.hpp"

namespace cube4::sysc {

StreamFormer::StreamFormer(const FramePlan& plan, VoxelMemory& mem, int frames)
    : plan_(plan), mem_(mem), frames_(frames) {
  traversal_.perm = plan.r.perm;
  traversal_.flip = plan.r.flip;
}

VoxelBeat StreamFormer::next() {
  VoxelBeat b;
  if (done()) return b;
  b.valid = true;
  b.f.beam_start = j_ == 0;
  b.f.beam_end = j_ == plan_.B - 1;
  b.f.slice_start = y_ == 0;
  b.f.slice_end = y_ == plan_.ny;
  if (!plan_.zero_pass(pass_)) {
    const golden::SliceControl& c = plan_.slices[static_cast<size_t>(pass_)];
    b.wx = c.wx;
    b.wy = c.wy;
    b.wz = c.wz;
  }
  b.tag = plan_.pass_tag(pass_);
  const int z = plan_.pass_voxel_slice(pass_);
  mem_.begin_cycle();
  if (y_ < plan_.ny && z < plan_.nz) {
    const golden::BeamAccess a = golden::beam_access(mem_.layout(), traversal_, y_, z, j_);
    // Each module is read once at the index the address generator gives
    // it; the de-skew rotation then hands pipeline k its module's word.
    uint16_t word[golden::kMaxSkewPipes];
    for (int m = 0; m < plan_.p; ++m) word[m] = mem_.read(m, a.module_index[static_cast<size_t>(m)]);
    for (int k = 0; k < plan_.p; ++k) {
      const int m = a.reverse ? ((a.rotation - k) % plan_.p + plan_.p) % plan_.p : (a.rotation + k) % plan_.p;
      b.voxel[static_cast<size_t>(k)] = word[m];
    }
  }
  ++beats_;
  if (++j_ == plan_.B) {
    j_ = 0;
    if (++y_ > plan_.ny) {
      y_ = 0;
      if (++pass_ == plan_.passes) {
        pass_ = 0;
        ++frame_;
      }
    }
  }
  return b;
}

}  // namespace cube4::sysc
