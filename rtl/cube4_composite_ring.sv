// cube4_composite_ring: the compositing units of p pipelines connected
// near-neighbour in a ring (VolumePro §3.6, §5.1, Fig. 11).
//
// Function: pipeline k (cube4_composite_unit) composites the shaded samples
// of the columns x = j*p + k of every partial beam j into its rays and emits
// the finished ones as base-plane pixels. The ray-alignment candidate of
// column x-1 comes from pipeline k-1's link of the same step; pipeline 0
// takes pipeline p-1's link and holds it for the next partial beam (the
// ring wrap, registered in pipeline 0). The stream control (valid, flags,
// slice tags, position) is common and fans out to every pipeline, where it
// travels with the data; x_i is the x of pipeline 0 (j*p), pipeline k's is
// x_i + k. Each pipeline has its own sample inputs and its own pixel port
// (all pipelines run in lock step), with the finished ray both rounded to
// a base-plane pixel and as its accumulator (a partial image for the
// composition network). Stream format, latency (pixel 7 cycles
// after its sample), storage order and preconditions: see
// cube4_composite_unit and docs/rtl-composite.md. nx not a multiple of p:
// the stream pads the last partial beam with samples of any value (columns
// x >= nx), which are never emitted.
//
// Polygons (HasPolygons, poly_enabled_i): every pipeline gets its samples'
// ray data (Z, front and back pixels) with them and reads its own slab
// lines through its run-length decoder (cube4_composite_unit,
// docs/rtl-composite.md, "Polygons"); slice_k_i is common.
//
// Handshake: valid-only, no back-pressure. Reset: control only.
//
// Parameters:
//   NumPipes                          - p, pipelines (>= 1)
//   VoxelBits, WeightBits, AlphaBits, AccGuardBits,
//   CutBits, CutInvShift, PosBits,
//   CutCoefBits, HasCutPlane          - as cube4_composite
//   HasPolygons, ZBits, SliceBits     - as cube4_composite_unit
//   MaxDim                            - largest nx and ny the ray storage holds
//   BeamDepth, SliceDepth             - (derived) per-pipeline ray beam delay
//                                       and ray slice store entries:
//                                       ceil(MaxDim / p) and MaxDim * that
`include "cube4_pkg.sv"

module cube4_composite_ring #(
  parameter int unsigned  NumPipes    = cube4_pkg::NumPipes,
  parameter int unsigned  VoxelBits   = cube4_pkg::VoxelBits,
  parameter int unsigned  WeightBits  = cube4_pkg::WeightBits,
  parameter int unsigned  AlphaBits   = cube4_pkg::AlphaBits,
  parameter int unsigned  AccGuardBits = cube4_pkg::AccGuardBits,
  parameter int unsigned  CutBits     = cube4_pkg::CutBits,
  parameter int unsigned  CutInvShift = cube4_pkg::CutInvShift,
  parameter int unsigned  PosBits     = cube4_pkg::PosBits,
  parameter int unsigned  CutCoefBits = cube4_pkg::CutCoefBits,
  parameter bit           HasCutPlane = 1'b1,
  parameter bit           HasPolygons = 1'b1,
  parameter int unsigned  ZBits       = cube4_pkg::ZBits,
  parameter int unsigned  SliceBits   = cube4_pkg::SliceBits,
  parameter int unsigned  MaxDim      = cube4_pkg::MaxDim,
  localparam int unsigned BeamDepth   = (MaxDim + NumPipes - 1) / NumPipes,
  localparam int unsigned SliceDepth  = MaxDim * BeamDepth
) (
  input  logic                             clk_i,
  input  logic                             rst_ni,
  // Frame registers of cube4_composite.
  input  cube4_pkg::blend_e                blend_mode_i,
  input  logic                             crop_enabled_i,
  input  logic [PosBits-1:0]               crop_x_lo_i,
  input  logic [PosBits-1:0]               crop_x_hi_i,
  input  logic [PosBits-1:0]               crop_y_lo_i,
  input  logic [PosBits-1:0]               crop_y_hi_i,
  input  logic [PosBits-1:0]               crop_z_lo_i,
  input  logic [PosBits-1:0]               crop_z_hi_i,
  input  logic [7:0]                       crop_mask_i,
  input  logic                             window_enabled_i,
  input  logic [PosBits-1:0]               window_x_lo_i,
  input  logic [PosBits-1:0]               window_x_hi_i,
  input  logic [PosBits-1:0]               window_y_lo_i,
  input  logic [PosBits-1:0]               window_y_hi_i,
  input  logic [PosBits-1:0]               window_z_lo_i,
  input  logic [PosBits-1:0]               window_z_hi_i,
  input  logic                             cut_enabled_i,
  input  logic signed [CutCoefBits-1:0]    cut_a_i,
  input  logic signed [CutCoefBits-1:0]    cut_b_i,
  input  logic signed [CutCoefBits-1:0]    cut_c_i,
  input  logic signed [CutBits-1:0]        cut_dmin_i,
  input  logic signed [CutBits-1:0]        cut_dmax_i,
  input  logic [CutBits-1:0]               cut_falloff_i,
  input  logic [AlphaBits+CutInvShift-1:0] cut_inv_falloff_i,
  input  logic                             cut_keep_inside_i,
  // Frame register: polygons.
  input  logic                             poly_enabled_i,
  // Frame values sampled with valid_i.
  input  logic [PosBits-1:0]               nx_i,
  input  logic [PosBits-1:0]               last_ix_i,
  input  logic [PosBits-1:0]               last_iy_i,
  // Sample stream: common control, one sample per pipeline ([k*Width +:]).
  input  logic                             valid_i,
  input  logic                             beam_start_i,
  input  logic                             beam_end_i,
  input  logic                             slice_start_i,
  input  logic                             slice_end_i,
  input  logic                             first_slice_i,
  input  logic                             last_slice_i,
  input  logic                             dx_i,
  input  logic                             dy_i,
  input  logic                             next_dx_i,
  input  logic                             next_dy_i,
  input  logic [PosBits-1:0]               ix_i,
  input  logic [PosBits-1:0]               iy_i,
  input  logic [PosBits-1:0]               x_i,
  input  logic [PosBits-1:0]               y_i,
  input  logic [PosBits-1:0]               z_i,
  input  logic [WeightBits-1:0]            wx_i,
  input  logic [WeightBits-1:0]            wy_i,
  input  logic [WeightBits-1:0]            wz_i,
  input  logic [NumPipes*AlphaBits-1:0]    red_i,
  input  logic [NumPipes*AlphaBits-1:0]    green_i,
  input  logic [NumPipes*AlphaBits-1:0]    blue_i,
  input  logic [NumPipes*AlphaBits-1:0]    alpha_i,
  input  logic [NumPipes*VoxelBits-1:0]    value_i,
  // Polygons: the slice (common), per pipeline its sample's ray data and
  // its slab line source.
  input  logic [SliceBits-1:0]             slice_k_i,
  input  logic [NumPipes*ZBits-1:0]        ray_z_i,
  input  logic [NumPipes*AlphaBits-1:0]    ray_front_red_i,
  input  logic [NumPipes*AlphaBits-1:0]    ray_front_green_i,
  input  logic [NumPipes*AlphaBits-1:0]    ray_front_blue_i,
  input  logic [NumPipes*AlphaBits-1:0]    ray_front_alpha_i,
  input  logic [NumPipes*AlphaBits-1:0]    ray_back_red_i,
  input  logic [NumPipes*AlphaBits-1:0]    ray_back_green_i,
  input  logic [NumPipes*AlphaBits-1:0]    ray_back_blue_i,
  input  logic [NumPipes*AlphaBits-1:0]    ray_back_alpha_i,
  output logic [NumPipes-1:0]              slab_line_o,
  input  logic [NumPipes*5*cube4_pkg::RleWordBits-1:0] slab_window_i,
  input  logic [NumPipes*3-1:0]            slab_avail_i,
  output logic [NumPipes*3-1:0]            slab_consume_o,
  // Pixel ports, pipeline k at bit k / [k*Width +:].
  output logic [NumPipes-1:0]              pixel_valid_o,
  output logic [NumPipes*PosBits-1:0]      pixel_u_o,
  output logic [NumPipes*PosBits-1:0]      pixel_v_o,
  output logic [NumPipes*AlphaBits-1:0]    pixel_red_o,
  output logic [NumPipes*AlphaBits-1:0]    pixel_green_o,
  output logic [NumPipes*AlphaBits-1:0]    pixel_blue_o,
  output logic [NumPipes*AlphaBits-1:0]    pixel_alpha_o,
  // The same rays' accumulators (golden RayAcc): partial images.
  output logic [NumPipes*(AlphaBits+AccGuardBits)-1:0] pixel_acc_red_o,
  output logic [NumPipes*(AlphaBits+AccGuardBits)-1:0] pixel_acc_green_o,
  output logic [NumPipes*(AlphaBits+AccGuardBits)-1:0] pixel_acc_blue_o,
  output logic [NumPipes*(AlphaBits+AccGuardBits)-1:0] pixel_acc_alpha_o,
  output logic [NumPipes*VoxelBits-1:0]    pixel_value_o,
  output logic [NumPipes-1:0]              pixel_selected_o
);

  localparam int unsigned A        = AlphaBits;
  localparam int unsigned AB       = AlphaBits + AccGuardBits;
  localparam int unsigned LinkBits = 4 * (AlphaBits + AccGuardBits) + VoxelBits + 1;
  localparam int unsigned WinBits  = 5 * cube4_pkg::RleWordBits;

  // Links as a packed vector (yosys 0.23: no unpacked wire arrays).
  logic [NumPipes*LinkBits-1:0] link;

  for (genvar k = 0; k < NumPipes; k++) begin : g_pipe
    localparam int unsigned Left = (k == 0) ? NumPipes - 1 : k - 1;
    logic [PosBits-1:0] x;
    assign x = x_i + PosBits'(k);

    cube4_composite_unit #(
      .VoxelBits  (VoxelBits),
      .WeightBits (WeightBits),
      .AlphaBits  (AlphaBits),
      .AccGuardBits(AccGuardBits),
      .CutBits    (CutBits),
      .CutInvShift(CutInvShift),
      .PosBits    (PosBits),
      .CutCoefBits(CutCoefBits),
      .HasCutPlane(HasCutPlane),
      .HasPolygons(HasPolygons),
      .ZBits      (ZBits),
      .SliceBits  (SliceBits),
      .BeamDepth  (BeamDepth),
      .SliceDepth (SliceDepth),
      .WrapIn     (k == 0)
    ) u_unit (
      .clk_i            (clk_i),
      .rst_ni           (rst_ni),
      .blend_mode_i     (blend_mode_i),
      .crop_enabled_i   (crop_enabled_i),
      .crop_x_lo_i      (crop_x_lo_i),
      .crop_x_hi_i      (crop_x_hi_i),
      .crop_y_lo_i      (crop_y_lo_i),
      .crop_y_hi_i      (crop_y_hi_i),
      .crop_z_lo_i      (crop_z_lo_i),
      .crop_z_hi_i      (crop_z_hi_i),
      .crop_mask_i      (crop_mask_i),
      .window_enabled_i (window_enabled_i),
      .window_x_lo_i    (window_x_lo_i),
      .window_x_hi_i    (window_x_hi_i),
      .window_y_lo_i    (window_y_lo_i),
      .window_y_hi_i    (window_y_hi_i),
      .window_z_lo_i    (window_z_lo_i),
      .window_z_hi_i    (window_z_hi_i),
      .cut_enabled_i    (cut_enabled_i),
      .cut_a_i          (cut_a_i),
      .cut_b_i          (cut_b_i),
      .cut_c_i          (cut_c_i),
      .cut_dmin_i       (cut_dmin_i),
      .cut_dmax_i       (cut_dmax_i),
      .cut_falloff_i    (cut_falloff_i),
      .cut_inv_falloff_i(cut_inv_falloff_i),
      .cut_keep_inside_i(cut_keep_inside_i),
      .poly_enabled_i   (poly_enabled_i),
      .nx_i             (nx_i),
      .last_ix_i        (last_ix_i),
      .last_iy_i        (last_iy_i),
      .valid_i          (valid_i),
      .beam_start_i     (beam_start_i),
      .beam_end_i       (beam_end_i),
      .slice_start_i    (slice_start_i),
      .slice_end_i      (slice_end_i),
      .first_slice_i    (first_slice_i),
      .last_slice_i     (last_slice_i),
      .dx_i             (dx_i),
      .dy_i             (dy_i),
      .next_dx_i        (next_dx_i),
      .next_dy_i        (next_dy_i),
      .ix_i             (ix_i),
      .iy_i             (iy_i),
      .x_i              (x),
      .y_i              (y_i),
      .z_i              (z_i),
      .wx_i             (wx_i),
      .wy_i             (wy_i),
      .wz_i             (wz_i),
      .red_i            (red_i[k*A +: A]),
      .green_i          (green_i[k*A +: A]),
      .blue_i           (blue_i[k*A +: A]),
      .alpha_i          (alpha_i[k*A +: A]),
      .value_i          (value_i[k*VoxelBits +: VoxelBits]),
      .slice_k_i        (slice_k_i),
      .ray_z_i          (ray_z_i[k*ZBits +: ZBits]),
      .ray_front_red_i  (ray_front_red_i[k*A +: A]),
      .ray_front_green_i(ray_front_green_i[k*A +: A]),
      .ray_front_blue_i (ray_front_blue_i[k*A +: A]),
      .ray_front_alpha_i(ray_front_alpha_i[k*A +: A]),
      .ray_back_red_i   (ray_back_red_i[k*A +: A]),
      .ray_back_green_i (ray_back_green_i[k*A +: A]),
      .ray_back_blue_i  (ray_back_blue_i[k*A +: A]),
      .ray_back_alpha_i (ray_back_alpha_i[k*A +: A]),
      .slab_line_o      (slab_line_o[k]),
      .slab_window_i    (slab_window_i[k*WinBits +: WinBits]),
      .slab_avail_i     (slab_avail_i[k*3 +: 3]),
      .slab_consume_o   (slab_consume_o[k*3 +: 3]),
      .link_o           (link[k*LinkBits +: LinkBits]),
      .link_i           (link[Left*LinkBits +: LinkBits]),
      .pixel_valid_o    (pixel_valid_o[k]),
      .pixel_u_o        (pixel_u_o[k*PosBits +: PosBits]),
      .pixel_v_o        (pixel_v_o[k*PosBits +: PosBits]),
      .pixel_red_o      (pixel_red_o[k*A +: A]),
      .pixel_green_o    (pixel_green_o[k*A +: A]),
      .pixel_blue_o     (pixel_blue_o[k*A +: A]),
      .pixel_alpha_o    (pixel_alpha_o[k*A +: A]),
      .pixel_acc_red_o  (pixel_acc_red_o[k*AB +: AB]),
      .pixel_acc_green_o(pixel_acc_green_o[k*AB +: AB]),
      .pixel_acc_blue_o (pixel_acc_blue_o[k*AB +: AB]),
      .pixel_acc_alpha_o(pixel_acc_alpha_o[k*AB +: AB]),
      .pixel_value_o    (pixel_value_o[k*VoxelBits +: VoxelBits]),
      .pixel_selected_o (pixel_selected_o[k])
    );
  end

endmodule
