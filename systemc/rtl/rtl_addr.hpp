// Address generation at RTL: cube4_addr, started and set up before the
// frame (its 6 setup cycles are not frame cycles), then one edge per clock.
#pragma once
#include "golden/units/addr.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/unit_if.hpp"
#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/rtl/rtl_model.hpp"

namespace cube4::sysc {

template <class M>
class RtlAddr final : public AddrIf {
 public:
  static constexpr int kDimBits = kRtlAddrDimBits;

  RtlAddr(const FramePlan& plan, const golden::SkewLayout& layout, VerilatedContext& ctx, const TraceWindow& trace)
      : p_(plan.p), index_bits_(3 * kDimBits + 4 - clog2(plan.p + 1)),
        m_(ctx, "addr", trace, "addr", Outputs::Registered) {
    for (int a = 0; a < 3; ++a)
      if (layout.n[a] >= (1 << kDimBits))
        throw std::invalid_argument("volume: dimension " + std::to_string(layout.n[a]) +
                                    " exceeds the RTL address generator's " + std::to_string(kDimBits) + " bits");
    M& m = *m_;
    m.perm_i = static_cast<uint32_t>(plan.r.perm[0] | plan.r.perm[1] << 2 | plan.r.perm[2] << 4);
    m.flip_i = static_cast<uint32_t>(plan.r.flip[0] | plan.r.flip[1] << 1 | plan.r.flip[2] << 2);
    m.dim_i = static_cast<uint32_t>(layout.n[0] | layout.n[1] << kDimBits) | static_cast<uint64_t>(layout.n[2])
                                                                                 << (2 * kDimBits);
    m.advance_i = 0;
    m.repeat_slice_i = 0;
    m.again_i = 0;
    m.start_i = 1;
    m_.setup_edge();
    m.start_i = 0;
    for (int i = 0; i < 5; ++i) m_.setup_edge();
    m_.restart_cycles();
  }

  const AddrResult& clock(const AddrRequest& next, int, int, int) override {
    using rtl::get_bits;
    M& m = *m_;
    m.advance_i = next.issue;
    m.repeat_slice_i = next.repeat_slice;
    m.again_i = next.again;
    m_.settle();
    AddrResult& r = out_;
    r.valid = m.valid_o;
    if (r.valid) {
      r.j = static_cast<int>(m.beam_o);
      r.y = static_cast<int>(m.y_o);
      r.z = static_cast<int>(m.z_o);
      r.access.rotation = static_cast<int>(m.rotation_o);
      r.access.reverse = m.reverse_o;
      for (int k = 0; k < p_; ++k)
        r.access.module_index[static_cast<size_t>(k)] =
            static_cast<int64_t>(get_bits(m.index_o, k * index_bits_, index_bits_));
    }
    m_.rise();
    return r;
  }
  Level level() const override { return Level::Rtl; }

 private:
  static int clog2(int v) {
    int b = 0;
    while ((1 << b) < v) ++b;
    return b;
  }
  int p_, index_bits_;
  RtlModel<M> m_;
  AddrResult out_;  // the last edge's outputs
};

}  // namespace cube4::sysc
