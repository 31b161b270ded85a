// cube4_to_acc: one channel of a pixel (AlphaBits) widened to the
// accumulator domain (AlphaBits + AccGuardBits), golden to_acc()
// (golden/units/composite.hpp): bit replication, so 0 stays 0 and full
// scale becomes full scale; cube4_acc_to_pixel undoes it exactly.
// Combinational. Used for the sample's colour and α before premultiplying
// (cube4_composite) and for polygon pixels entering a ray (the slab pixel,
// a ray's front and back pixels: golden pixel_to_acc()), so the widening is
// written once.
//
// Parameters (defaults = golden Precision): AlphaBits, AccGuardBits
// (<= AlphaBits).
`include "cube4_pkg.sv"

module cube4_to_acc #(
  parameter int unsigned AlphaBits    = cube4_pkg::AlphaBits,
  parameter int unsigned AccGuardBits = cube4_pkg::AccGuardBits
) (
  input  logic [AlphaBits-1:0]              pixel_i,
  output logic [AlphaBits+AccGuardBits-1:0] acc_o
);

  localparam int unsigned AB = AlphaBits + AccGuardBits;

  assign acc_o = (AB'(pixel_i) << AccGuardBits) | (AB'(pixel_i) >> (AlphaBits - AccGuardBits));

endmodule
