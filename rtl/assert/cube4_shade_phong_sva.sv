// cube4_shade_phong_sva: for coverage (scripts/coverage.sh), the case the
// Phong unit must be driven through: a colour channel whose diffuse plus
// specular sum passes the largest colour, saturated (c_saturated: golden
// phong's min with the maximum; any of red, green, blue).
//
// Simulation only: not part of the unit, never synthesised.
module cube4_shade_phong_sva (
  input logic       clk_i,
  input logic       stage3_valid,  // internal: valid_q[1], two registers after valid_i
  input logic [2:0] saturated      // internal: stage 3's channels
);

  c_saturated: cover property (@(posedge clk_i) stage3_valid && |saturated);

endmodule

bind cube4_shade_phong cube4_shade_phong_sva u_sva (.stage3_valid(valid_q[1]), .*);
