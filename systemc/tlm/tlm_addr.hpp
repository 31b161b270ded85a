// Address generation (`addr`) at TLM: golden beam_access()
// (golden/units/addr.hpp), answered one edge later as cube4_addr does
// (docs/system.md, "Structure"). The RTL model is systemc/rtl/rtl_addr.hpp.
#pragma once
#include "golden/units/addr.hpp"
#include "systemc/core/unit_if.hpp"

namespace cube4::sysc {

class TlmAddr final : public AddrIf {
 public:
  TlmAddr(const golden::SkewLayout& l, const golden::SkewTraversal& t) : layout_(l), traversal_(t) {}
  AddrResult clock(const AddrRequest& next, int j, int y, int z) override {
    const AddrResult out = pending_;
    pending_ = AddrResult{};
    if (next.issue) pending_ = {true, j, y, z, golden::beam_access(layout_, traversal_, y, z, j)};
    return out;
  }
  Level level() const override { return Level::Tlm; }
  const AddrResult* upcoming() const override { return pending_.valid ? &pending_ : nullptr; }

 private:
  golden::SkewLayout layout_;
  golden::SkewTraversal traversal_;
  AddrResult pending_;
};

}  // namespace cube4::sysc
