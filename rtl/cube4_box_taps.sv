// cube4_box_taps: one axis of the perspective box filter (Cube-4 §3;
// docs/rtl-interp-box.md): four values weighed by the box's four overlaps
// along that axis, exactly. The filter is this twice: along y over a voxel
// column's four cells (the column stage, DataBits = V: in the rings every
// pipeline forms it for its own column), then along x over four column
// sums (the row stage, DataBits = V+W+2: at a ray's home).
//
// Function: bit-exact with golden box_taps() (golden/units/interp_box.hpp):
//   sum_o = sum_i o_i * d_i   (exact)
// d_i = data_i[i*DataBits +: DataBits] (unsigned), o_i =
// overlap_i[i*(W+1) +: W+1], cube4_box_axis's overlaps, when the box starts
// at the data's first cell (shift_i = 0). In the rings the four data are a
// home's window, cells home-1 .. home+2, and a box may start at the home
// instead (shift_i = 1): its overlaps then weigh d_1 .. d_3 and d_0 weighs
// nothing (its fourth overlap, zero as the box ends by home + 2, is not
// used; docs/perspective.md, "The dataflow").
//
// Latency: 0 (combinational). Handshake: none (pure function).
//
// Widths (W = WeightBits): overlaps at most 2^W (one cell), so
// sum_o < 4 * 2^W * 2^DataBits: DataBits+W+2 bits, the least that holds it.
// The filter's own sums (at most 3 * 2^W of overlap per axis) exceed
// 2^(DataBits+W+1) at the largest data, so no bit can go.
//
// Signed data (Signed = 1: VolumePro's voxel z differences, V+1 bits, and
// their column sums, filtered by the same stages for the voxel-difference
// z gradient; golden box_taps() of int32_t): d_i and sum_o are two's
// complement; |sum_o| <= 3 * 2^W * 2^(DataBits-1) fits DataBits+W+2 bits.
//
// Parameters:
//   DataBits   - width of the four values
//   WeightBits - overlap fraction bits; overlaps are WeightBits+1 wide (8)
//   Signed     - 1: data_i and sum_o two's complement
`include "cube4_pkg.sv"

module cube4_box_taps #(
  parameter int unsigned  DataBits   = cube4_pkg::VoxelBits,
  parameter int unsigned  WeightBits = cube4_pkg::WeightBits,
  parameter bit           Signed     = 1'b0,
  localparam int unsigned SumBits    = DataBits + WeightBits + 2
) (
  input  logic [4*DataBits-1:0]        data_i,
  input  logic [4*(WeightBits+1)-1:0]  overlap_i,
  input  logic                         shift_i,
  output logic [SumBits-1:0]           sum_o
);

  localparam int unsigned OvBits = WeightBits + 1;

  // The overlaps in the data's order.
  logic [4*OvBits-1:0] weight;
  assign weight = shift_i ? {overlap_i[0 +: 3*OvBits], OvBits'(0)} : overlap_i;

  always_comb begin
    sum_o = '0;
    for (int i = 0; i < 4; i++) begin
      // Sign- or zero-extended to SumBits: the product modulo 2^SumBits is
      // the exact two's complement product.
      sum_o = sum_o + SumBits'(weight[i*OvBits +: OvBits]) *
                      {{(SumBits-DataBits){Signed && data_i[i*DataBits+DataBits-1]}}, data_i[i*DataBits +: DataBits]};
    end
  end

endmodule
