// cube4_gradient_sva: the input ranges cube4_gradient's header states, as an
// assertion bound to every cube4_gradient:
//   a_control_in_range - with valid_i, every realign weight lies in
//                        [0, 2^WeightBits] (the ports are a bit wider) and
//                        the supersampling factor S in 1 .. 2^SBits - 1:
//                        outside, the lerps leave [min, max] of their
//                        samples and gz is not golden's.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_gradient_sva #(
  parameter int unsigned WeightBits        = 8,
  parameter int unsigned SupersamplingBits = 4
) (
  input logic                         clk_i,
  input logic                         rst_ni,
  input logic                         valid_i,
  input logic [WeightBits:0]          behind_wx_i,
  input logic [WeightBits:0]          behind_wy_i,
  input logic [WeightBits:0]          ahead_wx_i,
  input logic [WeightBits:0]          ahead_wy_i,
  input logic [SupersamplingBits-1:0] supersampling_i
);

  localparam logic [WeightBits:0] One = {1'b1, {WeightBits{1'b0}}};

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_control_in_range: assert (!valid_i || (behind_wx_i <= One && behind_wy_i <= One && ahead_wx_i <= One
                                               && ahead_wy_i <= One && supersampling_i != '0))
        else $error("cube4_gradient: cycle %0d: realign weights behind (%0d, %0d), ahead (%0d, %0d) must lie in [0, %0d], supersampling %0d in [1, %0d]",
                    cycle, behind_wx_i, behind_wy_i, ahead_wx_i, ahead_wy_i, One, supersampling_i,
                    (1 << SupersamplingBits) - 1);
    end
  end

endmodule

bind cube4_gradient cube4_gradient_sva #(
  .WeightBits       (WeightBits),
  .SupersamplingBits(SupersamplingBits)
) u_sva (.*);
