// cube4_mul_frac: a value times a unit fraction, rounded to nearest (ties up;
// down with HalfDown).
//
// Function: y = (x * (f + (f >> (FBits-1))) + 2^(FBits-1) - HalfDown) >> FBits,
// with f in [0, 2^FBits - 1] standing for [0, 1]: the all-ones fraction is
// 1.0 (f + (f >> (FBits-1)) maps it onto 2^FBits), so y = x exactly at
// f = 1.0 and y <= x always; y keeps x's width. Bit-exact with golden
// mul_frac() (golden/fixed.hpp) at n = FBits with HalfDown = 0 (ties round
// up). HalfDown = 1 rounds ties down: x - mul_frac(x, f) equals it at
// one - f (cube4_compose_node's α). The compositor (α times the cut-plane
// factor, colour times α, the blend's transparency products) and the Phong
// unit (map values times the GmLUT factors) use this one module.
//
// Latency: 0 (combinational). Handshake: none (pure function).
//
// Parameters:
//   XBits - width of x and y
//   FBits - fraction bits of f (>= 1)
//   HalfDown - 0: ties round up (golden mul_frac); 1: ties round down
`include "cube4_pkg.sv"

module cube4_mul_frac #(
  parameter int unsigned XBits = cube4_pkg::AlphaBits,
  parameter int unsigned FBits = cube4_pkg::AlphaBits,
  parameter bit          HalfDown = 1'b0
) (
  input  logic [XBits-1:0] x_i,
  input  logic [FBits-1:0] f_i,
  output logic [XBits-1:0] y_o
);

  // x * (f + 1 ulp at 1.0) < 2^(XBits + FBits + 1): one bit above the
  // product holds the rounding add.
  localparam int unsigned ProdBits = XBits + FBits + 1;
  // The rounding constant: half an LSB of y, less one with HalfDown.
  localparam logic [ProdBits-1:0] Half = (ProdBits'(1) << (FBits - 1)) - ProdBits'(HalfDown);

  logic [FBits:0]    f_unit;
  logic [ProdBits-1:0] prod;

  assign f_unit = {1'b0, f_i} + (FBits + 1)'(f_i[FBits-1]);
  assign prod   = ProdBits'(x_i) * ProdBits'(f_unit) + Half;
  assign y_o    = prod[FBits +: XBits];

  // Above x's width the shifted product is zero (y <= x).
  logic unused_prod;
  assign unused_prod = ^{prod[FBits-1:0], prod[ProdBits-1]};

endmodule
