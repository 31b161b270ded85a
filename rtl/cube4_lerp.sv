// cube4_lerp: linear interpolation between two unsigned samples.
//
// Function: y = a + round_half_up((b - a) * w / 2^WeightBits), weight w in
// [0, 2^WeightBits] (w = 0 gives a, w = 2^WeightBits gives b). Bit-exact with
// golden lerp() (golden/units/interp.hpp). The result always lies between
// a and b, so it keeps the width of the inputs and needs no saturation.
//
// Latency: 0 (combinational). Handshake: none (pure function).
//
// Parameters:
//   VoxelBits  - width of a, b and y (golden Precision::voxel_bits, 12)
//   WeightBits - fraction bits of w; the weight port is WeightBits+1 wide so
//                that w = 2^WeightBits is representable (Precision::weight_bits, 8)
`include "cube4_pkg.sv"

module cube4_lerp #(
  parameter int unsigned VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned WeightBits = cube4_pkg::WeightBits
) (
  input  logic [VoxelBits-1:0]  a_i,
  input  logic [VoxelBits-1:0]  b_i,
  input  logic [WeightBits:0]   w_i,
  output logic [VoxelBits-1:0]  y_o
);

  // |b - a| < 2^VoxelBits and w <= 2^WeightBits, so the signed product fits
  // in VoxelBits + WeightBits + 1 bits; one more bit keeps the rounding add
  // from overflowing.
  localparam int unsigned ProdBits = VoxelBits + WeightBits + 2;
  localparam int unsigned DiffBits = VoxelBits + 1;
  localparam logic signed [ProdBits-1:0] Half =
      (WeightBits == 0) ? '0 : ProdBits'(1) << (WeightBits == 0 ? 0 : WeightBits - 1);

  logic signed [DiffBits-1:0] diff;
  logic signed [ProdBits-1:0] prod, rounded;
  logic signed [DiffBits-1:0] step;

  assign diff    = $signed({1'b0, b_i}) - $signed({1'b0, a_i});
  assign prod    = ProdBits'(diff) * $signed({1'b0, w_i});
  assign rounded = (prod + Half) >>> WeightBits;
  // The rounded step lies in [-(2^VoxelBits - 1), 2^VoxelBits - 1].
  assign step    = rounded[DiffBits-1:0];
  assign y_o     = VoxelBits'($signed({1'b0, a_i}) + step);

  logic unused_rounded;
  assign unused_rounded = ^rounded[ProdBits-1:DiffBits];

endmodule
