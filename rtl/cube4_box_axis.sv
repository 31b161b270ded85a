// cube4_box_axis: the perspective box filter's reach along one axis
// (Cube-4 §3): which four voxel cells a sample's box covers, and how much
// of each.
//
// Function: bit-exact with golden box_axis(pos, spacing, FracBits,
// WeightBits) (golden/units/dda_perspective.hpp). The box is `spacing`
// wide, centred on the sample at `pos`; cell i is [i - 1/2, i + 1/2):
//   start   = floor((pos + 2^(F-1) - floor(spacing / 2)) / 2^(F-W))
//   first_o = floor(start / 2^W)           (the first cell touched)
//   a       = start mod 2^W                (the box's start inside it)
//   e       = a + floor(spacing / 2^(F-W)) (the box's end; the extent is
//             golden box_extent(), the same for every box of a slice)
//   overlap_o[j] = max(0, min(e, (j+1) 2^W) - max(a, j 2^W)), j = 0..3:
//             the part of cell first_o + j the box covers, W fraction bits.
// An extent of exactly one voxel gives the linear interpolation weights
// between voxels first_o and first_o + 1: overlaps (2^W - f, f, 0, 0).
//
// Input range: the filter is meant for spacing in [1, 3] voxels, i.e.
// spacing_i in [2^F, 3 * 2^F], where four cells always hold the whole box
// (docs/rtl-interp-box.md). The arithmetic is nevertheless exact for every
// port value (spacing_i up to 2^(F+2) - 1 and every pos_i): beyond 3
// voxels the cells past the fourth are dropped exactly as golden drops
// them, and the test sweeps the whole port range. No assertion: the unit
// has no clock, and rtl/assert/'s checkers are clocked.
//
// Latency: 0 (combinational). Handshake: none (pure function).
//
// Widths (D = DdaBits, F = FracBits, W = WeightBits):
//   pos_i      D bits, signed, F of them fraction (the DDA's position)
//   spacing_i  F+2 bits, unsigned, F fraction: values below 4 voxels
//   first_o    D-F+1 bits, signed: pos + 1/2 - spacing/2 lies in
//              (-2^(D-1) - 2^(F+1), 2^(D-1) + 2^(F-1)), inside D+1 bits
//              for D >= F+2, so first_o is pos's integer part and one bit
//              more, and no pos_i wraps it
//   overlap_o  4 x (W+1) bits: an overlap is at most one cell, 2^W
//              (min(e, (j+1) 2^W) - max(a, j 2^W) <= 2^W), the width of
//              the lerp weights (cube4_lerp's w_i)
//
// Parameters:
//   DdaBits    - width of pos_i (40: 20 integer bits, enough for any volume
//                and eye distance the golden model renders)
//   FracBits   - DDA fraction bits (golden Precision::dda_frac_bits, 20; not
//                in cube4_pkg, which holds only what several units share)
//   WeightBits - overlap fraction bits (Precision::weight_bits, 8); needs
//                FracBits > WeightBits and DdaBits >= FracBits + 2
`include "cube4_pkg.sv"

module cube4_box_axis #(
  parameter int unsigned DdaBits    = 40,
  parameter int unsigned FracBits   = cube4_pkg::FracBits,
  parameter int unsigned WeightBits = cube4_pkg::WeightBits
) (
  input  logic signed [DdaBits-1:0]          pos_i,
  input  logic        [FracBits+1:0]         spacing_i,
  output logic signed [DdaBits-FracBits:0]   first_o,
  output logic        [4*(WeightBits+1)-1:0] overlap_o
);

  // pos + 1/2 - spacing/2 in two's complement, one bit wider than pos_i
  // (range above). The floors by 2^(F-W) and 2^F are bit selections.
  localparam int unsigned SumBits  = DdaBits + 1;
  localparam int unsigned Shift    = FracBits - WeightBits;
  // Cell edges 0 .. 4 (4 * 2^W) and the box's end e < 2^W + 2^(W+2) fit
  // in W+3 bits.
  localparam int unsigned EdgeBits = WeightBits + 3;
  localparam logic [SumBits-1:0] HalfCell = SumBits'(1) << (FracBits - 1);

  logic [SumBits-1:0]    pos_ext, half_spacing, box_lo;
  logic [WeightBits-1:0] a;
  logic [EdgeBits-1:0]   a_ext, extent, e;

  assign pos_ext      = {pos_i[DdaBits-1], pos_i};
  assign half_spacing = {{(SumBits - FracBits - 1){1'b0}}, spacing_i[FracBits+1:1]};
  assign box_lo       = pos_ext + HalfCell - half_spacing;

  assign first_o = box_lo[SumBits-1:FracBits];
  assign a       = box_lo[FracBits-1:Shift];
  assign a_ext   = {3'b000, a};
  // golden box_extent(): spacing truncated to W fraction bits (< 2^(W+2)).
  assign extent  = {1'b0, spacing_i[FracBits+1:Shift]};
  assign e       = a_ext + extent;

  // Cell j spans [j 2^W, (j+1) 2^W) in the box's coordinates; a < 2^W, so
  // max(a, j 2^W) is a for cell 0 and j 2^W for the others.
  logic [4*EdgeBits-1:0] diff;
  for (genvar j = 0; j < 4; j++) begin : g_cell
    localparam logic [EdgeBits-1:0] CellLo = EdgeBits'(j) << WeightBits;
    localparam logic [EdgeBits-1:0] CellHi = EdgeBits'(j + 1) << WeightBits;
    logic [EdgeBits-1:0] lo, hi;
    assign lo = (j == 0) ? a_ext : CellLo;
    assign hi = (e < CellHi) ? e : CellHi;
    assign diff[j*EdgeBits +: EdgeBits] = (hi > lo) ? hi - lo : '0;
    // At most 2^W (above): the upper two bits are zero.
    assign overlap_o[j*(WeightBits+1) +: WeightBits+1] = diff[j*EdgeBits +: WeightBits+1];
  end

  // Bits the floors drop, spacing's LSB (halved away, and below the
  // extent's W fraction bits), and the overlaps' zero upper bits.
  logic unused_bits;
  always_comb begin
    unused_bits = ^box_lo[Shift-1:0] ^ spacing_i[0];
    for (int j = 0; j < 4; j++) begin
      unused_bits = unused_bits ^ (^diff[j*EdgeBits+WeightBits+1 +: 2]);
    end
  end

endmodule
