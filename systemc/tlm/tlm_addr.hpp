// Address generation (`addr`) at TLM: golden beam_access_into()
// (golden/units/addr.hpp), answered one edge later as cube4_addr does
// (docs/system.md, "Structure"). The RTL model is systemc/rtl/rtl_addr.hpp.
#pragma once
#include <array>

#include "golden/units/addr.hpp"
#include "systemc/core/unit_if.hpp"

namespace cube4::sysc {

class TlmAddr final : public AddrIf {
 public:
  TlmAddr(const golden::SkewLayout& l, const golden::SkewTraversal& t)
      : layout_(l), strides_(golden::skew_strides(l)), traversal_(t) {}
  // An access holds every lane of kMaxSkewPipes (about 800 bytes), so the
  // two registers (the answer of this edge, the access pending for the
  // next) swap roles instead of being copied, and an invalid result's other
  // fields are stale.
  const AddrResult& clock(const AddrRequest& next, int j, int y, int z) override {
    answer_ ^= 1;
    AddrResult& pending = slot_[answer_ ^ 1];
    pending.valid = next.issue;
    if (next.issue) {
      pending.j = j;
      pending.y = y;
      pending.z = z;
      golden::beam_access_into(pending.access, layout_, strides_, traversal_, y, z, j);
    }
    return slot_[answer_];
  }
  Level level() const override { return Level::Tlm; }
  const AddrResult* upcoming() const override {
    const AddrResult& pending = slot_[answer_ ^ 1];
    return pending.valid ? &pending : nullptr;
  }

 private:
  golden::SkewLayout layout_;
  golden::SkewStrides strides_;
  golden::SkewTraversal traversal_;
  std::array<AddrResult, 2> slot_;
  int answer_ = 0;  // slot_[answer_ ^ 1] is pending
};

}  // namespace cube4::sysc
