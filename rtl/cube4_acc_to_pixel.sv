// cube4_acc_to_pixel: one channel of a finished ray (or composed pixel)
// from the accumulator domain, AlphaBits + AccGuardBits bits, to a
// base-plane pixel of AlphaBits. Bit-exact with golden acc_to_pixel()
// (golden/units/composite.hpp):
//   pixel = (v - (v >> AlphaBits) + half) >> AccGuardBits
// v - (v >> A) undoes the bit replication of golden to_acc(), so full scale
// maps to full scale and the result needs no saturation: v - (v >> A) +
// half stays below 2^(A+G), and its top A bits below 2^A. With
// AccGuardBits = 0 it is the identity. Combinational.
//
// Used by the compositing unit's pixel port and by the composition
// network's output stage (cube4_compose_out), so the rounding is written
// once.
//
// Parameters (defaults = golden Precision): AlphaBits, AccGuardBits
// (<= AlphaBits).
`include "cube4_pkg.sv"

module cube4_acc_to_pixel #(
  parameter int unsigned AlphaBits    = cube4_pkg::AlphaBits,
  parameter int unsigned AccGuardBits = cube4_pkg::AccGuardBits
) (
  input  logic [AlphaBits+AccGuardBits-1:0] acc_i,
  output logic [AlphaBits-1:0]              pixel_o
);

  localparam int unsigned A  = AlphaBits;
  localparam int unsigned G  = AccGuardBits;
  localparam int unsigned AB = AlphaBits + AccGuardBits;
  localparam logic [AB-1:0] Half = (G > 0) ? (AB'(1) << (G - 1)) : '0;

  logic [AB-1:0] scaled;
  assign scaled  = acc_i - (acc_i >> A) + Half;
  assign pixel_o = scaled[AB-1:G];

  if (G > 0) begin : g_rounded_away
    logic unused_fraction;
    assign unused_fraction = ^scaled[G-1:0];
  end

endmodule
