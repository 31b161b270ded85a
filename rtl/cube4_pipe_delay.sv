// cube4_pipe_delay: a value delayed by Depth clocks in a chain of registers,
// the way a pipelined unit keeps data beside a computation of known latency
// (the sample beside its shading, a gradient beside its magnitude). Short
// and always shifting; cube4_delay_ram is the delay of a beam or a slice.
//
// Why a chain of generate stages and not one packed vector of Depth * Width
// bits: Verilator keeps each stage a word of its own and copies it, where a
// packed vector wider than 64 bits costs a masked part-select per stage and
// clock (the shading unit's delays were 13 % of its simulation: docs/
// performance.md); yosys reads the stages as plain registers, where an
// unpacked array would be a memory replaced by registers, with a warning.
//
// Latency: q_o is d_i of Depth clocks before (Depth = 0: d_i itself).
// Handshake: none. Reset: none (the user's valid chain says what q_o means).
//
// Parameters:
//   Width - bits of the value (>= 1)
//   Depth - clocks of delay (>= 0)
module cube4_pipe_delay #(
  parameter int unsigned Width = 1,
  parameter int unsigned Depth = 1
) (
  input  logic             clk_i,
  input  logic [Width-1:0] d_i,
  output logic [Width-1:0] q_o
);

  if (Depth == 0) begin : g_wire
    assign q_o = d_i;
  end else begin : g_chain
    for (genvar k = 0; k < Depth; k++) begin : g_stage
      logic [Width-1:0] q;
      if (k == 0) begin : g_first
        always_ff @(posedge clk_i) q <= d_i;
      end else begin : g_next
        always_ff @(posedge clk_i) q <= g_stage[k-1].q;
      end
    end
    assign q_o = g_stage[Depth-1].q;
  end

endmodule
