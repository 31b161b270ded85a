// cube4_gradient_persp_ring: NumPipes perspective gradient pipelines in a
// ring (Cube-4 §3; docs/perspective.md, "The gradient ring's schedule" and
// "The plan for the ring's RTL"; docs/rtl-gradient-persp.md).
//
// Function: for every ray (u, v) of every sample slice k of the stream,
// golden perspective_gradient(): the lateral differences of its neighbours
// u -/+ 1 and v -/+ 1 on slice k, and the z difference of the points
// straight behind and ahead of it, bilinear over the 2x2 rays of slices
// k -/+ 1 around them. Each gradient leaves once, 3 cycles after the step
// that forms it (cube4_gradient's stages), on that step's lane, with its
// ray, its own sample and voxel tag and its pass's tag: where and when
// TlmGradientPersp (systemc/tlm/tlm_gradient_persp.hpp) has it.
//
// Schedule (golden gradient_cell()): the stream position of column c of
// beam b forms the gradient of cell (c - 5, b - 5) of the pass before the
// streaming one: its home cell + (5, 5) in the next pass. The last five
// cells of a beam are formed in the next beam's first five columns, the
// last five rows of a pass in the next pass's first five beams, so passes
// stay back to back and the stream ends with six flush beams.
//
// Dataflow: the interpolation ring's samples arrive on the lane of their
// home column + 2 (formed cell + 2), in the step that forms them, and are
// stored there (cube4_persp_column: four slice stores per
// pipeline, by pass mod 4, row and partial beam; a beam's last two cells,
// which arrive in the next beam's first two columns, go to the next row's
// entries of those lanes, which no cell of that row uses). Every step each
// pipeline reads its column at the seven rows its beam's gradients need
// (the gradient row's own, up and down rows on slice k, two rows each on
// slices k -/+ 1: the y walk and cube4_gradient_persp_homes along y, once
// per beam), a column packet. The gradient of home column X is formed at
// column X + 5, from the packets of columns X - 1 .. X + 5 (its own and the
// six to its left: this step's or a history of the last ceil(6/p) steps'),
// which cube4_gradient_persp_homes along x picks per operand (lane X + 3 -
// home). An operand formed in the very step that forms the gradient (ahead,
// three cells on in both axes) is taken from the beat (the column's bypass).
// Operands of rays that miss their slice (in x or in y) read zero.
//
// Input stream: one valid_i step per stream position, in the order the
// interpolation ring's stream has them (cube4_interp_persp_ring's flags,
// six flush beams at the end), with the samples the interpolation ring
// formed in that step (sample_valid_i per lane) and, from each pass's first
// step, that pass's constants (golden perspective_slice(): spacing, ray 0's
// positions, the rays that sample the slice, the realignment DDAs into the
// neighbouring slices, the lateral reciprocal; first_i / last_i: the frame's
// first or last slice, which have no slice behind or ahead; tag_i). The
// ring keeps the last four passes' constants.
//
// VolumePro's z gradient (HasVoxelZ = 1; docs/perspective.md, "Gradient"):
// each sample arrives with its filtered voxel z difference (zdiff_i, from
// cube4_interp_persp_ring with HasZDiff), stored beside it, and the
// gradient's z is C(the own sample's difference) (golden
// perspective_gradient_voxel_z(); cube4_gradient with HasVoxelZ builds no
// ABC lerps). The schedule stays the 12-neighbourhood's, so the cycles do
// not depend on the z gradient chosen. Without HasVoxelZ zdiff_i is
// ignored and nothing of it is built.
//
// Preconditions: every pass complete, with the same ny >= 6 rows and
// ceil(nx/p) <= BeamDepth partial beams per beam; ny <= MaxDim; spacing in
// [1, 3] voxels (the homes lie within three cells); supersampling_i held
// over the stream.
//
// Parameters:
//   NumPipes              - pipelines p
//   MaxDim                - largest nx and ny: sizes the stores
//   VoxelBits, WeightBits, GradientBits, GradientShift, SupersamplingBits
//                         - datapath widths (cube4_pkg, cube4_gradient)
//   FracBits, PosBits, RayBits - the walks' (cube4_persp_lanes)
//   TagBits               - the pass tag's width
//   VoxelTagBits          - voxel tag width (0: none)
//   HasVoxelZ             - VolumePro's z gradient (above)
`include "cube4_pkg.sv"

module cube4_gradient_persp_ring #(
  parameter int unsigned  NumPipes          = 4,
  parameter int unsigned  MaxDim            = 256,
  parameter int unsigned  VoxelBits         = cube4_pkg::VoxelBits,
  parameter int unsigned  WeightBits        = cube4_pkg::WeightBits,
  parameter int unsigned  GradientBits      = cube4_pkg::GradientBits,
  parameter int unsigned  GradientShift     = cube4_pkg::GradientShift,
  parameter int unsigned  SupersamplingBits = cube4_pkg::SupersamplingBits,
  parameter int unsigned  FracBits          = cube4_pkg::FracBits,
  parameter int unsigned  PosBits           = 48,
  parameter int unsigned  RayBits           = 16,
  parameter int unsigned  TagBits           = 8,
  parameter int unsigned  VoxelTagBits      = 0,
  parameter bit           HasVoxelZ         = 1'b0,
  localparam int unsigned VTagPortBits      = VoxelTagBits > 0 ? VoxelTagBits : 1,
  localparam int unsigned RecipBits         = VoxelBits + 2
) (
  input  logic                               clk_i,
  input  logic                               rst_ni,
  // Stream steps.
  input  logic                               valid_i,
  input  logic                               beam_start_i,
  input  logic                               beam_end_i,
  input  logic                               slice_start_i,
  input  logic                               slice_end_i,
  input  logic                               flush_i,
  // The step's pass's constants, taken at its first step.
  input  logic signed [PosBits-1:0]          spacing_i,
  input  logic signed [PosBits-1:0]          ray0_x_i,
  input  logic signed [PosBits-1:0]          ray0_y_i,
  input  logic signed [RayBits-1:0]          rays_x_lo_i,
  input  logic signed [RayBits-1:0]          rays_x_hi_i,
  input  logic signed [RayBits-1:0]          rays_y_lo_i,
  input  logic signed [RayBits-1:0]          rays_y_hi_i,
  input  logic signed [PosBits-1:0]          behind_start_x_i,
  input  logic signed [PosBits-1:0]          behind_start_y_i,
  input  logic signed [PosBits-1:0]          behind_step_i,
  input  logic signed [PosBits-1:0]          ahead_start_x_i,
  input  logic signed [PosBits-1:0]          ahead_start_y_i,
  input  logic signed [PosBits-1:0]          ahead_step_i,
  input  logic [RecipBits:0]                 lateral_recip_i,
  input  logic                               first_i,
  input  logic                               last_i,
  input  logic [TagBits-1:0]                 tag_i,
  input  logic [SupersamplingBits-1:0]       supersampling_i,
  // The samples the interpolation ring formed in this step.
  input  logic [NumPipes-1:0]                sample_valid_i,
  input  logic [NumPipes*VoxelBits-1:0]      sample_i,
  input  logic [NumPipes*VTagPortBits-1:0]   vtag_i,
  input  logic [NumPipes*(VoxelBits+1)-1:0]  zdiff_i,  // HasVoxelZ: two's complement
  // Gradients.
  output logic [NumPipes-1:0]                valid_o,
  output logic [NumPipes*GradientBits-1:0]   gx_o,
  output logic [NumPipes*GradientBits-1:0]   gy_o,
  output logic [NumPipes*GradientBits-1:0]   gz_o,
  output logic [NumPipes*VoxelBits-1:0]      sample_o,
  output logic [NumPipes*RayBits-1:0]        ray_u_o,
  output logic [NumPipes*RayBits-1:0]        ray_v_o,
  output logic [NumPipes*TagBits-1:0]        tag_o,
  output logic [NumPipes*VTagPortBits-1:0]   vtag_o
);

  localparam int unsigned P         = NumPipes;
  localparam int unsigned V         = VoxelBits;
  localparam int unsigned T         = VTagPortBits;
  localparam int unsigned ZBits     = HasVoxelZ ? V + 1 : 0;
  localparam int unsigned WordBits  = V + VoxelTagBits + ZBits;  // a stored sample: {z difference, voxel tag, value}
  localparam int unsigned BeamDepth = (MaxDim + P - 1) / P;
  localparam int unsigned RowBits   = $clog2(MaxDim);
  localparam int unsigned ColBits   = BeamDepth > 1 ? $clog2(BeamDepth) : 1;
  localparam int unsigned HomeBits  = PosBits - FracBits;
  localparam int unsigned Reads     = 7;  // a packet's rows: own, up, down, behind 0/1, ahead 0/1
  localparam int unsigned PktBits   = Reads * WordBits;
  localparam int unsigned GLatency  = 3;  // cube4_gradient
  // How far back the formation reaches, in steps: the cell five stream
  // positions back, the window's first column six.
  localparam int unsigned CellDepth = (5 + P - 1) / P;
  localparam int unsigned ColDepth  = (6 + P - 1) / P;

  // -------------------------------------------------------------------------
  // The last four passes' constants, by pass mod 4.
  // A pass's constants in one word, fields from the LSB up. Words and
  // offsets, not structs: yosys 0.23 misreads a struct declared in a
  // generate block and takes no member of an array element.
  localparam int unsigned PTag        = 0;
  localparam int unsigned PLast       = PTag + TagBits;
  localparam int unsigned PFirst      = PLast + 1;
  localparam int unsigned PLateral    = PFirst + 1;
  localparam int unsigned PAheadStep  = PLateral + RecipBits + 1;
  localparam int unsigned PAheadY     = PAheadStep + PosBits;
  localparam int unsigned PAheadX     = PAheadY + PosBits;
  localparam int unsigned PBehindStep = PAheadX + PosBits;
  localparam int unsigned PBehindY    = PBehindStep + PosBits;
  localparam int unsigned PBehindX    = PBehindY + PosBits;
  localparam int unsigned PYHi        = PBehindX + PosBits;
  localparam int unsigned PYLo        = PYHi + RayBits;
  localparam int unsigned PXHi        = PYLo + RayBits;
  localparam int unsigned PXLo        = PXHi + RayBits;
  localparam int unsigned PRay0Y      = PXLo + RayBits;
  localparam int unsigned PRay0X      = PRay0Y + PosBits;
  localparam int unsigned PSpacing    = PRay0X + PosBits;
  localparam int unsigned PassBits    = PSpacing + PosBits;

  // Where the step is (cube4_persp_stream): its pass and partial beam, and
  // the beams before it, d back (0: its own): whether each was a pass's
  // beam (not a flush beam) and of one after the stream's first (whose
  // beams form the cells of the pass before), whether it was its pass's
  // last, its row and its pass.
  logic                 pass_start;
  logic [1:0]           pass_now;
  logic [ColBits-1:0]   col_now;
  /* verilator lint_off UNUSEDSIGNAL */  // each use reads the beams it needs (2 to 5 back here)
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
                              behind_start_x_i, behind_start_y_i, behind_step_i, ahead_start_x_i,
                              ahead_start_y_i, ahead_step_i, lateral_recip_i, first_i, last_i, tag_i};
    end
  end

  // The row after r in its pass's store: a beam's last two cells are stored
  // in the next row's entries, the last row's in row 0's. For the rows the
  // gradients read, whose pass (or the one before it: every pass of a
  // stream has the same rows) has ended; the writes know from their beam.
  function automatic logic [RowBits-1:0] next_row(input logic [RowBits-1:0] r);
    next_row = ((RowBits+1)'(r) + (RowBits+1)'(1) == ny_q) ? '0 : r + RowBits'(1);
  endfunction

  // -------------------------------------------------------------------------
  // The gradient row of a beam: beam b - 5's cells, of the pass before
  // that beam's. The y walk starts at the end of the beam before the one
  // whose gradient row is a pass's row 0, and advances at every other beam
  // end; its outputs describe the current beam's gradient row.
  // Waiver (here and below): the beams, passes and rows are words read
  // field by field, each use a few of the fields (the y walk the y
  // constants, the x walk the x constants, and so on).
  /* verilator lint_off UNUSEDSIGNAL */
  logic [1:0] gpass;  // the gradient row's pass: the one before beam 5 back's
  assign gpass = beam_pass[5*2 +: 2] - 2'd1;
  logic [PassBits-1:0] gp, gp_behind, gp_ahead;  // its constants and the passes' beside it
  assign gp        = passes_q[gpass];
  assign gp_behind = passes_q[gpass - 2'd1];
  assign gp_ahead  = passes_q[gpass + 2'd1];

  logic  beam_last;
  assign beam_last = valid_i && beam_end_i;
  logic [PassBits-1:0] next_gp;  // the next beam's gradient row's pass
  assign next_gp = passes_q[beam_pass[4*2 +: 2] - 2'd1];
  /* verilator lint_on UNUSEDSIGNAL */

  // The gradient row's ray (y) and, a step ahead, its cells' (x).
  logic                    y_valid;
  logic [RayBits-1:0]      y_ray;
  logic [WeightBits-1:0]   y_unused_weight;
  logic [P-1:0]            x_valid;
  logic [P*RayBits-1:0]    x_ray;
  logic [P*WeightBits-1:0] x_unused_weight;
  cube4_persp_cell_walks #(
    .NumPipes  (P),
    .FracBits  (FracBits),
    .WeightBits(WeightBits),
    .PosBits   (PosBits),
    .RayBits   (RayBits)
  ) u_walks (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    .valid_i        (valid_i),
    .beam_end_i     (beam_end_i),
    .next_forms_i   (beam_real[4] && beam_after_first[4]),
    .next_row_zero_i(beam_row[4*RowBits +: RowBits] == '0),
    .spacing_i      (next_gp[PSpacing +: PosBits]),
    .ray0_x_i       (next_gp[PRay0X +: PosBits]),
    .ray0_y_i       (next_gp[PRay0Y +: PosBits]),
    .rays_x_lo_i    (next_gp[PXLo +: RayBits]),
    .rays_x_hi_i    (next_gp[PXHi +: RayBits]),
    .rays_y_lo_i    (next_gp[PYLo +: RayBits]),
    .rays_y_hi_i    (next_gp[PYHi +: RayBits]),
    .row_valid_o    (y_valid),
    .row_ray_o      (y_ray),
    .row_weight_o   (y_unused_weight),
    .lane_valid_o   (x_valid),
    .lane_ray_o     (x_ray),
    .lane_weight_o  (x_unused_weight)
  );
  logic unused_weights;  // the gradient needs no sample places
  assign unused_weights = ^{y_unused_weight, x_unused_weight};

  // The rows the beam's gradients read, and the realigned y weights.
  logic signed [HomeBits-1:0] y_home;
  logic [1:0]                 y_side_valid, y_behind_valid, y_ahead_valid;
  logic [2*HomeBits-1:0]      y_side, y_behind, y_ahead;
  logic [WeightBits-1:0]      y_behind_w, y_ahead_w;
  cube4_gradient_persp_homes #(
    .FracBits  (FracBits),
    .WeightBits(WeightBits),
    .PosBits   (PosBits),
    .RayBits   (RayBits)
  ) u_homes_y (
    .u_i             (y_ray),
    .spacing_i       (gp[PSpacing +: PosBits]),
    .ray0_i          (gp[PRay0Y +: PosBits]),
    .rays_lo_i       (gp[PYLo +: RayBits]),
    .rays_hi_i       (gp[PYHi +: RayBits]),
    .behind_present_i(!gp[PFirst +: 1]),
    .behind_spacing_i(gp_behind[PSpacing +: PosBits]),
    .behind_ray0_i   (gp_behind[PRay0Y +: PosBits]),
    .behind_lo_i     (gp_behind[PYLo +: RayBits]),
    .behind_hi_i     (gp_behind[PYHi +: RayBits]),
    .behind_start_i  (gp[PBehindY +: PosBits]),
    .behind_step_i   (gp[PBehindStep +: PosBits]),
    .ahead_present_i (!gp[PLast +: 1]),
    .ahead_spacing_i (gp_ahead[PSpacing +: PosBits]),
    .ahead_ray0_i    (gp_ahead[PRay0Y +: PosBits]),
    .ahead_lo_i      (gp_ahead[PYLo +: RayBits]),
    .ahead_hi_i      (gp_ahead[PYHi +: RayBits]),
    .ahead_start_i   (gp[PAheadY +: PosBits]),
    .ahead_step_i    (gp[PAheadStep +: PosBits]),
    .home_o          (y_home),
    .side_valid_o    (y_side_valid),
    .side_o          (y_side),
    .behind_valid_o  (y_behind_valid),
    .behind_o        (y_behind),
    .behind_weight_o (y_behind_w),
    .ahead_valid_o   (y_ahead_valid),
    .ahead_o         (y_ahead),
    .ahead_weight_o  (y_ahead_w)
  );
  // The gradient row's own home is the beam's row (the walk's cell).
  logic unused_y_home;
  assign unused_y_home = ^y_home;

  // A beam's reads: the row of each packet slot, whether a ray of the right
  // slice has it, and the context its gradients take along.
  // (A word, fields from the LSB up, as a pass's.)
  localparam int unsigned RAheadWy   = 0;
  localparam int unsigned RBehindWy  = RAheadWy + WeightBits;
  localparam int unsigned RRows      = RBehindWy + WeightBits;          // per slot
  localparam int unsigned RRowValid  = RRows + Reads * RowBits;         // per slot
  localparam int unsigned RV         = RRowValid + Reads;
  localparam int unsigned RPass      = RV + RayBits;                    // the gradient row's pass
  localparam int unsigned RForms     = RPass + 2;  // a ray of that pass has its home row here
  localparam int unsigned RowsBits   = RForms + 1;

  function automatic logic [RowBits-1:0] row_of(input logic [2*HomeBits-1:0] homes, input int unsigned i);
    row_of = homes[i*HomeBits +: RowBits];
  endfunction

  /* verilator lint_off UNUSEDSIGNAL */  // the early columns read the rows (waiver above)
  logic [RowsBits-1:0] rows_now, rows_prev_q;
  /* verilator lint_on UNUSEDSIGNAL */
  assign rows_now = {beam_real[5] && beam_after_first[5] && y_valid, gpass, y_ray,
                      {y_ahead_valid, y_behind_valid, y_side_valid, 1'b1},
                      {row_of(y_ahead, 1), row_of(y_ahead, 0), row_of(y_behind, 1), row_of(y_behind, 0),
                       row_of(y_side, 1), row_of(y_side, 0), beam_row[5*RowBits +: RowBits]},
                      y_behind_w, y_ahead_w};
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rows_prev_q <= '0;
    end else if (beam_last) begin
      rows_prev_q <= rows_now;
    end
  end

  // -------------------------------------------------------------------------
  // Column stages: the stores and this step's packets.
  logic [P*PktBits-1:0] pkt_live;
  for (genvar k = 0; k < P; k++) begin : g_column
    // Columns 0 and 1 of a beam hold the previous beam's last cells (stored
    // in the next row's entries) and read its rows.
    localparam int unsigned Early2 = (k >= 2) ? 0 : (2 - k + P - 1) / P;
    logic early;
    if (Early2 > 0) begin : g_early
      assign early = 32'(col_now) < Early2;
    end else begin : g_late
      assign early = 1'b0;
    end

    logic [1:0]         wstore;
    logic [RowBits-1:0] wrow;
    assign wstore = early ? beam_pass[3*2 +: 2] : beam_pass[2*2 +: 2];
    assign wrow   = early ? (beam_last_row[3] ? '0 : beam_row[3*RowBits +: RowBits] + RowBits'(1)) : beam_row[2*RowBits +: RowBits];

    logic [Reads*RowBits-1:0] r_rows;
    logic [1:0]               r_pass;
    assign r_rows = early ? rows_prev_q[RRows +: Reads*RowBits] : rows_now[RRows +: Reads*RowBits];
    assign r_pass = early ? rows_prev_q[RPass +: 2] : rows_now[RPass +: 2];
    logic [Reads*2-1:0]       stores;
    logic [Reads*RowBits-1:0] rrows;
    for (genvar i = 0; i < Reads; i++) begin : g_slot
      // Slots 0-2 read slice k's store, 3-4 slice k - 1's, 5-6 slice k + 1's.
      localparam logic [1:0] Offset = (i < 3) ? 2'd0 : (i < 5) ? 2'd3 : 2'd1;
      logic [RowBits-1:0] row;
      assign row = r_rows[i*RowBits +: RowBits];
      assign stores[i*2 +: 2]              = r_pass + Offset;
      assign rrows[i*RowBits +: RowBits]   = early ? next_row(row) : row;
    end

    logic [V+VoxelTagBits-1:0] wsample;
    if (VoxelTagBits > 0) begin : g_tagged
      assign wsample = {vtag_i[k*T +: VoxelTagBits], sample_i[k*V +: V]};
    end else begin : g_plain
      assign wsample = sample_i[k*V +: V];
      logic unused_vtag;
      assign unused_vtag = ^vtag_i[k*T +: T];
    end
    logic [WordBits-1:0] wdata;
    if (HasVoxelZ) begin : g_zdiff
      assign wdata = {zdiff_i[k*(V+1) +: V+1], wsample};
    end else begin : g_no_zdiff
      assign wdata = wsample;
      logic unused_zdiff;
      assign unused_zdiff = ^zdiff_i[k*(V+1) +: V+1];
    end

    cube4_persp_column #(
      .Width    (WordBits),
      .Reads    (Reads),
      .StoreBits(2),
      .MaxDim   (MaxDim),
      .BeamDepth(BeamDepth)
    ) u_column (
      .clk_i   (clk_i),
      .we_i    (valid_i && sample_valid_i[k]),
      .wstore_i(wstore),
      .wrow_i  (wrow),
      .wcol_i  (col_now),
      .wdata_i (wdata),
      .col_i   (col_now),
      .store_i (stores),
      .row_i   (rrows),
      .packet_o(pkt_live[k*PktBits +: PktBits])
    );
  end

  // -------------------------------------------------------------------------
  // Histories, shifted at every step: the packets of the last ColDepth
  // steps, the x walk's lanes and the beam's rows of the last CellDepth.
  // Index 0 is live.
  localparam int unsigned LaneBits = 1 + RayBits;
  localparam int unsigned CtxBits  = RowsBits;
  logic [(ColDepth+1)*P*PktBits-1:0]   pkt_hist;
  logic [(CellDepth+1)*P*LaneBits-1:0] lane_hist;
  logic [(CellDepth+1)*CtxBits-1:0]    ctx_hist;
  logic [ColDepth*P*PktBits-1:0]       pkt_hist_q;
  logic [CellDepth*P*LaneBits-1:0]     lane_hist_q;
  logic [CellDepth*CtxBits-1:0]        ctx_hist_q;

  assign pkt_hist = {pkt_hist_q, pkt_live};
  for (genvar k = 0; k < P; k++) begin : g_lane_live
    assign lane_hist[k*LaneBits +: LaneBits] = {x_valid[k], x_ray[k*RayBits +: RayBits]};
  end
  assign lane_hist[P*LaneBits +: CellDepth*P*LaneBits] = lane_hist_q;
  assign ctx_hist = {ctx_hist_q, rows_now};

  always_ff @(posedge clk_i) begin
    if (valid_i) begin
      pkt_hist_q  <= pkt_hist[0 +: ColDepth*P*PktBits];
      lane_hist_q <= lane_hist[0 +: CellDepth*P*LaneBits];
    end
  end
  // The context says whether a step forms: reset, so that the stream's
  // first steps find nothing before it.
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ctx_hist_q <= '0;
    end else if (valid_i) begin
      ctx_hist_q <= ctx_hist[0 +: CellDepth*CtxBits];
    end
  end
  logic unused_hist;  // the deepest entries are read by some pipelines only
  assign unused_hist = ^{pkt_hist, lane_hist, ctx_hist};

  // -------------------------------------------------------------------------
  // Formation: pipeline k's stream position s forms the gradient of the
  // cell at s - 5, from the packets at s - 6 .. s. Position s - i lies at
  // pipeline (k - i) mod P, (i - k) / P steps back, rounded up (0 when
  // k >= i). All static but the window's choice.
  for (genvar k = 0; k < P; k++) begin : g_form
    localparam int unsigned CellPipe = (k + 5 * P - 5) % P;
    localparam int unsigned CellBack = (k >= 5) ? 0 : (5 - k + P - 1) / P;

    logic               lane_valid;
    logic [RayBits-1:0] u;
    assign {lane_valid, u} = lane_hist[(CellBack*P + CellPipe)*LaneBits +: LaneBits];
    /* verilator lint_off UNUSEDSIGNAL */  // all but the rows (waiver above)
    logic [RowsBits-1:0] ctx;
    /* verilator lint_on UNUSEDSIGNAL */
    assign ctx = ctx_hist[CellBack*CtxBits +: CtxBits];

    // The window: the packets of positions s - d, d = 0 .. 6.
    logic [7*PktBits-1:0] window;
    for (genvar d = 0; d <= 6; d++) begin : g_window
      localparam int unsigned SrcPipe = (k + 7 * P - d) % P;
      localparam int unsigned SrcBack = (k >= d) ? 0 : (d - k + P - 1) / P;
      assign window[d*PktBits +: PktBits] = pkt_hist[(SrcBack*P + SrcPipe)*PktBits +: PktBits];
    end

    /* verilator lint_off UNUSEDSIGNAL */  // the x constants (waiver above)
    logic [PassBits-1:0] fp, fp_behind, fp_ahead;
    /* verilator lint_on UNUSEDSIGNAL */
    assign fp        = passes_q[ctx[RPass +: 2]];
    assign fp_behind = passes_q[ctx[RPass +: 2] - 2'd1];
    assign fp_ahead  = passes_q[ctx[RPass +: 2] + 2'd1];

    logic signed [HomeBits-1:0] x_home;
    logic [1:0]                 x_side_valid, x_behind_valid, x_ahead_valid;
    logic [2*HomeBits-1:0]      x_side, x_behind, x_ahead;
    logic [WeightBits-1:0]      x_behind_w, x_ahead_w;
    cube4_gradient_persp_homes #(
      .FracBits  (FracBits),
      .WeightBits(WeightBits),
      .PosBits   (PosBits),
      .RayBits   (RayBits)
    ) u_homes_x (
      .u_i             (u),
      .spacing_i       (fp[PSpacing +: PosBits]),
      .ray0_i          (fp[PRay0X +: PosBits]),
      .rays_lo_i       (fp[PXLo +: RayBits]),
      .rays_hi_i       (fp[PXHi +: RayBits]),
      .behind_present_i(!fp[PFirst +: 1]),
      .behind_spacing_i(fp_behind[PSpacing +: PosBits]),
      .behind_ray0_i   (fp_behind[PRay0X +: PosBits]),
      .behind_lo_i     (fp_behind[PXLo +: RayBits]),
      .behind_hi_i     (fp_behind[PXHi +: RayBits]),
      .behind_start_i  (fp[PBehindX +: PosBits]),
      .behind_step_i   (fp[PBehindStep +: PosBits]),
      .ahead_present_i (!fp[PLast +: 1]),
      .ahead_spacing_i (fp_ahead[PSpacing +: PosBits]),
      .ahead_ray0_i    (fp_ahead[PRay0X +: PosBits]),
      .ahead_lo_i      (fp_ahead[PXLo +: RayBits]),
      .ahead_hi_i      (fp_ahead[PXHi +: RayBits]),
      .ahead_start_i   (fp[PAheadX +: PosBits]),
      .ahead_step_i    (fp[PAheadStep +: PosBits]),
      .home_o          (x_home),
      .side_valid_o    (x_side_valid),
      .side_o          (x_side),
      .behind_valid_o  (x_behind_valid),
      .behind_o        (x_behind),
      .behind_weight_o (x_behind_w),
      .ahead_valid_o   (x_ahead_valid),
      .ahead_o         (x_ahead),
      .ahead_weight_o  (x_ahead_w)
    );

    // Slot `slot` of the packet of the column that stores the sample homed
    // at `home` (lane home + 2, counted back from the forming lane x_home +
    // 5), or zero where the ray misses its slice in x or in y.
    function automatic logic [WordBits-1:0] operand(input logic [7*PktBits-1:0] win,
                                                    input logic signed [HomeBits-1:0] home_x,
                                                    input logic signed [HomeBits-1:0] home, input logic x_ok,
                                                    input logic y_ok, input int unsigned slot);
      logic [HomeBits-1:0] back;
      back    = home_x + HomeBits'(3) - home;
      operand = '0;
      for (int unsigned d = 0; d <= 6; d++) begin
        if (x_ok && y_ok && back == HomeBits'(d)) operand = win[d*PktBits + slot*WordBits +: WordBits];
      end
    endfunction

    function automatic logic signed [HomeBits-1:0] home_at(input logic [2*HomeBits-1:0] homes,
                                                           input int unsigned i);
      home_at = homes[i*HomeBits +: HomeBits];
    endfunction

    logic [WordBits-1:0] own, left, right, up, down;
    logic [4*WordBits-1:0] behind, ahead;
    assign own   = operand(window, x_home, x_home, 1'b1, 1'b1, 0);
    assign left  = operand(window, x_home, home_at(x_side, 0), x_side_valid[0], 1'b1, 0);
    assign right = operand(window, x_home, home_at(x_side, 1), x_side_valid[1], 1'b1, 0);
    assign up    = operand(window, x_home, x_home, 1'b1, ctx[RRowValid + 1], 1);
    assign down  = operand(window, x_home, x_home, 1'b1, ctx[RRowValid + 2], 2);
    // The 2x2s: [0] (q, py), [1] x + 1, [2] y + 1, [3] both.
    for (genvar i = 0; i < 4; i++) begin : g_abc
      localparam int unsigned Ix = i % 2, Iy = i / 2;
      assign behind[i*WordBits +: WordBits] = operand(window, x_home, home_at(x_behind, Ix), x_behind_valid[Ix],
                                                      ctx[RRowValid + 3 + Iy], 3 + Iy);
      assign ahead[i*WordBits +: WordBits]  = operand(window, x_home, home_at(x_ahead, Ix), x_ahead_valid[Ix],
                                                      ctx[RRowValid + 5 + Iy], 5 + Iy);
    end

    function automatic logic [4*V-1:0] values(input logic [4*WordBits-1:0] words);
      for (int unsigned i = 0; i < 4; i++) values[i*V +: V] = words[i*WordBits +: V];
    endfunction

    logic form;
    assign form = valid_i && lane_valid && ctx[RForms +: 1];

    // VolumePro's z: the own sample's stored difference.
    logic [V:0] own_zdiff;
    if (HasVoxelZ) begin : g_own_zdiff
      assign own_zdiff = own[V + VoxelTagBits +: V + 1];
    end else begin : g_no_own_zdiff
      assign own_zdiff = '0;
    end

    logic [GradientBits-1:0] gx, gy, gz;
    cube4_gradient #(
      .VoxelBits        (V),
      .WeightBits       (WeightBits),
      .GradientBits     (GradientBits),
      .GradientShift    (GradientShift),
      .SupersamplingBits(SupersamplingBits),
      .HasPerspective   (1'b1),
      .HasVoxelZ        (HasVoxelZ)
    ) u_gradient (
      .clk_i          (clk_i),
      .rst_ni         (rst_ni),
      .valid_i        (form),
      .left_i         (left[0 +: V]),
      .right_i        (right[0 +: V]),
      .up_i           (up[0 +: V]),
      .down_i         (down[0 +: V]),
      .behind_i       (values(behind)),
      .ahead_i        (values(ahead)),
      .behind_wx_i    ({1'b0, x_behind_w}),
      .behind_wy_i    ({1'b0, ctx[RBehindWy +: WeightBits]}),
      .ahead_wx_i     ({1'b0, x_ahead_w}),
      .ahead_wy_i     ({1'b0, ctx[RAheadWy +: WeightBits]}),
      .supersampling_i(supersampling_i),
      .lateral_recip_i(fp[PLateral +: RecipBits+1]),
      .zdiff_i        (own_zdiff),
      .valid_o        (valid_o[k]),
      .gx_o           (gx),
      .gy_o           (gy),
      .gz_o           (gz)
    );
    assign gx_o[k*GradientBits +: GradientBits] = gx;
    assign gy_o[k*GradientBits +: GradientBits] = gy;
    assign gz_o[k*GradientBits +: GradientBits] = gz;

    // The ray, its sample, voxel tag and pass tag beside the datapath.
    logic [T-1:0] own_vtag;
    if (VoxelTagBits > 0) begin : g_own_tag
      assign own_vtag = own[V +: VoxelTagBits];
    end else begin : g_no_tag
      assign own_vtag = '0;
    end
    localparam int unsigned SideBits = 2 * RayBits + V + TagBits + T;
    logic [GLatency*SideBits-1:0] side_q;
    always_ff @(posedge clk_i) begin
      side_q <= {side_q[0 +: (GLatency-1)*SideBits], u, ctx[RV +: RayBits], own[0 +: V], fp[PTag +: TagBits], own_vtag};
    end
    assign {ray_u_o[k*RayBits +: RayBits], ray_v_o[k*RayBits +: RayBits], sample_o[k*V +: V],
            tag_o[k*TagBits +: TagBits], vtag_o[k*T +: T]} = side_q[(GLatency-1)*SideBits +: SideBits];

    // Unused by design: the operands' voxel tags (only the own sample's leaves).
    logic unused_tags;
    assign unused_tags = ^{left, right, up, down, behind, ahead};
  end

endmodule
