// cube4_compose_node_sva: the compositing node's invariant and its
// frame-register rule (cube4_compose_node's header), as assertions bound
// to every node, the compositor's blend stage included:
//   a_alpha_no_wrap  - in over mode the composed α is never below the front
//                      pixel's: front.α + (1 - front.α)·back.α stays within
//                      1.0 (all ones), so a ray's accumulated α never passes
//                      1.0 and wraps to a small value (the compositor's
//                      accumulator is the front pixel of its blend);
//   a_mode_stable    - blend_mode_i does not change while a pixel is inside
//                      the node (Latency 2: stage 1 has chosen base and
//                      increment by the mode the add then uses);
// and, for coverage (scripts/coverage.sh), a colour channel's sum saturating
// in the add (c_colour_saturated: possible only in the network's add and
// overlay nodes, where both pixels carry colour).
//
// Simulation only: not part of the unit, never synthesised.
module cube4_compose_node_sva #(
  parameter int unsigned  AlphaBits    = 16,
  parameter int unsigned  AccGuardBits = 8,
  parameter int unsigned  Latency      = 2,
  localparam int unsigned AB           = AlphaBits + AccGuardBits
) (
  input logic              clk_i,
  input logic              rst_ni,
  input cube4_pkg::blend_e blend_mode_i,
  input logic              valid_i,
  input logic [AB-1:0]     front_alpha_i,
  input logic              valid_o,
  input logic [AB-1:0]     alpha_o,
  input logic [2:0]        colour_saturated  // internal: the add's carries
);

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  // The front α and the mode of each pixel, beside the node's stages (a
  // node of Latency 0 has none: its output is its input's).
  localparam int unsigned Stages = (Latency > 0) ? Latency : 1;
  logic [Stages*AB-1:0] front_q;
  logic [Stages*2-1:0]  mode_q;
  logic                  valid_q;  // a pixel entered in the cycle before
  always_ff @(posedge clk_i) begin
    front_q[0 +: AB] <= front_alpha_i;
    mode_q[0 +: 2]   <= blend_mode_i;
    for (int unsigned k = 1; k < Stages; k++) begin
      front_q[k*AB +: AB] <= front_q[(k-1)*AB +: AB];
      mode_q[k*2 +: 2]    <= mode_q[(k-1)*2 +: 2];
    end
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= 1'b0;
    end else begin
      valid_q <= valid_i;
    end
  end

  logic [AB-1:0] front_o;
  logic [1:0]    mode_o;
  assign front_o = (Latency == 0) ? front_alpha_i : front_q[(Stages-1)*AB +: AB];
  assign mode_o  = (Latency == 0) ? blend_mode_i : mode_q[(Stages-1)*2 +: 2];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_alpha_no_wrap: assert (!valid_o || mode_o == 2'(cube4_pkg::BlendMip) || mode_o == 2'(cube4_pkg::BlendMinIp)
                               || alpha_o >= front_o)
        else $error("cube4_compose_node: cycle %0d: over mode composed alpha %0d below the front pixel's %0d: the sum passed 1.0 (%0d)",
                    cycle, alpha_o, front_o, {AB{1'b1}});
      a_mode_stable: assert (Latency < 2 || !valid_q || blend_mode_i == mode_q[1:0])
        else $error("cube4_compose_node: cycle %0d: blend mode %0d -> %0d with a pixel inside the node",
                    cycle, mode_q[1:0], blend_mode_i);
    end
  end

  // The pixel in the add: the input's (Latency 0 or 1) or the one of the
  // cycle before (Latency 2).
  c_colour_saturated: cover property (@(posedge clk_i) (Latency == 2 ? valid_q : valid_i) && |colour_saturated);

endmodule

bind cube4_compose_node cube4_compose_node_sva #(
  .AlphaBits   (AlphaBits),
  .AccGuardBits(AccGuardBits),
  .Latency     (Latency)
) u_sva (.*);
