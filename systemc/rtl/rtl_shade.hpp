// Shading at RTL: one cube4_shade_unit (magnitude + shader) per pipeline,
// tables loaded through their write ports before the frame (host load
// time, not counted in the frame's cycles). The position and slice travel
// on the unit's side channel. With voxel tags (bela §III) M is the unit
// with kRtlVoxelTagBits of tag hardware: each sample's tag goes in, the
// classification table is loaded at {tag, value} and each tag's material
// through the mat_* port.
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

namespace cube4::sysc {

// Side channel layout (cube4_shade_unit SideBits = kShadeSideBits).
constexpr int kShadeSideBits = 4 + 3 * 16;

template <class M>
class RtlShade final : public ShadeIf {
 public:
  RtlShade(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace, int first = 0, int last = -1)
      : plan_(plan), first_(first), last_(last < 0 ? plan.p : last) {
    for (int k = first_; k < last_; ++k) {
      const std::string name = "shade" + std::to_string(k);
      // Only pipeline 0 is traced: the others run the same control.
      units_.push_back(std::make_unique<RtlModel<M>>(ctx, name, k == 0 ? trace : TraceWindow{}, name));
      load_tables(*units_.back());
      units_.back()->restart_cycles();
    }
  }

  void clock(const GradientBeat& in, ShadedBeat& out) override {
    using rtl::get_bits;
    using rtl::put_bits;
    const golden::Precision& pr = plan_.r.p;
    const uint64_t side = (in.f.beam_start ? 1u : 0u) | (in.f.beam_end ? 2u : 0u) | (in.f.slice_start ? 4u : 0u) |
                          (in.f.slice_end ? 8u : 0u) | (uint64_t(in.x & 0xffff) << 4) |
                          (uint64_t(in.y & 0xffff) << 20) | (uint64_t(in.slice & 0xffff) << 36);
    for (int k = first_; k < last_; ++k) {
      RtlModel<M>& unit = *units_[static_cast<size_t>(k - first_)];
      M& m = *unit;
      const auto i = static_cast<size_t>(k);
      m.valid_i = in.valid;
      m.sample_i = in.sample[i];
      if (plan_.r.p.tag_bits > 0) put_bits(m.vtag_i, 0, kRtlVoxelTagBits, in.vtag[i]);
      put_bits(m.grad_x_i, 0, pr.gradient_bits, static_cast<uint64_t>(in.gx[i]));
      put_bits(m.grad_y_i, 0, pr.gradient_bits, static_cast<uint64_t>(in.gy[i]));
      put_bits(m.grad_z_i, 0, pr.gradient_bits, static_cast<uint64_t>(in.gz[i]));
      m.side_i = side;
      unit.settle();
      out.red[i] = static_cast<uint16_t>(m.red_o);
      out.green[i] = static_cast<uint16_t>(m.green_o);
      out.blue[i] = static_cast<uint16_t>(m.blue_o);
      out.alpha[i] = static_cast<uint16_t>(m.alpha_o);
      out.value[i] = static_cast<uint16_t>(m.value_o);
      if (k == 0) {
        out.valid = m.valid_o;
        const uint64_t s = m.side_o;
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
  int first_, last_;
  std::vector<std::unique_ptr<RtlModel<M>>> units_;
};

}  // namespace cube4::sysc
