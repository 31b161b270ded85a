// cube4_gradient: the gradient unit, central differences in x and y and
// Cube-4's 12-neighbourhood ABC method in z.
//
// Function: bit-exact with golden sample_gradient() (golden/pipeline.hpp),
// i.e. abc_sample() and gradient_12n() (golden/units/gradient.hpp):
//   behind = bilerp(behind[0..3], behind_wx, behind_wy)   (x, then y)
//   ahead  = bilerp(ahead[0..3],  ahead_wx,  ahead_wy)
//   gx = C(right - left),  gy = C(down - up),  gz = C((ahead - behind) * S)
//   C(d) = saturate(round_half_up(d / 2^GradientShift)) to the symmetric
//          range +-(2^(GradientBits-1) - 1) (never -2^(GradientBits-1)).
// The 2x2 neighbourhoods are packed as [i*VoxelBits +: VoxelBits] with
// [0] at (base, base), [1] x+1, [2] y+1, [3] both; realign weights are in
// [0, 2^WeightBits]; supersampling S = 1 .. 2^SupersamplingBits - 1.
// With HasPerspective (Cube-4's perspective, golden gradient_perspective()):
//   gx = C(L(right - left)),  gy = C(L(down - up)),
//   L(d) = round_half_up(d * lateral_recip / 2^RecipBits)   (scale_lateral())
// where lateral_recip_i is the slice's round(2^(RecipBits+F) / m) for a ray
// spacing m >= 1 (golden lateral_reciprocal(); 2^RecipBits at m = 1, where
// L is the identity); any value of the port's range is taken exactly. The
// ABC z path is the same: in perspective its weights vary per sample, which
// the ports already allow. Without HasPerspective the port is ignored and
// no multiplier is built (parallel-projection scenes simulate none of it).
//
// Latency: 3 cycles, fully pipelined (one new input set per clock):
//   stage 1 registers gx, gy and the four x lerps of the ABC samples,
//   stage 2 the two y lerps (behind, ahead), stage 3 gz; the outputs are
//   driven by stage-3 registers.
// Handshake: valid-only. valid_i travels with the data to valid_o; only the
//   valid pipeline is reset.
//
// Parameters:
//   VoxelBits         - sample width (golden Precision::voxel_bits, 12)
//   WeightBits        - realign weight fraction bits; weight ports are
//                       WeightBits+1 wide (Precision::weight_bits, 8)
//   GradientBits      - signed component width (Precision::gradient_bits, 8)
//   GradientShift     - full difference >> shift (Precision::gradient_shift, 5)
//   SupersamplingBits - width of the supersampling factor port (4: S <= 15)
//   HasPerspective    - the lateral scale of perspective's x and y
//                       differences (two (V+1) x (V+3) multipliers in stage 1)
//   HasVoxelZ         - VolumePro's z gradient: gz = C(zdiff_i), the sample's
//                       interpolated voxel z difference (golden
//                       gradient_voxel_z(); V+1 bits, two's complement, from
//                       cube4_interp_zdiff); no ABC lerps are built and the
//                       behind/ahead ports and S are ignored. Without it
//                       zdiff_i is ignored.
//   RecipBits         - (derived) the reciprocal's fraction, VoxelBits + 2
//                       (golden lateral_recip_bits())
`include "cube4_pkg.sv"

module cube4_gradient #(
  parameter int unsigned VoxelBits         = cube4_pkg::VoxelBits,
  parameter int unsigned WeightBits        = cube4_pkg::WeightBits,
  parameter int unsigned GradientBits      = cube4_pkg::GradientBits,
  parameter int unsigned GradientShift     = cube4_pkg::GradientShift,
  parameter int unsigned SupersamplingBits = cube4_pkg::SupersamplingBits,
  parameter bit          HasPerspective    = 1'b0,
  parameter bit          HasVoxelZ         = 1'b0,
  localparam int unsigned RecipBits        = VoxelBits + 2
) (
  input  logic                           clk_i,
  input  logic                           rst_ni,
  input  logic                           valid_i,
  input  logic [VoxelBits-1:0]           left_i,
  input  logic [VoxelBits-1:0]           right_i,
  input  logic [VoxelBits-1:0]           up_i,
  input  logic [VoxelBits-1:0]           down_i,
  input  logic [4*VoxelBits-1:0]         behind_i,
  input  logic [4*VoxelBits-1:0]         ahead_i,
  input  logic [WeightBits:0]            behind_wx_i,
  input  logic [WeightBits:0]            behind_wy_i,
  input  logic [WeightBits:0]            ahead_wx_i,
  input  logic [WeightBits:0]            ahead_wy_i,
  input  logic [SupersamplingBits-1:0]   supersampling_i,
  input  logic [RecipBits:0]             lateral_recip_i,
  input  logic [VoxelBits:0]             zdiff_i,
  output logic                           valid_o,
  output logic signed [GradientBits-1:0] gx_o,
  output logic signed [GradientBits-1:0] gy_o,
  output logic signed [GradientBits-1:0] gz_o
);

  localparam int unsigned Latency  = 3;
  localparam int unsigned DiffBits = VoxelBits + 1;
  // (ahead - behind) * S plus the rounding half, and room for the saturation
  // bound even when GradientBits exceeds the difference width.
  localparam int unsigned FullA    = DiffBits + SupersamplingBits + 2;
  localparam int unsigned FullB    = GradientBits + 1;
  localparam int unsigned FullBits = (FullA > FullB) ? FullA : FullB;
  localparam logic signed [FullBits-1:0] Half =
      (GradientShift == 0) ? '0 : FullBits'(1) << (GradientShift == 0 ? 0 : GradientShift - 1);
  localparam logic signed [FullBits-1:0] MaxG = (FullBits'(1) << (GradientBits - 1)) - FullBits'(1);
  localparam logic signed [FullBits-1:0] MinG = -MaxG;

  // C(d) = saturated(rounded(d)): round half up by GradientShift, then
  // saturate symmetrically. Two functions, so that the rounded components
  // are signals the coverage checker can see saturate (Verilator counts no
  // branch inside a function).
  function automatic logic signed [FullBits-1:0] rounded(input logic signed [FullBits-1:0] full);
    rounded = (full + Half) >>> GradientShift;
  endfunction
  function automatic logic [GradientBits-1:0] saturated(input logic signed [FullBits-1:0] r);
    saturated = (r > MaxG) ? MaxG[GradientBits-1:0] : (r < -MaxG) ? MinG[GradientBits-1:0] : r[GradientBits-1:0];
  endfunction

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

  // Stage 1: gx, gy, and the x lerps of the behind/ahead neighbourhoods
  // ([0]/[1]: behind rows y, y+1; [2]/[3]: ahead rows y, y+1).
  logic signed [DiffBits-1:0] dx, dy;
  logic [GradientBits-1:0]    gx1_q, gy1_q;
  logic [4*VoxelBits-1:0]     abc_x_d, abc_x_q;
  logic [WeightBits:0]        behind_wy_q, ahead_wy_q;
  logic [SupersamplingBits-1:0] s1_q;

  assign dx = $signed({1'b0, right_i}) - $signed({1'b0, left_i});
  assign dy = $signed({1'b0, down_i}) - $signed({1'b0, up_i});

  if (!HasVoxelZ) begin : g_abc_x_on
    for (genvar i = 0; i < 4; i++) begin : g_abc_x
      // i = 0, 1: behind rows; i = 2, 3: ahead rows.
      logic [VoxelBits-1:0] a, b;
      logic [WeightBits:0]  wx;
      assign a  = (i < 2) ? behind_i[(2*(i%2))*VoxelBits +: VoxelBits]
                          : ahead_i[(2*(i%2))*VoxelBits +: VoxelBits];
      assign b  = (i < 2) ? behind_i[(2*(i%2)+1)*VoxelBits +: VoxelBits]
                          : ahead_i[(2*(i%2)+1)*VoxelBits +: VoxelBits];
      assign wx = (i < 2) ? behind_wx_i : ahead_wx_i;
      cube4_lerp #(
        .VoxelBits (VoxelBits),
        .WeightBits(WeightBits)
      ) u_lerp_x (
        .a_i(a),
        .b_i(b),
        .w_i(wx),
        .y_o(abc_x_d[i*VoxelBits +: VoxelBits])
      );
    end
  end else begin : g_abc_x_off
    // Waiver: VolumePro's z takes no re-aligned samples.
    logic unused_abc;
    assign unused_abc = ^{behind_i, ahead_i, behind_wx_i, ahead_wx_i};
    assign abc_x_d    = '0;
  end

  // What C() takes in x and y: the differences, or in perspective the
  // differences scaled to the rays' spacing (L above).
  logic signed [FullBits-1:0] lx, ly;
  if (HasPerspective) begin : g_lateral
    localparam int unsigned ProdBits = DiffBits + RecipBits + 2;
    localparam logic signed [ProdBits-1:0] HalfR = ProdBits'(1) << (RecipBits - 1);
    logic signed [ProdBits-1:0] px, py, sx, sy;
    assign px = ProdBits'(dx) * $signed({1'b0, lateral_recip_i});
    assign py = ProdBits'(dy) * $signed({1'b0, lateral_recip_i});
    assign sx = (px + HalfR) >>> RecipBits;
    assign sy = (py + HalfR) >>> RecipBits;
    // |L(d)| <= 2|d| + 1 below 2^(VoxelBits+2): FullBits (>= VoxelBits + 7)
    // hold it, and the bits above are its sign.
    assign lx = sx[FullBits-1:0];
    assign ly = sy[FullBits-1:0];
    if (ProdBits > FullBits) begin : g_sign
      logic unused_sign;
      assign unused_sign = ^{sx[ProdBits-1:FullBits], sy[ProdBits-1:FullBits]};
    end
  end else begin : g_parallel
    assign lx = FullBits'(dx);
    assign ly = FullBits'(dy);
    // Waiver: the reciprocal only scales perspective's differences.
    logic unused_recip;
    assign unused_recip = ^lateral_recip_i;
  end

  logic signed [FullBits-1:0] gx_rounded, gy_rounded;
  assign gx_rounded = rounded(lx);
  assign gy_rounded = rounded(ly);

  always_ff @(posedge clk_i) begin
    gx1_q       <= saturated(gx_rounded);
    gy1_q       <= saturated(gy_rounded);
    abc_x_q     <= abc_x_d;
    behind_wy_q <= behind_wy_i;
    ahead_wy_q  <= ahead_wy_i;
    s1_q        <= supersampling_i;
  end

  // Stage 2: y lerps give the re-aligned behind and ahead samples.
  logic [2*VoxelBits-1:0]       abc_d, abc_q;
  logic [GradientBits-1:0]      gx2_q, gy2_q;
  logic [SupersamplingBits-1:0] s2_q;

  if (!HasVoxelZ) begin : g_abc_y_on
    for (genvar i = 0; i < 2; i++) begin : g_abc_y
      cube4_lerp #(
        .VoxelBits (VoxelBits),
        .WeightBits(WeightBits)
      ) u_lerp_y (
        .a_i(abc_x_q[(2*i)*VoxelBits +: VoxelBits]),
        .b_i(abc_x_q[(2*i+1)*VoxelBits +: VoxelBits]),
        .w_i((i == 0) ? behind_wy_q : ahead_wy_q),
        .y_o(abc_d[i*VoxelBits +: VoxelBits])
      );
    end
  end else begin : g_abc_y_off
    logic unused_abc_x;
    assign unused_abc_x = ^{abc_x_q, behind_wy_q, ahead_wy_q};
    assign abc_d        = '0;
  end

  always_ff @(posedge clk_i) begin
    abc_q <= abc_d;
    gx2_q <= gx1_q;
    gy2_q <= gy1_q;
    s2_q  <= s1_q;
  end

  // Stage 3: gz = C((ahead - behind) * S), or C(zdiff) (HasVoxelZ: the
  // difference waits beside stages 1 and 2).
  logic signed [FullBits-1:0] gz_rounded;
  logic [GradientBits-1:0]    gx3_q, gy3_q, gz3_q;

  if (HasVoxelZ) begin : g_voxel_z
    logic signed [VoxelBits:0] zdiff1_q, zdiff2_q;
    always_ff @(posedge clk_i) begin
      zdiff1_q <= zdiff_i;
      zdiff2_q <= zdiff1_q;
    end
    assign gz_rounded = rounded(FullBits'(zdiff2_q));
    // Waiver: the ABC samples and S are not built or used in this mode.
    logic unused_abc_z;
    assign unused_abc_z = ^{abc_q, s2_q};
  end else begin : g_abc_z
    logic signed [DiffBits-1:0] dz;
    logic signed [FullBits-1:0] dz_scaled;
    assign dz        = $signed({1'b0, abc_q[2*VoxelBits-1:VoxelBits]}) -
                       $signed({1'b0, abc_q[VoxelBits-1:0]});
    assign dz_scaled = FullBits'(dz) * $signed({1'b0, s2_q});
    assign gz_rounded = rounded(dz_scaled);
    logic unused_zdiff;
    assign unused_zdiff = ^zdiff_i;
  end

  always_ff @(posedge clk_i) begin
    gx3_q <= gx2_q;
    gy3_q <= gy2_q;
    gz3_q <= saturated(gz_rounded);
  end

  assign gx_o = gx3_q;
  assign gy_o = gy3_q;
  assign gz_o = gz3_q;

endmodule
