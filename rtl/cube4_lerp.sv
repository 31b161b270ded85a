// cube4_lerp: linear interpolation between two samples, unsigned or (with
// Signed) two's complement.
//
// Function: y = a + round_half_up((b - a) * w / 2^WeightBits), weight w in
// [0, 2^WeightBits] (w = 0 gives a, w = 2^WeightBits gives b); rounding half
// up is floor(x + 1/2) for negative steps too. Bit-exact with golden lerp()
// (golden/units/interp.hpp). The result always lies between a and b, so it
// keeps the width of the inputs and needs no saturation.
//
// Latency: 0 (combinational). Handshake: none (pure function).
//
// Parameters:
//   VoxelBits  - width of a, b and y (golden Precision::voxel_bits, 12)
//   WeightBits - fraction bits of w; the weight port is WeightBits+1 wide so
//                that w = 2^WeightBits is representable (Precision::weight_bits, 8)
//   Signed     - 1: a, b and y are two's complement (the z gradient's voxel
//                differences, cube4_interp_zdiff); 0: unsigned samples
`include "cube4_pkg.sv"

module cube4_lerp #(
  parameter int unsigned VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned WeightBits = cube4_pkg::WeightBits,
  parameter bit          Signed     = 1'b0
) (
  input  logic [VoxelBits-1:0]  a_i,
  input  logic [VoxelBits-1:0]  b_i,
  input  logic [WeightBits:0]   w_i,
  output logic [VoxelBits-1:0]  y_o
);

  // |b - a| < 2^VoxelBits (both unsigned, or both signed) and
  // w <= 2^WeightBits, so the signed product fits
  // in VoxelBits + WeightBits + 1 bits; one more bit keeps the rounding add
  // from overflowing.
  localparam int unsigned ProdBits = VoxelBits + WeightBits + 2;
  localparam int unsigned DiffBits = VoxelBits + 1;
  localparam logic signed [ProdBits-1:0] Half =
      (WeightBits == 0) ? '0 : ProdBits'(1) << (WeightBits == 0 ? 0 : WeightBits - 1);

  logic signed [DiffBits-1:0] diff;
  logic signed [ProdBits-1:0] prod, rounded;
  logic signed [DiffBits-1:0] step;

  // The extension bit: the sign for two's complement inputs, else 0.
  logic a_ext, b_ext;
  if (Signed) begin : g_signed
    assign a_ext = a_i[VoxelBits-1];
    assign b_ext = b_i[VoxelBits-1];
  end else begin : g_unsigned
    assign a_ext = 1'b0;
    assign b_ext = 1'b0;
  end
  assign diff    = $signed({b_ext, b_i}) - $signed({a_ext, a_i});
  assign prod    = ProdBits'(diff) * $signed({1'b0, w_i});
  assign rounded = (prod + Half) >>> WeightBits;
  // The rounded step lies in [-(2^VoxelBits - 1), 2^VoxelBits - 1].
  assign step    = rounded[DiffBits-1:0];
  assign y_o     = VoxelBits'($signed({a_ext, a_i}) + step);

  logic unused_rounded;
  assign unused_rounded = ^rounded[ProdBits-1:DiffBits];

endmodule
