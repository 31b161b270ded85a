// Shading at RTL: one cube4_shade_unit (magnitude + shader) per pipeline,
// tables loaded through their write ports before the frame (host load
// time, not counted in the frame's cycles). The position and slice travel
// on the unit's side channel.
#pragma once
#include <memory>
#include <vector>

#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/rtl/rtl_model.hpp"

namespace cube4::sysc {

// Side channel layout (cube4_shade_unit SideBits = kShadeSideBits).
constexpr int kShadeSideBits = 4 + 3 * 16;

template <class M>
class RtlShade final : public ShadeIf {
 public:
  RtlShade(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace) : plan_(plan), p_(plan.p) {
    for (int k = 0; k < p_; ++k) {
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
    for (int k = 0; k < p_; ++k) {
      M& m = **units_[static_cast<size_t>(k)];
      const auto i = static_cast<size_t>(k);
      m.valid_i = in.valid;
      m.sample_i = in.sample[i];
      put_bits(m.grad_x_i, 0, pr.gradient_bits, static_cast<uint64_t>(in.gx[i]));
      put_bits(m.grad_y_i, 0, pr.gradient_bits, static_cast<uint64_t>(in.gy[i]));
      put_bits(m.grad_z_i, 0, pr.gradient_bits, static_cast<uint64_t>(in.gz[i]));
      m.side_i = side;
      units_[i]->settle();
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
      units_[i]->rise();
    }
  }
  Level level() const override { return Level::Rtl; }

 private:
  void load_tables(RtlModel<M>& u) {
    using rtl::put_bits;
    const golden::Registers& r = plan_.r;
    const golden::Precision& p = r.p;
    M& m = *u;
    m.valid_i = 0;
    m.class_we_i = m.gmlut_we_i = m.dmap_we_i = m.smap_we_i = 0;
    // One entry per clock through a table's write port.
    auto load = [&u](auto& we, auto& addr, auto& data, size_t n, auto&& entry) {
      for (size_t i = 0; i < n; ++i) {
        we = 1;
        addr = static_cast<uint32_t>(i);
        put_bits(data, 0, 64, entry(i));
        u.setup_edge();
      }
      we = 0;
    };
    load(m.class_we_i, m.class_waddr_i, m.class_wdata_i, r.classification.size(), [&](size_t i) {
      const golden::ClassEntry& e = r.classification[i];
      return ((((uint64_t{e.r} << p.color_bits | e.g) << p.color_bits) | e.b) << p.alpha_bits) | e.a;
    });
    load(m.gmlut_we_i, m.gmlut_waddr_i, m.gmlut_wdata_i, r.gm_lut.size(), [&](size_t i) { return uint64_t{r.gm_lut[i]}; });
    load(m.dmap_we_i, m.dmap_waddr_i, m.dmap_wdata_i, r.diffuse_map.size(),
         [&](size_t i) { return uint64_t{r.diffuse_map[i]}; });
    load(m.smap_we_i, m.smap_waddr_i, m.smap_wdata_i, r.specular_map.size(),
         [&](size_t i) { return uint64_t{r.specular_map[i]}; });
    m.magnitude_i = r.magnitude;
    m.shading_i = r.shading;
    m.specular_i = r.specular;
    m.gm_opacity_i = r.gm_opacity;
    m.gm_diffuse_i = r.gm_diffuse;
    m.gm_specular_i = r.gm_specular;
    m.ke_i = r.coefs.ke;
    m.kd_i = r.coefs.kd;
    m.ks_i = r.coefs.ks;
    m.spec_red_i = r.coefs.specular[0];
    m.spec_green_i = r.coefs.specular[1];
    m.spec_blue_i = r.coefs.specular[2];
    put_bits(m.eye_x_i, 0, p.eye_bits, static_cast<uint64_t>(r.eye[0]));
    put_bits(m.eye_y_i, 0, p.eye_bits, static_cast<uint64_t>(r.eye[1]));
    put_bits(m.eye_z_i, 0, p.eye_bits, static_cast<uint64_t>(r.eye[2]));
  }

  const FramePlan& plan_;
  int p_;
  std::vector<std::unique_ptr<RtlModel<M>>> units_;
};

}  // namespace cube4::sysc
