// cube4_interp_persp_home: the perspective interpolation unit's home stage
// (Cube-4 §3; docs/rtl-interp-persp.md): at a ray's home column, the ray's
// sample from the four column sums of its window (cube4_interp_persp_column's,
// its own and its neighbours') of both voxel slices.
//
// Function: bit-exact with golden perspective_sample() (golden/perspective.hpp)
// given the column sums golden box_taps() makes of the window's columns
// home-1 .. home+2 (cols_*_i[i*ColBits +: ColBits] is column home-1+i):
//   lo       = box_mean(box_taps(cols_front, x box), recip)
//   hi       = box_mean(box_taps(cols_back,  x box), recip)
//   sample_o = lerp(lo, hi, wz)
// The x box is cube4_persp_lanes' (overlaps ox_i, and ox_left_i: the box
// starts at home-1, else at the home). golden perspective_filtered() takes
// hi only for wz > 0; lerp with wz = 0 is lo exactly.
//
// Latency: 3 cycles, fully pipelined: stage 1 registers the two row sums
// (cube4_box_taps), stage 2 the two means (cube4_box_mean), stage 3 the z
// lerp (cube4_lerp). Handshake: valid-only; valid_i travels with the data
// to valid_o; only the valid pipeline is reset.
//
// Widths (V = VoxelBits, W = WeightBits, D = V, or V+1 when Signed):
// column sums D+W+2 bits, row sums D+2W+4, recip_i V+6 (cube4_box_mean),
// wz_i W+1 (cube4_lerp), sample_o D.
//
// Signed = 1: the same filter over VolumePro's voxel z differences (two's
// complement, V+1 bits; golden perspective_z_difference(), which filters
// them with the sample's own boxes, reciprocal and z lerp): a ring with
// the voxel-difference z gradient has a second home stage of this kind.
//
// Parameters:
//   VoxelBits, WeightBits - as cube4_box_taps (Precision defaults 12, 8)
//   Signed                - 1: the data are signed voxel z differences
`include "cube4_pkg.sv"

module cube4_interp_persp_home #(
  parameter int unsigned  VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned  WeightBits = cube4_pkg::WeightBits,
  parameter bit           Signed     = 1'b0,
  localparam int unsigned DataBits   = VoxelBits + (Signed ? 1 : 0),
  localparam int unsigned ColBits    = DataBits + WeightBits + 2
) (
  input  logic                         clk_i,
  input  logic                         rst_ni,
  input  logic                         valid_i,
  input  logic [4*ColBits-1:0]         cols_front_i,
  input  logic [4*ColBits-1:0]         cols_back_i,
  input  logic [4*(WeightBits+1)-1:0]  ox_i,
  input  logic                         ox_left_i,
  input  logic [VoxelBits+5:0]         recip_i,
  input  logic [WeightBits:0]          wz_i,
  output logic                         valid_o,
  output logic [DataBits-1:0]          sample_o
);

  localparam int unsigned Latency   = 3;
  localparam int unsigned SumBits   = DataBits + 2 * WeightBits + 4;
  localparam int unsigned RecipBits = VoxelBits + 6;

  logic [Latency-1:0] valid_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= '0;
    end else begin
      valid_q <= {valid_q[Latency-2:0], valid_i};
    end
  end
  assign valid_o = valid_q[Latency-1];

  // Stage 1: the row sums along x.
  logic [SumBits-1:0]   front_d, back_d, front_q, back_q;
  logic [RecipBits-1:0] recip_q;
  logic [WeightBits:0]  wz1_q, wz2_q;
  cube4_box_taps #(
    .DataBits  (ColBits),
    .WeightBits(WeightBits),
    .Signed    (Signed)
  ) u_front (
    .data_i   (cols_front_i),
    .overlap_i(ox_i),
    .shift_i  (!ox_left_i),
    .sum_o    (front_d)
  );
  cube4_box_taps #(
    .DataBits  (ColBits),
    .WeightBits(WeightBits),
    .Signed    (Signed)
  ) u_back (
    .data_i   (cols_back_i),
    .overlap_i(ox_i),
    .shift_i  (!ox_left_i),
    .sum_o    (back_d)
  );
  always_ff @(posedge clk_i) begin
    front_q <= front_d;
    back_q  <= back_d;
    recip_q <= recip_i;
    wz1_q   <= wz_i;
  end

  // Stage 2: the two means.
  logic [DataBits-1:0] lo_d, hi_d, lo_q, hi_q;
  cube4_box_mean #(
    .VoxelBits (VoxelBits),
    .WeightBits(WeightBits),
    .Signed    (Signed)
  ) u_lo (
    .sum_i   (front_q),
    .recip_i (recip_q),
    .sample_o(lo_d)
  );
  cube4_box_mean #(
    .VoxelBits (VoxelBits),
    .WeightBits(WeightBits),
    .Signed    (Signed)
  ) u_hi (
    .sum_i   (back_q),
    .recip_i (recip_q),
    .sample_o(hi_d)
  );
  always_ff @(posedge clk_i) begin
    lo_q  <= lo_d;
    hi_q  <= hi_d;
    wz2_q <= wz1_q;
  end

  // Stage 3: the z lerp between the two voxel slices.
  logic [DataBits-1:0] sample_d, sample_q;
  cube4_lerp #(
    .VoxelBits (DataBits),
    .WeightBits(WeightBits),
    .Signed    (Signed)
  ) u_lerp (
    .a_i(lo_q),
    .b_i(hi_q),
    .w_i(wz2_q),
    .y_o(sample_d)
  );
  always_ff @(posedge clk_i) begin
    sample_q <= sample_d;
  end
  assign sample_o = sample_q;

endmodule
