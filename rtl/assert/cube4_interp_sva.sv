// cube4_interp_sva: the weight range cube4_interp's header states, as an
// assertion bound to every cube4_interp:
//   a_weights_in_range - with valid_i, wx, wy and wz lie in [0, 2^WeightBits]
//                        (the ports are a bit wider): beyond, a lerp leaves
//                        [min, max] of its two voxels and wraps.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_interp_sva #(
  parameter int unsigned WeightBits = 8
) (
  input logic                clk_i,
  input logic                rst_ni,
  input logic                valid_i,
  input logic [WeightBits:0] wx_i,
  input logic [WeightBits:0] wy_i,
  input logic [WeightBits:0] wz_i
);

  localparam logic [WeightBits:0] One = {1'b1, {WeightBits{1'b0}}};

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_weights_in_range: assert (!valid_i || (wx_i <= One && wy_i <= One && wz_i <= One))
        else $error("cube4_interp: cycle %0d: weights (%0d, %0d, %0d) must lie in [0, %0d]",
                    cycle, wx_i, wy_i, wz_i, One);
    end
  end

endmodule

bind cube4_interp cube4_interp_sva #(.WeightBits(WeightBits)) u_sva (.*);
