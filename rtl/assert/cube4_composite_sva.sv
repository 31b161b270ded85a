// cube4_composite_sva: the frame-register rule cube4_composite's header
// states, as an assertion bound to every compositor datapath:
//   a_frame_registers_stable - blend mode, cropping and cut-plane registers
//                      do not change while a sample is in flight: they are
//                      read in stages 1 to 7, so a sample that entered in
//                      one of the Latency - 1 cycles before a change would
//                      be cropped, cut or blended under two settings
//                      (poly_enabled_i included);
//   a_polygons_composite - with polygons the blend mode is composite (golden
//                      refuses polygons with MIP/MinIP: the second node
//                      composites over whatever the first chose);
//   a_slice_in_range - with polygons a sample's slice k is below 2^15
//                      (SliceBits - 1 bits), so that k << ZFracBits stays
//                      below kZNone, the depth of "no opaque polygon", and
//                      no sample is hidden where no surface is.
// and, for coverage (scripts/coverage.sh), the cases a test suite must
// reach: a sample under each blend mode (c_blend_*), in each of the eight
// crop regions with cropping on (c_crop_region_r, r = in_x | in_y << 1 |
// in_z << 2, the crop-mask bit that decides it: golden crop_visible), with
// polygons (c_polygons), in each of the cut plane's three regions with the
// cut plane on (c_cut_inside, c_cut_ramp, c_cut_beyond: golden cut_factor's
// cases), and each saturation: the plane distance at either bound
// (c_cut_distance_hi, _lo), the ramp above one (c_cut_ramp_saturated), the
// premultiplied colour clamped to alpha (c_premultiply_clamped, only with
// guard bits). One statement per case: verilator_coverage merges the
// iterations of a generate loop into one point.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_composite_sva #(
  parameter int unsigned AlphaBits   = 16,
  parameter int unsigned CutBits     = 32,
  parameter int unsigned CutInvShift = 24,
  parameter int unsigned PosBits     = 16,
  parameter int unsigned CutCoefBits = 12,
  parameter int unsigned SliceBits   = 16,
  parameter bit          HasCutPlane = 1'b1
) (
  input logic                             clk_i,
  input logic                             rst_ni,
  input cube4_pkg::blend_e                blend_mode_i,
  input logic                             crop_enabled_i,
  input logic [PosBits-1:0]               crop_x_lo_i,
  input logic [PosBits-1:0]               crop_x_hi_i,
  input logic [PosBits-1:0]               crop_y_lo_i,
  input logic [PosBits-1:0]               crop_y_hi_i,
  input logic [PosBits-1:0]               crop_z_lo_i,
  input logic [PosBits-1:0]               crop_z_hi_i,
  input logic [7:0]                       crop_mask_i,
  input logic                             cut_enabled_i,
  input logic [CutCoefBits-1:0]           cut_a_i,
  input logic [CutCoefBits-1:0]           cut_b_i,
  input logic [CutCoefBits-1:0]           cut_c_i,
  input logic [CutBits-1:0]               cut_dmin_i,
  input logic [CutBits-1:0]               cut_dmax_i,
  input logic [CutBits-1:0]               cut_falloff_i,
  input logic [AlphaBits+CutInvShift-1:0] cut_inv_falloff_i,
  input logic                             cut_keep_inside_i,
  input logic                             poly_enabled_i,
  input logic [SliceBits-1:0]             slice_k_i,
  input logic [PosBits-1:0]               x_i,
  input logic [PosBits-1:0]               y_i,
  input logic [PosBits-1:0]               z_i,
  input logic                             valid_i,
  // Internal: the valid of a sample in stage 2 (the cut distance), 4 (the
  // ramp), 5 (the cut region) and 6 (the premultiplication), valid_q[s - 2]
  // of the compositor, and the coverage signals.
  input logic                             stage2_valid,
  input logic                             stage4_valid,
  input logic                             stage5_valid,
  input logic                             stage6_valid,
  input logic                             cut_in_slab,
  input logic                             cut_beyond,
  input logic                             cut_distance_hi,
  input logic                             cut_distance_lo,
  input logic                             cut_ramp_saturated,
  input logic [2:0]                       pre_clamped
);

  // cube4_composite's Latency is 7: a sample entered in the last 6 cycles
  // still has stages that read the registers.
  localparam int unsigned InFlight = 6;
  localparam int unsigned CropBits = 1 + 6 * PosBits + 8;
  localparam int unsigned CutRegs  = 1 + 3 * CutCoefBits + 3 * CutBits + AlphaBits + CutInvShift + 1;
  localparam int unsigned RegBits  = 2 + CropBits + CutRegs + 1;

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  logic [RegBits-1:0]  regs, regs_q;
  logic [InFlight-1:0] entered;
  assign regs = {blend_mode_i,
                 crop_enabled_i, crop_x_lo_i, crop_x_hi_i, crop_y_lo_i, crop_y_hi_i, crop_z_lo_i, crop_z_hi_i,
                 crop_mask_i,
                 cut_enabled_i, cut_a_i, cut_b_i, cut_c_i, cut_dmin_i, cut_dmax_i, cut_falloff_i, cut_inv_falloff_i,
                 cut_keep_inside_i, poly_enabled_i};
  cube4_sva_frame_registers #(.Width(RegBits), .Cycles(InFlight)) u_frame (
    .clk_i, .rst_ni, .valid_i, .regs_i(regs), .entered_o(entered), .regs_q_o(regs_q));

  logic [1:0] mode_q;
  logic       crop_changed, cut_changed;
  assign mode_q       = regs_q[RegBits-1 -: 2];
  assign crop_changed = regs[1 + CutRegs +: CropBits] != regs_q[1 + CutRegs +: CropBits];
  assign cut_changed  = regs[1 +: CutRegs] != regs_q[1 +: CutRegs];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_frame_registers_stable: assert (entered == '0 || regs == regs_q)
        else $error("cube4_composite: cycle %0d: frame registers changed with samples in flight (entered %b cycles ago, bit i: i+1): blend mode %0d -> %0d, cropping changed %0d, cut plane changed %0d",
                    cycle, entered, mode_q, blend_mode_i, crop_changed, cut_changed);
      a_polygons_composite: assert (!(valid_i && poly_enabled_i) || blend_mode_i == cube4_pkg::BlendComposite
                                    || blend_mode_i == 2'd3)
        else $error("cube4_composite: cycle %0d: polygons with blend mode %0d (composite only)", cycle, blend_mode_i);
      a_slice_in_range: assert (!(valid_i && poly_enabled_i) || slice_k_i[SliceBits-1] == 1'b0)
        else $error("cube4_composite: cycle %0d: sample slice %0d with polygons: at most %0d, so that k << ZFracBits stays below kZNone",
                    cycle, slice_k_i, (1 << (SliceBits - 1)) - 1);
    end
  end

  c_blend_composite: cover property (@(posedge clk_i) valid_i && blend_mode_i == cube4_pkg::BlendComposite);
  c_blend_mip: cover property (@(posedge clk_i) valid_i && blend_mode_i == cube4_pkg::BlendMip);
  c_blend_minip: cover property (@(posedge clk_i) valid_i && blend_mode_i == cube4_pkg::BlendMinIp);
  c_polygons: cover property (@(posedge clk_i) valid_i && poly_enabled_i);

  logic [2:0] crop_region;
  assign crop_region = {crop_z_lo_i <= z_i && z_i <= crop_z_hi_i, crop_y_lo_i <= y_i && y_i <= crop_y_hi_i,
                        crop_x_lo_i <= x_i && x_i <= crop_x_hi_i};
  logic crop_sample;
  assign crop_sample = valid_i && crop_enabled_i;
  c_crop_region_0: cover property (@(posedge clk_i) crop_sample && crop_region == 3'd0);
  c_crop_region_1: cover property (@(posedge clk_i) crop_sample && crop_region == 3'd1);
  c_crop_region_2: cover property (@(posedge clk_i) crop_sample && crop_region == 3'd2);
  c_crop_region_3: cover property (@(posedge clk_i) crop_sample && crop_region == 3'd3);
  c_crop_region_4: cover property (@(posedge clk_i) crop_sample && crop_region == 3'd4);
  c_crop_region_5: cover property (@(posedge clk_i) crop_sample && crop_region == 3'd5);
  c_crop_region_6: cover property (@(posedge clk_i) crop_sample && crop_region == 3'd6);
  c_crop_region_7: cover property (@(posedge clk_i) crop_sample && crop_region == 3'd7);

  logic cut_on;
  assign cut_on = HasCutPlane && cut_enabled_i;
  c_cut_inside: cover property (@(posedge clk_i) stage5_valid && cut_on && cut_in_slab);
  c_cut_ramp: cover property (@(posedge clk_i) stage5_valid && cut_on && !cut_in_slab && !cut_beyond);
  c_cut_beyond: cover property (@(posedge clk_i) stage5_valid && cut_on && cut_beyond);
  c_cut_distance_hi: cover property (@(posedge clk_i) stage2_valid && cut_on && cut_distance_hi);
  c_cut_distance_lo: cover property (@(posedge clk_i) stage2_valid && cut_on && cut_distance_lo);
  c_cut_ramp_saturated: cover property (@(posedge clk_i) stage4_valid && cut_on && cut_ramp_saturated);
  c_premultiply_clamped: cover property (@(posedge clk_i) stage6_valid && |pre_clamped);

endmodule

bind cube4_composite cube4_composite_sva #(
  .AlphaBits  (AlphaBits),
  .CutBits    (CutBits),
  .CutInvShift(CutInvShift),
  .PosBits    (PosBits),
  .CutCoefBits(CutCoefBits),
  .SliceBits  (SliceBits),
  .HasCutPlane(HasCutPlane)
) u_sva (.stage2_valid(valid_q[0]), .stage4_valid(valid_q[2]), .stage5_valid(valid_q[3]),
         .stage6_valid(valid_q[4]), .*);
