#include "systemc/core/stream_former.hpp"

#include <stdexcept>
#include <string>

namespace cube4::sysc {

StreamFormer::StreamFormer(const FramePlan& plan, VoxelMemory& mem, AddrIf& addr, int frames)
    : plan_(plan), mem_(mem), addr_(addr), frames_(frames) {
  at_.pass = plan_.first_pass();
  for (int pass = plan_.first_pass(); pass < plan_.passes; ++pass) {
    slices_.push_back(plan_.pass_voxel_slice(pass));
    tags_.push_back(plan_.pass_tag(pass));
  }
  // The first beat reads: issue it now, so its access arrives with it.
  const Pos first = next_read(at_);
  if (first.frame < frames_) {
    addr_.clock(request_for(first), first.j, first.y, slice(first.pass));
  }
}

StreamFormer::Pos StreamFormer::following(Pos p) const {
  if (++p.j == plan_.B) {
    p.j = 0;
    const int passes = plan_.passes_in_stream(p.frame + 1 == frames_);
    if (++p.y == plan_.beams(p.frame + 1 == frames_ && p.pass + 1 == passes)) {
      p.y = 0;
      if (++p.pass == passes) {
        p.pass = plan_.first_pass();
        ++p.frame;
      }
    }
  }
  return p;
}

StreamFormer::Pos StreamFormer::next_read(Pos p) const {
  while (p.frame < frames_ && !reads(p)) p = following(p);
  return p;
}

AddrRequest StreamFormer::request_for(const Pos& p) const {
  AddrRequest r;
  r.issue = true;
  if (p.y != plan_.ny - 1 || p.j != plan_.B - 1) return r;  // not a slice's last partial beam
  // The next pass that reads, in this frame: the same slice again?
  const int z = slice(p.pass);
  for (int pass = p.pass + 1; pass < plan_.passes_in_stream(p.frame + 1 == frames_); ++pass) {
    const int zn = slice(pass);
    if (zn < plan_.nz) {
      r.repeat_slice = zn == z;
      return r;
    }
  }
  r.again = p.frame + 1 < frames_;  // the frame's last read
  return r;
}

VoxelBeat StreamFormer::next() {
  VoxelBeat b;
  if (done()) return b;
  const Pos cur = at_;
  const PassStep st = plan_.step(cur.pass, cur.y, cur.j);
  b.valid = true;
  b.f = st.f;
  b.wx = st.wx;
  b.wy = st.wy;
  b.wz = st.wz;
  b.tag = tags_[static_cast<size_t>(cur.pass - plan_.first_pass())];
  // One edge of the address generator: it answers this beat's read (issued
  // at the previous edge) and takes the next beat's, if that one reads.
  at_ = following(cur);
  AddrRequest req;
  int nj = 0, ny = 0, nz = 0;
  if (reads(at_)) {
    req = request_for(at_);
    nj = at_.j;
    ny = at_.y;
    nz = slice(at_.pass);
  }
  const AddrResult& a = addr_.clock(req, nj, ny, nz);
  if (const AddrResult* soon = addr_.upcoming())
    for (int m = 0; m < plan_.p; ++m) mem_.prefetch(m, soon->access.module_index[static_cast<size_t>(m)]);
  mem_.begin_cycle();
  if (reads(cur)) {
    const int z = slice(cur.pass);
    if (!a.valid || a.j != cur.j || a.y != cur.y || a.z != z)
      throw std::logic_error("address generation (" + std::string(level_name(addr_.level())) + "): expected partial beam (j " +
                             std::to_string(cur.j) + ", y " + std::to_string(cur.y) + ", z " + std::to_string(z) +
                             "), got " + (a.valid ? "(j " + std::to_string(a.j) + ", y " + std::to_string(a.y) + ", z " +
                                                        std::to_string(a.z) + ")"
                                                  : std::string("none")));
    // Each module is read once at the index the address generator gives
    // it; the de-skew rotation then hands pipeline k its module's word.
    uint16_t word[golden::kMaxSkewPipes];
    for (int m = 0; m < plan_.p; ++m) word[m] = mem_.read(m, a.access.module_index[static_cast<size_t>(m)]);
    golden::deskew(a.access, plan_.p, word, b.voxel.data());
  } else if (a.valid) {
    throw std::logic_error("address generation: a partial beam arrived for a beat that reads nothing");
  }
  ++beats_;
  return b;
}

}  // namespace cube4::sysc
