// The slab memory behind cube4_persp_slab_decode (docs/rtl-rle-decode.md,
// "In perspective"): the word source of its 2p run-length decoders, bound
// to their ports once for the system's wrapper (rtl_persp_slab_decode.hpp)
// and the unit's testbench (tb/rtl/test_persp_slab_decode.cpp). Header-only,
// without SystemC.
//
// The frame's rows of rays in stream order (slice by slice, each slice's
// rows) are the rows of its slab images: row y of slice k is beam y of k's
// image, its p lines the pixels x = l, l + p, ... (golden SlabImage). Bank b
// shows the lines of rows b, b + 2, ...; each line's read position advances
// by the words its decoder consumed, and the bank moves on two rows at an
// edge that ends a cycle with its line_o high. Frames back to back repeat
// the rows.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "golden/rle_buffer.hpp"
#include "systemc/core/beats.hpp"
#include "systemc/rtl/vl_bits.hpp"

namespace cube4::rtl {

class PerspSlabLines {
 public:
  struct Row {
    const golden::SlabImage* image;
    int y;
  };

  PerspSlabLines(std::vector<Row> rows, int pipes) : rows_(std::move(rows)), p_(pipes) {
    for (const Row& r : rows_)
      if (r.image->lanes() != pipes)
        throw std::logic_error("perspective slab lines: an image of " + std::to_string(r.image->lanes()) +
                               " lanes for " + std::to_string(pipes) + " pipelines");
    for (int b = 0; b < 2; ++b) {
      banks_[static_cast<size_t>(b)].row = b;
      load(banks_[static_cast<size_t>(b)]);
    }
  }

  // This cycle's windows on every decoder's ports (decoder bank * p +
  // line); junk() gives the words shown past a line's end.
  template <class M, class Junk>
  void present(M& m, Junk&& junk) const {
    for (int b = 0; b < 2; ++b) {
      const Bank& bank = banks_[static_cast<size_t>(b)];
      for (int l = 0; l < p_; ++l) {
        const int d = b * p_ + l;
        const golden::RleLine& line = bank.lines[static_cast<size_t>(l)];
        const size_t at = bank.at[static_cast<size_t>(l)], left = line.size() - std::min(at, line.size());
        for (int i = 0; i < 5; ++i)
          put_bits(m.window_i, (d * 5 + i) * 16, 16,
                   static_cast<size_t>(i) < left ? line[at + static_cast<size_t>(i)] : static_cast<uint16_t>(junk()));
        put_bits(m.avail_i, d * 3, 3, std::min<size_t>(5, left));
      }
    }
  }
  // The cycle's consume_o and line_o, read before its clock edge.
  template <class M>
  void take(const M& m) {
    for (int b = 0; b < 2; ++b) {
      Bank& bank = banks_[static_cast<size_t>(b)];
      for (int l = 0; l < p_; ++l)
        bank.consumed[static_cast<size_t>(l)] = get_bits(m.consume_o, (b * p_ + l) * 3, 3);
      bank.next_row = get_bits(m.line_o, b, 1) != 0;
    }
  }
  // After the edge: the read positions advance, or a bank's lines move on.
  void clocked() {
    for (Bank& bank : banks_) {
      for (int l = 0; l < p_; ++l) bank.at[static_cast<size_t>(l)] += bank.consumed[static_cast<size_t>(l)];
      if (bank.next_row) {
        bank.row += 2;
        load(bank);
      }
    }
  }
  // Damages line l of bank b's current row: its last word goes (the test of
  // the unit's error_o).
  void truncate(int b, int l) { banks_[static_cast<size_t>(b)].lines[static_cast<size_t>(l)].pop_back(); }

 private:
  struct Bank {
    size_t row = 0;
    std::array<golden::RleLine, sysc::kMaxLanes> lines;
    std::array<size_t, sysc::kMaxLanes> at{}, consumed{};
    bool next_row = false;
  };
  void load(Bank& bank) const {
    for (int l = 0; l < p_; ++l) {
      golden::RleLine& line = bank.lines[static_cast<size_t>(l)];
      bank.at[static_cast<size_t>(l)] = 0;
      line.clear();
      if (rows_.empty()) continue;
      const Row& r = rows_[bank.row % rows_.size()];
      line = r.image->empty() ? golden::rle_clear(r.image->lane_width(l)) : r.image->line(r.y, l).line();
    }
  }

  std::vector<Row> rows_;
  int p_;
  std::array<Bank, 2> banks_;
};

}  // namespace cube4::rtl
