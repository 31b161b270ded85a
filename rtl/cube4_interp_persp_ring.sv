// cube4_interp_persp_ring: NumPipes perspective interpolation pipelines in a
// ring (Cube-4 §3; docs/perspective.md, "The dataflow";
// docs/rtl-interp-persp.md, "cube4_interp_persp_ring").
//
// Function: for every sample slice k of the stream and every ray (u, v)
// that samples it, golden perspective_sample(regs, perspective_slice(k), u,
// v): the ray's box filters over voxel slices z_voxel and z_voxel + 1 and the
// z lerp. Each sample leaves once, on the lane of the pipeline that forms
// it, with its ray (u, v) and the tag of its pass.
//
// Dataflow: pipeline k holds the voxel columns x = j * NumPipes + k (j the
// partial beam). Every pipeline weighs its own column's window rows with
// the beam's y box (cube4_interp_persp_column; the beam's cell row is
// b - 2). A ray's sample is formed where the last column of its window
// arrives: a ray homed in column X (its position's cell) needs the column
// sums of X-1 .. X+2, so the pipeline of column X+2 forms it, taking the
// other three sums from the three pipelines to its left (this step or the
// steps before: a history of the last three steps' sums per pipeline),
// with the ray's x box from cube4_persp_lanes (the walk along the beam), in
// cube4_interp_persp_home. Every stream position forms the cell two
// columns back; the last two cells of a beam are formed in the next beam's
// first two columns (which form none of their own), as a pass's last two
// cell rows are formed in the next pass's first two beams (which form none
// of theirs). So the stream keeps ny beams of ceil(nx/p) partial beams per
// pass, and ends with three flush beams: two drain the last pass's last
// cell rows, and the third's first columns form the last row's last cells.
// Columns of another beam than the cell's read zero (the volume's border).
//
// Input stream: cube4_interp_persp_column's (the parallel ring's flags,
// here three flush beams at the end), one voxel per pipeline (zero past nx), and with
// every step its pass's constants (golden perspective_slice(): spacing,
// ray 0's position in x and y, the rays that sample the slice in x and y,
// the box's reciprocal, wz; the per-slice control the weight generator
// cube4_persp_slice makes) and tag. They must hold over the pass. The
// drain beams (the next pass's first two, or the flush beams) form the
// finished pass's cells with that pass's constants, which the ring keeps
// from the pass's last step.
//
// Output: per pipeline valid_o with sample_o, the ray (ray_u_o, ray_v_o)
// and tag_o, 4 cycles after the step that forms it (the column stage's
// register, then cube4_interp_persp_home's three stages).
//
// Voxel tags (bela §III; VoxelTagBits > 0): voxels_i holds the memory words
// {tag, value}; vtag_o is each sample's tag, that of the voxel nearest it
// (golden render_perspective(): nearest_voxel() in x and y, upper_corner()
// of wz in z): each column stage picks its column's nearest row and slice,
// the forming pipeline the nearest of the window's columns X and X+1.
// Without tags vtag_o is 0 and none of it is built.
//
// VolumePro's z gradient (HasZDiff = 1; docs/perspective.md, "Gradient"):
// each sample also leaves with zdiff_o, golden perspective_z_difference():
// the voxel z differences of the sample's two voxel slices through its own
// box filters and z lerp. The column stages weigh the differences too
// (reading a slice ahead after the frame's priming pass, prime_i), their
// sums travel beside the voxels' in the history, and a second home stage
// (cube4_interp_persp_home, Signed) filters them. The priming pass brings
// no rays (its constants are the zero pass's), so it forms no cells.
// Without HasZDiff zdiff_o is 0 and none of it is built.
//
// Preconditions: as cube4_interp_persp_column's (ny >= 2, complete passes,
// nx <= MaxDim, ny * ceil(nx/p) <= SliceDepth); spacing in [1, 3] voxels.
//
// Parameters:
//   NumPipes              - pipelines p
//   MaxDim                - largest nx and ny: sizes the delays
//   VoxelBits, WeightBits - datapath widths (cube4_pkg)
//   FracBits, PosBits, RayBits - the walks' (cube4_persp_lanes)
//   TagBits               - the pass tag's width
//   VoxelTagBits          - voxel tag width (0: none)
//   HasZDiff              - VolumePro's z gradient: zdiff_o (above)
`include "cube4_pkg.sv"

module cube4_interp_persp_ring #(
  parameter int unsigned  NumPipes   = 4,
  parameter int unsigned  MaxDim     = 256,
  parameter int unsigned  VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned  WeightBits = cube4_pkg::WeightBits,
  parameter int unsigned  FracBits   = cube4_pkg::FracBits,
  parameter int unsigned  PosBits    = 48,
  parameter int unsigned  RayBits    = 16,
  parameter int unsigned  TagBits    = 8,
  parameter int unsigned  VoxelTagBits = 0,
  parameter bit           HasZDiff   = 1'b0,
  localparam int unsigned WordBits   = VoxelBits + VoxelTagBits,
  localparam int unsigned VTagPortBits = VoxelTagBits > 0 ? VoxelTagBits : 1,
  localparam int unsigned BeamDepth  = (MaxDim + NumPipes - 1) / NumPipes,
  localparam int unsigned SliceDepth = MaxDim * BeamDepth,
  localparam int unsigned RecipBits  = VoxelBits + 6
) (
  input  logic                            clk_i,
  input  logic                            rst_ni,
  // Voxel stream.
  input  logic                            valid_i,
  input  logic                            beam_start_i,
  input  logic                            beam_end_i,
  input  logic                            slice_start_i,
  input  logic                            slice_end_i,
  input  logic                            flush_i,
  input  logic                            prime_i,   // HasZDiff: a frame's priming pass
  input  logic [NumPipes*WordBits-1:0]    voxels_i,
  input  logic [WeightBits:0]             wz_i,
  input  logic [TagBits-1:0]              tag_i,
  // The step's pass's constants.
  input  logic signed [PosBits-1:0]       spacing_i,
  input  logic signed [PosBits-1:0]       ray0_x_i,
  input  logic signed [PosBits-1:0]       ray0_y_i,
  input  logic signed [RayBits-1:0]       rays_x_lo_i,
  input  logic signed [RayBits-1:0]       rays_x_hi_i,
  input  logic signed [RayBits-1:0]       rays_y_lo_i,
  input  logic signed [RayBits-1:0]       rays_y_hi_i,
  input  logic [RecipBits-1:0]            recip_i,
  // Samples.
  output logic [NumPipes-1:0]             valid_o,
  output logic [NumPipes*VoxelBits-1:0]   sample_o,
  output logic [NumPipes*RayBits-1:0]     ray_u_o,
  output logic [NumPipes*RayBits-1:0]     ray_v_o,
  output logic [NumPipes*TagBits-1:0]     tag_o,
  output logic [NumPipes*VTagPortBits-1:0] vtag_o,
  output logic [NumPipes*(VoxelBits+1)-1:0] zdiff_o  // HasZDiff: two's complement, else 0
);

  localparam int unsigned P       = NumPipes;
  localparam int unsigned V       = VoxelBits;
  localparam int unsigned OvBits  = WeightBits + 1;
  localparam int unsigned BoxBits = 4 * OvBits;
  localparam int unsigned ColBits = V + WeightBits + 2;
  localparam int unsigned T        = VTagPortBits;
  localparam int unsigned DColBits = V + WeightBits + 3;  // a difference column sum
  localparam int unsigned DB       = V + 1;               // a voxel z difference
  // {dhi, dlo (HasZDiff), tag, back, front} of a column
  localparam int unsigned PairBits = 2 * ColBits + T + (HasZDiff ? 2 * DColBits : 0);
  // How many steps back the formation reaches: the window's first column
  // lies three stream positions back, the cell two.
  localparam int unsigned ColDepth  = (3 + P - 1) / P;
  localparam int unsigned CellDepth = (2 + P - 1) / P;
  localparam int unsigned HomeLatency = 3;  // cube4_interp_persp_home

  // -------------------------------------------------------------------------
  // The finished pass's constants, kept from its last step for its drain.
  logic pass_last;
  assign pass_last = valid_i && slice_end_i && beam_end_i && !flush_i;

  logic signed [PosBits-1:0] old_spacing_q, old_ray0_x_q;
  logic signed [RayBits-1:0] old_x_lo_q, old_x_hi_q;
  logic [RecipBits-1:0]      old_recip_q;
  logic [WeightBits:0]       old_wz_q;
  logic [TagBits-1:0]        old_tag_q;
  always_ff @(posedge clk_i) begin
    if (pass_last) begin
      old_spacing_q <= spacing_i;
      old_ray0_x_q  <= ray0_x_i;
      old_x_lo_q    <= rays_x_lo_i;
      old_x_hi_q    <= rays_x_hi_i;
      old_recip_q   <= recip_i;
      old_wz_q      <= wz_i;
      old_tag_q     <= tag_i;
    end
  end

  // -------------------------------------------------------------------------
  // Column stages. Every pipeline's control is the same; pipeline 0's says
  // where the step is.
  logic [P-1:0]          col_valid;
  logic [P*PairBits-1:0] col_live;  // this step's {tag, back, front} per pipeline
  logic                  y_near, z_upper;  // the cell's nearest row and slice (tags)
  logic                  draining;
  logic [1:0]            beam;
  logic [BoxBits-1:0]    y_box;
  logic                  y_left, y_valid;
  logic signed [RayBits-1:0] y_ray;

  for (genvar k = 0; k < P; k++) begin : g_column
    logic       draining_k;
    logic [1:0] beam_k;
    logic [DColBits-1:0] dlo_k, dhi_k;
    if (HasZDiff) begin : g_diffs
      assign col_live[k*PairBits + 2*ColBits + T +: 2*DColBits] = {dhi_k, dlo_k};
    end else begin : g_no_diffs
      logic unused_diffs;  // zero without HasZDiff
      assign unused_diffs = ^{dlo_k, dhi_k};
    end
    cube4_interp_persp_column #(
      .VoxelBits (V),
      .WeightBits(WeightBits),
      .BeamDepth (BeamDepth),
      .SliceDepth(SliceDepth),
      .VoxelTagBits(VoxelTagBits),
      .HasZDiff  (HasZDiff)
    ) u_column (
      .clk_i        (clk_i),
      .rst_ni       (rst_ni),
      .valid_i      (valid_i),
      .beam_start_i (beam_start_i),
      .beam_end_i   (beam_end_i),
      .slice_start_i(slice_start_i),
      .slice_end_i  (slice_end_i),
      .flush_i      (flush_i),
      .prime_i      (prime_i),
      .voxel_i      (voxels_i[k*WordBits +: WordBits]),
      .wz_i         (wz_i),
      .oy_i         (y_box),
      .oy_left_i    (y_left),
      .y_near_i     (y_near),
      .z_upper_i    (z_upper),
      .valid_o      (col_valid[k]),
      .col_front_o  (col_live[k*PairBits +: ColBits]),
      .col_back_o   (col_live[k*PairBits + ColBits +: ColBits]),
      .col_tag_o    (col_live[k*PairBits + 2*ColBits +: T]),
      .col_dlo_o    (dlo_k),
      .col_dhi_o    (dhi_k),
      .draining_o   (draining_k),
      .beam_o       (beam_k)
    );
    if (k == 0) begin : g_control
      assign draining = draining_k;
      assign beam     = beam_k;
    end else begin : g_same
      logic unused_control;
      assign unused_control = ^{draining_k, beam_k, col_valid[k]};
    end
  end

  // The cell pass's constants of this step: the finished pass's in a drain.
  logic signed [PosBits-1:0] cell_spacing, cell_ray0_x;
  logic signed [RayBits-1:0] cell_x_lo, cell_x_hi;
  assign cell_spacing = draining ? old_spacing_q : spacing_i;
  assign cell_ray0_x  = draining ? old_ray0_x_q  : ray0_x_i;
  assign cell_x_lo    = draining ? old_x_lo_q    : rays_x_lo_i;
  assign cell_x_hi    = draining ? old_x_hi_q    : rays_x_hi_i;

  // -------------------------------------------------------------------------
  // The walk along y: one step per beam, the cell row b - 2. A pass's walk
  // starts at the end of its beam 1 (for its beam 2: row 0) and runs
  // through its drain beams; every other beam end advances it.
  logic y_start, y_advance;
  assign y_start   = valid_i && beam_end_i && !flush_i && beam == 2'd1;
  assign y_advance = valid_i && beam_end_i && !y_start;

  logic [RayBits-1:0] y_ray_bits;
  logic [0:0]         y_valid_bits, y_left_bits;
  logic [WeightBits-1:0] y_weight;
  cube4_persp_lanes #(
    .Pipes     (1),
    .FracBits  (FracBits),
    .WeightBits(WeightBits),
    .PosBits   (PosBits),
    .RayBits   (RayBits)
  ) u_walk_y (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .spacing_i (spacing_i),
    .ray0_i    (ray0_y_i),
    .rays_lo_i (rays_y_lo_i),
    .rays_hi_i (rays_y_hi_i),
    .start_i   (y_start),
    .advance_i (y_advance),
    .valid_o   (y_valid_bits),
    .ray_o     (y_ray_bits),
    .box_left_o(y_left_bits),
    .overlap_o (y_box),
    .weight_o  (y_weight)
  );
  assign y_valid = y_valid_bits[0];
  assign y_left  = y_left_bits[0];
  assign y_ray   = $signed(y_ray_bits);
  // The nearest row (the position's fraction at least half) and slice of
  // the cell, for the tags; the rest of the weight is the cut plane's.
  assign y_near  = y_weight[WeightBits-1];
  assign z_upper = (draining ? old_wz_q : wz_i) >= (WeightBits+1)'(1 << (WeightBits - 1));
  logic unused_y_weight;
  assign unused_y_weight = ^y_weight[WeightBits-2:0];

  // The walk along x: one step per partial beam, from each beam's first;
  // not restarted by the third flush beam, which forms no cells of its own
  // and brings no slice (its wrapped cells are the history's).
  logic x_start;
  assign x_start = valid_i && beam_start_i && !(flush_i && !draining);
  logic [P-1:0]          x_valid, x_left;
  logic [P*RayBits-1:0]  x_ray;
  logic [P*BoxBits-1:0]  x_box;
  logic [P*WeightBits-1:0] x_weight;
  cube4_persp_lanes #(
    .Pipes     (P),
    .FracBits  (FracBits),
    .WeightBits(WeightBits),
    .PosBits   (PosBits),
    .RayBits   (RayBits)
  ) u_walk_x (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .spacing_i (cell_spacing),
    .ray0_i    (cell_ray0_x),
    .rays_lo_i (cell_x_lo),
    .rays_hi_i (cell_x_hi),
    .start_i   (x_start),
    .advance_i (valid_i && !x_start),
    .valid_o   (x_valid),
    .ray_o     (x_ray),
    .box_left_o(x_left),
    .overlap_o (x_box),
    .weight_o  (x_weight)
  );
  logic [P-1:0] x_near;  // the nearest of the window's columns X and X+1
  for (genvar k = 0; k < P; k++) begin : g_x_near
    assign x_near[k] = x_weight[k*WeightBits + WeightBits - 1];
  end
  logic unused_x_weight;
  assign unused_x_weight = ^x_weight;

  // -------------------------------------------------------------------------
  // The step's context, registered with the column sums: whether its beam
  // forms cells (a drain beam, or beam 2 on), the cell row's ray, and the
  // cell pass's tag, wz and reciprocal; the beam's parity tells the
  // window's columns of another beam.
  localparam int unsigned CtxBits = 1 + 1 + RayBits + TagBits + WeightBits + 1 + RecipBits + 1;
  logic               beam_id_q, beam_id;
  logic [CtxBits-1:0] ctx_d, ctx_q;
  assign beam_id = beam_start_i ? !beam_id_q : beam_id_q;
  assign ctx_d = {beam_id,
                  draining || (beam[1] && !flush_i),
                  y_valid,
                  y_ray,
                  draining ? old_tag_q : tag_i,
                  draining ? old_wz_q : wz_i,
                  draining ? old_recip_q : recip_i};
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      beam_id_q <= 1'b0;
    end else if (valid_i) begin
      beam_id_q <= beam_id;
    end
  end
  // The context is control (whether a step forms cells): reset, so that
  // the first steps' wrapped cells find none before the stream began.
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ctx_q <= '0;
    end else if (valid_i) begin
      ctx_q <= ctx_d;
    end
  end

  // -------------------------------------------------------------------------
  // Histories, shifted at each formation (the cycle after a step): the
  // column sums of the last ColDepth steps (with their beam's parity), and
  // the lanes and context of the last CellDepth steps. Index 0 is live.
  localparam int unsigned LaneBits = 1 + 1 + 1 + RayBits + BoxBits;  // valid, left, near, ray, box
  logic form;
  assign form = col_valid[0];

  logic [(ColDepth+1)*P*(PairBits+1)-1:0] col_hist;  // [d][k] {parity, pair}
  logic [(CellDepth+1)*P*LaneBits-1:0]    lane_hist; // [d][k]
  logic [(CellDepth+1)*CtxBits-1:0]       ctx_hist;  // [d]
  logic [ColDepth*P*(PairBits+1)-1:0]     col_hist_q;
  logic [CellDepth*P*LaneBits-1:0]        lane_hist_q;
  logic [CellDepth*CtxBits-1:0]           ctx_hist_q;

  for (genvar k = 0; k < P; k++) begin : g_live
    assign col_hist[k*(PairBits+1) +: PairBits+1] = {ctx_q[CtxBits-1], col_live[k*PairBits +: PairBits]};
    assign lane_hist[k*LaneBits +: LaneBits] =
        {x_valid[k], x_left[k], x_near[k], x_ray[k*RayBits +: RayBits], x_box[k*BoxBits +: BoxBits]};
  end
  assign ctx_hist[0 +: CtxBits] = ctx_q;
  assign col_hist[P*(PairBits+1) +: ColDepth*P*(PairBits+1)] = col_hist_q;
  assign lane_hist[P*LaneBits +: CellDepth*P*LaneBits]        = lane_hist_q;
  assign ctx_hist[CtxBits +: CellDepth*CtxBits]               = ctx_hist_q;

  always_ff @(posedge clk_i) begin
    if (form) begin
      col_hist_q  <= col_hist[0 +: ColDepth*P*(PairBits+1)];
      lane_hist_q <= lane_hist[0 +: CellDepth*P*LaneBits];
    end
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ctx_hist_q <= '0;
    end else if (form) begin
      ctx_hist_q <= ctx_hist[0 +: CellDepth*CtxBits];
    end
  end

  // The deepest entries are read by some pipelines only (which depends on
  // P): the rest of them is unused by design.
  logic unused_hist;
  assign unused_hist = ^{col_hist, lane_hist};

  // -------------------------------------------------------------------------
  // Formation: pipeline k's stream position s forms the cell at s - 2 with
  // the columns at s - 3 .. s. Position s - i lies at pipeline (k - i) mod P,
  // (i - k) / P steps back, rounded up (0 when k >= i). All static.
  for (genvar k = 0; k < P; k++) begin : g_home
    localparam int unsigned CellPipe = (k + 2 * P - 2) % P;
    localparam int unsigned CellBack = (k >= 2) ? 0 : (2 - k + P - 1) / P;

    logic [LaneBits-1:0] lane;
    logic [CtxBits-1:0]  ctx;
    assign lane = lane_hist[(CellBack*P + CellPipe)*LaneBits +: LaneBits];
    assign ctx  = ctx_hist[CellBack*CtxBits +: CtxBits];

    logic                  cell_parity, cell_forms, cell_row_valid;
    logic [RayBits-1:0]    cell_v;
    logic [TagBits-1:0]    cell_tag;
    logic [WeightBits:0]   cell_wz;
    logic [RecipBits-1:0]  cell_recip;
    assign {cell_parity, cell_forms, cell_row_valid, cell_v, cell_tag, cell_wz, cell_recip} = ctx;

    logic                  lane_valid, lane_left, lane_near;
    logic [RayBits-1:0]    lane_ray;
    logic [BoxBits-1:0]    lane_box;
    assign {lane_valid, lane_left, lane_near, lane_ray, lane_box} = lane;

    // The window's four columns (position s - 3 + i at i), zero where they
    // belong to another beam than the cell's.
    logic [4*ColBits-1:0] front, back;
    logic [4*T-1:0]       tags;
    logic [4*DColBits-1:0] dlo, dhi;  // HasZDiff
    for (genvar i = 0; i < 4; i++) begin : g_col
      localparam int unsigned Back    = 3 - i;  // stream positions back
      localparam int unsigned SrcPipe = (k + 4 * P - Back) % P;
      localparam int unsigned SrcStep = (k >= Back) ? 0 : (Back - k + P - 1) / P;
      logic [PairBits:0] entry;
      logic              same;
      assign entry = col_hist[(SrcStep*P + SrcPipe)*(PairBits+1) +: PairBits+1];
      assign same  = entry[PairBits] == cell_parity;
      assign front[i*ColBits +: ColBits] = same ? entry[0 +: ColBits] : '0;
      assign back[i*ColBits +: ColBits]  = same ? entry[ColBits +: ColBits] : '0;
      assign tags[i*T +: T]              = same ? entry[2*ColBits +: T] : '0;
      if (HasZDiff) begin : g_diff
        assign dlo[i*DColBits +: DColBits] = same ? entry[2*ColBits + T +: DColBits] : '0;
        assign dhi[i*DColBits +: DColBits] = same ? entry[2*ColBits + T + DColBits +: DColBits] : '0;
      end else begin : g_no_diff
        assign dlo[i*DColBits +: DColBits] = '0;
        assign dhi[i*DColBits +: DColBits] = '0;
      end
    end
    // The nearest column's tag: window column 1 (X) or 2 (X+1).
    logic [T-1:0] vtag;
    assign vtag = lane_near ? tags[2*T +: T] : tags[T +: T];
    logic unused_far_tags;  // columns X-1 and X+2 are never the nearest
    assign unused_far_tags = ^{tags[0 +: T], tags[3*T +: T]};

    logic home_valid;
    cube4_interp_persp_home #(
      .VoxelBits (V),
      .WeightBits(WeightBits)
    ) u_home (
      .clk_i       (clk_i),
      .rst_ni      (rst_ni),
      .valid_i     (form && lane_valid && cell_forms && cell_row_valid),
      .cols_front_i(front),
      .cols_back_i (back),
      .ox_i        (lane_box),
      .ox_left_i   (lane_left),
      .recip_i     (cell_recip),
      .wz_i        (cell_wz),
      .valid_o     (home_valid),
      .sample_o    (sample_o[k*V +: V])
    );
    assign valid_o[k] = home_valid;

    // The second home stage: the same boxes over the voxel z differences.
    if (HasZDiff) begin : g_zdiff_home
      logic zdiff_valid;
      cube4_interp_persp_home #(
        .VoxelBits (V),
        .WeightBits(WeightBits),
        .Signed    (1'b1)
      ) u_zdiff_home (
        .clk_i       (clk_i),
        .rst_ni      (rst_ni),
        .valid_i     (form && lane_valid && cell_forms && cell_row_valid),
        .cols_front_i(dlo),
        .cols_back_i (dhi),
        .ox_i        (lane_box),
        .ox_left_i   (lane_left),
        .recip_i     (cell_recip),
        .wz_i        (cell_wz),
        .valid_o     (zdiff_valid),
        .sample_o    (zdiff_o[k*DB +: DB])
      );
      logic unused_zdiff_valid;  // the same cycle as home_valid
      assign unused_zdiff_valid = zdiff_valid;
    end else begin : g_no_zdiff_home
      assign zdiff_o[k*DB +: DB] = '0;
      logic unused_dcols;
      assign unused_dcols = ^{dlo, dhi};
    end

    // The ray and tag beside the home stage.
    localparam int unsigned SideBits = 2 * RayBits + TagBits + T;
    logic [HomeLatency*SideBits-1:0] side_q;
    always_ff @(posedge clk_i) begin
      side_q <= {side_q[0 +: (HomeLatency-1)*SideBits], lane_ray, cell_v, cell_tag, vtag};
    end
    assign {ray_u_o[k*RayBits +: RayBits], ray_v_o[k*RayBits +: RayBits], tag_o[k*TagBits +: TagBits],
            vtag_o[k*T +: T]} = side_q[(HomeLatency-1)*SideBits +: SideBits];
  end

endmodule
