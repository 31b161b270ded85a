// Shading at RTL: one cube4_shade_unit (magnitude + shader) per pipeline,
// tables loaded through their write ports before the frame (host load
// time, not counted in the frame's cycles). In a parallel frame the
// position and slice travel on the unit's side channel; in a perspective
// one (RtlShadePersp) each lane's ray and slice on its own unit's. With
// voxel tags (bela §III) M is the unit with kRtlVoxelTagBits of tag
// hardware: each sample's tag goes in, the classification table is loaded
// at {tag, value} and each tag's material through the mat_* port.
// An RtlShade may hold only pipelines [first, last): the frame's shading
// units split between two threads (systemc/core/schedules.cpp), each group
// writing its own lanes of the shaded beat; the group with pipeline 0
// writes the beat's valid, flags and position (which every pipeline
// carries alike).
#pragma once
#include <memory>
#include <vector>

#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/rtl/rtl_model.hpp"
#include "systemc/rtl/unit_registers.hpp"
#include "systemc/rtl/vl_bits.hpp"
#include "systemc/tlm/tlm_shade.hpp"

namespace cube4::sysc {

// Side channel layout (cube4_shade_unit SideBits = kShadeSideBits).
constexpr int kShadeSideBits = 4 + 3 * 16;

// The shading units of pipelines [first, last), each with its tables loaded
// through its write ports before the frame (host load time, not counted
// in the frame's cycles), and the lane a beat drives into one of them.
template <class M>
class RtlShadeUnits {
 public:
  RtlShadeUnits(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace, int first, int last)
      : first(first), last(last < 0 ? plan.p : last), plan_(plan) {
    for (int k = first; k < this->last; ++k) {
      const std::string name = "shade" + std::to_string(k);
      // Only pipeline 0 is traced: the others run the same control.
      units_.push_back(
          std::make_unique<RtlModel<M>>(ctx, name, k == 0 ? trace : TraceWindow{}, name, Outputs::Registered));
      load_tables(*units_.back());
      units_.back()->restart_cycles();
    }
  }
  RtlModel<M>& unit(int k) { return *units_[static_cast<size_t>(k - first)]; }

  // Pipeline k's inputs for this clock: a sample, its voxel tag and gradient.
  void drive(int k, bool valid, uint16_t sample, uint8_t vtag, int16_t gx, int16_t gy, int16_t gz, uint64_t side) {
    using rtl::put_bits;
    const golden::Precision& pr = plan_.r.p;
    M& m = *unit(k);
    m.valid_i = valid;
    m.sample_i = sample;
    if (pr.tag_bits > 0) put_bits(m.vtag_i, 0, kRtlVoxelTagBits, vtag);
    put_bits(m.grad_x_i, 0, pr.gradient_bits, static_cast<uint64_t>(gx));
    put_bits(m.grad_y_i, 0, pr.gradient_bits, static_cast<uint64_t>(gy));
    put_bits(m.grad_z_i, 0, pr.gradient_bits, static_cast<uint64_t>(gz));
    m.side_i = side;
  }
  // Its shaded sample, after settle().
  template <class Beat>
  void read(int k, Beat& out) {
    M& m = *unit(k);
    const auto i = static_cast<size_t>(k);
    out.red[i] = static_cast<uint16_t>(m.red_o);
    out.green[i] = static_cast<uint16_t>(m.green_o);
    out.blue[i] = static_cast<uint16_t>(m.blue_o);
    out.alpha[i] = static_cast<uint16_t>(m.alpha_o);
    out.value[i] = static_cast<uint16_t>(m.value_o);
  }

  const int first, last;

 private:
  void load_tables(RtlModel<M>& u) {
    const golden::Registers& r = plan_.r;
    M& m = *u;
    m.valid_i = 0;
    m.class_we_i = m.gmlut_we_i = m.dmap_we_i = m.smap_we_i = m.mat_we_i = 0;
    // The loads write only the scene's address bits: with narrower tags than
    // the model's the top address bits must be 0, not the random reset's.
    m.class_waddr_i = 0;
    m.mat_waddr_i = 0;
    auto edge = [&u] { u.setup_edge(); };
    rtl::load_class_table(m, r.p, r.classification, edge);
    rtl::load_gm_lut(m, r.p, r.gm_lut, edge);
    rtl::load_map(m, r.p, rtl::Map::Diffuse, r.diffuse_map, edge);
    rtl::load_map(m, r.p, rtl::Map::Specular, r.specular_map, edge);
    if (r.p.tag_bits > 0) rtl::load_materials(m, r.p, r.tag_coefs, edge);
    rtl::drive_shade_registers(m, r);
  }

