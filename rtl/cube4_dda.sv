// cube4_dda: the weight generator of parallel projection, slice by slice.
//
// Function: after start_i, the outputs hold sample slice 0's control; each
// advance_i moves them to the next slice. A slice's control is golden
// slice_control() (golden/pipeline.hpp, from golden/units/dda.hpp; docs/rtl-dda.md):
//   - the rays' offset in x and y, start + k * step, split into the whole
//     voxels ix, iy and the weights wx, wy (the fraction's top WeightBits);
//   - dx, dy: ix and iy less those of slice k - 1 (zero at k = 0), which the
//     compositor's ray alignment follows;
//   - z_voxel = k / S and wz = floor((k mod S) * 2^W / S);
//   - the 12-neighbourhood's realignment of slice k - 1 (behind) and k + 1
//     (ahead): weight = (w_here - w_there) mod 2^W, base -1 when that
//     subtraction borrows (golden realign()). Slice -1 and slice K are the
//     DDA's continuation either way, as golden computes them.
// The positions are three accumulators per axis (slices k - 1, k, k + 1)
// rather than products, so the unit is adders only; z's weight is one small
// division (a 4-bit divisor) of the slice's position in its voxel slab.
//
// Timing: start_i or advance_i at a clock edge; the outputs show the new
// slice from that edge on (registers, then adders and the division).
// start_i wins over advance_i. The frame registers are sampled at start_i
// and at every advance_i (they must be stable over a frame).
// Handshake: none (a command per cycle at most, one slice per command).
// Reset: the slice counters and valid_o; positions are loaded by start_i.
//
// Preconditions: 1 <= supersampling_i; start + k * step fits PosBits
// signed for every slice of the frame; WeightBits < FracBits.
//
// Parameters:
//   FracBits          - DDA fraction bits (golden Precision::dda_frac_bits,
//                       20: as cube4_persp_slice, its test ties the default
//                       to golden's)
//   WeightBits        - weights' fraction (cube4_pkg::WeightBits)
//   PosBits           - DDA registers and positions, signed (48)
//   SliceBits         - sample slice index (cube4_pkg::SliceBits)
//   SupersamplingBits - S (cube4_pkg::SupersamplingBits)
//   IntBits           - (derived) whole voxels of a position, signed
`include "cube4_pkg.sv"

module cube4_dda #(
  parameter int unsigned  FracBits          = cube4_pkg::FracBits,
  parameter int unsigned  WeightBits        = cube4_pkg::WeightBits,
  parameter int unsigned  PosBits           = 48,
  parameter int unsigned  SliceBits         = cube4_pkg::SliceBits,
  parameter int unsigned  SupersamplingBits = cube4_pkg::SupersamplingBits,
  localparam int unsigned IntBits           = PosBits - FracBits
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  // Frame registers (golden Registers).
  input  logic signed [PosBits-1:0]     x_start_i,
  input  logic signed [PosBits-1:0]     x_step_i,
  input  logic signed [PosBits-1:0]     y_start_i,
  input  logic signed [PosBits-1:0]     y_step_i,
  input  logic [SupersamplingBits-1:0]  supersampling_i,
  // Command.
  input  logic                          start_i,
  input  logic                          advance_i,
  // Slice k's control.
  output logic                          valid_o,
  output logic [SliceBits-1:0]          k_o,
  output logic [SliceBits-1:0]          z_voxel_o,
  output logic [WeightBits-1:0]         wx_o,
  output logic [WeightBits-1:0]         wy_o,
  output logic [WeightBits-1:0]         wz_o,
  output logic signed [IntBits-1:0]     ix_o,
  output logic signed [IntBits-1:0]     iy_o,
  output logic signed [IntBits-1:0]     dx_o,
  output logic signed [IntBits-1:0]     dy_o,
  // Realignment to slice k - 1 (behind) and k + 1 (ahead): base_o is 1 for
  // a base of -1.
  output logic                          behind_x_base_o,
  output logic [WeightBits-1:0]         behind_x_weight_o,
  output logic                          behind_y_base_o,
  output logic [WeightBits-1:0]         behind_y_weight_o,
  output logic                          ahead_x_base_o,
  output logic [WeightBits-1:0]         ahead_x_weight_o,
  output logic                          ahead_y_base_o,
  output logic [WeightBits-1:0]         ahead_y_weight_o
);

  // ---- Positions of slices k - 1, k and k + 1, per axis.
  logic signed [PosBits-1:0] x_behind_q, x_here_q, x_ahead_q;
  logic signed [PosBits-1:0] y_behind_q, y_here_q, y_ahead_q;

  always_ff @(posedge clk_i) begin
    if (start_i) begin
      x_behind_q <= x_start_i - x_step_i;
      x_here_q   <= x_start_i;
      x_ahead_q  <= x_start_i + x_step_i;
      y_behind_q <= y_start_i - y_step_i;
      y_here_q   <= y_start_i;
      y_ahead_q  <= y_start_i + y_step_i;
    end else if (advance_i) begin
      x_behind_q <= x_here_q;
      x_here_q   <= x_ahead_q;
      x_ahead_q  <= x_ahead_q + x_step_i;
      y_behind_q <= y_here_q;
      y_here_q   <= y_ahead_q;
      y_ahead_q  <= y_ahead_q + y_step_i;
    end
  end

  // ---- Slice counters: k, its voxel slice and its place j = k mod S there.
  logic [SliceBits-1:0]         k_q, z_voxel_q;
  logic [SupersamplingBits-1:0] j_q;
  logic                         valid_q;
  logic                         slab_ends;

  assign slab_ends = j_q == supersampling_i - SupersamplingBits'(1);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q   <= 1'b0;
      k_q       <= '0;
      z_voxel_q <= '0;
      j_q       <= '0;
    end else if (start_i) begin
      valid_q   <= 1'b1;
      k_q       <= '0;
      z_voxel_q <= '0;
      j_q       <= '0;
    end else if (advance_i) begin
      k_q       <= k_q + SliceBits'(1);
      z_voxel_q <= z_voxel_q + SliceBits'(slab_ends);
      j_q       <= slab_ends ? '0 : j_q + SupersamplingBits'(1);
    end
  end

  assign valid_o   = valid_q;
  assign k_o       = k_q;
  assign z_voxel_o = z_voxel_q;

  // ---- Whole voxels and weights of a position (golden dda_split()): the
  // bits above the fraction, and the fraction's top WeightBits.
  localparam int unsigned WLo = FracBits - WeightBits;
  logic [WeightBits-1:0] wx_behind, wx_ahead, wy_behind, wy_ahead;
  assign wx_o      = x_here_q[FracBits-1:WLo];
  assign wy_o      = y_here_q[FracBits-1:WLo];
  assign wx_behind = x_behind_q[FracBits-1:WLo];
  assign wx_ahead  = x_ahead_q[FracBits-1:WLo];
  assign wy_behind = y_behind_q[FracBits-1:WLo];
  assign wy_ahead  = y_ahead_q[FracBits-1:WLo];
  assign ix_o      = x_here_q[PosBits-1:FracBits];
  assign iy_o      = y_here_q[PosBits-1:FracBits];
  assign dx_o      = k_q == '0 ? '0 : x_here_q[PosBits-1:FracBits] - x_behind_q[PosBits-1:FracBits];
  assign dy_o      = k_q == '0 ? '0 : y_here_q[PosBits-1:FracBits] - y_behind_q[PosBits-1:FracBits];

  // The low fraction bits below the weights never reach an output: the
  // weights are truncated (golden dda_split()).
  logic unused_fraction;
  assign unused_fraction = ^{x_behind_q[WLo-1:0], x_here_q[WLo-1:0],
                             x_ahead_q[WLo-1:0], y_behind_q[WLo-1:0],
                             y_here_q[WLo-1:0], y_ahead_q[WLo-1:0],
                             x_ahead_q[PosBits-1:FracBits], y_ahead_q[PosBits-1:FracBits]};

  // ---- Realignment (golden realign()): the difference modulo 2^W, and its
  // borrow as the base -1.
  function automatic logic [WeightBits:0] realign(input logic [WeightBits-1:0] here,
                                                  input logic [WeightBits-1:0] there);
    realign = {1'b0, here} - {1'b0, there};
  endfunction

  assign {behind_x_base_o, behind_x_weight_o} = realign(wx_o, wx_behind);
  assign {behind_y_base_o, behind_y_weight_o} = realign(wy_o, wy_behind);
  assign {ahead_x_base_o, ahead_x_weight_o}   = realign(wx_o, wx_ahead);
  assign {ahead_y_base_o, ahead_y_weight_o}   = realign(wy_o, wy_ahead);

  // ---- z weight (golden z_weight()): j * 2^W / S, j < S < 2^SupersamplingBits,
  // so the quotient is below 2^W.
  localparam int unsigned NumBits = SupersamplingBits + WeightBits;
  logic [NumBits-1:0] z_quotient;
  assign z_quotient = {j_q, {WeightBits{1'b0}}} / NumBits'(supersampling_i);
  assign wz_o       = z_quotient[WeightBits-1:0];

  logic unused_z_quotient;
  assign unused_z_quotient = ^z_quotient[NumBits-1:WeightBits];

endmodule
