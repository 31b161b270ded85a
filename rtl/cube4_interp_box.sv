// cube4_interp_box: the perspective interpolation unit's box filter
// (Cube-4 §3): the mean of a 4x4 window of one voxel slice over a box as
// wide as the rays are apart there.
//
// Function: bit-exact with golden box_filter() (golden/units/interp_box.hpp):
//   col_i    = sum_j oy_j * v[j][i]          (exact; cube4_box_taps)
//   sum      = sum_i ox_i * col_i            (exact; cube4_box_taps)
//   sample_o = (sum * recip + 2^(Q-1)) >> Q  (the mean, rounded half up;
//                                             cube4_box_mean)
// The rings compute the same stages spread over the pipelines (a column's
// sum at its own pipeline, the row and mean at the ray's home); this unit
// is them in one place, for a 4 x 4 window.
// v[j][i] = voxels_i[(4j+i)*VoxelBits +: VoxelBits] is voxel
// (x.first + i, y.first + j) of the slice (0 outside it); ox_i =
// ox_i[i*(W+1) +: W+1] and oy_j likewise are cube4_box_axis's overlaps;
// recip_i = golden box_reciprocal(E, Q) = round(2^Q / E^2) for the slice's
// extent E (golden box_extent(), W fraction bits), Q = golden
// box_recip_bits() = VoxelBits + 2 WeightBits + 5.
//
// Input range: overlaps at most 2^W (one cell; the ports allow 2^(W+1)-1),
// each axis's overlaps summing to at most E, and 2^W <= E < 2^(W+2)
// (spacing in [1, 4) voxels; the filter is meant for [1, 3]). Then
// sum <= E^2 (2^V - 1) and sum * recip + 2^(Q-1) < 2^Q (2^V - 1) +
// 2^Q (1/2 + 1/4): the mean never exceeds the largest voxel, so sample_o
// needs no saturation. cube4_box_axis's overlaps with the reciprocal of
// the same extent always satisfy this (their sum is E, or less when a box
// wider than 3 voxels reaches a fifth cell).
//
// Latency: 3 cycles, fully pipelined (one new window per clock):
//   stage 1 registers the four column sums, stage 2 the row sum, stage 3
//   the rounded product (sample_o is driven by the stage-3 register).
// Handshake: valid-only. valid_i travels with the data and appears on
//   valid_o 3 cycles later; only the valid pipeline is reset, data
//   registers are not (sample_o is meaningful only while valid_o is high).
//
// Widths (V = VoxelBits, W = WeightBits, Q = V + 2W + 5), each the least
// that holds its worst case for overlaps <= 2^W:
//   recip_i  V+6 = Q-2W+1 bits: round(2^Q / E^2) <= 2^(Q-2W) at E = 2^W
//   col_i    V+W+2 bits: 4 * 2^W * (2^V - 1) < 2^(V+W+2)
//   sum      V+2W+4 bits: 4 * 2^W * (2^(V+W+2) - 2^(W+2)) < 2^(V+2W+4);
//            with the filter's sums (<= 3 * 2^W per axis) it is still
//            above 2^(V+2W+3), so no bit can go
//   product  Q+V bits, modulo 2^(Q+V): sample_o is bits [Q, Q+V) of
//            sum * recip + 2^(Q-1), which is below 2^(Q+V) (input range),
//            so the multiplier's partial products above bit Q+V-1 are
//            never needed (the full product would have Q+V+5 bits)
//
// Parameters:
//   VoxelBits  - voxel and sample width (golden Precision::voxel_bits, 12)
//   WeightBits - overlap fraction bits; overlap ports are WeightBits+1 wide
//                (Precision::weight_bits, 8)
`include "cube4_pkg.sv"

module cube4_interp_box #(
  parameter int unsigned VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned WeightBits = cube4_pkg::WeightBits
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                valid_i,
  input  logic [16*VoxelBits-1:0]             voxels_i,
  input  logic [4*(WeightBits+1)-1:0]         ox_i,
  input  logic [4*(WeightBits+1)-1:0]         oy_i,
  input  logic [VoxelBits+5:0]                recip_i,
  output logic                                valid_o,
  output logic [VoxelBits-1:0]                sample_o
);

  localparam int unsigned Latency   = 3;
  localparam int unsigned OvBits    = WeightBits + 1;
  localparam int unsigned RecipBits = VoxelBits + 6;
  localparam int unsigned ColBits   = VoxelBits + WeightBits + 2;
  localparam int unsigned SumBits   = VoxelBits + 2 * WeightBits + 4;

  // Valid pipeline: the only reset state.
  logic [Latency-1:0] valid_d, valid_q;
  assign valid_d = {valid_q[Latency-2:0], valid_i};

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= '0;
    end else begin
      valid_q <= valid_d;
    end
  end
  assign valid_o = valid_q[Latency-1];

  // Stage 1: the four column sums along y (cube4_box_taps), as the
  // rings form them, one per pipeline (docs/perspective.md, "The dataflow").
  // Packed vectors: unpacked-array assignment is not accepted by yosys 0.23.
  logic [4*ColBits-1:0]   col_d, col_q;
  logic [4*OvBits-1:0]    ox_q;
  logic [RecipBits-1:0]   recip1_q;

  for (genvar i = 0; i < 4; i++) begin : g_column
    logic [4*VoxelBits-1:0] column;
    for (genvar j = 0; j < 4; j++) begin : g_cell
      assign column[j*VoxelBits +: VoxelBits] = voxels_i[(4*j+i)*VoxelBits +: VoxelBits];
    end
    cube4_box_taps #(
      .DataBits  (VoxelBits),
      .WeightBits(WeightBits)
    ) u_column (
      .data_i   (column),
      .overlap_i(oy_i),
      .shift_i  (1'b0),
      .sum_o    (col_d[i*ColBits +: ColBits])
    );
  end

  always_ff @(posedge clk_i) begin
    col_q    <= col_d;
    ox_q     <= ox_i;
    recip1_q <= recip_i;
  end

  // Stage 2: the row sum along x (cube4_box_taps).
  logic [SumBits-1:0]   sum_d, sum_q;
  logic [RecipBits-1:0] recip2_q;

  cube4_box_taps #(
    .DataBits  (ColBits),
    .WeightBits(WeightBits)
  ) u_row (
    .data_i   (col_q),
    .overlap_i(ox_q),
    .shift_i  (1'b0),
    .sum_o    (sum_d)
  );

  always_ff @(posedge clk_i) begin
    sum_q    <= sum_d;
    recip2_q <= recip1_q;
  end

  // Stage 3: times the reciprocal of the box's area, rounded half up
  // (cube4_box_mean).
  logic [VoxelBits-1:0] mean, sample_q;

  cube4_box_mean #(
    .VoxelBits (VoxelBits),
    .WeightBits(WeightBits)
  ) u_mean (
    .sum_i   (sum_q),
    .recip_i (recip2_q),
    .sample_o(mean)
  );

  always_ff @(posedge clk_i) begin
    sample_q <= mean;
  end
  assign sample_o = sample_q;

endmodule