  const FramePlan& plan_;
  std::vector<std::unique_ptr<RtlModel<M>>> units_;
};

template <class M>
class RtlShade final : public ShadeIf {
 public:
  RtlShade(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace, int first = 0, int last = -1)
      : units_(plan, ctx, trace, first, last) {}

  void clock(const GradientBeat& in, ShadedBeat& out) override {
    const uint64_t side = (in.f.beam_start ? 1u : 0u) | (in.f.beam_end ? 2u : 0u) | (in.f.slice_start ? 4u : 0u) |
                          (in.f.slice_end ? 8u : 0u) | (uint64_t(in.x & 0xffff) << 4) |
                          (uint64_t(in.y & 0xffff) << 20) | (uint64_t(in.slice & 0xffff) << 36);
    for (int k = units_.first; k < units_.last; ++k) {
      const auto i = static_cast<size_t>(k);
      units_.drive(k, in.valid, in.sample[i], in.vtag[i], in.gx[i], in.gy[i], in.gz[i], side);
      RtlModel<M>& unit = units_.unit(k);
      unit.settle();
      units_.read(k, out);
      if (k == 0) {
        out.valid = unit->valid_o;
        const uint64_t s = unit->side_o;
        out.f.beam_start = s & 1;
        out.f.beam_end = s >> 1 & 1;
        out.f.slice_start = s >> 2 & 1;
        out.f.slice_end = s >> 3 & 1;
        out.x = static_cast<int>(s >> 4 & 0xffff);
        out.y = static_cast<int>(s >> 20 & 0xffff);
        out.slice = static_cast<uint32_t>(s >> 36 & 0xffff);
      }
      unit.rise();
    }
  }
  Level level() const override { return Level::Rtl; }

 private:
  RtlShadeUnits<M> units_;
};

// Shading of perspective samples at RTL: the same units, each pipeline's
// fed its lane of the ray beat, its own valid; each lane's ray (u, v) and
// slice travel on its unit's side channel (16 bits each, the rings' ray
// width kPerspRayBits), so they leave with the shaded sample.
template <class M>
class RtlShadePersp final : public PerspShadeIf {
 public:
  RtlShadePersp(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace)
      : units_(plan, ctx, trace, 0, -1), control_(static_cast<size_t>(shade_latency(plan.r.p))) {}

  void clock(const RayGradientBeat& in, RayShadedBeat& out) override {
    out.valid = 0;
    // The stream step's control travels beside the units (the rings' does).
    Control& c = control_[head_];
    out.step = c.step;
    out.f = c.f;
    out.pass_tag = c.pass_tag;
    c = {in.step, in.f, in.pass_tag};
    if (++head_ == control_.size()) head_ = 0;
    for (int k = units_.first; k < units_.last; ++k) {
      const auto i = static_cast<size_t>(k);
      const uint64_t side = (uint64_t(in.u[i] & 0xffff) << 4) | (uint64_t(in.v[i] & 0xffff) << 20) |
                            (uint64_t(in.tag[i] & 0xffff) << 36);
      units_.drive(k, in.valid >> k & 1, in.sample[i], in.vtag[i], in.gx[i], in.gy[i], in.gz[i], side);
      RtlModel<M>& unit = units_.unit(k);
      unit.settle();
      if (unit->valid_o) {
        units_.read(k, out);
        const uint64_t s = unit->side_o;
        out.valid |= 1u << k;
        out.u[i] = static_cast<int32_t>(rtl::sign_extend(s >> 4 & 0xffff, 16));
        out.v[i] = static_cast<int32_t>(rtl::sign_extend(s >> 20 & 0xffff, 16));
        out.tag[i] = static_cast<uint32_t>(s >> 36 & 0xffff);
      }
      unit.rise();
    }
  }
  Level level() const override { return Level::Rtl; }

 private:
  RtlShadeUnits<M> units_;
  struct Control {
    int64_t step = -1;
    BeamFlags f;
    uint64_t pass_tag = 0;
  };
  std::vector<Control> control_;  // circular, the units' latency long
  size_t head_ = 0;
};

}  // namespace cube4::sysc
