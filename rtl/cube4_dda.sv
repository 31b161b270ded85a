// cube4_dda: the weight generator, for parallel and perspective
// projection, slice by slice.
//
// Function: after start_i, the outputs hold sample slice 0's control; each
// advance_i moves them to the next slice.
//
// Parallel projection (perspective_i low): a slice's control is golden
// slice_control() (golden/pipeline.hpp, from golden/units/dda.hpp;
// docs/rtl-dda.md):
//   - the rays' offset in x and y, start + k * step, split into the whole
//     voxels ix, iy and the weights wx, wy (the fraction's top WeightBits);
//   - dx, dy: ix and iy less those of slice k - 1 (zero at k = 0), which the
//     compositor's ray alignment follows;
//   - z_voxel = k / S and wz = floor((k mod S) * 2^W / S);
//   - the 12-neighbourhood's realignment of slice k - 1 (behind) and k + 1
//     (ahead): weight = (w_here - w_there) mod 2^W, base -1 when that
//     subtraction borrows (golden realign()). Slice -1 and slice K are the
//     DDA's continuation either way, as golden computes them.
//
// Perspective projection (perspective_i high, HasPerspective = 1): the
// same walks are ray 0's position c_k (x, y), a third walks the rays'
// spacing m_k (SCALE_START, SCALE_STEP), and z_voxel, wz are the same z
// DDA's; from them cube4_persp_slice divides out the rest of golden
// perspective_slice() (rays inside, the box and lateral reciprocals, the
// realignment DDAs), which ready_o says is done. Perspective samples at
// spacing one are parallel projection's, but the realignment is not (it
// truncates the exact difference of the slices' positions where parallel
// projection subtracts the two truncated weights), so each projection
// reads its own realignment outputs.
//
// The positions are accumulators (cube4_dda_walk) rather than products,
// so the walks are adders only; z's weight is one small division (a 4-bit
// divisor) of the slice's position in its voxel slab, and the perspective
// constants share one serial divider.
//
// Timing: start_i or advance_i at a clock edge; the outputs show the new
// slice from that edge on (registers, then adders and the division). In a
// perspective frame the divided constants follow 841 edges later (at the
// default widths: cube4_persp_slice's latency), when ready_o rises; a
// command before then starts the divisions over for the new slice. start_i
// wins over advance_i. The frame registers are sampled at start_i and at
// every advance_i, and read by the divisions (they must be stable over a
// frame).
// Handshake: none (a command per cycle at most, one slice per command);
// ready_o for the perspective constants.
// Reset: the slice counters, valid_o and the divider; positions are loaded
// by start_i.
//
// Preconditions: 1 <= supersampling_i; start + k * step (and in
// perspective frames scale_start + k * scale_step) fits PosBits signed for
// slices -1 .. K + 1 of the frame; WeightBits < FracBits; a perspective
// frame's spacing in [1, 4).
//
// Parameters:
//   HasPerspective    - the spacing walk and the divisions (0: a parallel-
//                       projection machine; the perspective outputs are 0
//                       and ready_o is valid_o)
//   FracBits          - DDA fraction bits (golden Precision::dda_frac_bits,
//                       20: the unit's test ties the default to golden's)
//   WeightBits        - weights' fraction (cube4_pkg::WeightBits)
//   VoxelBits         - sample width, which sets the perspective
//                       reciprocals' precision (cube4_pkg::VoxelBits)
//   PosBits           - DDA registers and positions, signed (48)
//   DimBits           - volume size per axis (cube4_pkg::DimBits)
//   SliceBits         - sample slice index (cube4_pkg::SliceBits)
//   SupersamplingBits - S (cube4_pkg::SupersamplingBits)
//   IntBits           - (derived) whole voxels of a position, signed
`include "cube4_pkg.sv"

module cube4_dda #(
  parameter bit           HasPerspective    = 1'b1,
  parameter int unsigned  FracBits          = cube4_pkg::FracBits,
  parameter int unsigned  WeightBits        = cube4_pkg::WeightBits,
  parameter int unsigned  VoxelBits         = cube4_pkg::VoxelBits,
  parameter int unsigned  PosBits           = 48,
  parameter int unsigned  DimBits           = cube4_pkg::DimBits,
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
  // Perspective frames' registers: MODE's perspective bit, SCALE_START,
  // SCALE_STEP, the volume's size across the slices, and K - 1.
  input  logic                          perspective_i,
  input  logic signed [PosBits-1:0]     scale_start_i,
  input  logic signed [PosBits-1:0]     scale_step_i,
  input  logic [DimBits-1:0]            dim_x_i,
  input  logic [DimBits-1:0]            dim_y_i,
  input  logic [SliceBits-1:0]          last_slice_i,
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
  output logic [WeightBits-1:0]         ahead_y_weight_o,
  // Perspective: slice k's spacing and ray 0's position (from the command
  // edge on), and the divided constants (when ready_o).
  output logic                          ready_o,
  output logic signed [PosBits-1:0]     spacing_o,
  output logic signed [PosBits-1:0]     ray0_x_o,
  output logic signed [PosBits-1:0]     ray0_y_o,
  output logic signed [PosBits-1:0]     rays_x_lo_o,
  output logic signed [PosBits-1:0]     rays_x_hi_o,
  output logic signed [PosBits-1:0]     rays_y_lo_o,
  output logic signed [PosBits-1:0]     rays_y_hi_o,
  output logic [PosBits-1:0]            box_recip_o,
  output logic [PosBits-1:0]            lateral_recip_o,
  output logic signed [PosBits-1:0]     behind_start_x_o,
  output logic signed [PosBits-1:0]     behind_start_y_o,
  output logic signed [PosBits-1:0]     behind_step_o,
  output logic signed [PosBits-1:0]     ahead_start_x_o,
  output logic signed [PosBits-1:0]     ahead_start_y_o,
  output logic signed [PosBits-1:0]     ahead_step_o
);

  // ---- Positions of slices k - 1, k and k + 1, per axis.
  logic signed [PosBits-1:0] x_behind_q, x_here_q, x_ahead_q;
  logic signed [PosBits-1:0] y_behind_q, y_here_q, y_ahead_q;

  cube4_dda_walk #(.PosBits(PosBits)) u_walk_x (
    .clk_i, .start_i(x_start_i), .step_i(x_step_i), .load_i(start_i), .advance_i,
    .behind_o(x_behind_q), .here_o(x_here_q), .ahead_o(x_ahead_q));
  cube4_dda_walk #(.PosBits(PosBits)) u_walk_y (
    .clk_i, .start_i(y_start_i), .step_i(y_step_i), .load_i(start_i), .advance_i,
    .behind_o(y_behind_q), .here_o(y_here_q), .ahead_o(y_ahead_q));

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

  // ---- Perspective: the spacing walk and the divisions.
  if (HasPerspective) begin : g_perspective
    logic signed [PosBits-1:0] m_behind, m_here, m_ahead;
    logic                      busy;
    logic                      done_unused;

    cube4_dda_walk #(.PosBits(PosBits)) u_walk_spacing (
      .clk_i, .start_i(scale_start_i), .step_i(scale_step_i), .load_i(start_i), .advance_i,
      .behind_o(m_behind), .here_o(m_here), .ahead_o(m_ahead));

    cube4_persp_slice #(
      .FracBits(FracBits), .WeightBits(WeightBits), .VoxelBits(VoxelBits), .PosBits(PosBits), .DimBits(DimBits)
    ) u_divisions (
      .clk_i, .rst_ni,
      .spacing_behind_i(m_behind), .spacing_i(m_here), .spacing_ahead_i(m_ahead),
      .ray0_x_behind_i(x_behind_q), .ray0_x_i(x_here_q), .ray0_x_ahead_i(x_ahead_q),
      .ray0_y_behind_i(y_behind_q), .ray0_y_i(y_here_q), .ray0_y_ahead_i(y_ahead_q),
      .has_behind_i(k_q != '0), .has_ahead_i(k_q != last_slice_i),
      .dim_x_i, .dim_y_i,
      .start_i(perspective_i && (start_i || advance_i)),
      .busy_o(busy), .done_o(done_unused),
      .rays_x_lo_o, .rays_x_hi_o, .rays_y_lo_o, .rays_y_hi_o, .box_recip_o, .lateral_recip_o,
      .behind_start_x_o, .behind_start_y_o, .behind_step_o, .ahead_start_x_o, .ahead_start_y_o, .ahead_step_o);

    assign spacing_o = m_here;
    assign ready_o   = valid_q && !busy;
  end else begin : g_no_perspective
    assign spacing_o        = '0;
    assign rays_x_lo_o      = '0;
    assign rays_x_hi_o      = '0;
    assign rays_y_lo_o      = '0;
    assign rays_y_hi_o      = '0;
    assign box_recip_o      = '0;
    assign lateral_recip_o  = '0;
    assign behind_start_x_o = '0;
    assign behind_start_y_o = '0;
    assign behind_step_o    = '0;
    assign ahead_start_x_o  = '0;
    assign ahead_start_y_o  = '0;
    assign ahead_step_o     = '0;
    assign ready_o          = valid_q;
    // A parallel-projection machine has no perspective registers.
    logic unused_perspective;
    assign unused_perspective = ^{perspective_i, scale_start_i, scale_step_i, dim_x_i, dim_y_i, last_slice_i};
  end

  // Ray 0's position is the rays' offset (golden Registers::ray0()).
  assign ray0_x_o = x_here_q;
  assign ray0_y_o = y_here_q;

endmodule
