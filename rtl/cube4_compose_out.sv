// cube4_compose_out: the output stage of an image composition network: the
// root node's composed pixel, in the accumulator domain (golden RayAcc), to
// a frame-buffer pixel of AlphaBits per channel. Bit-exact with golden
// pixel_of() (golden/units/composite.hpp): each of R, G, B and α through
// cube4_acc_to_pixel, the rounding the compositing unit's pixel port uses,
// so a partitioned volume's image and a one-pass image round alike. The
// MIP/MinIP value and selected bit stay behind: the frame buffer holds
// colour and α.
//
// Latency: 1 cycle (the output registers). Handshake: valid-only, one
// pixel per clock. Only the valid register is reset.
//
// Parameters (defaults = golden Precision): AlphaBits, AccGuardBits
// (<= AlphaBits).
`include "cube4_pkg.sv"

module cube4_compose_out #(
  parameter int unsigned AlphaBits    = cube4_pkg::AlphaBits,
  parameter int unsigned AccGuardBits = cube4_pkg::AccGuardBits
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  input  logic                              valid_i,
  input  logic [AlphaBits+AccGuardBits-1:0] red_i,
  input  logic [AlphaBits+AccGuardBits-1:0] green_i,
  input  logic [AlphaBits+AccGuardBits-1:0] blue_i,
  input  logic [AlphaBits+AccGuardBits-1:0] alpha_i,
  output logic                              valid_o,
  output logic [AlphaBits-1:0]              red_o,
  output logic [AlphaBits-1:0]              green_o,
  output logic [AlphaBits-1:0]              blue_o,
  output logic [AlphaBits-1:0]              alpha_o
);

  localparam int unsigned A = AlphaBits;
  localparam int unsigned G = AccGuardBits;

  logic [A-1:0] red_d, green_d, blue_d, alpha_d;
  cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(G)) u_red   (.acc_i(red_i),   .pixel_o(red_d));
  cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(G)) u_green (.acc_i(green_i), .pixel_o(green_d));
  cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(G)) u_blue  (.acc_i(blue_i),  .pixel_o(blue_d));
  cube4_acc_to_pixel #(.AlphaBits(A), .AccGuardBits(G)) u_alpha (.acc_i(alpha_i), .pixel_o(alpha_d));

  always_ff @(posedge clk_i) begin : pixel_regs
    red_o   <= red_d;
    green_o <= green_d;
    blue_o  <= blue_d;
    alpha_o <= alpha_d;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin : valid_reg
    if (!rst_ni) begin
      valid_o <= 1'b0;
    end else begin
      valid_o <= valid_i;
    end
  end

endmodule
