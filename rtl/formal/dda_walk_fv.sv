// Formal harness for cube4_dda_walk: whatever the commands (loads and
// advances in any order, idle cycles between), once loaded the walk holds
// slices k - 1, k and k + 1 of the DDA exactly: here = start + k * step
// (modulo 2^PosBits, as the accumulators wrap) with k the advances since
// the last load, behind = here - step and ahead = here + step. This is
// golden dda_position() for every run length, which the unit's header
// claims and the RTL tests sample. The registers' precondition (step_i
// held over a frame) is assumed; start_i may change (it is read at load).
//
// Proof: 1-induction; the asserted relations are the invariant (the walk's
// registers are its outputs), so no probes are needed.
module dda_walk_fv #(
  parameter int unsigned PosBits = 8
) (
  input logic                      clk_i,
  input logic signed [PosBits-1:0] start_i,
  input logic signed [PosBits-1:0] step_i,
  input logic                      load_i,
  input logic                      advance_i
);

  logic signed [PosBits-1:0] behind, here, ahead;

  cube4_dda_walk #(
    .PosBits(PosBits)
  ) u_dut (
    .clk_i,
    .start_i,
    .step_i,
    .load_i,
    .advance_i,
    .behind_o(behind),
    .here_o  (here),
    .ahead_o (ahead)
  );

  // The frame: its start and step at the load, and the advances since.
  logic                      loaded_q = 1'b0;
  logic signed [PosBits-1:0] start_q, step_q;
  logic [PosBits-1:0]        k_q;

  always_ff @(posedge clk_i) begin
    if (load_i) begin
      loaded_q <= 1'b1;
      start_q  <= start_i;
      step_q   <= step_i;
      k_q      <= '0;
    end else if (advance_i) begin
      k_q <= k_q + PosBits'(1);
    end
  end

  always_comb begin
    if (loaded_q && !load_i) assume (step_i == step_q);
    if (loaded_q) begin
      assert (here == start_q + PosBits'(k_q * step_q));
      assert (behind == here - step_q);
      assert (ahead == here + step_q);
    end
  end

endmodule
