// cube4_composite_unit: one pipeline's compositing unit with its ray storage
// and ray alignment (VolumePro §3.6 and Fig. 4: Ray Slice FIFO, Ray Beam
// FIFO, Ray Shift Register and the Ray Alignment multiplexers; §5.1: the
// shift registers as near-neighbour links). docs/rtl-composite.md describes
// the dataflow.
//
// Function: pipeline k of p receives, for every sample slice, the shaded
// samples of its columns x = j*p + k in beam order (beams y = 0 .. ny-1,
// partial beams j = 0 .. B-1, B = ceil(nx/p)), and blends each into the
// partially composited ray it continues (cube4_composite, instantiated
// unchanged: cropping, cut plane, blend). Golden render_fixed():
//   - the ray at (x, y) of slice k continues the ray at (x - dx, y - dy) of
//     slice k-1 ((dx, dy) of slice k, each 0 or 1), or starts empty when
//     that lies outside the slice (x - dx < 0 or y - dy < 0) and in the
//     first slice of a frame;
//   - a ray of slice k is final when it has no successor in slice k+1
//     (x + dx' >= nx or y + dy' >= ny, (dx', dy') of slice k+1) or k is the
//     last slice: it is emitted on the pixel port as base-plane pixel
//     (u, v) = (x + last_ix - ix, y + last_iy - iy) (ix, iy: the DDA integer
//     offsets of slice k; last_ix, last_iy: those of the last slice). Every
//     ray is emitted exactly once, as its last sample is composited, so the
//     port carries at most one pixel per cycle. (Golden writes a side-face
//     ray while compositing slice k+1; the pixel and its value are the same.)
// The four candidates of the previous slice come from:
//   (x, y)     : the ray slice store (own entry, read before it is rewritten);
//   (x, y-1)   : the ray beam delay (the store's output, one beam later);
//   (x-1, .)   : pipeline k-1's candidate (link_i), selected by dy there;
//                for pipeline 0 (WrapIn) pipeline p-1's candidate of the
//                previous partial beam, held in the wrap register (the Ray
//                Shift Register of the rightmost pipeline, Fig. 11).
// Padding columns (x >= nx, when p does not divide nx) are composited like
// the others but never emitted; nothing reads their rays.
//
// Storage order (the brief's hazard): the store is single-buffered, in
// place. A slice-k sample of ray (x, y) is composited AccDelay cycles after
// it enters; in that cycle the store entry of (x, y) is read (it still holds
// slice k-1), the candidate at (x, y-1) comes from the beam delay (a copy of
// slice k-1 made when that entry was read, one beam earlier, before it was
// overwritten), the (x-1, .) candidates are the neighbour's reads of the same
// step (or the wrap register's copy of the previous step), and the slice-k
// result is written into the entry of (x, y) one cycle later. So every read
// of slice k-1 precedes the write of slice k to the same entry, and no
// slice-k result is ever a candidate. When the previous step wrote the entry
// being read in the cycle before (a slice of one step: ny = 1, nx <= p,
// back to back), its result is bypassed from cube4_composite's output.
//
// Stream (valid_i cycles; any number of idle cycles between them; all
// pipelines of a ring get the same control):
//   beam_start_i / beam_end_i   : partial beam j = 0 / j = B-1
//   slice_start_i / slice_end_i : beam y = 0 / y = ny-1
//   first_slice_i / last_slice_i: slice 0 / slice K-1 of a frame
//   dx_i, dy_i                  : the slice's offset change since the
//                                 previous slice (golden SliceControl dx, dy)
//   next_dx_i, next_dy_i        : the next slice's (ignored in the last slice)
//   ix_i, iy_i                  : the slice's DDA integer offsets
//   x_i, y_i, z_i               : the sample's position (z = voxel slice
//                                 z_voxel), wx_i, wy_i, wz_i: slice weights
//   nx_i, last_ix_i, last_iy_i  : the frame's permuted nx and the last slice's
//                                 offsets; sampled with each valid_i (only at
//                                 the input), so they may change between two
//                                 frames without a gap
//   red_i, green_i, blue_i, alpha_i, value_i: the shaded sample before
//                                 cropping and the cut plane (not premultiplied)
// The frame registers of cube4_composite (blend mode, crop, window, cut) may change
// only while no sample is in flight (Latency cycles after the last input).
//
// The pixel port carries each finished ray twice: rounded to AlphaBits
// (pixel_red_o .. pixel_alpha_o, golden pixel_of(), the base plane) and as
// its accumulator (pixel_acc_*_o, pixel_value_o, pixel_selected_o: golden
// RayAcc), the partial image a block of a partitioned volume hands to the
// composition network (golden/blocks.hpp), which composes before rounding.
//
// Latency: a sample's pixel (if its ray ends there) appears on pixel_*_o
// Latency = 7 cycles after it enters (cube4_composite's latency); the ray
// storage steps AccDelay = 6 cycles after the input. One sample per clock.
// Handshake: valid-only, no back-pressure. Reset: control only (valid
// delays, store pointers); data registers and RAMs are not reset.
//
// Polygons (HasPolygons and poly_enabled_i; Cube-5 §5, golden
// SliceCompositor with a PolygonFrame; docs/rtl-composite.md, "Polygons"):
//   - a ray starts (no predecessor) as its front pixel, widened
//     (pixel_to_acc), instead of the empty ray;
//   - each sample passes the Z test against its ray's Z and is followed by
//     its slab pixel (cube4_composite: double_composite);
//   - a ray leaves as pixel_of(ray over back pixel) (leave_with_polygons);
//     pixel_acc_*_o stay the ray itself.
// With every sample the stream brings its ray's polygon data, read by (u, v)
// from the composite buffer: ray_z_i, ray_front_*_i, ray_back_*_i (the same
// values for every sample of a ray), and the sample slice slice_k_i. The
// slab pixels come from this pipeline's run-length decoder
// (cube4_rle_decode), one per sample of a real column (x < nx), the lines
// beam by beam in stream order: its word source outside moves to the next
// line at the clock edge that ends a cycle with slab_line_o high (two
// cycles before the line's first pixel is decoded, at stage 5), and by
// slab_consume_o words at every edge; it shows slab_window_i and
// slab_avail_i (cube4_rle_decode's header). Pixels no ray reaches are the
// host's (front over back) and never emitted. Same latency, one sample per
// clock; polygons off, the unit is exactly the one without them.
//
// Preconditions: every slice is complete (ny beams of the same B partial
// beams); B <= BeamDepth; ny * B <= SliceDepth; dx, dy, next_dx, next_dy as
// golden (a change of the DDA offset by 0 or 1 per slice).
//
// Parameters:
//   VoxelBits, WeightBits, AlphaBits, AccGuardBits, CutBits, CutInvShift,
//   PosBits, CutCoefBits  - as cube4_composite (golden Precision defaults)
//   HasCutPlane           - as cube4_composite (0: no cut-plane hardware)
//   HasPolygons           - 0: no polygon hardware (no decoder, no front
//                           and back pixels; the polygon ports are ignored)
//   ZBits, SliceBits      - as cube4_composite
//   BeamDepth             - ray beam delay entries: max partial beams per beam
//   SliceDepth            - ray slice store entries: max ny * partial beams
//   WrapIn                - 1 for pipeline 0: link_i is pipeline p-1's link_o
//                           of the same step, registered here (the ring wrap)
//   AccBits               - (derived) a ray: {selected, value, alpha, blue,
//                           green, red}, golden RayAcc
`include "cube4_pkg.sv"

module cube4_composite_unit #(
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
  parameter int unsigned  BeamDepth   = 64,
  parameter int unsigned  SliceDepth  = 16384,
  parameter bit           WrapIn      = 1'b0,
  localparam int unsigned AccBits     = 4 * (AlphaBits + AccGuardBits) + VoxelBits + 1
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
  // Sample stream.
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
  input  logic [AlphaBits-1:0]             red_i,
  input  logic [AlphaBits-1:0]             green_i,
  input  logic [AlphaBits-1:0]             blue_i,
  input  logic [AlphaBits-1:0]             alpha_i,
  input  logic [VoxelBits-1:0]             value_i,
  // Polygons, with the sample: its slice, its ray's depth, front and back
  // pixels (premultiplied, AlphaBits each).
  input  logic [SliceBits-1:0]             slice_k_i,
  input  logic [ZBits-1:0]                 ray_z_i,
  input  logic [AlphaBits-1:0]             ray_front_red_i,
  input  logic [AlphaBits-1:0]             ray_front_green_i,
  input  logic [AlphaBits-1:0]             ray_front_blue_i,
  input  logic [AlphaBits-1:0]             ray_front_alpha_i,
  input  logic [AlphaBits-1:0]             ray_back_red_i,
  input  logic [AlphaBits-1:0]             ray_back_green_i,
  input  logic [AlphaBits-1:0]             ray_back_blue_i,
  input  logic [AlphaBits-1:0]             ray_back_alpha_i,
  // This pipeline's slab lines (cube4_rle_decode's word source).
  output logic                             slab_line_o,
  input  logic [5*cube4_pkg::RleWordBits-1:0] slab_window_i,
  input  logic [2:0]                       slab_avail_i,
  output logic [2:0]                       slab_consume_o,
  // Near-neighbour links: this step's candidate of column x (to pipeline
  // k+1), and pipeline k-1's (or, WrapIn, pipeline p-1's) candidate.
  output logic [AccBits-1:0]               link_o,
  input  logic [AccBits-1:0]               link_i,
  // Finished base-plane pixels.
  output logic                             pixel_valid_o,
  output logic [PosBits-1:0]               pixel_u_o,
  output logic [PosBits-1:0]               pixel_v_o,
  output logic [AlphaBits-1:0]             pixel_red_o,
  output logic [AlphaBits-1:0]             pixel_green_o,
  output logic [AlphaBits-1:0]             pixel_blue_o,
  output logic [AlphaBits-1:0]             pixel_alpha_o,
  output logic [AlphaBits+AccGuardBits-1:0] pixel_acc_red_o,
  output logic [AlphaBits+AccGuardBits-1:0] pixel_acc_green_o,
  output logic [AlphaBits+AccGuardBits-1:0] pixel_acc_blue_o,
  output logic [AlphaBits+AccGuardBits-1:0] pixel_acc_alpha_o,
  output logic [VoxelBits-1:0]             pixel_value_o,
  output logic                             pixel_selected_o
);

  localparam int unsigned A              = AlphaBits;
  localparam int unsigned G              = AccGuardBits;
  localparam int unsigned AB             = AlphaBits + AccGuardBits;  // accumulator channel
  // cube4_composite's timing (its header): the predecessor enters AccDelay
  // cycles after the sample, the result leaves Latency cycles after it.
  localparam int unsigned AccDelay       = 6;
  localparam int unsigned Latency        = 7;
  localparam int unsigned CtrlBits       = 7;
  localparam int unsigned ExitBits       = 1 + 2 * PosBits;
  localparam int unsigned PtrBits        = (SliceDepth > 1) ? $clog2(SliceDepth) : 1;
  localparam int unsigned BeamDepthBits  = $clog2(BeamDepth + 1);

  // -------------------------------------------------------------------------
  // Input stage: whether the sample's ray ends here, and its pixel address.
  logic                 exit_d;
  logic [PosBits:0]     x_next;
  logic [PosBits-1:0]   u_d, v_d;
  assign x_next = {1'b0, x_i} + (PosBits+1)'(1);
  assign exit_d = (x_i < nx_i)
               && (last_slice_i
                   || (next_dx_i && x_next == {1'b0, nx_i})
                   || (next_dy_i && slice_end_i));
  assign u_d    = x_i + last_ix_i - ix_i;
  assign v_d    = y_i + last_iy_i - iy_i;

  // Delay lines beside cube4_composite (packed: yosys 0.23). The ray-storage
  // control reaches stage AccDelay, the exit flag and pixel address the
  // output. Only the valid delay is reset.
  logic [AccDelay-1:0]          step_q;
  logic [AccDelay*CtrlBits-1:0] ctrl_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      step_q <= '0;
    end else begin
      step_q <= {step_q[AccDelay-2:0], valid_i};
    end
  end

  always_ff @(posedge clk_i) begin
    ctrl_q <= {ctrl_q[(AccDelay-1)*CtrlBits-1:0],
               first_slice_i, slice_start_i, slice_end_i, beam_start_i, beam_end_i, dx_i, dy_i};
  end

  // Stage AccDelay: one step of the ray storage per sample.
  logic step, first_a, slice_start_a, slice_end_a, beam_start_a, beam_end_a, dx_a, dy_a;
  assign step = step_q[AccDelay-1];
  assign {first_a, slice_start_a, slice_end_a, beam_start_a, beam_end_a, dx_a, dy_a} =
      ctrl_q[(AccDelay-1)*CtrlBits +: CtrlBits];

  // -------------------------------------------------------------------------
  // Polygons: the slab decoder (asked at stage 5, its pixel at stage
  // AccDelay with the predecessor), the front pixel delayed to stage
  // AccDelay (a ray's start), the back pixel to the output (its end).
  localparam int unsigned PixBits = 4 * A;  // {red, green, blue, alpha}
  logic [PixBits-1:0]   slab_pixel;         // the slab pixel of the stage-6 sample
  logic [AccBits-1:0]   start_ray;          // a ray with no predecessor
  logic [AB-1:0]        exit_red, exit_green, exit_blue, exit_alpha;  // what the pixel port rounds

  // -------------------------------------------------------------------------
  // Compositing datapath; its result is the ray of this slice.
  logic [AccBits-1:0] pred, result;
  logic               result_valid;
  logic [AB-1:0]      res_red, res_green, res_blue, res_alpha;
  logic [VoxelBits-1:0] res_value;
  logic               res_selected;

  cube4_composite #(
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
    .SliceBits  (SliceBits)
  ) u_composite (
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
    .slice_k_i        (slice_k_i),
    .ray_z_i          (ray_z_i),
    .slab_red_i       (slab_pixel[3*A +: A]),
    .slab_green_i     (slab_pixel[2*A +: A]),
    .slab_blue_i      (slab_pixel[A +: A]),
    .slab_alpha_i     (slab_pixel[0 +: A]),
    .valid_i          (valid_i),
    .red_i            (red_i),
    .green_i          (green_i),
    .blue_i           (blue_i),
    .alpha_i          (alpha_i),
    .value_i          (value_i),
    .x_i              (x_i),
    .y_i              (y_i),
    .z_i              (z_i),
    .wx_i             (wx_i),
    .wy_i             (wy_i),
    .wz_i             (wz_i),
    .acc_red_i        (pred[0 +: AB]),
    .acc_green_i      (pred[AB +: AB]),
    .acc_blue_i       (pred[2*AB +: AB]),
    .acc_alpha_i      (pred[3*AB +: AB]),
    .acc_value_i      (pred[4*AB +: VoxelBits]),
    .acc_selected_i   (pred[4*AB+VoxelBits]),
    .valid_o          (result_valid),
    .red_o            (res_red),
    .green_o          (res_green),
    .blue_o           (res_blue),
    .alpha_o          (res_alpha),
    .value_o          (res_value),
    .selected_o       (res_selected)
  );
  assign result = {res_selected, res_value, res_alpha, res_blue, res_green, res_red};

  // Polygon hardware (the declarations above the datapath).
  if (HasPolygons) begin : g_polygons
    localparam int unsigned W = cube4_pkg::RleWordBits;
    // Stages 1..5 of (valid and x < nx) beside the control delay.
    logic [AccDelay-2:0] real_q;
    logic [AccDelay*PixBits-1:0] front_q;
    logic [Latency*PixBits-1:0]  back_q;
    always_ff @(posedge clk_i) begin
      real_q  <= {real_q[AccDelay-3:0], x_i < nx_i};
      front_q <= {front_q[(AccDelay-1)*PixBits-1:0],
                  ray_front_red_i, ray_front_green_i, ray_front_blue_i, ray_front_alpha_i};
      back_q  <= {back_q[(Latency-1)*PixBits-1:0],
                  ray_back_red_i, ray_back_green_i, ray_back_blue_i, ray_back_alpha_i};
    end

    // Control bit 3 is beam_start (ctrl_q's order). A line per beam: the
    // source moves at the end of stage 4, the decoder starts at stage 5.
    logic line_4, start_5, next_5;
    assign line_4      = poly_enabled_i && step_q[3] && ctrl_q[3*CtrlBits + 3];
    assign start_5     = poly_enabled_i && step_q[4] && ctrl_q[4*CtrlBits + 3];
    assign next_5      = poly_enabled_i && step_q[4] && real_q[AccDelay-2];
    assign slab_line_o = line_4;

    // Waiver: a slab word is 16 bits and a pixel channel AlphaBits of them
    // (the low ones, below); with AlphaBits < 16 the words' top bits go
    // unused.
    /* verilator lint_off UNUSEDSIGNAL */
    logic [W-1:0] slab_r, slab_g, slab_b, slab_a;
    /* verilator lint_on UNUSEDSIGNAL */
    logic         slab_valid, slab_error, slab_finished;
    cube4_rle_decode u_slab_decode (
      .clk_i,
      .rst_ni,
      .start_i      (start_5),
      .next_i       (next_5),
      .window_i     (slab_window_i),
      .avail_i      (slab_avail_i),
      .consume_o    (slab_consume_o),
      .pixel_valid_o(slab_valid),
      .pixel_red_o  (slab_r),
      .pixel_green_o(slab_g),
      .pixel_blue_o (slab_b),
      .pixel_alpha_o(slab_a),
      .error_o      (slab_error),
      .finished_o   (slab_finished)
    );
    // A padding column asked nothing: its (unused) pixel is the decoder's
    // blank. Words are 16 bits, pixels AlphaBits (<= 16): the low bits.
    assign slab_pixel = {A'(slab_r), A'(slab_g), A'(slab_b), A'(slab_a)};

    // A ray's start: its front pixel widened (golden pixel_to_acc: MIP
    // value 0, not selected); the empty ray with polygons off.
    logic [PixBits-1:0] front_6, back_7;
    logic [4*AB-1:0]    front_acc, back_acc;  // red at [3*AB +: AB]
    assign front_6 = front_q[(AccDelay-1)*PixBits +: PixBits];
    assign back_7  = back_q[(Latency-1)*PixBits +: PixBits];
    for (genvar ch = 0; ch < 4; ch++) begin : g_widen
      cube4_to_acc #(.AlphaBits(A), .AccGuardBits(G)) u_front (
        .pixel_i(front_6[ch*A +: A]), .acc_o(front_acc[ch*AB +: AB]));
      cube4_to_acc #(.AlphaBits(A), .AccGuardBits(G)) u_back (
        .pixel_i(back_7[ch*A +: A]), .acc_o(back_acc[ch*AB +: AB]));
    end
    assign start_ray = poly_enabled_i
        ? {1'b0, VoxelBits'(0), front_acc[0 +: AB], front_acc[AB +: AB], front_acc[2*AB +: AB], front_acc[3*AB +: AB]}
        : '0;

    // A ray's end: the ray over its back pixel (golden leave_with_polygons;
    // a blank back pixel, or polygons off, leaves the ray as it is), in the
    // output cycle, before the rounding to AlphaBits.
    logic [4*AB-1:0] back_in;
    logic            unused_exit, unused_exit_valid;
    logic [VoxelBits-1:0] unused_exit_value;
    assign back_in = poly_enabled_i ? back_acc : '0;
    cube4_compose_node #(
      .VoxelBits(VoxelBits), .AlphaBits(AlphaBits), .AccGuardBits(AccGuardBits), .Latency(0)
    ) u_leave (
      .clk_i,
      .rst_ni,
      .blend_mode_i     (cube4_pkg::BlendComposite),
      .valid_i          (result_valid),
      .front_red_i      (res_red),
      .front_green_i    (res_green),
      .front_blue_i     (res_blue),
      .front_alpha_i    (res_alpha),
      .front_value_i    (res_value),
      .front_selected_i (res_selected),
      .back_red_i       (back_in[3*AB +: AB]),
      .back_green_i     (back_in[2*AB +: AB]),
      .back_blue_i      (back_in[AB +: AB]),
      .back_alpha_i     (back_in[0 +: AB]),
      .back_value_i     ('0),
      .back_selected_i  (1'b0),
      .valid_o          (unused_exit_valid),
      .red_o            (exit_red),
      .green_o          (exit_green),
      .blue_o           (exit_blue),
      .alpha_o          (exit_alpha),
      .value_o          (unused_exit_value),
      .selected_o       (unused_exit)
    );

    // The decoder's pixel valid, error and end of line: the host's lines
    // are well formed (checked by the tests against golden).
    logic unused_decoder;
    assign unused_decoder = ^{slab_valid, slab_error, slab_finished, real_q[0]} ^ ^unused_exit_value ^ unused_exit
                          ^ unused_exit_valid;
  end else begin : g_no_polygons
    assign slab_pixel     = '0;
    assign start_ray      = '0;
    assign slab_line_o    = 1'b0;
    assign slab_consume_o = 3'd0;
    assign {exit_red, exit_green, exit_blue, exit_alpha} = {res_red, res_green, res_blue, res_alpha};
    logic unused_polygon_inputs;
    assign unused_polygon_inputs = ^{poly_enabled_i, slice_k_i, ray_z_i, ray_front_red_i, ray_front_green_i,
                                     ray_front_blue_i, ray_front_alpha_i, ray_back_red_i, ray_back_green_i,
                                     ray_back_blue_i, ray_back_alpha_i, slab_window_i, slab_avail_i};
  end

  // -------------------------------------------------------------------------
  // Ray slice store: one ray per column of the slice, in stream order, in
  // place. The entry of a step is read in the step's cycle (the read
  // register follows the read pointer every clock) and rewritten with the
  // step's result one cycle later (write address = read pointer of the step).
  // Not a cube4_delay_ram: its write lags its read by a cycle, so it needs
  // two pointers. The lap ends with the slice (pointer back to entry 0).
  logic [AccBits-1:0] mem_q [SliceDepth];
  logic [PtrBits-1:0] rptr_q, rptr_d, waddr_q;
  logic [AccBits-1:0] rdata_q, own_slice;
  logic               lap_end;

  assign lap_end = (slice_end_a && beam_end_a) || (rptr_q == PtrBits'(SliceDepth - 1));
  always_comb begin
    rptr_d = rptr_q;
    if (step) begin
      rptr_d = lap_end ? '0 : rptr_q + PtrBits'(1);
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rptr_q <= '0;
    end else begin
      rptr_q <= rptr_d;
    end
  end

  always_ff @(posedge clk_i) begin
    if (step) begin
      waddr_q <= rptr_q;
    end
  end

  always_ff @(posedge clk_i) begin
    if (result_valid) begin
      mem_q[waddr_q] <= result;
    end
  end

  // Read port: the next step's entry, every clock, write data forwarded.
  // The RAM's own read is a plain registered read (so synthesis keeps it a
  // RAM); the forwarding decision and data are registered beside it.
  logic [AccBits-1:0] mem_rdata_q, fwd_data_q;
  logic               fwd_q;
  always_ff @(posedge clk_i) begin
    mem_rdata_q <= mem_q[rptr_d];
    fwd_q       <= result_valid && waddr_q == rptr_d;
    fwd_data_q  <= result;
  end
  assign rdata_q = fwd_q ? fwd_data_q : mem_rdata_q;
  // Bypass: the entry was written in this very cycle by the step before
  // (a lap of one step, back to back).
  assign own_slice = (result_valid && waddr_q == rptr_q) ? result : rdata_q;

  // -------------------------------------------------------------------------
  // Ray beam delay: the store's output of this column one beam (one lap of
  // B steps, ended by beam_end) later: the previous slice's ray at (x, y-1).
  logic [AccBits-1:0] own_beam;

  cube4_delay_ram #(
    .Width   (AccBits),
    .MaxDepth(BeamDepth)
  ) u_beam_delay (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .depth_i  (BeamDepthBits'(BeamDepth)),
    .clear_i  (1'b0),
    .advance_i(step),
    .last_i   (beam_end_a),
    .write_i  (1'b1),
    .wdata_i  (own_slice),
    .rdata_o  (own_beam)
  );

  // -------------------------------------------------------------------------
  // Ray alignment. dy picks the row here (and in every pipeline, for the
  // link); dx picks this column or the left neighbour's.
  logic [AccBits-1:0] own_cand, left_cand;
  logic               no_pred;

  assign own_cand = dy_a ? own_beam : own_slice;
  assign link_o   = own_cand;

  if (WrapIn) begin : g_wrap
    // Pipeline 0: the left column is pipeline p-1's of the previous partial
    // beam (the previous step of the same beam).
    logic [AccBits-1:0] wrap_q;
    always_ff @(posedge clk_i) begin
      if (step) begin
        wrap_q <= link_i;
      end
    end
    assign left_cand = wrap_q;
  end else begin : g_left
    assign left_cand = link_i;
  end

  // No predecessor: the first slice, y - dy < 0, or x - dx < 0 (x = 0 is
  // pipeline 0's first partial beam).
  assign no_pred = first_a || (dy_a && slice_start_a) || (dx_a && WrapIn && beam_start_a);
  assign pred    = no_pred ? start_ray : (dx_a ? left_cand : own_cand);

  // -------------------------------------------------------------------------
  // Pixel port: the finished rays from the compositing datapath, scaled
  // from the accumulator domain to AlphaBits, and as they are.
  cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(G)) u_pixel_red   (.acc_i(exit_red),   .pixel_o(pixel_red_o));
  cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(G)) u_pixel_green (.acc_i(exit_green), .pixel_o(pixel_green_o));
  cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(G)) u_pixel_blue  (.acc_i(exit_blue),  .pixel_o(pixel_blue_o));
  cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(G)) u_pixel_alpha (.acc_i(exit_alpha), .pixel_o(pixel_alpha_o));

  logic               exit_o;
  logic [PosBits-1:0] u_o, v_o;
  cube4_pipe_delay #(.Width(ExitBits), .Depth(Latency)) u_exit_delay (
    .clk_i, .d_i({exit_d, u_d, v_d}), .q_o({exit_o, u_o, v_o})
  );

  assign pixel_valid_o = result_valid && exit_o;
  assign pixel_u_o     = u_o;
  assign pixel_v_o     = v_o;
  assign pixel_acc_red_o   = res_red;
  assign pixel_acc_green_o = res_green;
  assign pixel_acc_blue_o  = res_blue;
  assign pixel_acc_alpha_o = res_alpha;
  assign pixel_value_o     = res_value;
  assign pixel_selected_o  = res_selected;

endmodule
