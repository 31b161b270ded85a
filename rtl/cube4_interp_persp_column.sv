// cube4_interp_persp_column: one pipeline's column stage of the perspective
// interpolation unit (Cube-4 §3; docs/perspective.md, "The dataflow";
// docs/rtl-interp-persp.md). For every voxel of the stream it weighs its
// own column's four window rows with the beam's y overlaps, for both voxel
// slices of the sample slice; a ray's home then takes four such column
// sums (its own and its neighbours') for the row stage.
//
// Function: in the step of column x of beam b of a pass (b = 0 .. ny-1, and
// the drain beams below), with the window rows r = b-3 .. b (cell row
// Y = b - 2, its box's rows Y-1 .. Y+2):
//   col_front_o = golden box_taps(v(x, b-3 .. b, z_voxel),     window oy)
//   col_back_o  = golden box_taps(v(x, b-3 .. b, z_voxel + 1), window oy)
// with rows outside 0 .. ny-1 of the pass reading zero. The window oy are
// the y box's overlaps in window order: (o0, o1, o2, o3) when the box starts
// at Y-1 (oy_left_i), else (0, o0, o1, o2), its fourth overlap being zero
// then (docs/perspective.md: the box ends by home + 2).
//
// Passes back to back: a pass's last two cell rows (Y = ny-2, ny-1) need
// rows ny and ny+1, the zero border, so they are formed in the two beams
// after the pass: the next pass's beams 0 and 1, whose own cells start at
// beam 2 (Y = 0), or flush beams at the stream's end. In those drain beams
// the unit gives the finished pass's column sums: its rows still in the
// row delay, and zero for the rows past it (the new pass's rows, which the
// delay takes meanwhile). The beam's oy_i are then the finished pass's
// (the weight generator's business, not this unit's).
//
// Where the rows come from: the current row from the stream (voxel slice
// z_voxel + 1 in a pass with wz > 0, z_voxel when wz = 0) and the slice
// store (z_voxel, written in the wz = 0 pass, as cube4_interp_unit's), rows
// b-1 .. b-3 from the row delay: one entry per partial beam holding three
// rows of (front, back) pairs, shifted by a row each lap.
//
// Stream format (valid_i cycles, any number of idle cycles between them):
// cube4_interp_unit's (docs/rtl-interp.md), with the flush beams two:
//   beam_start_i / beam_end_i  : first / last partial beam of a beam
//   slice_start_i / slice_end_i: beam 0 / beam ny-1 of a pass
//   flush_i                    : a beam of no voxels after the stream's
//                                last pass (two of them drain it)
//   wz_i                       : the sample slice's z weight (only whether
//                                it is zero matters here)
// Output: valid_o one cycle after each valid_i, with that step's sums.
//
// Preconditions: ny >= 2 (the drain must fit into the next pass's first two
// beams); every pass is complete, with the same ceil(nx/p) <= BeamDepth
// partial beams per beam; ny * ceil(nx/p) <= SliceDepth; the stream
// carries z_voxel whenever wz = 0, which every voxel slice pair starts with.
// Reset: control (valid, the drain count); data registers and RAMs are not
// reset.
//
// Voxel tags (bela §III; VoxelTagBits > 0): voxel_i is the memory word
// {tag, value}, kept whole in the store and the row delay, so a tag moves as
// its value does. col_tag_o is the tag of the column's voxel nearest the
// cell's sample along y and z: window row 1 + y_near_i (the sample's row
// weight at least half: row Y+1, else Y) of voxel slice z_voxel + z_upper_i
// (its z weight at least half; golden upper_corner()), zero where that row
// lies outside the pass, as golden's tag_at() outside the volume. Both
// inputs belong to the cell's pass, as oy_i does. Without tags col_tag_o is
// 0 and none of it is built.
//
// VolumePro's z gradient (HasZDiff = 1; docs/perspective.md, "Gradient"):
// the column also weighs the voxel z differences of its window rows,
//   col_dlo_o = golden box_taps(D(x, b-3 .. b, z_voxel),     window oy)
//   col_dhi_o = golden box_taps(D(x, b-3 .. b, z_voxel + 1), window oy)
// with D(z) = V(z+1) - V(z-1) (signed, V+1 bits; golden
// voxel_z_difference()), the second home stage's inputs. The stream then
// reads one voxel slice ahead after a priming pass (prime_i), as
// cube4_interp_unit's: the slice store entry holds {z-1 value, z word,
// z+1 word}, a pass with wz = 0 (and the priming pass) streams z+1 and
// shifts the entry down by a slice, the others stream z+2; the row delay
// carries the outer values (z-1, z+2) beside each pair. With wz = 0 the
// upper differences are weighted zero, so z+2 reads zero there. Without
// HasZDiff prime_i is ignored, the difference sums are zero and none of it
// is built.
//
// Widths (V = VoxelBits, W = WeightBits): a column sum is V+W+2 bits
// (cube4_box_taps), a difference sum V+W+3 (two's complement).
//
// Parameters:
//   VoxelBits, WeightBits - as cube4_box_taps (Precision defaults 12, 8)
//   VoxelTagBits          - voxel tag width (0: none)
//   WordBits, TagPortBits - (derived) voxel word and col_tag_o widths
//   BeamDepth             - row delay entries: max partial beams per beam
//   SliceDepth            - slice store entries: max ny * partial beams
//   HasZDiff              - VolumePro's z gradient: the difference sums
`include "cube4_pkg.sv"

module cube4_interp_persp_column #(
  parameter int unsigned  VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned  WeightBits = cube4_pkg::WeightBits,
  parameter int unsigned  BeamDepth  = 64,
  parameter int unsigned  SliceDepth = 16384,
  parameter int unsigned  VoxelTagBits = 0,
  parameter bit           HasZDiff   = 1'b0,
  localparam int unsigned ColBits    = VoxelBits + WeightBits + 2,
  localparam int unsigned DColBits   = VoxelBits + WeightBits + 3,
  localparam int unsigned WordBits   = VoxelBits + VoxelTagBits,
  localparam int unsigned TagPortBits = VoxelTagBits > 0 ? VoxelTagBits : 1
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  // Voxel stream.
  input  logic                          valid_i,
  input  logic                          beam_start_i,
  input  logic                          beam_end_i,
  input  logic                          slice_start_i,
  input  logic                          slice_end_i,
  input  logic                          flush_i,
  input  logic                          prime_i,   // HasZDiff: a frame's priming pass
  input  logic [WordBits-1:0]           voxel_i,
  input  logic [WeightBits:0]           wz_i,
  // The beam's y box (cube4_persp_lanes along y).
  input  logic [4*(WeightBits+1)-1:0]   oy_i,
  input  logic                          oy_left_i,
  // The cell's nearest voxel along y and z (tags only).
  input  logic                          y_near_i,
  input  logic                          z_upper_i,
  // Column sums.
  output logic                          valid_o,
  output logic [ColBits-1:0]            col_front_o,
  output logic [ColBits-1:0]            col_back_o,
  output logic [TagPortBits-1:0]        col_tag_o,
  output logic [DColBits-1:0]           col_dlo_o,  // HasZDiff, else 0
  output logic [DColBits-1:0]           col_dhi_o,
  // The step's place in the stream, for the ring's control (combinational):
  // its beam drains the finished pass, and the beam of its pass (0, 1, 2,
  // then 3 for any later beam).
  output logic                          draining_o,
  output logic [1:0]                    beam_o
);

  localparam int unsigned V              = WordBits;  // storage holds whole words
  localparam int unsigned VB             = VoxelBits;
  localparam int unsigned BeamDepthBits  = $clog2(BeamDepth + 1);

  // -------------------------------------------------------------------------
  // The current row's pair (front = z_voxel, back = z_voxel + 1), and with
  // HasZDiff the outer values (below = z_voxel - 1, above = z_voxel + 2).
  localparam int unsigned StoreBits = HasZDiff ? 2 * V + VB : V;
  localparam int unsigned RowBits   = HasZDiff ? 2 * V + 2 * VB : 2 * V;
  logic                 on_slice, pass_last;
  logic [V-1:0]         vox, front_cur, back_cur;
  logic [VB-1:0]        below_cur, above_cur;
  logic [StoreBits-1:0] store_rdata, store_wdata;
  assign on_slice  = wz_i == '0;
  assign pass_last = slice_end_i && beam_end_i && !flush_i;
  assign vox       = flush_i ? '0 : voxel_i;

  if (HasZDiff) begin : g_zdiff_in
    // A wz = 0 pass streams z+1 and finds the entry a slice behind,
    // {z-2, z-1, z}; it writes it shifted, {z-1, z, z+1}. The priming pass
    // streams slice 0 and writes zero as slice "z", which the frame's first
    // pass reads as slice -1.
    logic [V-1:0]  st_next, st_cur;
    logic [VB-1:0] st_prev;
    assign {st_prev, st_cur, st_next} = store_rdata;
    assign front_cur   = flush_i ? '0 : on_slice ? st_next : st_cur;
    assign back_cur    = flush_i ? '0 : on_slice ? vox : st_next;
    assign below_cur   = flush_i ? '0 : on_slice ? st_cur[0 +: VB] : st_prev;
    assign above_cur   = (flush_i || on_slice) ? '0 : vox[0 +: VB];
    assign store_wdata = {st_cur[0 +: VB], prime_i ? '0 : st_next, voxel_i};
  end else begin : g_plain_in
    assign front_cur   = (on_slice || flush_i) ? vox : store_rdata;
    assign back_cur    = vox;
    assign below_cur   = '0;
    assign above_cur   = '0;
    assign store_wdata = voxel_i;
    logic unused_prime;
    assign unused_prime = prime_i;
  end

  cube4_slice_store #(
    .Width     (StoreBits),
    .SliceDepth(SliceDepth)
  ) u_slice_store (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .valid_i    (valid_i),
    .flush_i    (flush_i),
    .pass_last_i(pass_last),
    .on_slice_i (on_slice),
    .wdata_i    (store_wdata),
    .rdata_o    (store_rdata)
  );

  // Row delay: entry {row b-1, row b-2, row b-3} of this column (b-3 in
  // the low bits), each row {back, front}, with HasZDiff {above, below,
  // back, front}; a step reads it and writes {b, b-1, b-2}.
  logic [RowBits-1:0]   row_cur;
  logic [3*RowBits-1:0] rows_rdata, rows_wdata;
  if (HasZDiff) begin : g_zdiff_row
    assign row_cur = {above_cur, below_cur, back_cur, front_cur};
  end else begin : g_plain_row
    assign row_cur = {back_cur, front_cur};
    logic unused_outer;
    assign unused_outer = ^{below_cur, above_cur};
  end
  assign rows_wdata = {row_cur, rows_rdata[RowBits +: 2*RowBits]};
  cube4_delay_ram #(
    .Width   (3 * RowBits),
    .MaxDepth(BeamDepth)
  ) u_row_delay (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .depth_i  (BeamDepthBits'(BeamDepth)),
    .clear_i  (1'b0),
    .advance_i(valid_i),
    .last_i   (beam_end_i),
    .write_i  (1'b1),
    .wdata_i  (rows_wdata),
    .rdata_o  (rows_rdata)
  );

  // -------------------------------------------------------------------------
  // Which window rows belong to the cell's pass. depth d = 0 is the current
  // row b, d = 1 .. 3 the delayed rows b-1 .. b-3.
  //   - a drain beam (the first or second after a pass's last beam; drain_q
  //     counts the beams still owed): only the finished pass's rows, those
  //     deeper than the drain beams so far (depth > 0 in the first, > 1 in
  //     the second) and not above its row 0 (in the first drain beam of a
  //     pass of two beams, depth 3 is the pass before's);
  //   - beam b < 3 of a pass: rows 0 .. b, depth <= b;
  //   - later beams: all four.
  logic [1:0] drain_q, drain_d;  // drain beams still owed
  logic [1:0] beam_q, beam_d;    // beam of the pass, saturating at 3
  logic [3:0] keep;              // bit d: window row at depth d is inside
  logic       draining;
  logic       short_q;  // the finished pass had two beams
  assign draining = drain_q != 2'd0;

  always_comb begin
    if (draining) begin
      // drain_q = 2: the first drain beam, keep depths 1..3; 1: depths 2..3.
      keep = (drain_q == 2'd1) ? 4'b1100 : short_q ? 4'b0110 : 4'b1110;
    end else begin
      unique case (beam_d)
        2'd0:    keep = 4'b0001;
        2'd1:    keep = 4'b0011;
        2'd2:    keep = 4'b0111;
        default: keep = 4'b1111;
      endcase
    end
  end

  // The pass's beam count: this step's beam (0 at a pass's first beam).
  always_comb begin
    beam_d = beam_q;
    if (slice_start_i && beam_start_i) beam_d = 2'd0;
    else if (beam_start_i && beam_q != 2'd3) beam_d = beam_q + 2'd1;
  end

  always_comb begin
    drain_d = drain_q;
    if (valid_i && beam_end_i) begin
      if (pass_last) drain_d = 2'd2;
      else if (draining) drain_d = drain_q - 2'd1;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      drain_q <= 2'd0;
    end else begin
      drain_q <= drain_d;
    end
  end

  always_ff @(posedge clk_i) begin
    if (valid_i && !flush_i) beam_q <= beam_d;
    if (valid_i && pass_last) short_q <= beam_d == 2'd1;
  end

  // -------------------------------------------------------------------------
  // The window's four rows of each slice, row r = b-3+j at j (depth 3-j),
  // zero where not kept; the box weighs them from row 1 when it starts at
  // the home row (cube4_box_taps' shift_i).
  logic [4*V-1:0]  win_front_w, win_back_w;  // words
  logic [4*VB-1:0] win_front, win_back;      // values
  logic [4*RowBits-1:0] win_rows;            // the kept rows, whole
  for (genvar j = 0; j < 4; j++) begin : g_window
    logic [RowBits-1:0] row;
    if (j == 3) begin : g_current
      assign row = row_cur;
    end else begin : g_delayed
      assign row = rows_rdata[j*RowBits +: RowBits];
    end
    assign win_rows[j*RowBits +: RowBits] = keep[3-j] ? row : '0;
    assign win_front_w[j*V +: V] = win_rows[j*RowBits +: V];
    assign win_back_w[j*V +: V]  = win_rows[j*RowBits + V +: V];
    assign win_front[j*VB +: VB] = win_front_w[j*V +: VB];
    assign win_back[j*VB +: VB]  = win_back_w[j*V +: VB];
  end

  // VolumePro's z differences of the window rows: D(z) = back - below,
  // D(z+1) = above - front (values, V+1 bits two's complement).
  localparam int unsigned DB = VB + 1;
  logic [DColBits-1:0] dlo_d, dhi_d, dlo_q, dhi_q;
  if (HasZDiff) begin : g_zdiff_sums
    logic [4*DB-1:0] win_dlo, win_dhi;
    for (genvar j = 0; j < 4; j++) begin : g_diff
      logic [VB-1:0] below, above;
      assign below = win_rows[j*RowBits + 2*V +: VB];
      assign above = win_rows[j*RowBits + 2*V + VB +: VB];
      assign win_dlo[j*DB +: DB] = {1'b0, win_back[j*VB +: VB]} - {1'b0, below};
      assign win_dhi[j*DB +: DB] = {1'b0, above} - {1'b0, win_front[j*VB +: VB]};
    end
    cube4_box_taps #(
      .DataBits  (DB),
      .WeightBits(WeightBits),
      .Signed    (1'b1)
    ) u_dlo (
      .data_i   (win_dlo),
      .overlap_i(oy_i),
      .shift_i  (!oy_left_i),
      .sum_o    (dlo_d)
    );
    cube4_box_taps #(
      .DataBits  (DB),
      .WeightBits(WeightBits),
      .Signed    (1'b1)
    ) u_dhi (
      .data_i   (win_dhi),
      .overlap_i(oy_i),
      .shift_i  (!oy_left_i),
      .sum_o    (dhi_d)
    );
  end else begin : g_no_diff
    assign dlo_d = '0;
    assign dhi_d = '0;
  end

  // The tag of the cell's nearest voxel of the column: window row 1 or 2.
  logic [TagPortBits-1:0] tag_d, tag_q;
  if (VoxelTagBits > 0) begin : g_tag
    assign tag_d = z_upper_i ? (y_near_i ? win_back_w[2*V+VB +: VoxelTagBits] : win_back_w[V+VB +: VoxelTagBits])
                             : (y_near_i ? win_front_w[2*V+VB +: VoxelTagBits] : win_front_w[V+VB +: VoxelTagBits]);
    // Window rows 0 and 3 are never the nearest (the sample lies in row 1).
    logic unused_far_tags;
    assign unused_far_tags = ^{win_front_w[VB +: VoxelTagBits], win_front_w[3*V+VB +: VoxelTagBits],
                               win_back_w[VB +: VoxelTagBits], win_back_w[3*V+VB +: VoxelTagBits]};
  end else begin : g_no_tag
    logic unused_tag;
    assign unused_tag = ^{y_near_i, z_upper_i, win_front_w, win_back_w};
    assign tag_d = '0;
  end
  logic [ColBits-1:0] front_d, back_d, front_q, back_q;
  cube4_box_taps #(
    .DataBits  (VB),
    .WeightBits(WeightBits)
  ) u_front (
    .data_i   (win_front),
    .overlap_i(oy_i),
    .shift_i  (!oy_left_i),
    .sum_o    (front_d)
  );
  cube4_box_taps #(
    .DataBits  (VB),
    .WeightBits(WeightBits)
  ) u_back (
    .data_i   (win_back),
    .overlap_i(oy_i),
    .shift_i  (!oy_left_i),
    .sum_o    (back_d)
  );

  logic valid_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= 1'b0;
    end else begin
      valid_q <= valid_i;
    end
  end
  always_ff @(posedge clk_i) begin
    if (valid_i) begin
      front_q <= front_d;
      back_q  <= back_d;
      dlo_q   <= dlo_d;
      dhi_q   <= dhi_d;
      tag_q   <= tag_d;
    end
  end
  assign draining_o  = draining;
  assign beam_o      = beam_d;
  assign valid_o     = valid_q;
  assign col_front_o = front_q;
  assign col_back_o  = back_q;
  assign col_tag_o   = tag_q;
  assign col_dlo_o   = dlo_q;
  assign col_dhi_o   = dhi_q;

endmodule
