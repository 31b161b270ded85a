// Formal harness for cube4_composite: the compositing datapath never
// exceeds its saturation limits. Samples are A bits, the accumulator
// A + G bits (AccGuardBits); 1.0 is the all-ones value of each, so
// "alpha never above 1.0" means no sum wraps around its bits:
//   - the cut plane never raises a sample's opacity (cut alpha <= alpha);
//   - a premultiplied colour never exceeds its opacity (r, g, b <= alpha in
//     the accumulator domain, the property that keeps MIP/MinIP results and
//     the blend in range; premultiply()'s clamp);
//   - front to back (modes 0, 3): the new alpha is the old plus at most the
//     remaining transparency (alpha_o >= acc alpha: no wrap) and at most
//     the sample's premultiplied alpha; each colour saturates instead of
//     wrapping (c_o >= acc c);
//   - MIP/MinIP (modes 1, 2): the result is the accumulator unchanged or
//     the taken sample, whose colour is <= its alpha.
// Every input is free in every cycle (mode and cut registers too: the
// properties hold per sample whatever the frame registers do).
//
// Proof: 1-induction, strengthened with the unit's stage registers
// (probes): the alpha delay line equals the harness's, each stage's result
// is bounded by its predecessor's, registered one cycle back in the
// harness. The output stage is checked against the accumulator inputs of
// the cycle before (stage 7 registers them).
module composite_fv #(
  parameter int unsigned AlphaBits    = 16,
  parameter int unsigned AccGuardBits = 8,
  parameter bit          HasCutPlane  = 1'b1
) (
  input logic                   clk_i,
  input logic                   rst_ni,
  input logic [1:0]             blend_mode_i,
  input logic                   crop_enabled_i,
  input logic [15:0]            crop_x_lo_i,
  input logic [15:0]            crop_x_hi_i,
  input logic [15:0]            crop_y_lo_i,
  input logic [15:0]            crop_y_hi_i,
  input logic [15:0]            crop_z_lo_i,
  input logic [15:0]            crop_z_hi_i,
  input logic [7:0]             crop_mask_i,
  input logic                   window_enabled_i,
  input logic [15:0]            window_x_lo_i,
  input logic [15:0]            window_x_hi_i,
  input logic [15:0]            window_y_lo_i,
  input logic [15:0]            window_y_hi_i,
  input logic [15:0]            window_z_lo_i,
  input logic [15:0]            window_z_hi_i,
  input logic                   cut_enabled_i,
  input logic signed [11:0]     cut_a_i,
  input logic signed [11:0]     cut_b_i,
  input logic signed [11:0]     cut_c_i,
  input logic signed [31:0]     cut_dmin_i,
  input logic signed [31:0]     cut_dmax_i,
  input logic [31:0]            cut_falloff_i,
  input logic [AlphaBits+23:0]  cut_inv_falloff_i,
  input logic                   cut_keep_inside_i,
  input logic                   valid_i,
  input logic [AlphaBits-1:0]   red_i,
  input logic [AlphaBits-1:0]   green_i,
  input logic [AlphaBits-1:0]   blue_i,
  input logic [AlphaBits-1:0]   alpha_i,
  input logic [11:0]            value_i,
  input logic [15:0]            x_i,
  input logic [15:0]            y_i,
  input logic [15:0]            z_i,
  input logic [7:0]             wx_i,
  input logic [7:0]             wy_i,
  input logic [7:0]             wz_i,
  input logic [AlphaBits+AccGuardBits-1:0] acc_red_i,
  input logic [AlphaBits+AccGuardBits-1:0] acc_green_i,
  input logic [AlphaBits+AccGuardBits-1:0] acc_blue_i,
  input logic [AlphaBits+AccGuardBits-1:0] acc_alpha_i,
  input logic [11:0]            acc_value_i,
  input logic                   acc_selected_i
);

  localparam int unsigned A  = AlphaBits;
  localparam int unsigned G  = AccGuardBits;
  localparam int unsigned AB = AlphaBits + AccGuardBits;

  // golden to_acc(): the A-bit value in the accumulator domain.
  function automatic logic [AB-1:0] to_acc(input logic [A-1:0] v);
    to_acc = (AB'(v) << G) | (AB'(v) >> (A - G));
  endfunction

  logic          valid, selected;
  logic [AB-1:0] red, green, blue, alpha;
  logic [11:0]  value;

  cube4_composite #(
    .AlphaBits   (AlphaBits),
    .AccGuardBits(AccGuardBits),
    .HasCutPlane (HasCutPlane),
    // The proof as it was before polygons: the datapath without them (the
    // polygon variant's second node is left to the simulation tests).
    .HasPolygons (1'b0)
  ) u_dut (
    .clk_i,
    .rst_ni,
    .blend_mode_i,
    .crop_enabled_i,
    .crop_x_lo_i,
    .crop_x_hi_i,
    .crop_y_lo_i,
    .crop_y_hi_i,
    .crop_z_lo_i,
    .crop_z_hi_i,
    .crop_mask_i,
    .window_enabled_i,
    .window_x_lo_i,
    .window_x_hi_i,
    .window_y_lo_i,
    .window_y_hi_i,
    .window_z_lo_i,
    .window_z_hi_i,
    .cut_enabled_i,
    .cut_a_i,
    .cut_b_i,
    .cut_c_i,
    .cut_dmin_i,
    .cut_dmax_i,
    .cut_falloff_i,
    .cut_inv_falloff_i,
    .cut_keep_inside_i,
    .poly_enabled_i   (1'b0),
    .slice_k_i        ('0),
    .ray_z_i          ('0),
    .slab_red_i       ('0),
    .slab_green_i     ('0),
    .slab_blue_i      ('0),
    .slab_alpha_i     ('0),
    .valid_i,
    .red_i,
    .green_i,
    .blue_i,
    .alpha_i,
    .value_i,
    .x_i,
    .y_i,
    .z_i,
    .wx_i,
    .wy_i,
    .wz_i,
    .acc_red_i,
    .acc_green_i,
    .acc_blue_i,
    .acc_alpha_i,
    .acc_value_i,
    .acc_selected_i,
    .valid_o   (valid),
    .red_o     (red),
    .green_o   (green),
    .blue_o    (blue),
    .alpha_o   (alpha),
    .value_o   (value),
    .selected_o(selected)
  );

  // Probes (connected by scripts/formal.sh): stage registers.
  logic [4*A-1:0] probe_alpha_q;    // alpha delay line, stages 1..4
  logic [A-1:0]   probe_cut_alpha_q;
  logic [AB-1:0]  probe_pre_alpha_q;
  logic [AB-1:0]  probe_pre_red_q, probe_pre_green_q, probe_pre_blue_q;

  // The same values one cycle back, and the accumulator the output stage
  // consumed.
  logic [4*A-1:0] alpha_exp_q;
  logic [A-1:0]   alpha4_q, cut_alpha_prev_q;
  logic [AB-1:0]  pre_alpha_prev_q;
  logic [AB-1:0]  acc_red_q, acc_green_q, acc_blue_q, acc_alpha_q;
  logic [1:0]     mode_q;
  logic [3:0]     filled_q = '0;

  always_ff @(posedge clk_i) begin
    alpha_exp_q      <= {alpha_exp_q[0 +: 3*A], alpha_i};
    alpha4_q         <= probe_alpha_q[3*A +: A];
    cut_alpha_prev_q <= probe_cut_alpha_q;
    pre_alpha_prev_q <= probe_pre_alpha_q;
    acc_red_q        <= acc_red_i;
    acc_green_q      <= acc_green_i;
    acc_blue_q       <= acc_blue_i;
    acc_alpha_q      <= acc_alpha_i;
    mode_q           <= blend_mode_i;
    if (filled_q != 4'd15) filled_q <= filled_q + 4'd1;
  end

  logic front_to_back;
  assign front_to_back = mode_q == 2'd0 || mode_q == 2'd3;

  always_comb begin
    for (int unsigned k = 1; k <= 4; k++) begin
      if (filled_q >= 4'(k)) assert (probe_alpha_q[(k-1)*A +: A] == alpha_exp_q[(k-1)*A +: A]);
    end
    if (filled_q >= 4'd1) begin
      assert (probe_cut_alpha_q <= alpha4_q);
      assert (probe_pre_alpha_q == to_acc(cut_alpha_prev_q));
      assert (probe_pre_red_q <= probe_pre_alpha_q);
      assert (probe_pre_green_q <= probe_pre_alpha_q);
      assert (probe_pre_blue_q <= probe_pre_alpha_q);
    end
    // The output stage's inputs are the stage-6 registers of the cycle
    // before: checked once those have been checked.
    if (filled_q >= 4'd2) begin
      if (front_to_back) begin
        assert (alpha >= acc_alpha_q);
        assert (alpha - acc_alpha_q <= pre_alpha_prev_q);
        assert (red >= acc_red_q);
        assert (green >= acc_green_q);
        assert (blue >= acc_blue_q);
      end else begin
        assert (alpha == acc_alpha_q || alpha == pre_alpha_prev_q);
        if (alpha != acc_alpha_q) begin
          assert (red <= alpha && green <= alpha && blue <= alpha);
        end
      end
    end
  end

  logic unused_outputs;
  assign unused_outputs = ^{valid, value, selected};

endmodule
