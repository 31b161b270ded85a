// cube4_sva_cycle: the cycle number the checkers (rtl/assert/*_sva.sv) put
// in their messages: clock edges since reset was released, counted from 1,
// so the edge that ends the first cycle after reset is cycle 1. The system
// model resets every verilated unit right before a frame, so this is the
// frame's cycle number of its reports and traces (docs/system.md); a unit
// test's is its cycle since reset. A counter of its own, because Verilator's
// $time is whatever the harness sets (the system and the tests set none).
//
// Simulation only: not part of any unit, never synthesised.
module cube4_sva_cycle (
  input  logic        clk_i,
  input  logic        rst_ni,
  output logic [63:0] cycle_o   // the number of the cycle this edge ends
);

  logic [63:0] count_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      count_q <= '0;
    end else begin
      count_q <= count_q + 64'd1;
    end
  end
  assign cycle_o = count_q + 64'd1;

endmodule
