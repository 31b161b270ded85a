// cube4_sva_frame_registers: what the checkers of the units' frame-register
// rule ("change them only while no sample is in flight") observe: which of
// the last Cycles cycles let a sample in, and the registers' values of the
// cycle before, so that a checker can assert that they did not change while
// a sample that entered then is still inside (Cycles = the unit's latency
// - 1: a sample entered Latency - 1 cycles ago is in its last stage).
//
// Simulation only: not part of any unit, never synthesised.
module cube4_sva_frame_registers #(
  parameter int unsigned Width  = 1,
  parameter int unsigned Cycles = 2
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              valid_i,
  input  logic [Width-1:0]  regs_i,
  output logic [Cycles-1:0] entered_o,  // bit i: a sample entered i + 1 cycles ago
  output logic [Width-1:0]  regs_q_o    // regs_i of the cycle before
);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      entered_o <= '0;
    end else begin
      entered_o <= {entered_o[Cycles-2:0], valid_i};
    end
  end

  always_ff @(posedge clk_i) begin
    regs_q_o <= regs_i;
  end

endmodule
