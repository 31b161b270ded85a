// cube4_interp_unit: one pipeline's interpolation unit with its delay
// storage and near-neighbour links (VolumePro §3.1, §5.1; Cube-4 §5, partial
// beams and beam extension). docs/rtl-interp.md describes the dataflow.
//
// Function: pipeline k of p receives, for every sample slice k_s, the voxel
// slice the sample slice needs last, in beam order (beams y = 0 .. ny-1),
// one partial beam j per valid cycle: voxel_i is v(x, y, z_in) with
// x = j*p + k, z_in = z_voxel(k_s) if wz_i = 0 (the sample slice lies on
// that voxel slice) and z_voxel(k_s) + 1 otherwise. The unit emits, for
// every voxel (x, y+1) of beams 1 .. ny-1, the sample S(x, y) of slice k_s:
// bit-exact golden trilinear() (cube4_interp) of
//   v(x .. x+1, y .. y+1, z_voxel .. z_voxel+1), zero outside the volume,
// and the pass's last sample beam S(x, ny-1) (whose y+1 voxels are the
// zero border) in the beam after the pass: the next pass's beam 0, which
// gives no sample of its own, or a flush beam (flush_i), which carries no
// voxels. So passes follow back to back at ny beams each, and a stream
// ends with one flush beam (docs/rtl-interp.md, "Passes back to back").
// The voxels come from:
//   - the slice store: voxel slice z_voxel, written from the stream in the
//     slice's wz = 0 pass, read in its wz > 0 passes (ny * ceil(nx/p) entries);
//   - the beam delay: this pipeline's (front, back) voxel pair of beam y, one
//     lap of ceil(nx/p) steps (the lap ends at beam_end_i);
//   - the stream itself: beam y+1 of slice z_in;
//   - the right neighbour (pipeline k+1) for the x+1 column: its registered
//     link_o; or, for pipeline p-1 (WrapIn = 1), pipeline 0's link_now_o, the
//     next partial beam's column (the ring wrap), which is why every pipeline
//     holds its own column one valid cycle (the alignment register: Cube-4's
//     beam extension). x+1 = nx (after the last partial beam of a beam) reads
//     zero instead.
//
// Stream format (valid_i cycles, any number of idle cycles between them):
//   beam_start_i / beam_end_i  : first / last partial beam of a beam
//   slice_start_i / slice_end_i: beam 0 / beam ny-1 of a pass
//   flush_i                    : a beam of no voxels (voxel_i, weights and
//                                tag ignored) after a pass: it emits the
//                                pass's last sample beam; after nothing
//                                (reset or another flush) it emits nothing
//   wx_i, wy_i, wz_i            : the sample slice's weights (golden
//                                 slice_control()), constant over a pass
//   tag_i                       : travels to tag_o with the sample (the weight
//                                 generator's per-slice control for later units)
// Output: valid_o with sample_o = S(x, y) in beam order (beams 0 .. ny-1 of
// each pass), flags beam_start_o / beam_end_o (j = 0 / last), slice_start_o /
// slice_end_o (y = 0 / ny - 1) and the tag of the pass that produced it.
//
// Latency: the sample of input step t (voxel (x, y+1), or the step of the
// following beam that emits row ny-1) leaves the alignment register in the
// next valid cycle t' (or at t + 1 if t ends a beam: it needs no next
// column), enters cube4_interp then, and appears on sample_o 3 cycles
// later: t + 4 without stalls. One sample per clock.
// Handshake: valid-only, no back-pressure. Reset: control (valid, alignment,
// open-pass and slice-start state, delay pointers); data registers and RAMs
// are not reset.
//
// VolumePro's z gradient (HasZDiff = 1; VolumePro §3.2, §5.3): beside each
// sample the unit emits zdiff_o, golden interpolated_z_difference() of the
// sample's eight voxel z differences d = V(z+1) - V(z-1) (lower corners) and
// V(z+2) - V(z) (upper corners), with the sample's weights (cube4_interp_zdiff).
// The stream then reads one voxel slice ahead: a pass streams z_voxel + 1
// when wz = 0 and z_voxel + 2 otherwise, and every frame starts with a
// priming pass (prime_i: voxel slice 0, wz = 0, no samples). The slice
// store holds three voxel slices {z-1 (values), z, z+1}; a wz = 0 pass (and
// the priming pass) shifts them down by one slice as it reads them, taking
// the stream as the new z+1 (the priming pass takes zero as the new z, so
// slice -1 reads zero). The beam delay and the links carry the outer
// voxels (z-1 and z+2, values only) beside the sample's. A pass with wz = 0
// needs no z+2: its upper corners are weighted zero exactly. Without
// HasZDiff prime_i is ignored, zdiff_o is zero and none of it is built
// (docs/rtl-interp-zdiff.md, "In the ring").
//
// Preconditions: every pass is complete (ny >= 1 beams of the same
// ceil(nx/p) partial beams, and a flush beam has the pass's length);
// ceil(nx/p) <= BeamDepth; ny * ceil(nx/p) <= SliceDepth; the stream carries
// z_voxel whenever wz = 0 (and z_voxel + 1 otherwise; with HasZDiff one
// slice more, after the frame's priming pass): golden z_weight(k) = 0 for
// k mod S = 0, so every voxel slice pair starts with such a pass, which
// fills the store.
//
// Parameters:
//   VoxelBits, WeightBits - as cube4_interp (Precision defaults 12, 8)
//   TagBits               - width of the stream-control tag that travels
//                           with the data (not the voxel tags)
//   VoxelTagBits          - voxel tag width (bela §III; 0: none): voxel_i is
//                           the memory word {tag, value}, stored and linked
//                           whole; vtag_o is each sample's nearest voxel's
//                           tag (cube4_interp), 0 without tags
//   BeamDepth             - beam delay entries: max partial beams per beam
//   SliceDepth            - slice store entries: max ny * partial beams
//   WrapIn                - 1 for pipeline p-1: link_i is pipeline 0's
//                           link_now_o (masked to zero at a beam's end)
//   HasZDiff              - VolumePro's z gradient: zdiff_o, the stream read
//                           one slice ahead, a priming pass (above)
//   WordBits              - (derived) voxel word width, VoxelBits + VoxelTagBits
//   VTagPortBits          - (derived) vtag_o width, at least one bit
//   LinkBits              - (derived) width of a link: four voxel words,
//                           [0] front y, [1] front y+1, [2] back y, [3] back y+1;
//                           with HasZDiff four values above them, [4] below y,
//                           [5] below y+1, [6] above y, [7] above y+1
//   StoreBits             - (derived) slice store entry: a word, or with
//                           HasZDiff {z-1 value, z word, z+1 word}
`include "cube4_pkg.sv"

module cube4_interp_unit #(
  parameter int unsigned  VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned  WeightBits = cube4_pkg::WeightBits,
  parameter int unsigned  TagBits    = 8,
  parameter int unsigned  BeamDepth  = 64,
  parameter int unsigned  SliceDepth = 16384,
  parameter bit           WrapIn     = 1'b0,
  parameter int unsigned  VoxelTagBits = cube4_pkg::VoxelTagBits,
  parameter bit           HasZDiff     = 1'b0,
  localparam int unsigned WordBits     = VoxelBits + VoxelTagBits,
  localparam int unsigned VTagPortBits = VoxelTagBits > 0 ? VoxelTagBits : 1,
  localparam int unsigned LinkBits     = 4 * WordBits + (HasZDiff ? 4 * VoxelBits : 0),
  localparam int unsigned StoreBits    = HasZDiff ? 2 * WordBits + VoxelBits : WordBits
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  // Voxel stream.
  input  logic                  valid_i,
  input  logic                  beam_start_i,
  input  logic                  beam_end_i,
  input  logic                  slice_start_i,
  input  logic                  slice_end_i,
  input  logic                  flush_i,
  input  logic                  prime_i,     // HasZDiff: a frame's priming pass
  input  logic [WordBits-1:0]   voxel_i,
  input  logic [WeightBits:0]   wx_i,
  input  logic [WeightBits:0]   wy_i,
  input  logic [WeightBits:0]   wz_i,
  input  logic [TagBits-1:0]    tag_i,
  // Near-neighbour links.
  output logic [LinkBits-1:0]   link_o,      // aligned column, to pipeline k-1
  output logic [LinkBits-1:0]   link_now_o,  // this cycle's column (ring wrap)
  input  logic [LinkBits-1:0]   link_i,      // x+1 column
  // Sample stream.
  output logic                  valid_o,
  output logic                  beam_start_o,
  output logic                  beam_end_o,
  output logic                  slice_start_o,
  output logic                  slice_end_o,
  output logic [VoxelBits-1:0]  sample_o,
  output logic [VTagPortBits-1:0] vtag_o,
  output logic [VoxelBits:0]    zdiff_o,     // HasZDiff: two's complement, else 0
  output logic [TagBits-1:0]    tag_o
);

  // Storage and links hold whole voxel words {tag, value}: a tag moves
  // exactly as its value does, so the tag path needs no control of its own.
  localparam int unsigned V             = WordBits;
  localparam int unsigned T             = VoxelTagBits;
  // Latency of cube4_interp (its header): the flags and the tag travel
  // beside it in a shift register of this length.
  localparam int unsigned TriLatency    = 3;
  localparam int unsigned BeamDepthBits  = $clog2(BeamDepth + 1);

  logic [2*V-1:0] beam_rdata; // {back, front} of column x, beam y

  // -------------------------------------------------------------------------
  // Input: the voxel pair (front = slice z_voxel, back = slice z_voxel+1) of
  // column x, beam y+1, and with HasZDiff the outer pair's values (below =
  // slice z_voxel-1, above = slice z_voxel+2).
  localparam int unsigned VB = VoxelBits;
  logic           on_slice;   // wz = 0 (and the priming pass)
  logic           prime;      // the priming pass (HasZDiff only)
  logic           pass_last;  // the pass's last step
  logic [V-1:0]   vox, front_cur, back_cur;
  logic [VB-1:0]  below_cur, above_cur;
  logic [StoreBits-1:0] store_rdata, store_wdata;

  assign on_slice  = wz_i == '0;
  assign prime     = HasZDiff && prime_i;
  assign pass_last = slice_end_i && beam_end_i && !flush_i;
  assign vox       = flush_i ? '0 : voxel_i;

  if (HasZDiff) begin : g_zdiff_in
    // Store entry {z-1 value, z word, z+1 word}. A wz = 0 pass streams
    // z+1 and finds the entry one slice behind, {z-2, z-1, z}: it reads
    // front = z, below = z-1, and writes the entry shifted, {z-1, z, z+1}.
    // The priming pass streams slice 0 and writes zero as slice "z", which
    // the first pass reads as slice -1.
    logic [V-1:0]  st_next, st_cur;
    logic [VB-1:0] st_prev;
    assign {st_prev, st_cur, st_next} = store_rdata;
    assign front_cur   = flush_i ? '0 : on_slice ? st_next : st_cur;
    assign back_cur    = flush_i ? '0 : on_slice ? vox : st_next;
    assign below_cur   = flush_i ? '0 : on_slice ? st_cur[0 +: VB] : st_prev;
    assign above_cur   = (flush_i || on_slice) ? '0 : vox[0 +: VB];
    assign store_wdata = {st_cur[0 +: VB], prime ? '0 : st_next, voxel_i};
  end else begin : g_plain_in
    logic use_store;  // the front voxel comes from the slice store
    assign use_store   = !on_slice && !flush_i;
    assign front_cur   = use_store ? store_rdata : vox;
    assign back_cur    = vox;
    assign below_cur   = '0;
    assign above_cur   = '0;
    assign store_wdata = voxel_i;
  end

  // A pass whose last sample beam is still to come (it needs the beam after
  // the pass): set by the pass's last step, cleared by the end of the beam
  // that emits it. A pass of one beam both emits the previous pass's row
  // and opens its own. The priming pass opens none: it has no samples.
  logic open_q, open_d, drain;
  assign drain  = open_q && (flush_i || slice_start_i);
  assign open_d = (valid_i && pass_last && !prime) ? 1'b1
                : (valid_i && drain && beam_end_i) ? 1'b0 : open_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      open_q <= 1'b0;
    end else begin
      open_q <= open_d;
    end
  end

  // Slice store: one entry per voxel of beams 0 .. ny-1, in stream order.
  // Written in a wz = 0 pass, re-read in the wz > 0 passes after it.
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

  // Beam delay: one lap per beam (the lap ends with the beam).
  localparam int unsigned BeamBits = HasZDiff ? 2 * V + 2 * VB : 2 * V;
  logic [BeamBits-1:0] beam_wdata;
  logic [2*VB-1:0]     outer_rdata;  // {above, below} of column x, beam y
  logic [BeamBits-1:0] beam_all;
  if (HasZDiff) begin : g_zdiff_beam
    assign beam_wdata = {above_cur, below_cur, back_cur, front_cur};
    assign outer_rdata = beam_all[2*V +: 2*VB];
  end else begin : g_plain_beam
    logic unused_outer;
    assign beam_wdata  = {back_cur, front_cur};
    assign outer_rdata = '0;
    assign unused_outer = ^{below_cur, above_cur};
  end
  assign beam_rdata = beam_all[0 +: 2*V];
  cube4_delay_ram #(
    .Width   (BeamBits),
    .MaxDepth(BeamDepth)
  ) u_beam_delay (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .depth_i  (BeamDepthBits'(BeamDepth)),
    .clear_i  (1'b0),
    .advance_i(valid_i),
    .last_i   (beam_end_i),
    .write_i  (1'b1),
    .wdata_i  (beam_wdata),
    .rdata_o  (beam_all)
  );

  // This cycle's column: [0] front y, [1] front y+1, [2] back y, [3] back y+1
  // (and with HasZDiff [4] below y, [5] below y+1, [6] above y, [7] above
  // y+1). A draining step's column is the finished pass's last beam over
  // the zero border (its y+1 voxels are zero), while the beam delay takes
  // the new pass's beam 0.
  logic [LinkBits-1:0] col_d;
  logic [V-1:0]        front_next, back_next;
  assign front_next = drain ? '0 : front_cur;
  assign back_next  = drain ? '0 : back_cur;
  if (HasZDiff) begin : g_zdiff_col
    logic [VB-1:0] below_next, above_next;
    assign below_next = drain ? '0 : below_cur;
    assign above_next = drain ? '0 : above_cur;
    assign col_d = {above_next, outer_rdata[VB +: VB], below_next, outer_rdata[0 +: VB],
                    back_next, beam_rdata[V +: V], front_next, beam_rdata[0 +: V]};
  end else begin : g_plain_col
    logic unused_outer_rdata;
    assign col_d = {back_next, beam_rdata[V +: V], front_next, beam_rdata[0 +: V]};
    assign unused_outer_rdata = ^outer_rdata;
  end
  assign link_now_o = col_d;

  // -------------------------------------------------------------------------
  // Alignment register: holds the column until the x+1 column is available
  // (the next valid cycle), or one cycle if it ends a beam (x+1 = nx: zero).
  // A draining column takes the finished pass's weights and tag, kept from
  // its last step (the draining beam may itself end a pass of one beam).
  logic                  valid_q, valid_d, fire;
  logic [LinkBits-1:0]   col_q;
  logic                  beam_start_q, beam_end_q, slice_start_q, drain_q, flush_q, prime_q;
  logic [WeightBits:0]   wx_q, wy_q, wz_q;
  logic [TagBits-1:0]    tag_q;
  logic [WeightBits:0]   open_wx_q, open_wy_q, open_wz_q;  // the open pass's
  logic [TagBits-1:0]    open_tag_q;
  logic                  second_q, second_d;  // the column's beam is beam 1

  assign fire    = valid_q && (valid_i || beam_end_q);
  assign valid_d = valid_i || (valid_q && !fire);
  // At the end of a beam the next beam's first output is slice_start iff the
  // beam that ended was beam 0: the next beam is then beam 1, or a beam
  // draining a pass of one beam.
  assign second_d = (fire && beam_end_q) ? slice_start_q : second_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q  <= 1'b0;
      second_q <= 1'b0;
    end else begin
      valid_q  <= valid_d;
      second_q <= second_d;
    end
  end

  always_ff @(posedge clk_i) begin
    if (valid_i) begin
      col_q         <= col_d;
      beam_start_q  <= beam_start_i;
      beam_end_q    <= beam_end_i;
      slice_start_q <= slice_start_i && !flush_i;
      drain_q       <= drain;
      flush_q       <= flush_i;
      prime_q       <= prime;
      wx_q          <= drain ? open_wx_q : wx_i;
      wy_q          <= drain ? open_wy_q : wy_i;
      wz_q          <= drain ? open_wz_q : wz_i;
      tag_q         <= drain ? open_tag_q : tag_i;
    end
    if (valid_i && pass_last) begin
      open_wx_q  <= wx_i;
      open_wy_q  <= wy_i;
      open_wz_q  <= wz_i;
      open_tag_q <= tag_i;
    end
  end
  assign link_o = col_q;

  // -------------------------------------------------------------------------
  // Trilinear interpolation of the eight voxels: this column gives the even
  // voxels (x), the neighbour's the odd ones (x+1).
  // Each word splits into its value (low VoxelBits) and tag (above).
  logic [LinkBits-1:0]    nb;
  logic [8*V-1:0]         words;
  logic [8*VoxelBits-1:0] voxels;
  logic [8*VTagPortBits-1:0] vtags;
  logic                   tri_valid;

  assign nb = (WrapIn && beam_end_q) ? '0 : link_i;
  for (genvar l = 0; l < 4; l++) begin : g_voxels
    assign words[(2*l)*V +: V]   = col_q[l*V +: V];
    assign words[(2*l+1)*V +: V] = nb[l*V +: V];
  end
  for (genvar i = 0; i < 8; i++) begin : g_split
    assign voxels[i*VoxelBits +: VoxelBits] = words[i*V +: VoxelBits];
    if (T > 0) begin : g_tag
      assign vtags[i*VTagPortBits +: VTagPortBits] = words[i*V + VoxelBits +: VTagPortBits];
    end else begin : g_no_tag
      assign vtags[i*VTagPortBits +: VTagPortBits] = '0;
    end
  end
  // A pass's beam 0 only fills the beam delay (no samples of its own); a
  // flush beam after nothing emits nothing, nor does a priming pass
  // (its beam 0 may drain the pass before it).
  assign tri_valid = fire && (drain_q || !slice_start_q && !flush_q && !prime_q);

  cube4_interp #(
    .VoxelBits   (VoxelBits),
    .WeightBits  (WeightBits),
    .VoxelTagBits(VoxelTagBits)
  ) u_trilinear (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .valid_i (tri_valid),
    .voxels_i(voxels),
    .wx_i    (wx_q),
    .wy_i    (wy_q),
    .wz_i    (wz_q),
    .vtags_i (vtags),
    .valid_o (valid_o),
    .sample_o(sample_o),
    .vtag_o  (vtag_o)
  );

  // VolumePro's z gradient: the eight outer values beside the eight voxels,
  // [0 .. 3] below (z-1), [4 .. 7] above (z+2), each x from this column
  // (even) and the neighbour's (odd), as the voxels.
  if (HasZDiff) begin : g_zdiff
    localparam int unsigned OuterBase = 4 * V;
    logic [8*VB-1:0] outer;
    logic            zdiff_valid;
    for (genvar l = 0; l < 4; l++) begin : g_outer
      assign outer[(2*l)*VB +: VB]   = col_q[OuterBase + l*VB +: VB];
      assign outer[(2*l+1)*VB +: VB] = nb[OuterBase + l*VB +: VB];
    end
    cube4_interp_zdiff #(
      .VoxelBits (VoxelBits),
      .WeightBits(WeightBits)
    ) u_zdiff (
      .clk_i   (clk_i),
      .rst_ni  (rst_ni),
      .valid_i (tri_valid),
      .voxels_i(voxels),
      .outer_i (outer),
      .wx_i    (wx_q),
      .wy_i    (wy_q),
      .wz_i    (wz_q),
      .valid_o (zdiff_valid),  // valid_o's twin
      .zdiff_o (zdiff_o)
    );
    logic unused_zdiff_valid;
    assign unused_zdiff_valid = zdiff_valid;
  end else begin : g_no_zdiff
    logic unused_prime;
    assign unused_prime = prime_i;
    assign zdiff_o      = '0;
  end

  // Flags and tag beside the trilinear pipeline (data: not reset).
  localparam int unsigned SideBits = 4 + TagBits;
  cube4_pipe_delay #(.Width(SideBits), .Depth(TriLatency)) u_side_delay (
    .clk_i,
    .d_i ({tag_q, drain_q, second_q, beam_end_q, beam_start_q}),
    .q_o ({tag_o, slice_end_o, slice_start_o, beam_end_o, beam_start_o})
  );

endmodule
