// cube4_interp: the interpolation unit, trilinear interpolation of eight
// voxels to one sample in Cube-4's SFG order: x, then y, then z.
//
// Function: bit-exact with golden trilinear() (golden/units/interp.hpp):
//   front  = lerp(lerp(v0, v1, wx), lerp(v2, v3, wx), wy)
//   back   = lerp(lerp(v4, v5, wx), lerp(v6, v7, wx), wy)
//   sample = lerp(front, back, wz)
// Voxel i of voxels_i (bits [i*VoxelBits +: VoxelBits]) is the voxel at
// (x + (i & 1), y + (i >> 1 & 1), z + (i >> 2)); each lerp rounds half up
// back to VoxelBits (cube4_lerp). Weights are in [0, 2^WeightBits].
//
// Voxel tags (bela §III; VoxelTagBits > 0): tag i of vtags_i is voxel i's;
// vtag_o is the sample's, that of its nearest voxel, golden sample_tag():
// per axis the upper voxel when the weight is at least half,
// w >= 2^(WeightBits-1), so a tie goes up. Tags are labels: selected, not
// interpolated, and delayed to leave with their sample. With
// VoxelTagBits = 0 there is no tag hardware; vtag_o is 0.
//
// Latency: 3 cycles, fully pipelined (one new input set per clock):
//   stage 1 registers the four x lerps, stage 2 the two y lerps, stage 3
//   the z lerp (sample_o is driven by the stage-3 register).
// Handshake: valid-only. valid_i travels with the data and appears on
//   valid_o 3 cycles later; only the valid pipeline is reset, data
//   registers are not (sample_o is meaningful only while valid_o is high).
//
// Parameters:
//   VoxelBits  - voxel and sample width (golden Precision::voxel_bits, 12)
//   WeightBits - weight fraction bits; weight ports are WeightBits+1 wide
//                (Precision::weight_bits, 8)
//   VoxelTagBits - voxel tag width (Precision::tag_bits, 0: none); the tag
//                ports are at least one bit wide
//   Signed     - 1: voxels and sample are two's complement (cube4_interp_zdiff
//                interpolates signed voxel differences through this unit)
`include "cube4_pkg.sv"

module cube4_interp #(
  parameter int unsigned VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned WeightBits = cube4_pkg::WeightBits,
  parameter int unsigned VoxelTagBits = cube4_pkg::VoxelTagBits,
  parameter bit          Signed     = 1'b0
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic                   valid_i,
  input  logic [8*VoxelBits-1:0] voxels_i,
  input  logic [WeightBits:0]    wx_i,
  input  logic [WeightBits:0]    wy_i,
  input  logic [WeightBits:0]    wz_i,
  input  logic [8*(VoxelTagBits > 0 ? VoxelTagBits : 1)-1:0] vtags_i,
  output logic                   valid_o,
  output logic [VoxelBits-1:0]   sample_o,
  output logic [(VoxelTagBits > 0 ? VoxelTagBits : 1)-1:0] vtag_o
);

  localparam int unsigned Latency = 3;

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

  // Stage 1: four lerps in x.
  // Unpacked-array assignment is not accepted by yosys 0.23: packed vectors.
  logic [4*VoxelBits-1:0] x_d, x_q;
  logic [WeightBits:0]   wy_q, wz1_q;

  for (genvar i = 0; i < 4; i++) begin : g_x
    cube4_lerp #(
      .VoxelBits (VoxelBits),
      .WeightBits(WeightBits),
      .Signed    (Signed)
    ) u_lerp_x (
      .a_i(voxels_i[(2*i)*VoxelBits +: VoxelBits]),
      .b_i(voxels_i[(2*i+1)*VoxelBits +: VoxelBits]),
      .w_i(wx_i),
      .y_o(x_d[i*VoxelBits +: VoxelBits])
    );
  end

  always_ff @(posedge clk_i) begin
    x_q   <= x_d;
    wy_q  <= wy_i;
    wz1_q <= wz_i;
  end

  // Stage 2: two lerps in y (front: voxels 0..3, back: voxels 4..7).
  logic [2*VoxelBits-1:0] y_d, y_q;
  logic [WeightBits:0]  wz2_q;

  for (genvar i = 0; i < 2; i++) begin : g_y
    cube4_lerp #(
      .VoxelBits (VoxelBits),
      .WeightBits(WeightBits),
      .Signed    (Signed)
    ) u_lerp_y (
      .a_i(x_q[(2*i)*VoxelBits +: VoxelBits]),
      .b_i(x_q[(2*i+1)*VoxelBits +: VoxelBits]),
      .w_i(wy_q),
      .y_o(y_d[i*VoxelBits +: VoxelBits])
    );
  end

  always_ff @(posedge clk_i) begin
    y_q   <= y_d;
    wz2_q <= wz1_q;
  end

  // Stage 3: one lerp in z.
  logic [VoxelBits-1:0] z_d, z_q;

  cube4_lerp #(
    .VoxelBits (VoxelBits),
    .WeightBits(WeightBits),
    .Signed    (Signed)
  ) u_lerp_z (
    .a_i(y_q[VoxelBits-1:0]),
    .b_i(y_q[2*VoxelBits-1:VoxelBits]),
    .w_i(wz2_q),
    .y_o(z_d)
  );

  always_ff @(posedge clk_i) begin
    z_q <= z_d;
  end
  assign sample_o = z_q;

  // The nearest voxel's tag, chosen as the voxels enter and delayed with
  // the lerps (golden sample_tag()).
  if (VoxelTagBits > 0) begin : g_vtag
    localparam logic [WeightBits:0] Half = (WeightBits + 1)'(1) << (WeightBits - 1);
    logic [2:0] corner;
    logic [Latency*VoxelTagBits-1:0] vtag_q;
    assign corner = {wz_i >= Half, wy_i >= Half, wx_i >= Half};
    always_ff @(posedge clk_i) begin
      vtag_q <= {vtag_q[(Latency-1)*VoxelTagBits-1:0], vtags_i[corner*VoxelTagBits +: VoxelTagBits]};
    end
    assign vtag_o = vtag_q[Latency*VoxelTagBits-1 -: VoxelTagBits];
  end else begin : g_no_vtag
    logic unused_vtags;
    assign unused_vtags = ^vtags_i;
    assign vtag_o = '0;
  end

endmodule
