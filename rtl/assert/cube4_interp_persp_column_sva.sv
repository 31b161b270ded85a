// cube4_interp_persp_column_sva: the preconditions cube4_interp_persp_column's
// header states, as assertions bound to every cube4_interp_persp_column:
//   a_two_beams   - a pass's last beam is not its first (ny >= 2): a pass
//                   of one beam would have its cells drained into passes
//                   that form their own;
//   a_beam_fits   - a beam has at most BeamDepth partial beams (the row
//                   delay's entries);
//   a_slice_fits  - a pass has at most SliceDepth voxel steps (the slice
//                   store's entries).
// Beyond the delays a lap wraps and the column sums mix rows silently.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_interp_persp_column_sva #(
  parameter int unsigned BeamDepth  = 64,
  parameter int unsigned SliceDepth = 16384
) (
  input logic       clk_i,
  input logic       rst_ni,
  input logic       valid_i,
  input logic       beam_start_i,
  input logic       slice_start_i,
  input logic       flush_i,
  input logic       pass_last,
  input logic [1:0] beam_d
);

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  // This step's partial beam of its beam, and voxel step of its pass.
  logic [31:0] j_q, j, n_q, n;
  assign j = beam_start_i ? 32'd0 : j_q + 32'd1;
  assign n = (slice_start_i && beam_start_i) ? 32'd0 : n_q + 32'd1;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      j_q <= '0;
      n_q <= '0;
    end else if (valid_i) begin
      j_q <= j;
      if (!flush_i) n_q <= n;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_two_beams: assert (!pass_last || beam_d != 2'd0)
        else $error("cube4_interp_persp_column: cycle %0d: a pass of one beam (the perspective ring needs ny >= 2)",
                    cycle);
      a_beam_fits: assert (!valid_i || j < BeamDepth)
        else $error("cube4_interp_persp_column: cycle %0d: partial beam %0d of a beam, but the row delay holds %0d",
                    cycle, j, BeamDepth);
      a_slice_fits: assert (!valid_i || flush_i || n < SliceDepth)
        else $error("cube4_interp_persp_column: cycle %0d: voxel %0d of a pass, but the slice store holds %0d",
                    cycle, n, SliceDepth);
    end
  end

endmodule

bind cube4_interp_persp_column cube4_interp_persp_column_sva #(.BeamDepth(BeamDepth), .SliceDepth(SliceDepth))
    u_sva (.*);
