// cube4_composite: the compositing unit's datapath (VolumePro §3.6, §4.3):
// cropping, the block window, the cut plane and the blend of one shaded
// sample into its ray's accumulator. Bit-exact with the composition in
// golden shade_sample() (golden/pipeline.hpp) and golden blend()
// (golden/units/composite.hpp):
//   visible = crop_enabled ? crop_visible(x, y, z, crop) : 1
//   visible &= !window_enabled || window_inside(x, y, z, window)
//   if cut_enabled:
//     d       = cut_distance(cut, (x << W) + wx, (y << W) + wy, (z << W) + wz)
//     f       = cut_factor(d, cut)
//     alpha   = cut_alpha(alpha, f)          (mul_frac)
//     visible &= f != 0
//   acc' = blend(mode, acc, {rgb, alpha, value, visible})
// With polygons (HasPolygons and poly_enabled_i; Cube-5 §5, golden
// composite_polygon.hpp), the Z test and the double composition:
//   visible &= sample_before_z(k, z)        (k << ZFracBits < z)
//   acc' = ray_over_pixel(blend(composite, acc, sample), slab)
// i.e. golden double_composite(acc, sample, before_z, slab): the sample
// first, then the slab pixel behind it (widened by to_acc), each by a
// compositing node rounding once per channel; a blank slab pixel leaves the
// blend's result exactly. A hidden sample is an invisible one: over adds
// nothing (golden composites it not at all; the value is the same).
// blend: front-to-back (mode 0, and 3), MIP (1), MinIP (2); an invisible
// sample leaves the accumulator unchanged. Both blends use the premultiplied
// colour premultiply(c, alpha) (AlphaBits + AccGuardBits wide, golden
// premultiply()), so it is computed before the accumulator is needed, and
// the accumulator path is one multiply deep. The accumulator ports are
// AccGuardBits wider than the sample: the guard bits keep the sub-LSB
// contributions of translucent samples (docs/fixed-point.md).
//
// The ray-alignment FIFOs are outside: the predecessor accumulator acc_*_i
// enters AccDelay = 6 cycles after its sample (valid_i) and the result
// appears one cycle later, so the accumulator -> result loop has a latency
// of 1 cycle (what bounds back-to-back samples of one ray), while the
// sample -> result latency is Latency = 7 cycles:
//   1: crop and window compares, the three products of d
//                                                   2: d = sum, saturated
//   3: outside distance and comparisons             4: ramp (the wide product)
//   5: cut factor and cut_alpha                     6: premultiplied colour
//   7: blend with acc_*_i (driven in cycle 6): cube4_compose_node, Latency 1;
//      with polygons the same node at Latency 0 and a second node over the
//      slab pixel slab_*_i (driven in cycle 6 too), one register after both
// Fully pipelined, one sample per clock. Handshake: valid-only; valid_i
// travels with the data to valid_o (acc_*_i carries no valid of its own; it
// is ignored in cycles whose sample was not valid). Only the valid registers
// are reset. The crop, cut and mode inputs are frame registers: change them
// only while no sample is in flight.
//
// Register widths (golden holds them in int32/int64; the RTL domain):
//   x, y, z, crop slabs, window bounds: unsigned PosBits; wx, wy, wz: WeightBits;
//   cut a, b, c: signed CutCoefBits (host: |a| <= 2^10);
//   dmin, dmax: signed CutBits; falloff: unsigned CutBits;
//   inv_falloff: unsigned AlphaBits + CutInvShift (host: <= (2^A-1) * 2^24).
// The ramp product (falloff - outside) * inv_falloff is exact: its low
// AlphaBits + CutInvShift + 1 bits, and whether any partial product above
// them is set (stage 4).
//
// Parameters (defaults = golden Precision, kCutInvShift): VoxelBits,
// WeightBits, AlphaBits, AccGuardBits (<= AlphaBits), CutBits, CutInvShift;
// PosBits, CutCoefBits;
// HasCutPlane (0: no cut-plane hardware, cut_enabled_i is ignored; equals
// golden with cut_enabled false; same latency).
// HasPolygons (0: no Z test and no second node, poly_enabled_i, slice_k_i,
// ray_z_i and slab_*_i are ignored; equals golden without a PolygonFrame;
// same latency). With it the accumulator loop is two nodes deep (two
// multiplies and two adds in one cycle), the price of keeping the loop at
// one cycle, which the ray storage of cube4_composite_unit relies on.
//
// Polygon registers and inputs (docs/rtl-composite.md, "Polygons"):
//   poly_enabled_i: frame register; the blend mode must then be composite
//     (golden refuses polygons with MIP/MinIP).
//   slice_k_i (SliceBits), ray_z_i (ZBits): with the sample: its sample
//     slice k and its ray's depth Z (kZBits, kZFracBits).
//   slab_*_i (AlphaBits): the slab pixel behind the sample, premultiplied,
//     with the accumulator (AccDelay cycles after the sample).
`include "cube4_pkg.sv"

module cube4_composite #(
  parameter int unsigned VoxelBits   = cube4_pkg::VoxelBits,
  parameter int unsigned WeightBits  = cube4_pkg::WeightBits,
  parameter int unsigned AlphaBits   = cube4_pkg::AlphaBits,
  parameter int unsigned AccGuardBits = cube4_pkg::AccGuardBits,
  parameter int unsigned CutBits     = cube4_pkg::CutBits,
  parameter int unsigned CutInvShift = cube4_pkg::CutInvShift,
  parameter int unsigned PosBits     = cube4_pkg::PosBits,
  parameter int unsigned CutCoefBits = cube4_pkg::CutCoefBits,
  // 0: no cut-plane hardware (stages 1..5 keep their timing, the factor is
  // one); for machines and scenes without a cut plane (docs/rtl-composite.md).
  parameter bit          HasCutPlane = 1'b1,
  // 0: no polygon hardware (no Z test, one node); for scenes without polygons.
  parameter bit          HasPolygons = 1'b1,
  parameter int unsigned ZBits       = cube4_pkg::ZBits,
  parameter int unsigned ZFracBits   = cube4_pkg::ZFracBits,
  parameter int unsigned SliceBits   = cube4_pkg::SliceBits
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  // Frame registers: blend mode (golden BlendMode), cropping (CropRegs).
  input  cube4_pkg::blend_e                    blend_mode_i,
  input  logic                                 crop_enabled_i,
  input  logic [PosBits-1:0]                   crop_x_lo_i,
  input  logic [PosBits-1:0]                   crop_x_hi_i,
  input  logic [PosBits-1:0]                   crop_y_lo_i,
  input  logic [PosBits-1:0]                   crop_y_hi_i,
  input  logic [PosBits-1:0]                   crop_z_lo_i,
  input  logic [PosBits-1:0]                   crop_z_hi_i,
  input  logic [7:0]                           crop_mask_i,
  // Frame registers: the block window (WindowRegs; golden/blocks.hpp): the
  // samples of a partitioned volume's block that the block composites.
  input  logic                                 window_enabled_i,
  input  logic [PosBits-1:0]                   window_x_lo_i,
  input  logic [PosBits-1:0]                   window_x_hi_i,
  input  logic [PosBits-1:0]                   window_y_lo_i,
  input  logic [PosBits-1:0]                   window_y_hi_i,
  input  logic [PosBits-1:0]                   window_z_lo_i,
  input  logic [PosBits-1:0]                   window_z_hi_i,
  // Frame registers: cut plane (CutRegs).
  input  logic                                 cut_enabled_i,
  input  logic signed [CutCoefBits-1:0]        cut_a_i,
  input  logic signed [CutCoefBits-1:0]        cut_b_i,
  input  logic signed [CutCoefBits-1:0]        cut_c_i,
  input  logic signed [CutBits-1:0]            cut_dmin_i,
  input  logic signed [CutBits-1:0]            cut_dmax_i,
  input  logic [CutBits-1:0]                   cut_falloff_i,
  input  logic [AlphaBits+CutInvShift-1:0]     cut_inv_falloff_i,
  input  logic                                 cut_keep_inside_i,
  // Frame register: polygons (Cube-5), and per sample its slice and its
  // ray's depth; the slab pixel behind it comes with the accumulator.
  input  logic                                 poly_enabled_i,
  input  logic [SliceBits-1:0]                 slice_k_i,
  input  logic [ZBits-1:0]                     ray_z_i,
  input  logic [AlphaBits-1:0]                 slab_red_i,
  input  logic [AlphaBits-1:0]                 slab_green_i,
  input  logic [AlphaBits-1:0]                 slab_blue_i,
  input  logic [AlphaBits-1:0]                 slab_alpha_i,
  // Shaded sample and its position (x, y, z_voxel, slice weights).
  input  logic                                 valid_i,
  input  logic [AlphaBits-1:0]                 red_i,
  input  logic [AlphaBits-1:0]                 green_i,
  input  logic [AlphaBits-1:0]                 blue_i,
  input  logic [AlphaBits-1:0]                 alpha_i,
  input  logic [VoxelBits-1:0]                 value_i,
  input  logic [PosBits-1:0]                   x_i,
  input  logic [PosBits-1:0]                   y_i,
  input  logic [PosBits-1:0]                   z_i,
  input  logic [WeightBits-1:0]                wx_i,
  input  logic [WeightBits-1:0]                wy_i,
  input  logic [WeightBits-1:0]                wz_i,
  // Predecessor accumulator (golden RayAcc), AccDelay cycles after valid_i.
  input  logic [AlphaBits+AccGuardBits-1:0]    acc_red_i,
  input  logic [AlphaBits+AccGuardBits-1:0]    acc_green_i,
  input  logic [AlphaBits+AccGuardBits-1:0]    acc_blue_i,
  input  logic [AlphaBits+AccGuardBits-1:0]    acc_alpha_i,
  input  logic [VoxelBits-1:0]                 acc_value_i,
  input  logic                                 acc_selected_i,  // RayAcc::valid
  // New accumulator.
  output logic                                 valid_o,
  output logic [AlphaBits+AccGuardBits-1:0]    red_o,
  output logic [AlphaBits+AccGuardBits-1:0]    green_o,
  output logic [AlphaBits+AccGuardBits-1:0]    blue_o,
  output logic [AlphaBits+AccGuardBits-1:0]    alpha_o,
  output logic [VoxelBits-1:0]                 value_o,
  output logic                                 selected_o
);

  localparam int unsigned A        = AlphaBits;
  localparam int unsigned G        = AccGuardBits;
  localparam int unsigned AB       = AlphaBits + AccGuardBits;       // accumulator domain
  localparam int unsigned PwBits   = PosBits + WeightBits;           // (x << W) + wx
  localparam int unsigned TermBits = CutCoefBits + PwBits;           // a * X, signed
  localparam int unsigned SumBits  = TermBits + 2;                   // a*X + b*Y + c*Z
  localparam int unsigned DBits    = (SumBits > CutBits) ? SumBits : CutBits;
  localparam int unsigned InvBits  = AlphaBits + CutInvShift;
  localparam int unsigned Latency  = 7;


  logic [Latency-2:0] valid_q;  // stages 1..6

  ////////////////////////////////////////////////
  // Stage 1: crop compares                     //
  ////////////////////////////////////////////////
  logic in_x, in_y, in_z, crop_visible;
  assign in_x = (crop_x_lo_i <= x_i) && (x_i <= crop_x_hi_i);
  assign in_y = (crop_y_lo_i <= y_i) && (y_i <= crop_y_hi_i);
  assign in_z = (crop_z_lo_i <= z_i) && (z_i <= crop_z_hi_i);
  assign crop_visible = !crop_enabled_i || crop_mask_i[{in_z, in_y, in_x}];

  // The block window: its own six compares, ANDed after the crop table
  // (which a window cannot be folded into: golden composite_window.hpp).
  logic in_window;
  assign in_window = (window_x_lo_i <= x_i) && (x_i <= window_x_hi_i) &&
                     (window_y_lo_i <= y_i) && (y_i <= window_y_hi_i) &&
                     (window_z_lo_i <= z_i) && (z_i <= window_z_hi_i);

  // The Z test (golden sample_before_z): k << ZFracBits < Z; a sample at
  // the surface's depth is hidden.
  logic before_z;
  if (HasPolygons) begin : g_z_test
    localparam int unsigned KzBits = (SliceBits + ZFracBits > ZBits) ? SliceBits + ZFracBits : ZBits;
    assign before_z = !poly_enabled_i || (KzBits'({slice_k_i, ZFracBits'(0)}) < KzBits'(ray_z_i));
  end else begin : g_no_z_test
    assign before_z = 1'b1;
    logic unused_z_inputs;
    assign unused_z_inputs = ^{poly_enabled_i, slice_k_i, ray_z_i};
  end

  logic [3:0]                 visible1_q;  // crop visibility, stages 1..4
  // Alpha delay line (stages 1..4), stage k at [(k-1)*A +: A]; the colour
  // (5 stages) and the value (6) wait in cube4_pipe_delay.
  logic [4*A-1:0]             alpha_q;
  logic [3*A-1:0]             rgb_5;
  logic [VoxelBits-1:0]       value_6;
  cube4_pipe_delay #(.Width(3 * A), .Depth(5)) u_rgb_delay (
    .clk_i, .d_i({red_i, green_i, blue_i}), .q_o(rgb_5)
  );
  cube4_pipe_delay #(.Width(VoxelBits), .Depth(6)) u_value_delay (.clk_i, .d_i(value_i), .q_o(value_6));

  always_ff @(posedge clk_i) begin : stage1_regs
    visible1_q[0] <= crop_visible && (!window_enabled_i || in_window) && before_z;
    alpha_q[0 +: A]           <= alpha_i;
  end

  // The sample's data waits for the cut factor.
  always_ff @(posedge clk_i) begin : sample_delay
    for (int unsigned k = 1; k < 4; k++) visible1_q[k] <= visible1_q[k-1];
    for (int unsigned k = 1; k < 4; k++) alpha_q[k*A +: A] <= alpha_q[(k-1)*A +: A];
  end

  // The cut factor of the sample in stage 5 (one: no cut-plane hardware).
  logic [A-1:0] factor;
  // Where that sample lies (inside the slab; beyond the falloff; else on the
  // ramp) and whether its distance saturated (stage 2) or its ramp did
  // (stage 4): module-level names for the coverage checker (rtl/assert).
  logic cut_in_slab, cut_beyond, cut_distance_hi, cut_distance_lo, cut_ramp_saturated;
  if (HasCutPlane) begin : g_cut_plane
    ////////////////////////////////////////////////
    // Stage 1: the three products of d           //
    ////////////////////////////////////////////////
    logic signed [TermBits-1:0] term_x, term_y, term_z;
    assign term_x = TermBits'(cut_a_i) * $signed(TermBits'({x_i, wx_i}));
    assign term_y = TermBits'(cut_b_i) * $signed(TermBits'({y_i, wy_i}));
    assign term_z = TermBits'(cut_c_i) * $signed(TermBits'({z_i, wz_i}));

    logic signed [TermBits-1:0] term_x_q, term_y_q, term_z_q;
    always_ff @(posedge clk_i) begin : stage1_terms
      term_x_q <= term_x;
      term_y_q <= term_y;
      term_z_q <= term_z;
    end

    ///////////////////////////////////////////
    // Stage 2: d = sat_signed(sum, CutBits) //
    ///////////////////////////////////////////
    localparam logic signed [DBits-1:0] DMax = DBits'((64'd1 << (CutBits - 1)) - 1);

    logic signed [DBits-1:0]   dist_sum;
    logic signed [CutBits-1:0] dist_d, dist_q;
    assign dist_sum = DBits'(term_x_q) + DBits'(term_y_q) + DBits'(term_z_q);
    assign cut_distance_hi = dist_sum > DMax;
    assign cut_distance_lo = dist_sum < -DMax;
    always_comb begin : saturate_distance
      if (cut_distance_hi) begin
        dist_d = CutBits'(DMax);
      end else if (cut_distance_lo) begin
        dist_d = CutBits'(-DMax);
      end else begin
        dist_d = CutBits'(dist_sum);
      end
    end

    always_ff @(posedge clk_i) begin : stage2_regs
      dist_q <= dist_d;
    end

    ////////////////////////////////////////////////////////////
    // Stage 3: distance outside [dmin, dmax], against falloff //
    ////////////////////////////////////////////////////////////
    // d - dmin and d - dmax fit CutBits+1 signed bits; the outside distance
    // (dmin - d or d - dmax, when positive) fits CutBits unsigned bits.
    logic signed [CutBits:0] below_diff, above_diff;
    logic                    below, above;
    logic [CutBits-1:0]      outside;
    assign below_diff = (CutBits+1)'(cut_dmin_i) - (CutBits+1)'(dist_q);
    assign above_diff = (CutBits+1)'(dist_q) - (CutBits+1)'(cut_dmax_i);
    assign below      = dist_q < cut_dmin_i;
    assign above      = dist_q > cut_dmax_i;
    assign outside    = below ? below_diff[CutBits-1:0]
                      : above ? above_diff[CutBits-1:0] : '0;

    logic unused_diff_msbs;
    assign unused_diff_msbs = below_diff[CutBits] ^ above_diff[CutBits];

    logic               in_slab_q, beyond_q;
    logic [CutBits-1:0] ramp_span_q;
    always_ff @(posedge clk_i) begin : stage3_regs
      in_slab_q   <= !below && !above;
      beyond_q    <= outside >= cut_falloff_i;
      ramp_span_q <= cut_falloff_i - outside;  // used only when outside < falloff
    end

    ////////////////////////////////////////////////////////////////////////
    // Stage 4: ramp = round_shift(span * inv_falloff, CutInvShift), <= one //
    ////////////////////////////////////////////////////////////////////////
    // The ramp is above one (saturates) iff prod + half >= 2^InvBits
    // (InvBits = CutInvShift + A). The full product is CutBits + InvBits
    // bits, but only its low InvBits + 1 bits ever reach the result:
    //   - if a partial product of weight >= 2^InvBits is set (span bit i and
    //     inv_falloff bit j, i + j >= InvBits), prod >= 2^InvBits: saturated;
    //   - if none is, span < 2^(i+1) and inv_falloff < 2^(j+1) for their
    //     leading ones i, j with i + j < InvBits, so prod < 2^(InvBits+1)
    //     and its low InvBits + 1 bits are all of it.
    // The first test is an AND-OR of the operands' bits (high_pp); the
    // product is truncated to InvBits + 1 bits (about 815 partial products
    // instead of 1,280 at the defaults). The same ramp, bit for bit, as the
    // full product's; the full product's saturation (the OR of its 33 top
    // bits, set by nearly every random operand pair) cost abc's SAT sweep
    // (scripts/gates.sh) minutes of counterexample search (docs/gates.md).
    localparam logic [InvBits+1:0] RampHalf = (InvBits+2)'(1) << (CutInvShift - 1);

    logic [CutBits-1:0]  high_pp;   // span bit i with inv_falloff bits of weight >= 2^(InvBits-i)
    logic [InvBits:0]    ramp_low;  // prod mod 2^(InvBits+1)
    logic [InvBits+1:0]  ramp_sum;
    logic [A-1:0]        ramp_d, ramp_q;
    logic                in_slab_qq, beyond_qq;
    for (genvar i = 0; i < CutBits; i++) begin : g_high_pp
      // inv_falloff's bits j >= InvBits - i (j < InvBits: none for i = 0).
      localparam int unsigned JMin = (i >= InvBits) ? 0 : InvBits - i;
      if (JMin < InvBits) begin : g_pp
        assign high_pp[i] = ramp_span_q[i] && |cut_inv_falloff_i[InvBits-1:JMin];
      end else begin : g_no_pp
        assign high_pp[i] = 1'b0;
      end
    end
    assign ramp_low = (InvBits+1)'(ramp_span_q) * (InvBits+1)'(cut_inv_falloff_i);
    assign ramp_sum = (InvBits+2)'(ramp_low) + RampHalf;
    assign cut_ramp_saturated = |high_pp || |ramp_sum[InvBits+1:InvBits];
    assign ramp_d = cut_ramp_saturated ? {A{1'b1}} : ramp_sum[InvBits-1:CutInvShift];

    logic unused_ramp_lsbs;
    assign unused_ramp_lsbs = ^ramp_sum[CutInvShift-1:0];

    always_ff @(posedge clk_i) begin : stage4_regs
      ramp_q     <= ramp_d;
      in_slab_qq <= in_slab_q;
      beyond_qq  <= beyond_q;
    end

    ////////////////////////////////////////////////
    // Stage 5: cut factor, cut_alpha, visibility //
    ////////////////////////////////////////////////
    logic [A-1:0] inside_factor;
    always_comb begin : cut_factor
      if (cut_in_slab) begin
        inside_factor = {A{1'b1}};
      end else if (cut_beyond) begin
        inside_factor = '0;
      end else begin
        inside_factor = ramp_q;
      end
      factor = cut_keep_inside_i ? inside_factor : {A{1'b1}} - inside_factor;
    end
    assign cut_in_slab = in_slab_qq;
    assign cut_beyond  = beyond_qq;
  end else begin : g_no_cut_plane
    assign factor = {A{1'b1}};
    assign {cut_in_slab, cut_beyond, cut_distance_hi, cut_distance_lo, cut_ramp_saturated} = '0;
    // The cut-plane registers and the weights (used only for d) stay ports,
    // so that both variants connect alike; the cut's coverage names stay
    // too (constant here), for one checker of both.
    logic unused_cut_inputs;
    assign unused_cut_inputs = ^{cut_a_i, cut_b_i, cut_c_i, cut_dmin_i, cut_dmax_i, cut_falloff_i,
                                 cut_inv_falloff_i, cut_keep_inside_i, wx_i, wy_i, wz_i, cut_in_slab,
                                 cut_beyond, cut_distance_hi, cut_distance_lo, cut_ramp_saturated};
  end

  logic [A-1:0] cut_alpha;
  cube4_mul_frac #(.XBits(A), .FBits(A)) u_cut_alpha (
    .x_i(alpha_q[3*A +: A]), .f_i(factor), .y_o(cut_alpha));

  logic [A-1:0] cut_alpha_q;
  logic         visible_q;
  always_ff @(posedge clk_i) begin : stage5_regs
    cut_alpha_q <= (HasCutPlane && cut_enabled_i) ? cut_alpha : alpha_q[3*A +: A];
    visible_q   <= visible1_q[3] && (!(HasCutPlane && cut_enabled_i) || factor != '0);
  end

  ///////////////////////////////////////////
  // Stage 6: premultiplied sample colour  //
  ///////////////////////////////////////////
  // golden premultiply() = min(mul_frac(to_acc(c), alpha, A), to_acc(alpha)):
  // the product is never above to_acc(c), so AB bits hold it; the clamp
  // keeps premultiplied colour <= alpha (a no-op when G = 0).
  // The clamp compares only the guard bits: the product is at most
  // alpha * 2^G + 2^G - 1 (to_acc(c) <= 2^AB - 1, and mul_frac's rounding
  // reaches (alpha + 1) * 2^G - 1 only from alpha >= 2^(A-1), where
  // unit(alpha) = alpha + 1), so its top A bits never exceed alpha, the top
  // A bits of the limit: product > limit exactly when those are equal and
  // the product's guard bits exceed the limit's. A full AB-bit compare
  // computes the same bit, but abc's SAT sweep (scripts/gates.sh) spent
  // minutes proving through the multiplier that its upper part never
  // decides (docs/gates.md).
  logic [AB-1:0]   pre_limit;
  logic [3*AB-1:0] pre_product, premultiplied;  // blue at [0 +: AB], green, red
  logic [2:0]      pre_clamped;                  // the clamp acts (coverage checker)
  cube4_to_acc #(.AlphaBits(A), .AccGuardBits(G)) u_alpha_acc (.pixel_i(cut_alpha_q), .acc_o(pre_limit));
  for (genvar ch = 0; ch < 3; ch++) begin : g_premultiply
    logic [AB-1:0] colour;
    cube4_to_acc #(.AlphaBits(A), .AccGuardBits(G)) u_colour_acc (
      .pixel_i(rgb_5[ch*A +: A]), .acc_o(colour));
    cube4_mul_frac #(.XBits(AB), .FBits(A)) u_product (
      .x_i(colour), .f_i(cut_alpha_q), .y_o(pre_product[ch*AB +: AB]));
    if (G > 0) begin : g_clamp
      assign pre_clamped[ch] = (pre_product[ch*AB+G +: A] == cut_alpha_q)
                            && (pre_product[ch*AB +: G] > pre_limit[G-1:0]);
    end else begin : g_no_clamp
      assign pre_clamped[ch] = 1'b0;  // the product is at most alpha
    end
    assign premultiplied[ch*AB +: AB] = pre_clamped[ch] ? pre_limit : pre_product[ch*AB +: AB];
  end

  logic [AB-1:0] pre_red_q, pre_green_q, pre_blue_q, pre_alpha_q;
  logic          pre_visible_q;
  always_ff @(posedge clk_i) begin : stage6_regs
    pre_red_q     <= premultiplied[2*AB +: AB];
    pre_green_q   <= premultiplied[AB +: AB];
    pre_blue_q    <= premultiplied[0 +: AB];
    pre_alpha_q   <= pre_limit;
    pre_visible_q <= visible_q;
  end

  ////////////////////////////////////////////////
  // Stage 7: blend with the accumulator        //
  ////////////////////////////////////////////////
  // golden blend() = compose(mode, acc, sample_pixel(s)): the compositing
  // node with the accumulator in front and the sample behind, one cycle
  // (Latency 1: the products and the add before one register). An
  // invisible sample is the empty pixel: over adds nothing, MIP/MinIP
  // never take it.
  logic [AB-1:0] back_red, back_green, back_blue, back_alpha;
  assign back_red   = pre_visible_q ? pre_red_q   : '0;
  assign back_green = pre_visible_q ? pre_green_q : '0;
  assign back_blue  = pre_visible_q ? pre_blue_q  : '0;
  assign back_alpha = pre_visible_q ? pre_alpha_q : '0;

  // With polygons the blend node is combinational and a second node puts
  // the slab pixel behind its result before the output register: one cycle
  // still, two nodes deep.
  localparam int unsigned BlendLatency = HasPolygons ? 0 : 1;

  logic          blend_valid, blend_selected;
  logic [AB-1:0] blend_red, blend_green, blend_blue, blend_alpha;
  logic [VoxelBits-1:0] blend_value;

  cube4_compose_node #(
    .VoxelBits(VoxelBits), .AlphaBits(AlphaBits), .AccGuardBits(AccGuardBits), .Latency(BlendLatency)
  ) u_blend (
    .clk_i,
    .rst_ni,
    .blend_mode_i,
    .valid_i          (valid_q[Latency-2]),
    .front_red_i      (acc_red_i),
    .front_green_i    (acc_green_i),
    .front_blue_i     (acc_blue_i),
    .front_alpha_i    (acc_alpha_i),
    .front_value_i    (acc_value_i),
    .front_selected_i (acc_selected_i),
    .back_red_i       (back_red),
    .back_green_i     (back_green),
    .back_blue_i      (back_blue),
    .back_alpha_i     (back_alpha),
    .back_value_i     (value_6),
    .back_selected_i  (pre_visible_q),
    .valid_o          (blend_valid),
    .red_o            (blend_red),
    .green_o          (blend_green),
    .blue_o           (blend_blue),
    .alpha_o          (blend_alpha),
    .value_o          (blend_value),
    .selected_o       (blend_selected)
  );

  if (HasPolygons) begin : g_slab
    // golden ray_over_pixel(ray, slab): the slab pixel widened by to_acc,
    // behind the ray, by the node in over mode (the polygon frame's blend
    // is composite). A blank pixel (or polygons off) adds nothing: the ray
    // passes unchanged, its MIP value and selected bit included.
    logic [4*AB-1:0] slab_acc;  // red at [3*AB +: AB], green, blue, alpha
    cube4_to_acc #(.AlphaBits(A), .AccGuardBits(G)) u_slab_red   (.pixel_i(slab_red_i),   .acc_o(slab_acc[3*AB +: AB]));
    cube4_to_acc #(.AlphaBits(A), .AccGuardBits(G)) u_slab_green (.pixel_i(slab_green_i), .acc_o(slab_acc[2*AB +: AB]));
    cube4_to_acc #(.AlphaBits(A), .AccGuardBits(G)) u_slab_blue  (.pixel_i(slab_blue_i),  .acc_o(slab_acc[AB +: AB]));
    cube4_to_acc #(.AlphaBits(A), .AccGuardBits(G)) u_slab_alpha (.pixel_i(slab_alpha_i), .acc_o(slab_acc[0 +: AB]));
    logic [AB-1:0] slab_red, slab_green, slab_blue, slab_alpha;
    assign {slab_red, slab_green, slab_blue, slab_alpha} = poly_enabled_i ? slab_acc : '0;

    cube4_compose_node #(
      .VoxelBits(VoxelBits), .AlphaBits(AlphaBits), .AccGuardBits(AccGuardBits), .Latency(1)
    ) u_slab (
      .clk_i,
      .rst_ni,
      .blend_mode_i     (cube4_pkg::BlendComposite),
      .valid_i          (blend_valid),
      .front_red_i      (blend_red),
      .front_green_i    (blend_green),
      .front_blue_i     (blend_blue),
      .front_alpha_i    (blend_alpha),
      .front_value_i    (blend_value),
      .front_selected_i (blend_selected),
      .back_red_i       (slab_red),
      .back_green_i     (slab_green),
      .back_blue_i      (slab_blue),
      .back_alpha_i     (slab_alpha),
      .back_value_i     ('0),
      .back_selected_i  (1'b0),
      .valid_o,
      .red_o,
      .green_o,
      .blue_o,
      .alpha_o,
      .value_o,
      .selected_o
    );
  end else begin : g_no_slab
    assign {valid_o, red_o, green_o, blue_o, alpha_o, value_o, selected_o} =
        {blend_valid, blend_red, blend_green, blend_blue, blend_alpha, blend_value, blend_selected};
    logic unused_slab_inputs;
    assign unused_slab_inputs = ^{slab_red_i, slab_green_i, slab_blue_i, slab_alpha_i};
  end

  // Stages 1..6 (the node holds the last valid register).
  always_ff @(posedge clk_i or negedge rst_ni) begin : valid_regs
    if (!rst_ni) begin
      valid_q <= '0;
    end else begin
      valid_q <= {valid_q[Latency-3:0], valid_i};
    end
  end

endmodule
