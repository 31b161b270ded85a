// cube4_gradient_sva: the input ranges cube4_gradient's header states, as an
// assertion bound to every cube4_gradient:
//   a_control_in_range - with valid_i, every realign weight lies in
//                        [0, 2^WeightBits] (the ports are a bit wider) and
//                        the supersampling factor S in 1 .. 2^SBits - 1:
//                        outside, the lerps leave [min, max] of their
//                        samples and gz is not golden's;
// and, for coverage (scripts/coverage.sh), the saturation of each component
// at either bound (c_saturate_{x,y,z}_{hi,lo}: the rounded difference
// beyond +-MaxG, golden's sat_signed).
//
// Simulation only: not part of the unit, never synthesised.
module cube4_gradient_sva #(
  parameter int unsigned WeightBits        = 8,
  parameter int unsigned SupersamplingBits = 4,
  parameter int unsigned FullBits          = 16,
  parameter logic signed [FullBits-1:0] MaxG = 127
) (
  input logic                         clk_i,
  input logic                         rst_ni,
  input logic                         valid_i,
  input logic [WeightBits:0]          behind_wx_i,
  input logic [WeightBits:0]          behind_wy_i,
  input logic [WeightBits:0]          ahead_wx_i,
  input logic [WeightBits:0]          ahead_wy_i,
  input logic [SupersamplingBits-1:0] supersampling_i,
  // Internal: the rounded components of stage 1 (x, y) and stage 3 (z),
  // whose sample is valid_q[1].
  input logic                         stage3_valid,
  input logic signed [FullBits-1:0]   gx_rounded,
  input logic signed [FullBits-1:0]   gy_rounded,
  input logic signed [FullBits-1:0]   gz_rounded
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

  c_saturate_x_hi: cover property (@(posedge clk_i) valid_i && gx_rounded > MaxG);
  c_saturate_x_lo: cover property (@(posedge clk_i) valid_i && gx_rounded < -MaxG);
  c_saturate_y_hi: cover property (@(posedge clk_i) valid_i && gy_rounded > MaxG);
  c_saturate_y_lo: cover property (@(posedge clk_i) valid_i && gy_rounded < -MaxG);
  c_saturate_z_hi: cover property (@(posedge clk_i) stage3_valid && gz_rounded > MaxG);
  c_saturate_z_lo: cover property (@(posedge clk_i) stage3_valid && gz_rounded < -MaxG);

endmodule

bind cube4_gradient cube4_gradient_sva #(
  .WeightBits       (WeightBits),
  .SupersamplingBits(SupersamplingBits),
  .FullBits         (FullBits),
  .MaxG             (MaxG)
) u_sva (.stage3_valid(valid_q[1]), .*);
