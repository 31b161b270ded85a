// The composition network's units at RTL (systemc/core/compose_network.hpp):
// a node is the verilated cube4_compose_node, the output stage the verilated
// cube4_compose_out, each clocked like every RTL unit (RtlModel: drive,
// settle, read, rise).
#pragma once
#include <stdexcept>
#include <string>

#include "systemc/core/compose_network.hpp"
#include "systemc/rtl/rtl_model.hpp"

namespace cube4::sysc {

template <class M>
class RtlComposeNode final : public ComposeNodeIf {
 public:
  RtlComposeNode(golden::BlendMode mode, const golden::Precision& p, VerilatedContext& ctx, const TraceWindow& trace,
                 const std::string& name)
      : p_(p), m_(ctx, name, trace, "compose") {
    m_->blend_mode_i = static_cast<uint8_t>(mode);
  }

  NodeBeat clock(const NodeBeat& front, const NodeBeat& back) override {
    M& m = *m_;
    m.valid_i = front.valid;
    m.front_red_i = front.px.r;
    m.front_green_i = front.px.g;
    m.front_blue_i = front.px.b;
    m.front_alpha_i = front.px.a;
    m.front_value_i = front.px.value;
    m.front_selected_i = front.px.valid;
    m.back_red_i = back.px.r;
    m.back_green_i = back.px.g;
    m.back_blue_i = back.px.b;
    m.back_alpha_i = back.px.a;
    m.back_value_i = back.px.value;
    m.back_selected_i = back.px.valid;
    m_.settle();
    NodeBeat out;
    out.valid = m.valid_o;
    out.px.r = static_cast<uint32_t>(m.red_o);
    out.px.g = static_cast<uint32_t>(m.green_o);
    out.px.b = static_cast<uint32_t>(m.blue_o);
    out.px.a = static_cast<uint32_t>(m.alpha_o);
    out.px.value = static_cast<uint16_t>(m.value_o);
    out.px.valid = m.selected_o;
    m_.rise();
    return out;
  }
  Level level() const override { return Level::Rtl; }

 private:
  golden::Precision p_;
  RtlModel<M> m_;
};

template <class M>
class RtlComposeOut final : public ComposeOutIf {
 public:
  RtlComposeOut(VerilatedContext& ctx) : m_(ctx, "compose_out", TraceWindow{}, "compose_out") {}

  OutBeat clock(const NodeBeat& in) override {
    M& m = *m_;
    m.valid_i = in.valid;
    m.red_i = in.px.r;
    m.green_i = in.px.g;
    m.blue_i = in.px.b;
    m.alpha_i = in.px.a;
    m_.settle();
    OutBeat out;
    out.valid = m.valid_o;
    out.px = {static_cast<uint16_t>(m.red_o), static_cast<uint16_t>(m.green_o), static_cast<uint16_t>(m.blue_o),
              static_cast<uint16_t>(m.alpha_o)};
    m_.rise();
    return out;
  }

 private:
  RtlModel<M> m_;
};

}  // namespace cube4::sysc
