// cube4_compose_node: one node of an image composition network (bela
// §III.D): two partial-image pixel streams in visibility order, front and
// back, merged into one, one pixel per clock. Bit-exact with golden
// compose() (golden/units/compose.hpp):
//   over (mode 0, and 3):  t = one - front.alpha
//                          c = sat(front.c + mul_frac(t, back.c))    (red, green, blue)
//                          alpha = front.alpha + mul_frac(t, back.alpha)
//                          value, selected = the front's
//   MIP (1) / MinIP (2):   out = back if back.selected and (!front.selected
//                          or back.value > front.value (MIP) / < (MinIP)),
//                          else front (ties keep the front)
// Pixels are premultiplied R, G, B, α in the accumulator domain,
// AlphaBits + AccGuardBits bits (one = all ones), plus the MIP/MinIP selected
// sample value (VoxelBits) and its selected bit: golden RayAcc, the value a
// compositing unit holds for a ray (docs/rtl-compose.md).
//
// Both modes share one adder per colour channel: stage 1 picks the base
// pixel (front, or back when MIP/MinIP takes it) and the increment (the
// products mul_frac(t, back.c) in over mode, zero otherwise); the last stage
// adds them, saturated. The over mode's α is no sum but one product, the
// remaining transparency (bit-exact, see "alpha" below), chosen in stage 1.
// Overlay and underlay are this node with one input held at a layer pixel
// (a register or an image memory).
//
// Latency (valid_i to valid_o): Latency cycles, 2 (default), 1 or 0.
//   Latency 2: 1: transparency, the four products, base and α select
//              (registered)
//              2: add, saturate (output registers)
//   Latency 1: the same logic with no register between the products and the
//              add (the compositor's blend stage: the accumulator loop of one
//              cycle, cube4_composite).
//   Latency 0: no register at all: the node feeds another in the same cycle
//              (the compositor's blend stage with polygons, whose result a
//              second node composites over the slab pixel before the
//              register: Cube-5's double composition, cube4_composite).
// Fully pipelined, one pixel per clock. Handshake: valid-only; valid_i
// travels with the data to valid_o. Only the valid registers are reset.
// blend_mode_i is a frame register: change it only with no pixel in flight.
//
// Parameters (defaults = golden Precision): VoxelBits, AlphaBits,
// AccGuardBits (<= AlphaBits); Latency (0, 1 or 2).
`include "cube4_pkg.sv"

module cube4_compose_node #(
  parameter int unsigned VoxelBits    = cube4_pkg::VoxelBits,
  parameter int unsigned AlphaBits    = cube4_pkg::AlphaBits,
  parameter int unsigned AccGuardBits = cube4_pkg::AccGuardBits,
  parameter int unsigned Latency      = 2
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  input  cube4_pkg::blend_e                 blend_mode_i,
  input  logic                              valid_i,
  // Front pixel (nearer the viewer).
  input  logic [AlphaBits+AccGuardBits-1:0] front_red_i,
  input  logic [AlphaBits+AccGuardBits-1:0] front_green_i,
  input  logic [AlphaBits+AccGuardBits-1:0] front_blue_i,
  input  logic [AlphaBits+AccGuardBits-1:0] front_alpha_i,
  input  logic [VoxelBits-1:0]              front_value_i,
  input  logic                              front_selected_i,
  // Back pixel.
  input  logic [AlphaBits+AccGuardBits-1:0] back_red_i,
  input  logic [AlphaBits+AccGuardBits-1:0] back_green_i,
  input  logic [AlphaBits+AccGuardBits-1:0] back_blue_i,
  input  logic [AlphaBits+AccGuardBits-1:0] back_alpha_i,
  input  logic [VoxelBits-1:0]              back_value_i,
  input  logic                              back_selected_i,
  // Composed pixel.
  output logic                              valid_o,
  output logic [AlphaBits+AccGuardBits-1:0] red_o,
  output logic [AlphaBits+AccGuardBits-1:0] green_o,
  output logic [AlphaBits+AccGuardBits-1:0] blue_o,
  output logic [AlphaBits+AccGuardBits-1:0] alpha_o,
  output logic [VoxelBits-1:0]              value_o,
  output logic                              selected_o
);

  localparam int unsigned AB = AlphaBits + AccGuardBits;  // accumulator domain
  // A pixel as one vector: {red, green, blue, alpha, value, selected}.
  localparam int unsigned PixBits = 4 * AB + VoxelBits + 1;

  ///////////////////////////////////////////////////
  // Stage 1: transparency, products, base select  //
  ///////////////////////////////////////////////////
  logic extreme, back_wins, take_back;
  assign extreme   = (blend_mode_i == cube4_pkg::BlendMip) || (blend_mode_i == cube4_pkg::BlendMinIp);
  assign back_wins = (blend_mode_i == cube4_pkg::BlendMip) ? (back_value_i > front_value_i)
                                                           : (back_value_i < front_value_i);
  assign take_back = extreme && back_selected_i && (!front_selected_i || back_wins);

  logic [AB-1:0] transparency;
  assign transparency = {AB{1'b1}} - front_alpha_i;

  // golden mul_frac(t, back.c, AB), red, green, blue (red at [2*AB +: AB]).
  logic [3*AB-1:0] product;
  cube4_mul_frac #(.XBits(AB), .FBits(AB)) u_mul_red (
    .x_i(transparency), .f_i(back_red_i), .y_o(product[2*AB +: AB]));
  cube4_mul_frac #(.XBits(AB), .FBits(AB)) u_mul_green (
    .x_i(transparency), .f_i(back_green_i), .y_o(product[AB +: AB]));
  cube4_mul_frac #(.XBits(AB), .FBits(AB)) u_mul_blue (
    .x_i(transparency), .f_i(back_blue_i), .y_o(product[0 +: AB]));

  // The over mode's alpha, golden front.alpha + mul_frac(t, back.alpha), as
  // one minus the transparency left behind both pixels:
  //   front.alpha + mul_frac(t, back.alpha) = one - (t - mul_frac(t, back.alpha))
  //   t - mul_frac(t, f) = (t * unit(one - f) + 2^(AB-1) - 1) >> AB
  // with unit(f) = f + (f >> (AB-1)) (cube4_mul_frac), because
  // unit(one - f) = 2^AB - unit(f) and -floor(-x) = ceil(x): the product of
  // the two transparencies, ties rounded down (HalfDown). Bit-exact with
  // golden for every input, and no adder after the product: the sum's
  // carry-out is zero only because mul_frac(t, f) <= t, and abc's SAT
  // sweep (&fraig, scripts/gates.sh) spent minutes per node proving facts
  // of that kind through the multiplier (docs/gates.md).
  logic [AB-1:0] remaining, alpha_over;
  cube4_mul_frac #(.XBits(AB), .FBits(AB), .HalfDown(1'b1)) u_mul_alpha (
    .x_i(transparency), .f_i(~back_alpha_i), .y_o(remaining));
  assign alpha_over = ~remaining;

  // base: {red, green, blue, alpha, value, selected}; its alpha is the
  // result's (the increment has no alpha).
  logic [PixBits-1:0] base_d, base;
  logic [3*AB-1:0]    inc_d, inc;
  assign base_d = take_back ? {back_red_i, back_green_i, back_blue_i, back_alpha_i, back_value_i, back_selected_i}
                            : {front_red_i, front_green_i, front_blue_i,
                               extreme ? front_alpha_i : alpha_over, front_value_i, front_selected_i};
  assign inc_d  = extreme ? '0 : product;

  if (Latency == 2) begin : g_product_regs
    logic [PixBits-1:0] base_q;
    logic [3*AB-1:0]    inc_q;
    always_ff @(posedge clk_i) begin : stage1_regs
      base_q <= base_d;
      inc_q  <= inc_d;
    end
    assign base = base_q;
    assign inc  = inc_q;
  end else begin : g_no_product_regs
    assign base = base_d;
    assign inc  = inc_d;
  end

  ///////////////////////////////////////////
  // Last stage: add (colours saturated)   //
  ///////////////////////////////////////////
  // red, green, blue at [2], [1], [0]: base + increment, saturated where
  // the sum carries (colour_saturated, also the coverage checker's).
  logic [2:0]      colour_saturated;
  logic [3*AB-1:0] colour_sum;
  for (genvar ch = 0; ch < 3; ch++) begin : g_add
    assign {colour_saturated[ch], colour_sum[ch*AB +: AB]} =
        {1'b0, base[PixBits-1-(2-ch)*AB -: AB]} + {1'b0, inc[ch*AB +: AB]};
  end

  logic [PixBits-1:0] out_d;
  assign out_d = {colour_saturated[2] ? {AB{1'b1}} : colour_sum[2*AB +: AB],
                  colour_saturated[1] ? {AB{1'b1}} : colour_sum[AB +: AB],
                  colour_saturated[0] ? {AB{1'b1}} : colour_sum[0 +: AB],
                  base[PixBits-1-3*AB -: AB],
                  base[1 +: VoxelBits],
                  base[0]};

  if (Latency == 0) begin : g_comb_out
    // A node without registers keeps the clock and reset ports, so that
    // every latency has one interface; Verilator's -Wall skips *unused*.
    logic unused_clk_rst;
    assign unused_clk_rst = clk_i ^ rst_ni;
    assign {red_o, green_o, blue_o, alpha_o, value_o, selected_o} = out_d;
    assign valid_o = valid_i;
  end else begin : g_out_regs
    always_ff @(posedge clk_i) begin : out_regs
      {red_o, green_o, blue_o, alpha_o, value_o, selected_o} <= out_d;
    end

    logic [Latency-1:0] valid_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin : valid_regs
      if (!rst_ni) begin
        valid_q <= '0;
      end else begin
        valid_q[0] <= valid_i;
        for (int unsigned k = 1; k < Latency; k++) valid_q[k] <= valid_q[k-1];
      end
    end
    assign valid_o = valid_q[Latency-1];
  end

endmodule
