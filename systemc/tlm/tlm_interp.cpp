#include "systemc/tlm/tlm_interp.hpp"

namespace cube4::sysc {

TlmInterp::TlmInterp(const FramePlan& plan)
    : plan_(plan), pass_(plan.nx, plan.ny, 1), store_(plan.nx, plan.ny, 1), samples_(plan.nx, plan.ny, 1),
      tagged_(plan.r.p.tag_bits > 0), interp_(plan.nx, plan.ny, plan.r.p.weight_bits) {
  if (tagged_) {
    pass_tags_ = store_tags_ = above_tags_ = sample_tags_ = golden::Plane(plan.nx, plan.ny, 1);
    whole_.assign(static_cast<size_t>(plan.ny), golden::Span{0, plan.nx});
  }
  if (plan.zdiff) below_ = above_ = d_lo_ = d_hi_ = zdiffs_ = golden::Plane(plan.nx, plan.ny, 1);
}

void TlmInterp::end_of_pass(const VoxelBeat& in) {
  golden::SliceControl c;
  c.wx = in.wx;
  c.wy = in.wy;
  c.wz = in.wz;
  if (!plan_.zdiff) {
    // A pass with wz = 0 streams the slice its samples lie on and becomes
    // the stored slice; the others stream the slice above it.
    if (in.wz == 0) {
      std::swap(store_, pass_);
      std::swap(store_tags_, pass_tags_);
    }
    interp_.slice(store_, pass_, c, samples_);
    if (tagged_) interp_.tags(store_tags_, pass_tags_, c, sample_tags_, 0, plan_.ny, whole_.data());
    return;
  }
  // One slice ahead: a wz = 0 pass (and the priming pass) streams z + 1 and
  // moves the slices down by one; the others stream z + 2.
  if (in.f.prime || in.wz == 0) {
    std::swap(below_, store_);  // below = z - 1
    std::swap(store_, above_);  // store = z
    std::swap(above_, pass_);   // above = z + 1, streamed
    std::swap(store_tags_, above_tags_);
    std::swap(above_tags_, pass_tags_);
    if (in.f.prime) {  // slice -1 below the frame's first
      store_.clear();
      store_tags_.clear();
      return;
    }
    golden::voxel_z_differences(above_, below_, d_lo_);
  } else {
    golden::voxel_z_differences(pass_, store_, d_hi_);
  }
  interp_.slice(store_, above_, c, samples_);
  if (tagged_) interp_.tags(store_tags_, above_tags_, c, sample_tags_, 0, plan_.ny, whole_.data());
  // wz = 0 weighs D(z + 1) zero, so d_hi_ may hold any slice's.
  interp_.slice(d_lo_, d_hi_, c, zdiffs_);
}

void TlmInterp::emit_pass(uint64_t tag) {
  for (int y = 0; y < plan_.ny; ++y)
    for (int j = 0; j < plan_.B; ++j) {
      SampleBeat& b = out_.recycled_back();
      b.valid = true;
      b.f = {j == 0, j == plan_.B - 1, y == 0, y == plan_.ny - 1};
      b.tag = tag;
      for (int k = 0; k < plan_.p; ++k) {
        const int x = j * plan_.p + k;
        const auto i = static_cast<size_t>(k);
        const bool inside = x < plan_.nx;  // padding columns carry zeros
        b.sample[i] = inside ? static_cast<uint16_t>(samples_.at(x, y)) : 0;
        if (tagged_) b.vtag[i] = inside ? static_cast<uint8_t>(sample_tags_.at(x, y)) : 0;
        if (plan_.zdiff) b.zdiff[i] = inside ? zdiffs_.row(y)[x] : 0;
      }
    }
}

void TlmInterp::clock(const VoxelBeat& in, SampleBeat& out) {
  if (in.valid && in.f.flush) {
    // The RTL emits a pass's last sample beam here; this model emitted the
    // whole pass at its last beat, so a flush beam leaves the slot free
    // (a gradient unit's own zero beam runs in it).
    out_.push_back(SampleBeat{});
  } else if (in.valid) {
    if (in.f.slice_start && in.f.beam_start) y_ = 0;
    if (y_ < plan_.ny) {
      // The voxel word {tag, value}: the value in its voxel_bits, the tag above.
      const int bits = plan_.r.p.voxel_bits;
      int32_t* row = pass_.row(y_);
      for (int k = 0; k < plan_.p; ++k) {
        const int x = j_ * plan_.p + k;
        if (x >= plan_.nx) continue;
        const uint32_t word = in.voxel[static_cast<size_t>(k)];
        row[x] = static_cast<int32_t>(word & ((1u << bits) - 1u));
        if (tagged_) pass_tags_.row(y_)[x] = static_cast<int32_t>(word >> bits);
      }
    }
    ++j_;
    if (in.f.beam_end) {
      j_ = 0;
      ++y_;
    }
    if (in.f.slice_end && in.f.beam_end) {
      end_of_pass(in);
      if (!in.f.prime) emit_pass(in.tag);  // a priming pass has no samples
    }
  }
  if (out_.empty()) {
    out = SampleBeat{};
  } else {
    out_.pop_front(out);
  }
}

}  // namespace cube4::sysc
