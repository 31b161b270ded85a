// cube4_delay_ram_sva: the run-time lap length cube4_delay_ram's header
// states, as an assertion bound to every delay RAM:
//   a_depth_in_range - a step (advance_i without clear_i) has depth_i in
//                      1 .. MaxDepth: with 0 the lap would never end at the
//                      depth (only at the RAM's end), beyond MaxDepth it is
//                      cut short there, and either way the line is no longer
//                      a FIFO of depth_i entries.
// The users' laps ended by last_i or clear_i have their own limits (beam
// and slice lengths), asserted by the users' checkers, which know them.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_delay_ram_sva #(
  parameter int unsigned  MaxDepth  = 64,
  localparam int unsigned DepthBits = $clog2(MaxDepth + 1)
) (
  input logic                 clk_i,
  input logic                 rst_ni,
  input logic [DepthBits-1:0] depth_i,
  input logic                 clear_i,
  input logic                 advance_i
);

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  // depth_i's width holds MaxDepth + 1 only when MaxDepth + 1 is no power
  // of two (the comparison would be constant otherwise).
  logic depth_ok;
  if (MaxDepth < (1 << DepthBits) - 1) begin : g_upper
    assign depth_ok = depth_i != '0 && depth_i <= DepthBits'(MaxDepth);
  end else begin : g_no_upper
    assign depth_ok = depth_i != '0;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_depth_in_range: assert (!(advance_i && !clear_i) || depth_ok)
        else $error("cube4_delay_ram: cycle %0d: a step with depth_i = %0d, outside 1 .. %0d",
                    cycle, depth_i, MaxDepth);
    end
  end

endmodule

bind cube4_delay_ram cube4_delay_ram_sva #(.MaxDepth(MaxDepth)) u_sva (.*);
