// cube4_shade_sva: the frame-register rule cube4_shade's header states, as
// an assertion bound to every shader (so to every cube4_shade_unit):
//   a_frame_registers_stable - the mode bits, coefficients, specular colour
//                      and eye vector do not change, and no table entry is
//                      written, while a sample entered in the Latency - 1
//                      cycles before: its later stages still read them, so
//                      it would be classified or lit under two settings.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_shade_sva #(
  parameter int unsigned AlphaBits = 16,
  parameter int unsigned CoefBits  = 10,
  parameter int unsigned EyeBits   = 8,
  parameter int unsigned Latency   = 17
) (
  input logic                clk_i,
  input logic                rst_ni,
  input logic                magnitude_i,
  input logic                shading_i,
  input logic                specular_i,
  input logic                gm_opacity_i,
  input logic                gm_diffuse_i,
  input logic                gm_specular_i,
  input logic [CoefBits-1:0] ke_i,
  input logic [CoefBits-1:0] kd_i,
  input logic [CoefBits-1:0] ks_i,
  input logic [AlphaBits-1:0] spec_red_i,
  input logic [AlphaBits-1:0] spec_green_i,
  input logic [AlphaBits-1:0] spec_blue_i,
  input logic [EyeBits-1:0]  eye_x_i,
  input logic [EyeBits-1:0]  eye_y_i,
  input logic [EyeBits-1:0]  eye_z_i,
  input logic                class_we_i,
  input logic                gmlut_we_i,
  input logic                dmap_we_i,
  input logic                smap_we_i,
  input logic                valid_i
);

  localparam int unsigned InFlight = Latency - 1;
  localparam int unsigned RegBits  = 6 + 3 * CoefBits + 3 * AlphaBits + 3 * EyeBits;

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  logic [RegBits-1:0]  regs, regs_q;
  logic [InFlight-1:0] entered;
  logic [3:0]          we;
  assign regs = {magnitude_i, shading_i, specular_i, gm_opacity_i, gm_diffuse_i, gm_specular_i, ke_i, kd_i, ks_i,
                 spec_red_i, spec_green_i, spec_blue_i, eye_x_i, eye_y_i, eye_z_i};
  assign we   = {class_we_i, gmlut_we_i, dmap_we_i, smap_we_i};
  cube4_sva_frame_registers #(.Width(RegBits), .Cycles(InFlight)) u_frame (
    .clk_i, .rst_ni, .valid_i, .regs_i(regs), .entered_o(entered), .regs_q_o(regs_q));

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_frame_registers_stable: assert (entered == '0 || (regs == regs_q && we == '0))
        else $error("cube4_shade: cycle %0d: with samples in flight (entered %b cycles ago, bit i: i+1): modes, coefficients or eye changed %0d, table writes (class, GmLUT, diffuse, specular) %b",
                    cycle, entered, regs != regs_q, we);
    end
  end

endmodule

bind cube4_shade cube4_shade_sva #(
  .AlphaBits(AlphaBits),
  .CoefBits (CoefBits),
  .EyeBits  (EyeBits),
  .Latency  (Latency)
) u_sva (.*);
