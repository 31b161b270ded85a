#include "systemc/tlm/tlm_interp_persp.hpp"

#include "golden/perspective.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/units/gradient.hpp"

namespace cube4::sysc {
namespace {
// The box reaches a cell before the home and two after it, and the window
// two beams past the last row: zeros around the slice, as the volume's border.
constexpr int kPad = 3;
}  // namespace

TlmInterpPersp::TlmInterpPersp(const FramePlan& plan)
    : plan_(plan), voxel_bits_(plan.r.p.voxel_bits), tagged_(plan.r.p.tag_bits > 0) {}

std::shared_ptr<TlmInterpPersp::Slice> TlmInterpPersp::new_slice() const {
  auto s = std::make_shared<Slice>();
  s->voxels = golden::Plane(plan_.nx, plan_.ny, kPad);
  if (tagged_) s->tags = golden::Plane(plan_.nx, plan_.ny, kPad);
  return s;
}

void TlmInterpPersp::start_pass(const VoxelBeat& in) {
  ++pass_;
  streaming_ = new_slice();
  Pass& p = passes_[static_cast<size_t>(pass_ & 1)];
  p = Pass{};
  p.index = pass_;
  p.tag = in.tag;
  p.prime = in.f.prime;
  if (plan_.zdiff) {
    if (in.f.prime || in.wz == 0) {
      below_ = store_;
      store_ = above_;
      above_ = streaming_;
      if (in.f.prime) store_ = new_slice();  // slice -1 below the frame's first
    }
    p.below = below_;
    p.lo = store_;
    p.hi = above_;
    if (in.wz != 0) p.above = streaming_;
    return;
  }
  p.hi = streaming_;
  // A pass on a voxel slice (wz = 0) streams it and stores it; the others
  // stream the slice above the stored one.
  if (in.wz == 0) store_ = streaming_;
  p.lo = store_ ? store_ : streaming_;
}

void TlmInterpPersp::form(int64_t position, int lane, RaySampleBeat& out) const {
  const golden::FormedCell c =
      golden::formed_cell(position, static_cast<int64_t>(plan_.B) * plan_.p, plan_.nx, plan_.ny);
  if (!c.valid) return;
  const Pass& p = passes_[static_cast<size_t>(c.pass & 1)];
  if (p.index != c.pass || p.prime || p.tag >= static_cast<uint64_t>(plan_.K)) return;  // none, the priming or zero pass
  const golden::PerspectiveSlice& s = plan_.persp[static_cast<size_t>(p.tag)];
  const int F = plan_.r.p.dda_frac_bits, W = plan_.r.p.weight_bits;
  const golden::HomeLane hu = golden::home_lane(s.ray0_x, s.spacing, s.rays_x, c.x, F, W);
  const golden::HomeLane hv = golden::home_lane(s.ray0_y, s.spacing, s.rays_y, c.y, F, W);
  if (!hu.valid || !hv.valid) return;
  // Slice z_voxel is the lower (the stored slice when wz > 0), z_voxel + 1
  // the streamed one; with zdiff both are stored.
  const Slice& lo = s.wz == 0 && !plan_.zdiff ? *p.hi : *p.lo;
  const Slice& hi = *p.hi;
  auto voxel = [&](int x, int y, int dz) { return (dz == 0 ? lo : hi).voxels.at(x, y); };
  const auto k = static_cast<size_t>(lane);
  out.valid |= 1u << lane;
  out.sample[k] = static_cast<uint16_t>(golden::perspective_sample(plan_.r, s, hu.ray, hv.ray, voxel));
  out.u[k] = static_cast<int32_t>(hu.ray);
  out.v[k] = static_cast<int32_t>(hv.ray);
  out.tag[k] = static_cast<uint32_t>(p.tag);
  if (plan_.zdiff) {
    // D(z) = V(z + 1) - V(z - 1) and, weighed only when wz > 0, D(z + 1).
    auto difference = [&](int x, int y, int dz) {
      const Slice& above = dz == 0 ? hi : *p.above;
      const Slice& below = dz == 0 ? *p.below : lo;
      return golden::voxel_z_difference(static_cast<uint32_t>(above.voxels.at(x, y)),
                                        static_cast<uint32_t>(below.voxels.at(x, y)));
    };
    out.zdiff[k] = golden::perspective_z_difference(plan_.r, s, hu.ray, hv.ray, difference);
  }
  if (tagged_) {
    const golden::TagVoxel t = golden::perspective_tag_voxel(plan_.r, s, hu.ray, hv.ray);
    out.vtag[k] = static_cast<uint8_t>((t.dz == 0 ? lo : hi).tags.at(t.x, t.y));
  }
}

void TlmInterpPersp::clock(const VoxelBeat& in, RaySampleBeat& out) {
  RaySampleBeat& slot = delay_[clocks_++ & 3];
  out = slot;
  slot = RaySampleBeat{};
  if (!in.valid) return;
  if (!in.f.flush) {
    if (in.f.slice_start && in.f.beam_start) {
      start_pass(in);
      y_ = j_ = 0;
    }
    for (int k = 0; k < plan_.p; ++k) {
      const int x = j_ * plan_.p + k;
      if (x >= plan_.nx || y_ >= plan_.ny) continue;
      const uint32_t word = in.voxel[static_cast<size_t>(k)];
      streaming_->voxels.row(y_)[x] = static_cast<int32_t>(word & ((1u << voxel_bits_) - 1u));
      if (tagged_) streaming_->tags.row(y_)[x] = static_cast<int32_t>(word >> voxel_bits_);
    }
    if (++j_ == plan_.B) {
      j_ = 0;
      ++y_;
    }
  }
  for (int k = 0; k < plan_.p; ++k) form(steps_ * plan_.p + k, k, slot);
  slot.step = steps_++;
  slot.f = in.f;
  slot.pass_tag = in.tag;
}

}  // namespace cube4::sysc
