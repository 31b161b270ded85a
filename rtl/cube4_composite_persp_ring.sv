// cube4_composite_persp_ring: NumPipes perspective compositing pipelines in
// a ring (Cube-4 §5 "Compositing"; docs/perspective.md, "The plan for the
// compositing ring"; docs/rtl-composite-persp.md).
//
// Function: every ray's samples of a frame's slices, in slice order,
// cropped, cut and blended into its accumulator (cube4_composite: golden
// crop_and_cut() and blend()), starting from the empty accumulator where
// the ray enters the volume; when a ray has blended its last sample (it
// does not sample the next slice, or the slice is the frame's last) its
// accumulator and pixel leave on the blending pipeline's pixel port, with
// the ray: exactly what TlmCompositePersp (systemc/tlm/
// tlm_composite_persp.hpp) writes, on the same schedule.
//
// Schedule: the shaded sample of cell (X, Y) of a pass arrives with the
// stream step at position X + 5 of beam Y + 5 of the next pass (the
// gradient ring's, carried through shading) and is blended Reach positions
// later, on lane X + 5 + Reach (golden composite_position()). Its ray's
// accumulator of the slice before, at home (X', Y') within Reach cells, is
// stored on lane X' + 5 at row Y' of the store of that slice's pass parity:
// every pipeline reads its own column, one word a step, at the row the
// beam's rays came from (a home row depends on v alone), and the blending
// lane takes the word of position X - X' + Reach back (the window: its own
// and the 2 Reach to its left, this step's or a history's). The new
// accumulator leaves cube4_composite 7 cycles later and goes back Reach
// lanes, a hop a cycle, to be stored at the ray's home. A beam's last five
// cells are stored in the next row's entries of the next beam's first five
// columns, which no cell of that row uses (the pass's last row's in row
// 0's), as the gradient ring stores its samples.
//
// Input stream: one valid_i step per stream position, the flags of the
// interpolation ring's stream (six flush beams at the end), with the
// shaded samples of the step on their lanes and, from each pass's first
// step, that pass's constants (golden perspective_slice(): spacing, ray 0's
// positions, the rays per axis; its voxel slice and z weight; whether it is
// the frame's first or last slice; its tag). The ring keeps four passes'.
//
// Polygons (Cube-5 in perspective; HasPolygons, poly_enabled_i): each
// sample comes with its ray's data, which the host's polygon images hold
// by pixel (the ray's depth Z, front and back pixels) and the slab pixel
// behind the sample (the slice's slab image at the ray's rank: the system
// reads it decoded, where the parallel ring decodes its slab lines); a ray
// starts from its front pixel instead of the empty accumulator, each
// sample passes the Z test and is followed by its slab pixel
// (cube4_composite's double composition), and a ray's pixel is its
// accumulator over its back pixel (golden write_ray() with a polygon
// frame; the accumulator leaves as it is). Rays that sample nothing are
// the host's front over back, as in parallel projection.
//
// Preconditions: every pass has the same ny >= 6 rows and ceil(nx/p) <=
// BeamDepth partial beams a beam, a beam at least 8 + Reach positions;
// nx, ny <= MaxDim; no ray moves more than Reach cells between slices
// (golden largest_home_move(); the system refuses frames that do); the
// blend mode and the crop and cut registers held over the stream.
//
// Parameters:
//   NumPipes - pipelines p
//   MaxDim   - largest nx and ny: sizes the stores
//   Reach    - the largest move R of a ray's home between slices
//   VoxelBits, WeightBits, AlphaBits, AccGuardBits, CutBits, CutInvShift,
//   PosBits, CutCoefBits, HasCutPlane - as cube4_composite
//   HasPolygons - the polygon hardware above (0: none; poly_enabled_i,
//              slice_k_i and the rays' polygon data are ignored)
//   ZBits, SliceBits - a ray's depth and the slice index, as cube4_composite
//   FracBits, DdaBits, RayBits - the walks' (cube4_persp_lanes: PosBits there)
//   TagBits  - the pass tag's width
`include "cube4_pkg.sv"

module cube4_composite_persp_ring #(
  parameter int unsigned  NumPipes     = 4,
  parameter int unsigned  MaxDim       = 256,
  parameter int unsigned  Reach        = 3,
  parameter int unsigned  VoxelBits    = cube4_pkg::VoxelBits,
  parameter int unsigned  WeightBits   = cube4_pkg::WeightBits,
  parameter int unsigned  AlphaBits    = cube4_pkg::AlphaBits,
  parameter int unsigned  AccGuardBits = cube4_pkg::AccGuardBits,
  parameter int unsigned  CutBits      = cube4_pkg::CutBits,
  parameter int unsigned  CutInvShift  = cube4_pkg::CutInvShift,
  parameter int unsigned  PosBits      = cube4_pkg::PosBits,
  parameter int unsigned  CutCoefBits  = cube4_pkg::CutCoefBits,
  parameter bit           HasCutPlane  = 1'b1,
  parameter bit           HasPolygons  = 1'b1,
  parameter int unsigned  ZBits        = cube4_pkg::ZBits,
  parameter int unsigned  SliceBits    = cube4_pkg::SliceBits,
  parameter int unsigned  FracBits     = cube4_pkg::FracBits,
  parameter int unsigned  DdaBits      = 48,
  parameter int unsigned  RayBits      = 16,
  parameter int unsigned  TagBits      = 8,
  localparam int unsigned AB           = AlphaBits + AccGuardBits
) (
  input  logic                               clk_i,
  input  logic                               rst_ni,
  // Frame registers of cube4_composite.
  input  cube4_pkg::blend_e                  blend_mode_i,
  input  logic                               crop_enabled_i,
  input  logic [PosBits-1:0]                 crop_x_lo_i,
  input  logic [PosBits-1:0]                 crop_x_hi_i,
  input  logic [PosBits-1:0]                 crop_y_lo_i,
  input  logic [PosBits-1:0]                 crop_y_hi_i,
  input  logic [PosBits-1:0]                 crop_z_lo_i,
  input  logic [PosBits-1:0]                 crop_z_hi_i,
  input  logic [7:0]                         crop_mask_i,
  input  logic                               window_enabled_i,
  input  logic [PosBits-1:0]                 window_x_lo_i,
  input  logic [PosBits-1:0]                 window_x_hi_i,
  input  logic [PosBits-1:0]                 window_y_lo_i,
  input  logic [PosBits-1:0]                 window_y_hi_i,
  input  logic [PosBits-1:0]                 window_z_lo_i,
  input  logic [PosBits-1:0]                 window_z_hi_i,
  input  logic                               cut_enabled_i,
  input  logic signed [CutCoefBits-1:0]      cut_a_i,
  input  logic signed [CutCoefBits-1:0]      cut_b_i,
  input  logic signed [CutCoefBits-1:0]      cut_c_i,
  input  logic signed [CutBits-1:0]          cut_dmin_i,
  input  logic signed [CutBits-1:0]          cut_dmax_i,
  input  logic [CutBits-1:0]                 cut_falloff_i,
  input  logic [AlphaBits+CutInvShift-1:0]   cut_inv_falloff_i,
  input  logic                               cut_keep_inside_i,
  // Frame register: polygons (with HasPolygons; the blend must then be
  // composite).
  input  logic                               poly_enabled_i,
  // Stream steps.
  input  logic                               valid_i,
  input  logic                               beam_start_i,
  input  logic                               beam_end_i,
  input  logic                               slice_start_i,
  input  logic                               slice_end_i,
  input  logic                               flush_i,
  // The step's pass's constants, taken at its first step.
  input  logic signed [DdaBits-1:0]          spacing_i,
  input  logic signed [DdaBits-1:0]          ray0_x_i,
  input  logic signed [DdaBits-1:0]          ray0_y_i,
  input  logic signed [RayBits-1:0]          rays_x_lo_i,
  input  logic signed [RayBits-1:0]          rays_x_hi_i,
  input  logic signed [RayBits-1:0]          rays_y_lo_i,
  input  logic signed [RayBits-1:0]          rays_y_hi_i,
  input  logic [PosBits-1:0]                 z_voxel_i,
  input  logic [WeightBits-1:0]              wz_i,
  input  logic                               first_i,
  input  logic                               last_i,
  input  logic [TagBits-1:0]                 tag_i,
  input  logic [SliceBits-1:0]               slice_k_i,  // the pass's slice (polygons' Z test)
  // The shaded samples of this step, on their lanes.
  input  logic [NumPipes-1:0]                sample_valid_i,
  input  logic [NumPipes*AlphaBits-1:0]      red_i,
  input  logic [NumPipes*AlphaBits-1:0]      green_i,
  input  logic [NumPipes*AlphaBits-1:0]      blue_i,
  input  logic [NumPipes*AlphaBits-1:0]      alpha_i,
  input  logic [NumPipes*VoxelBits-1:0]      value_i,
  // Polygons, with each sample: its ray's depth, front and back pixels,
  // and the slab pixel behind it (premultiplied).
  input  logic [NumPipes*ZBits-1:0]          ray_z_i,
  input  logic [NumPipes*AlphaBits-1:0]      ray_front_red_i,
  input  logic [NumPipes*AlphaBits-1:0]      ray_front_green_i,
  input  logic [NumPipes*AlphaBits-1:0]      ray_front_blue_i,
  input  logic [NumPipes*AlphaBits-1:0]      ray_front_alpha_i,
  input  logic [NumPipes*AlphaBits-1:0]      ray_back_red_i,
  input  logic [NumPipes*AlphaBits-1:0]      ray_back_green_i,
  input  logic [NumPipes*AlphaBits-1:0]      ray_back_blue_i,
  input  logic [NumPipes*AlphaBits-1:0]      ray_back_alpha_i,
  input  logic [NumPipes*AlphaBits-1:0]      slab_red_i,
  input  logic [NumPipes*AlphaBits-1:0]      slab_green_i,
  input  logic [NumPipes*AlphaBits-1:0]      slab_blue_i,
  input  logic [NumPipes*AlphaBits-1:0]      slab_alpha_i,
  // Rays that leave: their accumulator and pixel, per pipeline.
  output logic [NumPipes-1:0]                pixel_valid_o,
  output logic [NumPipes*RayBits-1:0]        ray_u_o,
  output logic [NumPipes*RayBits-1:0]        ray_v_o,
  output logic [NumPipes*TagBits-1:0]        tag_o,
  output logic [NumPipes*AlphaBits-1:0]      pixel_red_o,
  output logic [NumPipes*AlphaBits-1:0]      pixel_green_o,
  output logic [NumPipes*AlphaBits-1:0]      pixel_blue_o,
  output logic [NumPipes*AlphaBits-1:0]      pixel_alpha_o,
  output logic [NumPipes*AB-1:0]             acc_red_o,
  output logic [NumPipes*AB-1:0]             acc_green_o,
  output logic [NumPipes*AB-1:0]             acc_blue_o,
  output logic [NumPipes*AB-1:0]             acc_alpha_o,
  output logic [NumPipes*VoxelBits-1:0]      acc_value_o,
  output logic [NumPipes-1:0]                acc_selected_o
);

  localparam int unsigned P         = NumPipes;
  localparam int unsigned V         = VoxelBits;
  localparam int unsigned A         = AlphaBits;
  localparam int unsigned R         = Reach;
  localparam int unsigned BeamDepth = (MaxDim + P - 1) / P;
  localparam int unsigned RowBits   = $clog2(MaxDim);
  localparam int unsigned ColBits   = BeamDepth > 1 ? $clog2(BeamDepth) : 1;
  localparam int unsigned HomeBits  = DdaBits - FracBits;
  localparam int unsigned AccBits   = 1 + V + 4 * AB;  // {selected, value, alpha, blue, green, red}
  localparam int unsigned SampleBits = 4 * A + V;      // {value, alpha, blue, green, red}
  // A sample's polygon data: {slab, back, front (each alpha, blue, green,
  // red), Z}; one unused bit without polygons.
  localparam int unsigned PixBits  = 4 * A;
  localparam int unsigned PolyBits = HasPolygons ? ZBits + 3 * PixBits : 1;
  localparam int unsigned Latency   = 7;               // cube4_composite
  localparam int unsigned AccDelay  = 6;               // its accumulator input
  // The stream columns a cell's sample arrives and blends after its home.
  localparam int unsigned Arrive    = 5;
  localparam int unsigned Blend     = Arrive + R;
  // How far back, in steps, the blend reaches: its sample R positions, its
  // cell Blend, its window 2R.
  localparam int unsigned SampleDepth = (R + P - 1) / P;
  localparam int unsigned CellDepth   = (Blend + P - 1) / P;
  localparam int unsigned WinDepth    = (2 * R + P - 1) / P;

  // -------------------------------------------------------------------------
  // The last four passes' constants, in one word each (fields from the LSB
  // up; words, not structs, for yosys 0.23: docs/toolchain.md).
  localparam int unsigned PTag     = 0;
  localparam int unsigned PK       = PTag + TagBits;
  localparam int unsigned PLast    = PK + SliceBits;
  localparam int unsigned PFirst   = PLast + 1;
  localparam int unsigned PWz      = PFirst + 1;
  localparam int unsigned PZ       = PWz + WeightBits;
  localparam int unsigned PYHi     = PZ + PosBits;
  localparam int unsigned PYLo     = PYHi + RayBits;
  localparam int unsigned PXHi     = PYLo + RayBits;
  localparam int unsigned PXLo     = PXHi + RayBits;
  localparam int unsigned PRay0Y   = PXLo + RayBits;
  localparam int unsigned PRay0X   = PRay0Y + DdaBits;
  localparam int unsigned PSpacing = PRay0X + DdaBits;
  localparam int unsigned PassBits = PSpacing + DdaBits;

  // Where the step is (cube4_persp_stream): its pass and partial beam, and
  // the beams before it, d back (0: its own), as the gradient ring has them.
  logic                 pass_start;
  logic [1:0]           pass_now;
  logic [ColBits-1:0]   col_now;
  /* verilator lint_off UNUSEDSIGNAL */  // each use reads the beams it needs (4 and 5 back here)
  logic [6:0]           beam_real, beam_after_first, beam_last_row;
  logic [7*RowBits-1:0] beam_row;
  logic [7*2-1:0]       beam_pass;
  /* verilator lint_on UNUSEDSIGNAL */
  logic [RowBits:0]     ny_q;  // rows per pass, counted at each pass's end
  cube4_persp_stream #(
    .MaxDim  (MaxDim),
    .NumPipes(P)
  ) u_stream (
    .clk_i             (clk_i),
    .rst_ni            (rst_ni),
    .valid_i           (valid_i),
    .beam_start_i      (beam_start_i),
    .beam_end_i        (beam_end_i),
    .slice_start_i     (slice_start_i),
    .slice_end_i       (slice_end_i),
    .flush_i           (flush_i),
    .pass_start_o      (pass_start),
    .pass_now_o        (pass_now),
    .col_now_o         (col_now),
    .beam_real_o       (beam_real),
    .beam_after_first_o(beam_after_first),
    .beam_last_row_o   (beam_last_row),
    .beam_row_o        (beam_row),
    .beam_pass_o       (beam_pass),
    .ny_o              (ny_q)
  );

  logic [PassBits-1:0] passes_q [4];
  always_ff @(posedge clk_i) begin
    if (pass_start) begin
      passes_q[pass_now] <= {spacing_i, ray0_x_i, ray0_y_i, rays_x_lo_i, rays_x_hi_i, rays_y_lo_i, rays_y_hi_i,
                             z_voxel_i, wz_i, first_i, last_i, slice_k_i, tag_i};
    end
  end

  // The row after r in its pass's store (the entries of a beam's last cells).
  function automatic logic [RowBits-1:0] next_row(input logic [RowBits-1:0] r);
    next_row = ((RowBits+1)'(r) + (RowBits+1)'(1) == ny_q) ? '0 : r + RowBits'(1);
  endfunction

  function automatic logic [HomeBits-1:0] home_of(input logic [DdaBits-1:0] pos);
    home_of = HomeBits'($signed(pos) >>> FracBits);
  endfunction
  function automatic logic among(input logic [RayBits-1:0] a, input logic [RayBits-1:0] lo,
                                 input logic [RayBits-1:0] hi);
    among = $signed(a) >= $signed(lo) && $signed(a) < $signed(hi);
  endfunction

  // -------------------------------------------------------------------------
  // The blend row of a beam: beam b - 5's cells, of the pass before that
  // beam's (the gradient ring's gradient row). The y walk gives its ray v
  // and the sample's row and weight; the ray's home row on the slice before
  // and whether it samples the slices before and after come with them.
  logic [1:0] gpass;
  assign gpass = beam_pass[5*2 +: 2] - 2'd1;
  /* verilator lint_off UNUSEDSIGNAL */  // each use reads a few fields
  logic [PassBits-1:0] gp, gp_before, gp_after, next_gp;
  /* verilator lint_on UNUSEDSIGNAL */
  assign gp        = passes_q[gpass];
  assign gp_before = passes_q[gpass - 2'd1];
  assign gp_after  = passes_q[gpass + 2'd1];

  logic beam_last;
  assign beam_last = valid_i && beam_end_i;
  assign next_gp   = passes_q[beam_pass[4*2 +: 2] - 2'd1];

  // The blend row's ray and its weight (y) and, a step ahead, its cells'
  // rays and weights (x): the sample's place.
  logic                    y_valid;
  logic [RayBits-1:0]      y_ray;
  logic [WeightBits-1:0]   y_weight;
  logic [P-1:0]            x_valid;
  logic [P*RayBits-1:0]    x_ray;
  logic [P*WeightBits-1:0] x_weight;
  cube4_persp_cell_walks #(
    .NumPipes  (P),
    .FracBits  (FracBits),
    .WeightBits(WeightBits),
    .PosBits   (DdaBits),
    .RayBits   (RayBits)
  ) u_walks (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    .valid_i        (valid_i),
    .beam_end_i     (beam_end_i),
    .next_forms_i   (beam_real[4] && beam_after_first[4]),
    .next_row_zero_i(beam_row[4*RowBits +: RowBits] == '0),
    .spacing_i      (next_gp[PSpacing +: DdaBits]),
    .ray0_x_i       (next_gp[PRay0X +: DdaBits]),
    .ray0_y_i       (next_gp[PRay0Y +: DdaBits]),
    .rays_x_lo_i    (next_gp[PXLo +: RayBits]),
    .rays_x_hi_i    (next_gp[PXHi +: RayBits]),
    .rays_y_lo_i    (next_gp[PYLo +: RayBits]),
    .rays_y_hi_i    (next_gp[PYHi +: RayBits]),
    .row_valid_o    (y_valid),
    .row_ray_o      (y_ray),
    .row_weight_o   (y_weight),
    .lane_valid_o   (x_valid),
    .lane_ray_o     (x_ray),
    .lane_weight_o  (x_weight)
  );

  // The ray's row on the slice before: one multiply a beam.
  logic [DdaBits-1:0]  y_before_pos;
  logic [HomeBits-1:0] y_before;
  assign y_before_pos = gp_before[PRay0Y +: DdaBits] + DdaBits'($signed(y_ray)) * gp_before[PSpacing +: DdaBits];
  assign y_before     = home_of(y_before_pos);
  logic unused_y_before;  // a row that a ray samples fits RowBits; rays that miss are not read
  assign unused_y_before = ^y_before[HomeBits-1:RowBits];
  logic y_from_before, y_to_after;  // v samples the slices before and after (along y)
  assign y_from_before = !gp[PFirst] && among(y_ray, gp_before[PYLo +: RayBits], gp_before[PYHi +: RayBits]);
  assign y_to_after    = !gp[PLast] && among(y_ray, gp_after[PYLo +: RayBits], gp_after[PYHi +: RayBits]);

  // A beam's blend context (a word, fields from the LSB up).
  localparam int unsigned CWy     = 0;
  localparam int unsigned CRow    = CWy + WeightBits;      // the cells' row Y
  localparam int unsigned CRowB   = CRow + RowBits;        // the rays' row on the slice before, Y'
  localparam int unsigned CBefore = CRowB + RowBits;       // v samples the slice before
  localparam int unsigned CAfter  = CBefore + 1;           // v samples the slice after
  localparam int unsigned CV      = CAfter + 1;
  localparam int unsigned CPass   = CV + RayBits;          // the cells' pass
  localparam int unsigned CForms  = CPass + 2;             // a ray of that pass has its home row here
  localparam int unsigned CtxBits = CForms + 1;

  /* verilator lint_off UNUSEDSIGNAL */  // the column stages read the rows, the blends the rest
  logic [CtxBits-1:0] ctx_now, ctx_prev_q;
  /* verilator lint_on UNUSEDSIGNAL */
  assign ctx_now = {beam_real[5] && beam_after_first[5] && y_valid, gpass, y_ray, y_to_after, y_from_before,
                    y_before[RowBits-1:0], beam_row[5*RowBits +: RowBits], y_weight};
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ctx_prev_q <= '0;
    end else if (beam_last) begin
      ctx_prev_q <= ctx_now;
    end
  end

  // -------------------------------------------------------------------------
  // Write-back: each pipeline's new accumulators, Reach lanes back (below).
  logic [P-1:0]         wb_valid;
  logic [P-1:0]         wb_parity;
  logic [P*RowBits-1:0] wb_row;
  logic [P*ColBits-1:0] wb_col;
  logic [P*AccBits-1:0] wb_acc;

  // Column stages: the two accumulator stores and this step's packets.
  logic [P*AccBits-1:0] pkt_live;
  for (genvar k = 0; k < P; k++) begin : g_column
    // Columns 0 .. 4 of a beam hold the previous beam's last cells (stored
    // in the next row's entries) and read its rows.
    localparam int unsigned Early = (k >= Arrive) ? 0 : (Arrive - k + P - 1) / P;
    logic early;
    if (Early > 0) begin : g_early
      assign early = 32'(col_now) < Early;
    end else begin : g_late
      assign early = 1'b0;
    end
    logic [RowBits-1:0] rrow;
    logic               rparity;
    assign rrow    = early ? next_row(ctx_prev_q[CRowB +: RowBits]) : ctx_now[CRowB +: RowBits];
    // The accumulators of the slice before: its pass's parity.
    assign rparity = early ? !ctx_prev_q[CPass] : !ctx_now[CPass];

    cube4_persp_column #(
      .Width    (AccBits),
      .Reads    (1),
      .StoreBits(1),
      .MaxDim   (MaxDim),
      .BeamDepth(BeamDepth)
    ) u_column (
      .clk_i   (clk_i),
      .we_i    (wb_valid[k]),
      .wstore_i(wb_parity[k]),
      .wrow_i  (wb_row[k*RowBits +: RowBits]),
      .wcol_i  (wb_col[k*ColBits +: ColBits]),
      .wdata_i (wb_acc[k*AccBits +: AccBits]),
      .col_i   (col_now),
      .store_i (rparity),
      .row_i   (rrow),
      .packet_o(pkt_live[k*AccBits +: AccBits])
    );
  end

  // -------------------------------------------------------------------------
  // Histories, shifted at every step (index 0 live): the samples of the
  // last SampleDepth steps, the x walk's lanes (with the step's partial
  // beam) and the blend contexts of the last CellDepth, the packets of the
  // last WinDepth.
  localparam int unsigned SlotBits = 1 + PolyBits + SampleBits;
  localparam int unsigned LaneBits = 1 + RayBits + WeightBits + HomeBits;  // valid, u, wx, cell X
  logic [(SampleDepth+1)*P*SlotBits-1:0] smp_hist;
  logic [(CellDepth+1)*P*LaneBits-1:0]   lane_hist;
  logic [(CellDepth+1)*CtxBits-1:0]      ctx_hist;
  logic [(CellDepth+1)*ColBits-1:0]      col_hist;
  logic [(WinDepth+1)*P*AccBits-1:0]     pkt_hist;
  logic [SampleDepth*P*SlotBits-1:0]     smp_hist_q;
  logic [CellDepth*P*LaneBits-1:0]       lane_hist_q;
  logic [CellDepth*CtxBits-1:0]          ctx_hist_q;
  logic [CellDepth*ColBits-1:0]          col_hist_q;
  logic [WinDepth*P*AccBits-1:0]         pkt_hist_q;

  if (!HasPolygons) begin : g_no_polygon_inputs
    logic unused_polygon_inputs;  // a ring without polygon hardware ignores them
    assign unused_polygon_inputs = ^{ray_z_i, ray_front_red_i, ray_front_green_i, ray_front_blue_i,
                                     ray_front_alpha_i, ray_back_red_i, ray_back_green_i, ray_back_blue_i,
                                     ray_back_alpha_i, slab_red_i, slab_green_i, slab_blue_i, slab_alpha_i};
  end

  // The cell each lane of the x walk holds: j*p + k (its home column).
  for (genvar k = 0; k < P; k++) begin : g_live
    logic [PolyBits-1:0] poly;
    if (HasPolygons) begin : g_poly
      assign poly = {slab_alpha_i[k*A +: A], slab_blue_i[k*A +: A], slab_green_i[k*A +: A], slab_red_i[k*A +: A],
                     ray_back_alpha_i[k*A +: A], ray_back_blue_i[k*A +: A], ray_back_green_i[k*A +: A],
                     ray_back_red_i[k*A +: A], ray_front_alpha_i[k*A +: A], ray_front_blue_i[k*A +: A],
                     ray_front_green_i[k*A +: A], ray_front_red_i[k*A +: A], ray_z_i[k*ZBits +: ZBits]};
    end else begin : g_no_poly
      assign poly = 1'b0;
    end
    assign smp_hist[k*SlotBits +: SlotBits] =
        {sample_valid_i[k], poly, value_i[k*V +: V], alpha_i[k*A +: A], blue_i[k*A +: A], green_i[k*A +: A],
         red_i[k*A +: A]};
    assign lane_hist[k*LaneBits +: LaneBits] =
        {x_valid[k], x_ray[k*RayBits +: RayBits], x_weight[k*WeightBits +: WeightBits],
         HomeBits'(col_now) * HomeBits'(P) + HomeBits'(k)};
  end
  assign smp_hist[P*SlotBits +: SampleDepth*P*SlotBits] = smp_hist_q;
  assign lane_hist[P*LaneBits +: CellDepth*P*LaneBits]  = lane_hist_q;
  assign ctx_hist = {ctx_hist_q, ctx_now};
  assign col_hist = {col_hist_q, col_now};
  assign pkt_hist = {pkt_hist_q, pkt_live};

  always_ff @(posedge clk_i) begin
    if (valid_i) begin
      lane_hist_q <= lane_hist[0 +: CellDepth*P*LaneBits];
      col_hist_q  <= col_hist[0 +: CellDepth*ColBits];
      pkt_hist_q  <= pkt_hist[0 +: WinDepth*P*AccBits];
    end
  end
  // Whether a step forms, and whether a sample waits: reset, so that the
  // stream's first steps find nothing before it.
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ctx_hist_q <= '0;
      smp_hist_q <= '0;
    end else if (valid_i) begin
      ctx_hist_q <= ctx_hist[0 +: CellDepth*CtxBits];
      smp_hist_q <= smp_hist[0 +: SampleDepth*P*SlotBits];
    end
  end
  logic unused_hist;  // the deepest entries are read by some pipelines only
  assign unused_hist = ^{smp_hist, lane_hist, ctx_hist, col_hist, pkt_hist};

  // -------------------------------------------------------------------------
  // Blending: pipeline k's stream position s blends the sample that arrived
  // at s - R, of the cell at s - Blend, with the window's word at s - d.
  logic [P*AccBits-1:0] blended;   // cube4_composite's results
  logic [P-1:0]         blended_valid;
  logic [P*4*A-1:0]     back_out;  // with each result, its ray's back pixel
  localparam int unsigned WbBits = 1 + 1 + RowBits + HomeBits + 1 + 2 * RayBits + TagBits;
  logic [P*WbBits-1:0]  blended_where;  // {leaves, parity, row, stored lane, early, u, v, tag}

  for (genvar k = 0; k < P; k++) begin : g_blend
    localparam int unsigned SmpPipe  = (k + R * P - R) % P;
    localparam int unsigned SmpBack  = (k >= R) ? 0 : (R - k + P - 1) / P;
    localparam int unsigned CellPipe = (k + Blend * P - Blend) % P;
    localparam int unsigned CellBack = (k >= Blend) ? 0 : (Blend - k + P - 1) / P;

    logic                  smp_valid;
    logic [SampleBits-1:0] smp;
    logic [PolyBits-1:0]   smp_poly;
    assign {smp_valid, smp_poly, smp} = smp_hist[(SmpBack*P + SmpPipe)*SlotBits +: SlotBits];

    // Polygons: the ray's start (its front pixel widened: golden
    // pixel_to_acc), its depth, and the slab and back pixels, which join
    // the blend in its cycle 6 and its result in cycle 7.
    logic [AccBits-1:0]    start;
    logic [ZBits-1:0]      ray_z;
    logic [PixBits-1:0]    slab_pix, back_pix;
    if (HasPolygons) begin : g_poly
      logic [PixBits-1:0] front_pix;
      logic [4*AB-1:0]    front_acc;
      assign {slab_pix, back_pix, front_pix, ray_z} = smp_poly;
      for (genvar ch = 0; ch < 4; ch++) begin : g_widen
        cube4_to_acc #(.AlphaBits(A), .AccGuardBits(AccGuardBits)) u_front (
          .pixel_i(front_pix[ch*A +: A]), .acc_o(front_acc[ch*AB +: AB]));
      end
      assign start = poly_enabled_i ? {1'b0, V'(0), front_acc} : '0;
    end else begin : g_no_poly
      assign start    = '0;
      assign ray_z    = '0;
      assign slab_pix = '0;
      assign back_pix = '0;
      logic unused_poly;
      assign unused_poly = ^{smp_poly, poly_enabled_i};
    end

    logic                  lane_valid;
    logic [RayBits-1:0]    u;
    logic [WeightBits-1:0] wx;
    logic [HomeBits-1:0]   cell_x;
    assign {lane_valid, u, wx, cell_x} = lane_hist[(CellBack*P + CellPipe)*LaneBits +: LaneBits];
    /* verilator lint_off UNUSEDSIGNAL */  // each use reads a few fields
    logic [CtxBits-1:0] ctx;
    logic [PassBits-1:0] fp, fp_before, fp_after;
    /* verilator lint_on UNUSEDSIGNAL */
    assign ctx       = ctx_hist[CellBack*CtxBits +: CtxBits];
    assign fp        = passes_q[ctx[CPass +: 2]];
    assign fp_before = passes_q[ctx[CPass +: 2] - 2'd1];
    assign fp_after  = passes_q[ctx[CPass +: 2] + 2'd1];

    // The ray's home column on the slice before, and whether it samples
    // the slices before and after along x.
    logic [DdaBits-1:0]  x_before_pos;
    logic [HomeBits-1:0] x_before;
    logic                from_before, to_after;
    assign x_before_pos = fp_before[PRay0X +: DdaBits] + DdaBits'($signed(u)) * fp_before[PSpacing +: DdaBits];
    assign x_before     = home_of(x_before_pos);
    assign from_before  = ctx[CBefore] && !fp[PFirst] &&
                          among(u, fp_before[PXLo +: RayBits], fp_before[PXHi +: RayBits]);
    assign to_after     = ctx[CAfter] && !fp[PLast] && among(u, fp_after[PXLo +: RayBits], fp_after[PXHi +: RayBits]);

    // The window: the packets of positions s - d, d = 0 .. 2R.
    logic [(2*R+1)*AccBits-1:0] window;
    for (genvar d = 0; d <= 2 * R; d++) begin : g_window
      localparam int unsigned SrcPipe = (k + (2 * R + 1) * P - d) % P;
      localparam int unsigned SrcBack = (k >= d) ? 0 : (d - k + P - 1) / P;
      assign window[d*AccBits +: AccBits] = pkt_hist[(SrcBack*P + SrcPipe)*AccBits +: AccBits];
    end
    logic [HomeBits-1:0] back;
    logic [AccBits-1:0]  acc_in;
    assign back = cell_x - x_before + HomeBits'(R);
    always_comb begin
      acc_in = start;
      for (int unsigned d = 0; d <= 2 * R; d++) begin
        if (from_before && back == HomeBits'(d)) acc_in = window[d*AccBits +: AccBits];
      end
    end

    logic form;
    assign form = valid_i && smp_valid && lane_valid && ctx[CForms];

    // The accumulator enters cube4_composite AccDelay cycles after its sample.
    logic [AccDelay*AccBits-1:0] acc_q;
    always_ff @(posedge clk_i) begin
      acc_q <= {acc_q[0 +: (AccDelay-1)*AccBits], acc_in};
    end
    logic [AccBits-1:0] acc_late;
    assign acc_late = acc_q[(AccDelay-1)*AccBits +: AccBits];
    // The slab pixel with the accumulator, the back pixel with the result.
    logic [AccDelay*PixBits-1:0] slab_q;
    logic [Latency*PixBits-1:0]  back_q;
    always_ff @(posedge clk_i) begin
      slab_q <= {slab_q[0 +: (AccDelay-1)*PixBits], slab_pix};
      back_q <= {back_q[0 +: (Latency-1)*PixBits], back_pix};
    end
    logic [PixBits-1:0] slab_late;
    assign slab_late = slab_q[(AccDelay-1)*PixBits +: PixBits];
    assign back_out[k*PixBits +: PixBits] = back_q[(Latency-1)*PixBits +: PixBits];

    logic [AB-1:0] o_red, o_green, o_blue, o_alpha;
    logic [V-1:0]  o_value;
    logic          o_selected;
    cube4_composite #(
      .VoxelBits   (V),
      .WeightBits  (WeightBits),
      .AlphaBits   (A),
      .AccGuardBits(AccGuardBits),
      .CutBits     (CutBits),
      .CutInvShift (CutInvShift),
      .PosBits     (PosBits),
      .CutCoefBits (CutCoefBits),
      .HasCutPlane (HasCutPlane),
      .HasPolygons (HasPolygons),
      .ZBits       (ZBits),
      .SliceBits   (SliceBits)
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
      .slice_k_i        (fp[PK +: SliceBits]),
      .ray_z_i          (ray_z),
      .slab_red_i       (slab_late[0 +: A]),
      .slab_green_i     (slab_late[A +: A]),
      .slab_blue_i      (slab_late[2*A +: A]),
      .slab_alpha_i     (slab_late[3*A +: A]),
      .valid_i          (form),
      .red_i            (smp[0 +: A]),
      .green_i          (smp[A +: A]),
      .blue_i           (smp[2*A +: A]),
      .alpha_i          (smp[3*A +: A]),
      .value_i          (smp[4*A +: V]),
      .x_i              (PosBits'(cell_x)),
      .y_i              (PosBits'(ctx[CRow +: RowBits])),
      .z_i              (fp[PZ +: PosBits]),
      .wx_i             (wx),
      .wy_i             (ctx[CWy +: WeightBits]),
      .wz_i             (fp[PWz +: WeightBits]),
      .acc_red_i        (acc_late[0 +: AB]),
      .acc_green_i      (acc_late[AB +: AB]),
      .acc_blue_i       (acc_late[2*AB +: AB]),
      .acc_alpha_i      (acc_late[3*AB +: AB]),
      .acc_value_i      (acc_late[4*AB +: V]),
      .acc_selected_i   (acc_late[4*AB + V]),
      .valid_o          (blended_valid[k]),
      .red_o            (o_red),
      .green_o          (o_green),
      .blue_o           (o_blue),
      .alpha_o          (o_alpha),
      .value_o          (o_value),
      .selected_o       (o_selected)
    );
    assign blended[k*AccBits +: AccBits] = {o_selected, o_value, o_alpha, o_blue, o_green, o_red};

    // Where the new accumulator goes, beside the datapath: back R lanes to
    // the lane of the cell's home + 5, at the cell's row (a beam's last
    // cells' in the next row's entries of the next beam's first columns).
    logic [HomeBits-1:0] stored_lane;  // home + 5, in the cell row's stream positions
    assign stored_lane = cell_x + HomeBits'(Arrive);
    logic [WbBits-1:0] where_now;
    assign where_now = {!to_after, ctx[CPass], ctx[CRow +: RowBits], stored_lane, 1'b0, u,
                        ctx[CV +: RayBits], fp[PTag +: TagBits]};
    logic [Latency*WbBits-1:0] where_q;
    always_ff @(posedge clk_i) begin
      where_q <= {where_q[0 +: (Latency-1)*WbBits], where_now};
    end
    assign blended_where[k*WbBits +: WbBits] = where_q[(Latency-1)*WbBits +: WbBits];
  end

  // -------------------------------------------------------------------------
  // Results: a ray that leaves puts its accumulator and pixel out on the
  // blending pipeline; every new accumulator goes back R lanes (a hop a
  // cycle) to be stored. The stored lane L = home + 5 of the cell's row: the
  // pipeline L mod p, partial beam L / p, or in the next row's entries when
  // L is past the beam (L - row, the next beam's first columns).
  logic [HomeBits-1:0] row_len;  // stream positions a beam: the x walk's partial beams times p
  logic [ColBits:0]    beam_parts_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      beam_parts_q <= '0;
    end else if (valid_i && beam_end_i) begin
      beam_parts_q <= (ColBits+1)'(col_now) + (ColBits+1)'(1);
    end
  end
  assign row_len = HomeBits'(beam_parts_q) * HomeBits'(P);

  // The hops: R registered stages of every pipeline's result, each moving
  // one lane back (lane k to k - 1, pipeline 0 to p - 1: the ring's one
  // link against its direction).
  localparam int unsigned HopBits = 1 + AccBits + WbBits;
  logic [(R+1)*P*HopBits-1:0] hops;
  for (genvar k = 0; k < P; k++) begin : g_hop0
    assign hops[k*HopBits +: HopBits] = {blended_valid[k], blended[k*AccBits +: AccBits],
                                         blended_where[k*WbBits +: WbBits]};
  end
  for (genvar h = 1; h <= R; h++) begin : g_hops
    logic [P*HopBits-1:0] hop_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        hop_q <= '0;
      end else begin
        for (int unsigned k = 0; k < P; k++) hop_q[k*HopBits +: HopBits] <= hops[(h-1)*P*HopBits + ((k + 1) % P)*HopBits +: HopBits];
      end
    end
    assign hops[h*P*HopBits +: P*HopBits] = hop_q;
  end

  for (genvar k = 0; k < P; k++) begin : g_store
    logic                valid;
    logic [AccBits-1:0]  acc;
    logic [WbBits-1:0]   where;
    assign {valid, acc, where} = hops[R*P*HopBits + k*HopBits +: HopBits];
    logic                leaves, parity, unused_early;
    logic [RowBits-1:0]  row;
    logic [HomeBits-1:0] lane;
    logic [RayBits-1:0]  ru, rv;
    logic [TagBits-1:0]  rtag;
    assign {leaves, parity, row, lane, unused_early, ru, rv, rtag} = where;
    logic past;  // the stored lane lies in the next beam's first columns
    assign past = lane >= row_len;
    logic [HomeBits-1:0] column;
    assign column = past ? lane - row_len : lane;
    assign wb_valid[k]                        = valid;
    assign wb_parity[k]                       = parity;
    assign wb_row[k*RowBits +: RowBits]       = past ? next_row(row) : row;
    assign wb_col[k*ColBits +: ColBits]       = ColBits'(column / HomeBits'(P));
    assign wb_acc[k*AccBits +: AccBits]       = acc;
    logic unused_store;  // the pipeline is the lane's (lane mod p): the hops brought it there
    assign unused_store = ^{leaves, ru, rv, rtag, unused_early};
  end

  // Pixels: on the blending pipeline, as the result leaves cube4_composite.
  for (genvar k = 0; k < P; k++) begin : g_pixel
    logic                leaves, parity, early;
    logic [RowBits-1:0]  row;
    logic [HomeBits-1:0] lane;
    logic [RayBits-1:0]  ru, rv;
    logic [TagBits-1:0]  rtag;
    assign {leaves, parity, row, lane, early, ru, rv, rtag} = blended_where[k*WbBits +: WbBits];
    logic [AccBits-1:0] acc;
    assign acc = blended[k*AccBits +: AccBits];
    assign pixel_valid_o[k]              = blended_valid[k] && leaves;
    assign ray_u_o[k*RayBits +: RayBits] = ru;
    assign ray_v_o[k*RayBits +: RayBits] = rv;
    assign tag_o[k*TagBits +: TagBits]   = rtag;
    assign acc_red_o[k*AB +: AB]         = acc[0 +: AB];
    assign acc_green_o[k*AB +: AB]       = acc[AB +: AB];
    assign acc_blue_o[k*AB +: AB]        = acc[2*AB +: AB];
    assign acc_alpha_o[k*AB +: AB]       = acc[3*AB +: AB];
    assign acc_value_o[k*V +: V]         = acc[4*AB +: V];
    assign acc_selected_o[k]             = acc[4*AB + V];
    // The pixel: the ray over its back pixel with polygons (golden
    // leave_with_polygons(); a blank back pixel leaves the ray as it is).
    logic [4*AB-1:0] exit;  // {alpha, blue, green, red}
    if (HasPolygons) begin : g_leave
      logic [4*AB-1:0] back_acc, back_in;
      for (genvar ch = 0; ch < 4; ch++) begin : g_widen
        cube4_to_acc #(.AlphaBits(A), .AccGuardBits(AccGuardBits)) u_back (
          .pixel_i(back_out[k*4*A + ch*A +: A]), .acc_o(back_acc[ch*AB +: AB]));
      end
      assign back_in = poly_enabled_i ? back_acc : '0;
      logic                 unused_exit_valid, unused_exit_selected;
      logic [V-1:0]         unused_exit_value;
      cube4_compose_node #(
        .VoxelBits(V), .AlphaBits(A), .AccGuardBits(AccGuardBits), .Latency(0)
      ) u_leave (
        .clk_i,
        .rst_ni,
        .blend_mode_i    (cube4_pkg::BlendComposite),
        .valid_i         (blended_valid[k]),
        .front_red_i     (acc[0 +: AB]),
        .front_green_i   (acc[AB +: AB]),
        .front_blue_i    (acc[2*AB +: AB]),
        .front_alpha_i   (acc[3*AB +: AB]),
        .front_value_i   (acc[4*AB +: V]),
        .front_selected_i(acc[4*AB + V]),
        .back_red_i      (back_in[0 +: AB]),
        .back_green_i    (back_in[AB +: AB]),
        .back_blue_i     (back_in[2*AB +: AB]),
        .back_alpha_i    (back_in[3*AB +: AB]),
        .back_value_i    ('0),
        .back_selected_i (1'b0),
        .valid_o         (unused_exit_valid),
        .red_o           (exit[0 +: AB]),
        .green_o         (exit[AB +: AB]),
        .blue_o          (exit[2*AB +: AB]),
        .alpha_o         (exit[3*AB +: AB]),
        .value_o         (unused_exit_value),
        .selected_o      (unused_exit_selected)
      );
      logic unused_leave;
      assign unused_leave = ^{unused_exit_valid, unused_exit_selected, unused_exit_value};
    end else begin : g_no_leave
      assign exit = acc[0 +: 4*AB];
      logic unused_back;
      assign unused_back = ^back_out[k*4*A +: 4*A];
    end
    cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(AccGuardBits)) u_red   (.acc_i(exit[0 +: AB]),
                                                                           .pixel_o(pixel_red_o[k*A +: A]));
    cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(AccGuardBits)) u_green (.acc_i(exit[AB +: AB]),
                                                                           .pixel_o(pixel_green_o[k*A +: A]));
    cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(AccGuardBits)) u_blue  (.acc_i(exit[2*AB +: AB]),
                                                                           .pixel_o(pixel_blue_o[k*A +: A]));
    cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(AccGuardBits)) u_alpha (.acc_i(exit[3*AB +: AB]),
                                                                           .pixel_o(pixel_alpha_o[k*A +: A]));
    logic unused_where;
    assign unused_where = ^{parity, row, lane, early};
  end

endmodule
