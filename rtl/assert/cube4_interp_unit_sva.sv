// cube4_interp_unit_sva: the stream preconditions cube4_interp_unit's
// header states, as assertions bound to every instance (the pipelines of a
// ring all see the same stream, so each checks it):
//   a_stream_framing - beam_start_i marks the first partial beam after a
//                      beam's end (or reset); a beam after a pass's end, a
//                      flush beam or reset is slice_start_i's or a flush
//                      beam, no other, and no beam is both; a flush beam
//                      carries no slice flags; the beam flags hold for a
//                      whole beam; and every beam of a pass, and a flush
//                      beam after it, has the pass's first beam's
//                      ceil(nx/p) partial beams: the delays' laps follow
//                      these flags;
//   a_weights_constant - wx_i, wy_i and wz_i stay the pass's: the unit
//                      decides store write or read per step from wz_i;
//   a_beam_fits      - a beam has at most BeamDepth partial beams
//                      (ceil(nx/p) <= BeamDepth): a longer one wraps the
//                      beam delay (FIFO overflow);
//   a_slice_fits     - beams 0 .. ny-1 of a pass hold at most SliceDepth
//                      partial beams (ny * ceil(nx/p) <= SliceDepth): more
//                      overwrite the slice store's first entries;
//   a_store_filled   - a pass with wz > 0 reads voxel slice z_voxel from
//                      the slice store: a wz = 0 pass at least as long must
//                      have written it (FIFO underflow otherwise: the store
//                      holds another slice's voxels, or none since reset).
// A failure prints the cycle (cube4_sva_cycle) and the values at fault.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_interp_unit_sva #(
  parameter int unsigned  WeightBits = 8,
  parameter int unsigned  BeamDepth  = 64,
  parameter int unsigned  SliceDepth = 16384,
  localparam int unsigned BeamBits   = $clog2(BeamDepth + 1),
  localparam int unsigned CountBits  = $clog2(SliceDepth + 1)
) (
  input logic                clk_i,
  input logic                rst_ni,
  input logic                valid_i,
  input logic                beam_start_i,
  input logic                beam_end_i,
  input logic                slice_start_i,
  input logic                slice_end_i,
  input logic                flush_i,
  input logic [WeightBits:0] wx_i,
  input logic [WeightBits:0] wy_i,
  input logic [WeightBits:0] wz_i
);

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  // The stream so far: partial beams of the current beam (j_q) and of the
  // pass's first beam (b_q, 0 until it ended), voxel steps of the pass so
  // far (n_q), entries the last wz = 0 pass wrote (filled_q), the pass's
  // weights, and whether the previous step ended a beam / a pass or a
  // flush beam.
  logic [BeamBits-1:0]     j_q, b_q;
  logic [CountBits-1:0]    n_q, filled_q, n_cur;
  logic [3*WeightBits+2:0] w_q;
  logic                    beam_done_q, pass_done_q;
  logic                    ss_q, se_q, fl_q;  // the beam's flags
  logic [3*WeightBits+2:0] w;
  logic                    pass_start, pass_end;
  logic [BeamBits-1:0]     b_cur;   // the pass's beam length, 0 while its first beam runs
  assign w          = {wx_i, wy_i, wz_i};
  assign pass_start = slice_start_i && beam_start_i;
  assign pass_end   = beam_end_i && (flush_i || slice_end_i);
  assign b_cur      = pass_start ? '0 : b_q;
  assign n_cur      = pass_start ? '0 : n_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      j_q         <= '0;
      b_q         <= '0;
      n_q         <= '0;
      filled_q    <= '0;
      w_q         <= '0;
      beam_done_q <= 1'b1;
      pass_done_q <= 1'b1;
      ss_q        <= 1'b0;
      se_q        <= 1'b0;
      fl_q        <= 1'b0;
    end else if (valid_i) begin
      if (beam_start_i) begin
        ss_q <= slice_start_i;
        se_q <= slice_end_i;
        fl_q <= flush_i;
      end
      beam_done_q <= beam_end_i;
      pass_done_q <= pass_end;
      j_q         <= (beam_end_i || j_q == BeamBits'(BeamDepth)) ? '0 : j_q + BeamBits'(1);
      if (pass_start) w_q <= w;
      b_q <= (beam_end_i && b_cur == '0) ? j_q + BeamBits'(1) : b_cur;
      if (!flush_i) begin
        n_q <= (n_cur == CountBits'(SliceDepth)) ? n_cur : n_cur + CountBits'(1);
        // The pass's last step: its wz = 0 pass wrote this many entries.
        if (slice_end_i && beam_end_i && wz_i == '0) filled_q <= n_cur + CountBits'(1);
      end
    end
  end

  logic framing_ok;
  assign framing_ok = beam_start_i == beam_done_q
                   && (beam_start_i ? (slice_start_i || flush_i) == pass_done_q && !(slice_start_i && flush_i)
                                    : slice_start_i == ss_q && slice_end_i == se_q && flush_i == fl_q)
                   && !(flush_i && slice_end_i)
                   && (b_cur == '0 || beam_end_i == (j_q + BeamBits'(1) == b_cur));

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni && valid_i) begin
      a_stream_framing: assert (framing_ok)
        else $error("cube4_interp_unit: cycle %0d: flags beam_start %0d beam_end %0d slice_start %0d slice_end %0d flush %0d at partial beam %0d (beams of this pass: %0d partial beams, 0: its first beam; previous step ended a beam %0d, a pass %0d)",
                    cycle, beam_start_i, beam_end_i, slice_start_i, slice_end_i, flush_i, j_q, b_cur, beam_done_q, pass_done_q);
      a_weights_constant: assert (flush_i || pass_start || w == w_q)
        else $error("cube4_interp_unit: cycle %0d: weights (%0d, %0d, %0d) changed inside a pass that began with (%0d, %0d, %0d)",
                    cycle, wx_i, wy_i, wz_i, w_q[2*(WeightBits+1) +: WeightBits+1],
                    w_q[WeightBits+1 +: WeightBits+1], w_q[0 +: WeightBits+1]);
      a_beam_fits: assert (j_q < BeamBits'(BeamDepth))
        else $error("cube4_interp_unit: cycle %0d: partial beam %0d of a beam, but the beam delay holds %0d (ceil(nx/p) <= BeamDepth)",
                    cycle, j_q, BeamDepth);
      a_slice_fits: assert (flush_i || n_cur < CountBits'(SliceDepth))
        else $error("cube4_interp_unit: cycle %0d: voxel %0d of a pass, but the slice store holds %0d (ny * ceil(nx/p) <= SliceDepth)",
                    cycle, n_cur, SliceDepth);
      a_store_filled: assert (flush_i || wz_i == '0 || n_cur < filled_q)
        else $error("cube4_interp_unit: cycle %0d: a wz = %0d pass reads slice-store entry %0d, but the last wz = 0 pass wrote %0d entries",
                    cycle, wz_i, n_cur, filled_q);
    end
  end

endmodule

bind cube4_interp_unit cube4_interp_unit_sva #(
  .WeightBits(WeightBits),
  .BeamDepth (BeamDepth),
  .SliceDepth(SliceDepth)
) u_sva (.*);
