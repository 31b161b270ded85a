// cube4_shade_magnitude_sva: for coverage (scripts/coverage.sh), the case
// the gradient-magnitude unit must be driven through: a square root above
// the largest magnitude, saturated (c_saturated: golden
// gradient_magnitude's min with its maximum; |g| reaches sqrt(3)·2^(G-1)).
//
// Simulation only: not part of the unit, never synthesised.
module cube4_shade_magnitude_sva (
  input logic clk_i,
  input logic valid_o,
  input logic saturated  // internal: the last stage's comparison
);

  c_saturated: cover property (@(posedge clk_i) valid_o && saturated);

endmodule

bind cube4_shade_magnitude cube4_shade_magnitude_sva u_sva (.*);
