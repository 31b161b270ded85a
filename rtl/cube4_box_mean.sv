// cube4_box_mean: the perspective box filter's normalisation (Cube-4 §3;
// docs/rtl-interp-box.md): the weighted sum of the box (cube4_box_taps' row stage) times
// the slice's reciprocal of the box's area, rounded half up.
//
// Function: bit-exact with golden box_mean() (golden/units/interp_box.hpp):
//   sample_o = (sum_i * recip_i + 2^(Q-1)) >> Q,  Q = V + 2W + 5
// recip_i = golden box_reciprocal(E, Q) = round(2^Q / E^2) for the slice's
// extent E (golden box_extent()).
//
// Latency: 0 (combinational). Handshake: none (pure function).
//
// Input range: the filter's own sums (overlaps of one box with the
// reciprocal of its extent, 2^W <= E < 2^(W+2)): sum <= E^2 (2^V - 1), so
// sum * recip + 2^(Q-1) < 2^Q (2^V - 1) + 2^Q (1/2 + 1/4) and the mean never
// exceeds the largest voxel: sample_o needs no saturation, and the product
// needs only Q+V bits (modulo 2^(Q+V): its bits above are never needed).
//
// Widths (V = VoxelBits, W = WeightBits): sum_i V+2W+4 bits (the row stage),
// recip_i V+6 bits (round(2^Q / E^2) <= 2^(Q-2W) at E = 2^W).
//
// Signed means (Signed = 1, DataBits = V+1: VolumePro's voxel z
// differences, golden box_mean<int32_t>()): sum_i and sample_o are two's
// complement, the shift arithmetic (rounding half up, towards +infinity,
// as golden's). The product is taken modulo 2^(Q+DataBits) of the
// sign-extended sum, exact in the bits kept, and the mean lies between the
// extreme differences, so DataBits hold it. Q stays the voxels' (the
// reciprocal is the slice's, whatever it filters).
//
// Parameters:
//   VoxelBits  - voxel width (golden Precision::voxel_bits, 12): sets Q
//   WeightBits - overlap fraction bits (Precision::weight_bits, 8)
//   DataBits   - (Signed) the data's width: VoxelBits, or VoxelBits+1 signed
//   Signed     - 1: sum_i and sample_o two's complement
`include "cube4_pkg.sv"

module cube4_box_mean #(
  parameter int unsigned VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned WeightBits = cube4_pkg::WeightBits,
  parameter bit          Signed     = 1'b0,
  parameter int unsigned DataBits   = VoxelBits + (Signed ? 1 : 0),
  localparam int unsigned SumBits   = DataBits + 2 * WeightBits + 4
) (
  input  logic [SumBits-1:0]     sum_i,
  input  logic [VoxelBits+5:0]   recip_i,
  output logic [DataBits-1:0]    sample_o
);

  localparam int unsigned RecipFrac = VoxelBits + 2 * WeightBits + 5;  // Q
  localparam int unsigned ProdBits  = RecipFrac + DataBits;
  localparam logic [ProdBits-1:0] Half = ProdBits'(1) << (RecipFrac - 1);

  // ProdBits exceeds SumBits by V + 1, so the sum is always extended.
  logic [ProdBits-1:0] sum_ext, rounded;
  assign sum_ext  = {{(ProdBits-SumBits){Signed && sum_i[SumBits-1]}}, sum_i};
  assign rounded  = sum_ext * ProdBits'(recip_i) + Half;
  assign sample_o = rounded[ProdBits-1:RecipFrac];

  // The product's fraction bits, dropped by the rounding shift.
  logic unused_fraction;
  assign unused_fraction = ^rounded[RecipFrac-1:0];

endmodule
