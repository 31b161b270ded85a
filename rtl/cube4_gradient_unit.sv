// cube4_gradient_unit: one pipeline's gradient unit with its sample storage
// and near-neighbour links (VolumePro §3.2, §5.1; Cube-4 §5 "ABC gradient
// estimation" and "m < n"). docs/rtl-gradient.md describes the dataflow.
//
// Function: pipeline k of p receives the interpolation ring's sample stream
// (cube4_interp_ring's outputs for pipeline k): sample slice by sample
// slice, beam y = 0 .. ny-1 by beam, partial beam j by partial beam, one
// sample S(x, y, s) per valid cycle, x = j*p + k. For every sample of slice
// s it emits golden sample_gradient(regs, slice_control(s), neighbourhood)
// (cube4_gradient, bit-exact): central differences of S(x+-1, y, s) and
// S(x, y+-1, s), and the ABC z difference between the 2x2 samples around the
// re-aligned position in slices s+1 (ahead) and s-1 (behind), samples
// outside the grid being zero. The gradient of S(x, y, s) is computed when
// its column of beam y+1 of slice s+1 arrives: one slice, one beam and one
// sample behind the input (VolumePro §3.2); the last beam's (y = ny-1, over
// the zero border) in the beam after slice s+1, beam 0 of the next slice,
// which gives no gradient of its own (a "draining" beam). So slices follow
// back to back at ny beams each. The samples come from:
//   - the stream itself: slice s+1 (ahead), beam y+1;
//   - the slice delay (one 2V-bit RAM entry per sample of a slice): slice s
//     (current) and slice s-1 (behind) of the same (x, y+1);
//   - the beam delay (one 6V-bit entry per partial beam): those three
//     samples of beams y and y-1;
//   - the neighbours (pipeline k-1 and k+1): their columns' samples of the
//     current row and of the re-aligned ahead/behind row pairs. Pipeline p-1
//     takes its x+1 column from pipeline 0's next partial beam (link_now_o,
//     the ring wrap; zero after a beam's last partial beam); pipeline 0
//     takes its x-1 column from pipeline p-1's previous partial beam
//     (link_prev_o; zero before a beam's first partial beam). So every
//     pipeline holds its column one step in the alignment register (Cube-4's
//     beam extension), and pipeline p-1 holds one more (prev).
//
// Zero padding (docs/rtl-gradient.md, "Zero padding"):
//   - beams: a slice's last gradient beam takes zeros for beam ny; it is
//     computed in the next slice's beam 0 from the beam delay's rows, while
//     that beam is stored (with a zero row above it). After the stream's
//     last slice, the zero slice, the unit runs one zero beam of its own:
//     B = ceil(nx/p) steps (counted in that beam), one per clock, with zero
//     samples, producing the frame's last gradient beam. valid_i must stay
//     low in those B cycles: the interpolation ring leaves exactly them
//     free (its flush beam after the zero pass emits the zero slice's last
//     samples, and the next beam produces none). A valid_i in them is
//     ignored; the assertion a_zero_beam_idle
//     (rtl/assert/cube4_gradient_unit_sva.sv) reports it in simulation.
//   - slices: the slice behind a frame's first slice is zero, and so is the
//     slice ahead of its last. A frame's first slice carries the tag's
//     FrameStart bit: its input is stored as the new frame's slice 0 while
//     the unit computes the previous frame's last slice with zeros ahead
//     (frames back to back, no gap); after a reset or a zero slice it
//     produces no gradients. The stream's last frame ends with one zero
//     slice (the tag's ZeroSlice bit; its sample values are ignored and
//     taken as zero), which the stream former supplies as one more pass
//     through the interpolation ring (pass K: z_voxel = nz, wz = 0, voxels
//     zero, no memory read). Its input produces the gradients of the
//     frame's last slice.
//   - x: columns x >= nx of the last partial beam must carry zero samples
//     (cube4_interp_ring's padding columns do); x = B*p reads zero (mask).
//     Gradients of the padding columns are emitted too (x_o >= nx) and must
//     be discarded downstream.
//
// Tag (tag_i, constant over a slice; the weight generator's slice control,
// travelling through the interpolation ring), least significant field first:
//   [0*R +: R] behind_x  {base = -1, weight[WeightBits-1:0]}  (golden Realign:
//   [1*R +: R] behind_y   base bit 1 for base -1, 0 for base 0; R = WeightBits+1)
//   [2*R +: R] ahead_x
//   [3*R +: R] ahead_y
//   [4*R +: SupersamplingBits] S (registers' supersampling)
//   [4*R + SupersamplingBits]  ZeroSlice: the stream's trailing zero slice
//   [4*R + SupersamplingBits + 1] FrameStart: a frame's first slice
//   [CtrlBits +: UserTagBits]  user tag, out on tag_o with the slice's samples
//
// Voxel tags (bela §III; VoxelTagBits > 0): vtag_i is each sample's voxel
// tag (cube4_interp_ring's vtag_o); vtag_o is the centre sample's, beside
// sample_o (only classification and material use it, so no neighbour's tag
// is kept). It takes the centre's path: a slice delay of tags (the ahead
// slice's, read one lap later as the current slice's) and a beam delay of
// the current slice's (read as beam y's), both cube4_delay_ram with the
// sample delays' control, so the tags stay in step with their samples. The
// zero slice and the zero beam carry tag 0, as their samples carry 0. With VoxelTagBits = 0 there is none of it; vtag_o is 0.
//
// VolumePro's z gradient (HasVoxelZ): zdiff_i is each sample's
// interpolated voxel z difference (cube4_interp_ring's zdiff_o, V+1 bits,
// two's complement). It takes the voxel tag's way (the centre's) and gives
// gz = C(zdiff) of the centre sample (cube4_gradient with HasVoxelZ; golden
// gradient_voxel_z()): the difference waits a slice in the slice delay as
// the centre sample does. No behind or ahead row is kept or linked then:
// the slice delay holds the ahead slice's samples alone (read a lap later
// as the current slice's), a row and a link are the current sample, and
// no ABC lerp is built. Without HasVoxelZ zdiff_i is ignored.
//
// Output per gradient (valid_o): gx_o, gy_o, gz_o; sample_o = S(x, y, s)
// (the centre sample, for the shader) and vtag_o its voxel tag;
// x_o = j*p + k, y_o = y; flags beam_start_o / beam_end_o (j = 0 / B-1) and
// slice_start_o / slice_end_o (y = 0 / ny-1); tag_o = the user tag of
// slice s. Order: slice, beam, partial beam, as the input.
//
// Latency: a step (an input sample, or a zero-beam step) enters the
// alignment register; it leaves with the next step, or one cycle later if it
// ends a beam, into cube4_gradient (3 cycles). Without idle cycles the
// gradient of S(x, y, s) is on the outputs 4 cycles after the column of
// beam y+1 of slice s+1 (or of beam 0 of slice s+2, for y = ny-1) arrived;
// the last gradient of a stream 4 cycles after the last zero-beam step,
// i.e. B + 4 cycles after the zero slice's last input. One gradient per
// clock.
// Handshake: valid-only, no back-pressure. Reset: control (valid, counters,
// first-slice state, delay pointers); data registers and RAMs are not reset.
//
// Preconditions: every slice is complete (ny >= 1 beams of the same
// B <= BeamDepth partial beams, ny * B <= SliceDepth); frames back to back
// have the same ny and B (another frame follows a zero slice); the stream
// ends with a zero slice and B idle cycles after its last sample; all
// pipelines see the same valid_i and flags (lock step).
//
// Parameters:
//   NumPipes, PipeIndex   - p, and this pipeline's k (0 .. p-1): k = 0 takes
//                           link_left_i from pipeline p-1's link_prev_o,
//                           k = p-1 takes link_right_i from pipeline 0's
//                           link_now_o (both for p = 1)
//   VoxelBits, WeightBits, GradientBits, GradientShift, SupersamplingBits
//                         - as cube4_gradient (defaults 12, 8, 8, 5, 4)
//   UserTagBits           - width of the user part of the tag
//   MaxDim                - largest nx and ny the delay storage holds
//   BeamDepth, SliceDepth - (derived) beam delay and slice delay entries:
//                           ceil(MaxDim/p) and MaxDim * that
//   CtrlBits, TagBits     - (derived) slice-control part and whole tag width
//   DimBits               - (derived) width of x_o, y_o
//   VoxelTagBits          - voxel tag width (Precision::tag_bits, 0: none)
//   HasVoxelZ             - VolumePro's z gradient (below)
//   LinkBits              - (derived) link width: five samples, [0] current
//                           row y, [1]/[2] ahead rows, [3]/[4] behind rows;
//                           with HasVoxelZ the current row's sample alone
//   VTagPortBits          - (derived) vtag_i/vtag_o width, at least one bit
`include "cube4_pkg.sv"

module cube4_gradient_unit #(
  parameter int unsigned  NumPipes          = cube4_pkg::NumPipes,
  parameter int unsigned  PipeIndex         = 0,
  parameter int unsigned  VoxelBits         = cube4_pkg::VoxelBits,
  parameter int unsigned  WeightBits        = cube4_pkg::WeightBits,
  parameter int unsigned  GradientBits      = cube4_pkg::GradientBits,
  parameter int unsigned  GradientShift     = cube4_pkg::GradientShift,
  parameter int unsigned  SupersamplingBits = cube4_pkg::SupersamplingBits,
  parameter int unsigned  UserTagBits       = 8,
  parameter int unsigned  MaxDim            = cube4_pkg::MaxDim,
  parameter int unsigned  VoxelTagBits      = cube4_pkg::VoxelTagBits,
  parameter bit           HasVoxelZ         = 1'b0,
  localparam int unsigned BeamDepth         = (MaxDim + NumPipes - 1) / NumPipes,
  localparam int unsigned SliceDepth        = MaxDim * BeamDepth,
  localparam int unsigned CtrlBits          = 4 * (WeightBits + 1) + SupersamplingBits + 2,
  localparam int unsigned TagBits           = CtrlBits + UserTagBits,
  localparam int unsigned DimBits           = $clog2(MaxDim + NumPipes),
  localparam int unsigned LinkBits          = HasVoxelZ ? VoxelBits : 5 * VoxelBits,
  localparam int unsigned VTagPortBits      = VoxelTagBits > 0 ? VoxelTagBits : 1
) (
  input  logic                           clk_i,
  input  logic                           rst_ni,
  // Sample stream (cube4_interp_ring's output of this pipeline).
  input  logic                           valid_i,
  input  logic                           beam_start_i,
  input  logic                           beam_end_i,
  input  logic                           slice_start_i,
  input  logic                           slice_end_i,
  input  logic [VoxelBits-1:0]           sample_i,
  input  logic [TagBits-1:0]             tag_i,
  input  logic [VTagPortBits-1:0]        vtag_i,
  input  logic [VoxelBits:0]             zdiff_i,   // HasVoxelZ: the sample's z difference
  // Near-neighbour links.
  output logic [LinkBits-1:0]            link_o,       // aligned column, to k-1 and k+1
  output logic [LinkBits-1:0]            link_now_o,   // this step's column (wrap, k = 0)
  output logic [LinkBits-1:0]            link_prev_o,  // previous column (wrap, k = p-1)
  input  logic [LinkBits-1:0]            link_left_i,  // x-1 column
  input  logic [LinkBits-1:0]            link_right_i, // x+1 column
  // Gradient stream.
  output logic                           valid_o,
  output logic                           beam_start_o,
  output logic                           beam_end_o,
  output logic                           slice_start_o,
  output logic                           slice_end_o,
  output logic [VoxelBits-1:0]           sample_o,
  output logic [VTagPortBits-1:0]        vtag_o,
  output logic signed [GradientBits-1:0] gx_o,
  output logic signed [GradientBits-1:0] gy_o,
  output logic signed [GradientBits-1:0] gz_o,
  output logic [DimBits-1:0]             x_o,
  output logic [DimBits-1:0]             y_o,
  output logic [UserTagBits-1:0]         tag_o
);

  localparam int unsigned V              = VoxelBits;
  localparam int unsigned W              = WeightBits;
  localparam int unsigned R              = WeightBits + 1;  // one realign field
  localparam int unsigned SBits          = SupersamplingBits;
  localparam int unsigned ZeroBit        = 4 * R + SBits;
  localparam int unsigned StartBit       = ZeroBit + 1;
  localparam bit          First          = PipeIndex == 0;
  localparam bit          Last           = PipeIndex == NumPipes - 1;
  // Latency of cube4_gradient (its header): the side data travels beside it.
  localparam int unsigned GradLatency    = 3;
  localparam int unsigned BeamBits       = $clog2(BeamDepth + 1);
  localparam int unsigned SliceDepthBits = $clog2(SliceDepth + 1);
  localparam int unsigned BeamDepthBits  = $clog2(BeamDepth + 1);

  // -------------------------------------------------------------------------
  // Steps: an accepted input sample, or a step of the unit's own zero beam.
  logic                 zb_active, step_in, step;
  logic [BeamBits-1:0]  zb_left_q, zb_left_d;   // zero-beam steps still to run
  logic [BeamBits-1:0]  j_q, j_d, j_step;       // partial beam of the step
  logic [DimBits-1:0]   y_q, y_d, y_step;       // beam of the step (ny: zero beam)
  logic [DimBits-1:0]   last_y_q;               // the last slice's last beam, ny-1
  logic                 s_beam_start, s_beam_end, slice_last, in_zero, in_start;
  logic                 first_q, first_d;       // no slice before the input slice
  logic                 open_q, open_d;         // a slice's last gradient beam is due
  logic                 drain;                  // this step computes it
  logic [TagBits-1:0]   tag_in_q;               // tag of the input slice (s+1)
  logic [TagBits-1:0]   tag_out_q;              // tag of the output slice (s)
  logic [TagBits-1:0]   tag_prev_q;             // the slice before (s-1): a draining beam's
  logic [TagBits-1:0]   ctl;                    // this step's output slice's tag

  assign zb_active    = zb_left_q != '0;
  assign step_in      = valid_i && !zb_active;
  assign step         = step_in || zb_active;
  assign in_zero      = tag_i[ZeroBit];
  assign in_start     = tag_i[StartBit];
  assign s_beam_start = zb_active ? (j_q == '0) : beam_start_i;
  assign s_beam_end   = zb_active ? (zb_left_q == BeamBits'(1)) : beam_end_i;
  assign slice_last   = step_in && slice_end_i && beam_end_i;
  assign j_step       = s_beam_start ? '0 : j_q;
  assign y_step       = (step_in && slice_start_i) ? '0 : y_q;
  assign drain        = step_in && slice_start_i && open_q;

  always_comb begin
    j_d       = j_q;
    y_d       = y_q;
    zb_left_d = zb_left_q;
    first_d   = first_q;
    open_d    = open_q;
    if (step) begin
      j_d = s_beam_end ? '0 : j_step + BeamBits'(1);
      y_d = s_beam_end ? y_step + DimBits'(1) : y_step;
    end
    if (drain && s_beam_end) begin
      open_d = 1'b0;
    end
    if (slice_last) begin
      // A slice that produced gradients leaves its last beam's due; the
      // zero slice's own zero beam computes it instead.
      if (in_zero) begin
        zb_left_d = j_step + BeamBits'(1);  // B: the zero beam as long as this beam
      end else begin
        open_d = !first_q;
      end
      first_d = 1'b0;
    end else if (zb_active) begin
      zb_left_d = zb_left_q - BeamBits'(1);
    end
    // The slice after a zero slice starts a stream again.
    if (zb_active && s_beam_end) begin
      first_d = 1'b1;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      zb_left_q <= '0;
      j_q       <= '0;
      y_q       <= '0;
      first_q   <= 1'b1;
      open_q    <= 1'b0;
    end else begin
      zb_left_q <= zb_left_d;
      j_q       <= j_d;
      y_q       <= y_d;
      first_q   <= first_d;
      open_q    <= open_d;
    end
  end

  // The output slice's control is the tag its samples arrived with, one
  // slice earlier: it moves on when the next slice's first sample arrives;
  // a draining beam's output slice is the one before (still tag_out_q in
  // the beam's first step).
  always_ff @(posedge clk_i) begin
    if (step_in) begin
      tag_in_q <= tag_i;
    end
    if (step_in && slice_start_i && beam_start_i) begin
      tag_out_q  <= tag_in_q;
      tag_prev_q <= tag_out_q;
    end
    if (slice_last) begin
      last_y_q <= y_step;
    end
  end
  assign ctl = (drain && !beam_start_i) ? tag_prev_q : tag_out_q;

  logic [W-1:0]     behind_wx, behind_wy, ahead_wx, ahead_wy;
  logic             behind_mx, behind_my, ahead_mx, ahead_my;  // base -1
  logic [SBits-1:0] supersampling;
  logic [TagBits-1:0] ctl_q;  // the fired column's (below)
  assign behind_my              = ctl[1*R + W];
  assign ahead_my               = ctl[3*R + W];
  assign {behind_mx, behind_wx} = ctl_q[0*R +: R];
  assign behind_wy              = ctl_q[1*R +: W];
  assign {ahead_mx, ahead_wx}   = ctl_q[2*R +: R];
  assign ahead_wy               = ctl_q[3*R +: W];
  assign supersampling          = ctl_q[4*R +: SBits];

  // -------------------------------------------------------------------------
  // Storage. A row is {behind, current, ahead} = slices {s-1, s, s+1} of one
  // column x and one beam: [0 +: V] ahead, [V +: V] current, [2V +: V] behind.
  // With HasVoxelZ only the current sample is kept (z needs no neighbour
  // slice): a row is that sample, and the slice delay holds the ahead
  // slice's samples alone, read one lap later as the current slice's.
  localparam int unsigned RowBits   = HasVoxelZ ? V : 3 * V;
  localparam int unsigned SliceBits = HasVoxelZ ? V : 2 * V;
  logic [V-1:0]         cur_new;
  logic [SliceBits-1:0] slice_rdata, slice_wdata;
  logic [RowBits-1:0]   row_new;             // this step's row, beam y+1
  logic [RowBits-1:0]   row0, row1, row2;    // beams y+1, y, y-1
  logic [2*RowBits-1:0] beam_rdata;          // {row2, row1}

  // The zero slice and the zero beam carry zeros. A frame's first slice is
  // the zero slice ahead of the previous frame's last: its samples go
  // into the slice delay (as the slice current next) with a zero slice
  // behind them, but the column sees zeros ahead. After a reset or a zero
  // slice the current samples are the (zero) slice behind slice 0.
  logic [V-1:0]         ahead_w;
  logic [RowBits-1:0]   row1_w;  // the row written above this step's (zero above beam 0)
  assign ahead_w = (zb_active || in_zero) ? '0 : sample_i;
  assign cur_new = (zb_active || first_q) ? '0 : slice_rdata[0 +: V];
  if (HasVoxelZ) begin : g_rows_z
    assign slice_wdata = ahead_w;
    assign row_new     = cur_new;
  end else begin : g_rows_abc
    logic [V-1:0] ahead_col, cur_w, behind_new;
    assign ahead_col   = in_start ? '0 : ahead_w;
    assign cur_w       = in_start ? '0 : cur_new;
    assign behind_new  = zb_active ? '0 : slice_rdata[V +: V];
    assign slice_wdata = {cur_w, ahead_w};
    assign row_new     = {behind_new, cur_new, ahead_col};
  end
  // A draining step's column has the zero border for beam y+1.
  assign row0   = drain ? '0 : row_new;
  assign row1_w = (step_in && y_step == '0) ? '0 : row1;

  // Slice delay: one entry per sample of beams 0 .. ny-1, one lap per slice
  // (ended by the slice's last sample). Writing {current, ahead} and reading
  // one lap later gives {behind, current}: two slice FIFOs in one RAM.
  cube4_delay_ram #(
    .Width   (SliceBits),
    .MaxDepth(SliceDepth)
  ) u_slice_delay (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .depth_i  (SliceDepthBits'(SliceDepth)),
    .clear_i  (1'b0),
    .advance_i(step_in),
    .last_i   (slice_end_i && beam_end_i),
    .write_i  (1'b1),
    .wdata_i  (slice_wdata),
    .rdata_o  (slice_rdata)
  );

  // Beam delay: one lap per beam (zero beam included). Writing
  // {row1, row0} and reading one lap later gives {row2, row1}: two beam
  // FIFOs in one RAM. Beam 0 is written with a zero row above it, and a
  // draining step writes beam 0's own row, not its column's zero border.
  cube4_delay_ram #(
    .Width   (2 * RowBits),
    .MaxDepth(BeamDepth)
  ) u_beam_delay (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .depth_i  (BeamDepthBits'(BeamDepth)),
    .clear_i  (1'b0),
    .advance_i(step),
    .last_i   (s_beam_end),
    .write_i  (1'b1),
    .wdata_i  ({row1_w, drain ? row_new : row0}),
    .rdata_o  (beam_rdata)
  );
  assign row1 = beam_rdata[0 +: RowBits];
  assign row2 = beam_rdata[RowBits +: RowBits];

  // This step's column for output beam y: the current sample of rows
  // y-1, y, y+1 and the ahead and behind row pairs of the re-aligned
  // position (rows y+base, y+base+1).
  localparam int unsigned ColBits = LinkBits + 2 * V;
  logic [V-1:0]          c_up, c_mid, c_down;
  logic [LinkBits-1:0]   link_d;
  logic [ColBits-1:0]    col_d;

  if (HasVoxelZ) begin : g_col_z
    assign c_up   = row2;
    assign c_mid  = row1;
    assign c_down = row0;
    assign link_d = c_mid;
    // Waiver: the re-alignment's bases and a frame's start (zeros ahead,
    // none behind) serve the 12-neighbourhood's ahead and behind rows only.
    logic unused_abc_ctl;
    assign unused_abc_ctl = ^{ahead_my, behind_my, ahead_mx, behind_mx, in_start};
  end else begin : g_col_abc
    logic [V-1:0] a0, a1, b0, b1;
    assign c_up   = row2[V +: V];
    assign c_mid  = row1[V +: V];
    assign c_down = row0[V +: V];
    assign a0     = ahead_my  ? row2[0 +: V]   : row1[0 +: V];
    assign a1     = ahead_my  ? row1[0 +: V]   : row0[0 +: V];
    assign b0     = behind_my ? row2[2*V +: V] : row1[2*V +: V];
    assign b1     = behind_my ? row1[2*V +: V] : row0[2*V +: V];
    assign link_d = {b1, b0, a1, a0, c_mid};
  end
  assign col_d  = {c_down, c_up, link_d};
  assign link_now_o = link_d;

  // -------------------------------------------------------------------------
  // Alignment register: holds the column until its x+1 neighbour is
  // available (the next step), or one cycle if it ends a beam (x+1 = B*p).
  logic                  valid_q, valid_d, fire;
  logic [ColBits-1:0]    col_q;
  logic                  beam_start_q, beam_end_q, slice_start_q, slice_end_q, out_q;
  logic [BeamBits-1:0]   j_col_q;
  logic [DimBits-1:0]    y_col_q;

  assign fire    = valid_q && (step || beam_end_q);
  assign valid_d = step || (valid_q && !fire);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= 1'b0;
    end else begin
      valid_q <= valid_d;
    end
  end

  always_ff @(posedge clk_i) begin
    if (step) begin
      col_q         <= col_d;
      beam_start_q  <= s_beam_start;
      beam_end_q    <= s_beam_end;
      slice_start_q <= drain ? last_y_q == '0 : y_step == DimBits'(1);
      slice_end_q   <= zb_active || drain;
      // Beam 0 of a slice (unless it drains the last slice's last beam) and
      // a slice with none before it: no gradients.
      out_q         <= drain || (!first_q && (y_step != '0));
      j_col_q       <= j_step;
      y_col_q       <= drain ? last_y_q : y_step - DimBits'(1);
      ctl_q         <= ctl;
    end
  end
  assign link_o = col_q[0 +: LinkBits];

  // Pipeline p-1 keeps the column it fired last: pipeline 0's x-1 column.
  if (Last) begin : g_prev
    logic [LinkBits-1:0] prev_q;
    always_ff @(posedge clk_i) begin
      if (fire) begin
        prev_q <= col_q[0 +: LinkBits];
      end
    end
    assign link_prev_o = prev_q;
  end else begin : g_no_prev
    assign link_prev_o = '0;
  end

  // The centre's side data held with its column (below), and its z
  // difference for cube4_gradient.
  localparam int unsigned CentreBits = VoxelTagBits + (HasVoxelZ ? VoxelBits + 1 : 0);
  localparam int unsigned CentrePortBits = CentreBits > 0 ? CentreBits : 1;
  logic [CentrePortBits-1:0] col_side_q;
  logic [V:0]                col_zdiff;

  // -------------------------------------------------------------------------
  // The 12-neighbourhood: own column (x), left (x-1), right (x+1).
  logic [LinkBits-1:0]  own, left, right;
  logic [4*V-1:0]       ahead_nb, behind_nb;
  logic                 grad_valid;

  assign own   = col_q[0 +: LinkBits];
  assign left  = (First && beam_start_q) ? '0 : link_left_i;
  assign right = (Last && beam_end_q) ? '0 : link_right_i;

  // 2x2 packed [0] (base, base), [1] x+1, [2] y+1, [3] both; the x pair is
  // (x, x+1) for base 0 and (x-1, x) for base -1.
  if (HasVoxelZ) begin : g_nb_z
    assign ahead_nb  = '0;
    assign behind_nb = '0;
  end else begin : g_nb_abc
    assign ahead_nb  = ahead_mx
        ? {own[2*V +: V], left[2*V +: V], own[V +: V], left[V +: V]}
        : {right[2*V +: V], own[2*V +: V], right[V +: V], own[V +: V]};
    assign behind_nb = behind_mx
        ? {own[4*V +: V], left[4*V +: V], own[3*V +: V], left[3*V +: V]}
        : {right[4*V +: V], own[4*V +: V], right[3*V +: V], own[3*V +: V]};
  end
  assign grad_valid = fire && out_q;

  cube4_gradient #(
    .VoxelBits        (VoxelBits),
    .WeightBits       (WeightBits),
    .GradientBits     (GradientBits),
    .GradientShift    (GradientShift),
    .SupersamplingBits(SupersamplingBits),
    .HasVoxelZ        (HasVoxelZ)
  ) u_gradient (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    .valid_i        (grad_valid),
    .left_i         (left[0 +: V]),
    .right_i        (right[0 +: V]),
    .up_i           (col_q[LinkBits +: V]),
    .down_i         (col_q[LinkBits + V +: V]),
    .behind_i       (behind_nb),
    .ahead_i        (ahead_nb),
    .behind_wx_i    ({1'b0, behind_wx}),
    .behind_wy_i    ({1'b0, behind_wy}),
    .ahead_wx_i     ({1'b0, ahead_wx}),
    .ahead_wy_i     ({1'b0, ahead_wy}),
    .supersampling_i(supersampling),
    .lateral_recip_i('0),  // parallel projection: the ring carries no perspective yet
    .zdiff_i        (col_zdiff),
    .valid_o        (valid_o),
    .gx_o           (gx_o),
    .gy_o           (gy_o),
    .gz_o           (gz_o)
  );

  // Sample, position, flags and tag beside cube4_gradient (data: not reset).
  localparam int unsigned SideBits = V + 2 * DimBits + 4 + UserTagBits;
  logic [DimBits-1:0] x_fire;

  assign x_fire = DimBits'(j_col_q) * DimBits'(NumPipes) + DimBits'(PipeIndex);

  cube4_pipe_delay #(.Width(SideBits), .Depth(GradLatency)) u_side_delay (
    .clk_i,
    .d_i ({ctl_q[CtrlBits +: UserTagBits], y_col_q, x_fire, own[0 +: V],
           slice_end_q, slice_start_q, beam_end_q, beam_start_q}),
    .q_o ({tag_o, y_o, x_o, sample_o, slice_end_o, slice_start_o, beam_end_o, beam_start_o})
  );

  // -------------------------------------------------------------------------
  // The centre sample's side data: its voxel tag and (HasVoxelZ) its
  // interpolated z difference take the centre's way through the slice and
  // beam delays (same control), then are held with its column; the tag is
  // delayed beside cube4_gradient, the difference goes into it.
  if (CentreBits > 0) begin : g_centre
    localparam int unsigned C = CentreBits;
    logic [C-1:0] ahead_side, centre_in, slice_side_rdata, cur_side, mid_side;

    if (VoxelTagBits > 0 && HasVoxelZ) begin : g_both
      assign centre_in = {zdiff_i, vtag_i};
    end else if (HasVoxelZ) begin : g_z
      logic unused_vtag;
      assign unused_vtag = ^vtag_i;
      assign centre_in   = zdiff_i;
    end else begin : g_tag
      logic unused_zdiff;
      assign unused_zdiff = ^zdiff_i;
      assign centre_in    = vtag_i;
    end
    assign ahead_side = (zb_active || in_zero) ? '0 : centre_in;
    assign cur_side   = (zb_active || first_q) ? '0 : slice_side_rdata;

    cube4_delay_ram #(
      .Width   (C),
      .MaxDepth(SliceDepth)
    ) u_slice_side_delay (
      .clk_i    (clk_i),
      .rst_ni   (rst_ni),
      .depth_i  (SliceDepthBits'(SliceDepth)),
      .clear_i  (1'b0),
      .advance_i(step_in),
      .last_i   (slice_end_i && beam_end_i),
      .write_i  (1'b1),
      .wdata_i  (ahead_side),
      .rdata_o  (slice_side_rdata)
    );

    // Beam y+1's current side data in, beam y's (the centre row's) out.
    cube4_delay_ram #(
      .Width   (C),
      .MaxDepth(BeamDepth)
    ) u_beam_side_delay (
      .clk_i    (clk_i),
      .rst_ni   (rst_ni),
      .depth_i  (BeamDepthBits'(BeamDepth)),
      .clear_i  (1'b0),
      .advance_i(step),
      .last_i   (s_beam_end),
      .write_i  (1'b1),
      .wdata_i  (cur_side),
      .rdata_o  (mid_side)
    );

    always_ff @(posedge clk_i) begin
      if (step) begin
        col_side_q <= mid_side;
      end
    end
  end else begin : g_no_centre
    logic unused_centre;
    assign unused_centre = ^{vtag_i, zdiff_i, col_side_q};
    assign col_side_q    = '0;
  end

  if (VoxelTagBits > 0) begin : g_vtag
    localparam int unsigned T = VoxelTagBits;
    logic [GradLatency*T-1:0] vtag_q;
    always_ff @(posedge clk_i) begin
      vtag_q <= {vtag_q[(GradLatency-1)*T-1:0], col_side_q[0 +: T]};
    end
    assign vtag_o = vtag_q[GradLatency*T-1 -: T];
  end else begin : g_no_vtag
    assign vtag_o = '0;
  end
  if (HasVoxelZ) begin : g_col_zdiff
    assign col_zdiff = col_side_q[CentreBits-1 -: V+1];
  end else begin : g_no_col_zdiff
    assign col_zdiff = '0;
  end

  // The output slice's ZeroSlice and FrameStart bits and the weights' base
  // bits for y are used where the step forms its column, not at firing.
  logic unused_ctl;
  assign unused_ctl = ^{ctl_q[ZeroBit], ctl_q[StartBit], ctl_q[1*R + W], ctl_q[3*R + W]};

endmodule
