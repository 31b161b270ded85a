// cube4_shade_cube_coord: cube-map coordinates of an unnormalised vector,
// bit-exact with golden cube_coordinates() (golden/units/shade_cube_map.hpp).
//   face  = 2*axis + (c[axis] < 0), axis = the largest |component|, ties to
//           the lower axis (x before y before z);
//   m     = |c[axis]|, s = the in-plane component (x: y,z; y: z,x; z: x,y);
//   pos   = ((s + m) * (MapFaceRes-1) << WeightBits) / (2m), truncating;
//   cell  = pos >> WeightBits, weight = pos mod 2^WeightBits, except s = m
//           (the far edge): cell MapFaceRes-2 at weight 2^WeightBits.
// The zero vector gives coord_valid_o = 0 and zero face/cells/weights
// (golden CubeCoord{}).
//
// The two divisions (u and v) share the divisor 2m and run in a pipelined
// restoring divider: quotient bit i is set iff the remainder is at least
// 2m << i, resolved from the top, DivBitsPerStage bits per pipeline stage.
// The quotient has QuoBits = $clog2(MapFaceRes) + WeightBits bits (pos is at
// most (MapFaceRes-1) << WeightBits). The far edge is detected before the
// division (s + m == 2m), so the fix-up needs no comparison of pos.
//
// Inputs: any two's-complement value of GradientBits (the golden gradient is
// symmetric, ±(2^(GradientBits-1)-1), but -2^(GradientBits-1) works too).
//
// Latency: 1 + ceil(QuoBits / DivBitsPerStage) cycles (defaults: 1 + 6 = 7):
// one stage of face selection, then the divider stages (the last one also
// applies the far-edge fix-up and the zero-vector mask). Fully pipelined,
// one vector per clock. Handshake: valid-only; valid_i travels with the data
// to valid_o. Only the valid registers are reset.
//
// Parameters: GradientBits, WeightBits, MapFaceRes (golden Precision
// defaults), DivBitsPerStage (quotient bits per pipeline stage, >= 1).
`include "cube4_pkg.sv"

module cube4_shade_cube_coord #(
  parameter int unsigned GradientBits    = cube4_pkg::GradientBits,
  parameter int unsigned WeightBits      = cube4_pkg::WeightBits,
  parameter int unsigned MapFaceRes      = cube4_pkg::MapFaceRes,
  parameter int unsigned DivBitsPerStage = cube4_pkg::DivBitsPerStage
) (
  input  logic                               clk_i,
  input  logic                               rst_ni,
  input  logic                               valid_i,
  input  logic signed [GradientBits-1:0]     x_i,
  input  logic signed [GradientBits-1:0]     y_i,
  input  logic signed [GradientBits-1:0]     z_i,
  output logic                               valid_o,
  output logic                               coord_valid_o,
  output logic [2:0]                         face_o,
  output logic [$clog2(MapFaceRes)-1:0]      u_o,
  output logic [$clog2(MapFaceRes)-1:0]      v_o,
  output logic [WeightBits:0]                wu_o,
  output logic [WeightBits:0]                wv_o
);

  localparam int unsigned G            = GradientBits;
  localparam int unsigned CellBits     = $clog2(MapFaceRes);
  localparam int unsigned QuoBits      = CellBits + WeightBits;
  // s + m lies in [0, 2m]: G+1 bits; times (MapFaceRes-1): HiBits.
  localparam int unsigned HiBits       = G + 1 + CellBits;
  localparam int unsigned NumBits      = HiBits + WeightBits;
  localparam int unsigned NumDivStages = (QuoBits + DivBitsPerStage - 1) / DivBitsPerStage;
  localparam int unsigned LastStage    = NumDivStages - 1;

  /////////////////////////////
  // Stage 0: face selection //
  /////////////////////////////
  logic [G-1:0] ax, ay, az;
  assign ax = x_i[G-1] ? G'(-x_i) : G'(x_i);
  assign ay = y_i[G-1] ? G'(-y_i) : G'(y_i);
  assign az = z_i[G-1] ? G'(-z_i) : G'(z_i);

  logic sel_x, sel_y;
  assign sel_x = (ax >= ay) && (ax >= az);
  assign sel_y = !sel_x && (ay >= az);

  logic [G-1:0]        major;
  logic signed [G-1:0] s_u, s_v;
  logic [1:0]          axis;
  logic                negative;

  always_comb begin : face_select
    if (sel_x) begin
      axis = 2'd0; major = ax; negative = x_i[G-1]; s_u = y_i; s_v = z_i;
    end else if (sel_y) begin
      axis = 2'd1; major = ay; negative = y_i[G-1]; s_u = z_i; s_v = x_i;
    end else begin
      axis = 2'd2; major = az; negative = z_i[G-1]; s_u = x_i; s_v = y_i;
    end
  end

  // s + m in [0, 2m], non-negative in G+1 bits.
  logic [G:0] t_u, t_v, two_m;
  assign t_u   = (G+1)'(s_u) + (G+1)'(major);
  assign t_v   = (G+1)'(s_v) + (G+1)'(major);
  assign two_m = {major, 1'b0};

  logic [HiBits-1:0] hi_u, hi_v;
  assign hi_u = HiBits'(t_u) * HiBits'(MapFaceRes - 1);
  assign hi_v = HiBits'(t_v) * HiBits'(MapFaceRes - 1);

  //////////////////////////////////
  // Stages 1..: restoring divider //
  //////////////////////////////////
  // Divider stage k, a generate block each: its registers (*_q: the
  // previous stage's outputs, stage 0's the face selection's) and its
  // outputs (*_d). A block per stage, not one flattened vector of all
  // stages: Verilator then evaluates each stage's fields as words, not as
  // part-selects of a vector of several words (docs/performance.md).
  localparam int unsigned N = NumDivStages;
  for (genvar k = 0; k < N; k++) begin : g_div
    logic [NumBits-1:0] rem_u_q, rem_v_q, rem_u_d, rem_v_d;
    logic [QuoBits-1:0] quo_u_q, quo_v_q, quo_u_d, quo_v_d;
    logic [G-1:0]       major_q;
    logic [2:0]         face_q;
    logic               far_u_q, far_v_q, nonzero_q;

    // Each step: one subtractor whose borrow is the quotient bit, and a
    // select keeping the difference if it did not borrow (as cube4_udiv:
    // no compare-then-subtract if, which Verilator made a branch on the data).
    always_comb begin : divide
      logic [NumBits-1:0] step_divisor;
      logic [NumBits:0]   diff_u, diff_v;
      logic               fits_u, fits_v;
      rem_u_d = rem_u_q;
      rem_v_d = rem_v_q;
      quo_u_d = quo_u_q;
      quo_v_d = quo_v_q;
      // Quotient bit QuoBits-1 - (k*DivBitsPerStage + j).
      for (int j = 0; j < DivBitsPerStage; j++) begin
        if (k * DivBitsPerStage + j < QuoBits) begin
          // 2m << bit
          step_divisor = NumBits'(major_q) << (QuoBits - k * DivBitsPerStage - j);
          diff_u  = {1'b0, rem_u_d} - {1'b0, step_divisor};
          diff_v  = {1'b0, rem_v_d} - {1'b0, step_divisor};
          fits_u  = !diff_u[NumBits];
          fits_v  = !diff_v[NumBits];
          rem_u_d = fits_u ? diff_u[NumBits-1:0] : rem_u_d;
          rem_v_d = fits_v ? diff_v[NumBits-1:0] : rem_v_d;
          quo_u_d[QuoBits - 1 - k * DivBitsPerStage - j] = fits_u;
          quo_v_d[QuoBits - 1 - k * DivBitsPerStage - j] = fits_v;
        end
      end
    end

    if (k == 0) begin : g_first
      always_ff @(posedge clk_i) begin : divider_regs
        rem_u_q   <= {hi_u, {WeightBits{1'b0}}};
        rem_v_q   <= {hi_v, {WeightBits{1'b0}}};
        quo_u_q   <= '0;
        quo_v_q   <= '0;
        major_q   <= major;
        face_q    <= {axis, negative};
        far_u_q   <= (t_u == two_m);
        far_v_q   <= (t_v == two_m);
        nonzero_q <= |{x_i, y_i, z_i};
      end
    end else begin : g_next
      always_ff @(posedge clk_i) begin : divider_regs
        rem_u_q   <= g_div[k-1].rem_u_d;
        rem_v_q   <= g_div[k-1].rem_v_d;
        quo_u_q   <= g_div[k-1].quo_u_d;
        quo_v_q   <= g_div[k-1].quo_v_d;
        major_q   <= g_div[k-1].major_q;
        face_q    <= g_div[k-1].face_q;
        far_u_q   <= g_div[k-1].far_u_q;
        far_v_q   <= g_div[k-1].far_v_q;
        nonzero_q <= g_div[k-1].nonzero_q;
      end
    end
  end

  // Only the last stage's quotients are used, not its remainders.
  logic unused_d;
  assign unused_d = ^{g_div[LastStage].rem_u_d, g_div[LastStage].rem_v_d};

  logic [N-1:0] valid_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin : valid_regs
    if (!rst_ni) begin
      valid_q <= '0;
      valid_o <= 1'b0;
    end else begin
      valid_q[0] <= valid_i;
      for (int k = 1; k < N; k++) valid_q[k] <= valid_q[k-1];
      valid_o <= valid_q[LastStage];
    end
  end

  ////////////////////////////////////////
  // Output: far-edge fix-up, zero mask //
  ////////////////////////////////////////
  logic [QuoBits-1:0] pos_u, pos_v;
  logic               nonzero;
  assign pos_u   = g_div[LastStage].quo_u_d;
  assign pos_v   = g_div[LastStage].quo_v_d;
  assign nonzero = g_div[LastStage].nonzero_q;

  logic [CellBits-1:0] u_d, v_d;
  logic [WeightBits:0] wu_d, wv_d;

  always_comb begin : fixup
    if (g_div[LastStage].far_u_q) begin
      u_d  = CellBits'(MapFaceRes - 2);
      wu_d = {1'b1, {WeightBits{1'b0}}};
    end else begin
      u_d  = pos_u[QuoBits-1:WeightBits];
      wu_d = {1'b0, pos_u[WeightBits-1:0]};
    end
    if (g_div[LastStage].far_v_q) begin
      v_d  = CellBits'(MapFaceRes - 2);
      wv_d = {1'b1, {WeightBits{1'b0}}};
    end else begin
      v_d  = pos_v[QuoBits-1:WeightBits];
      wv_d = {1'b0, pos_v[WeightBits-1:0]};
    end
    if (!nonzero) begin
      u_d  = '0;
      v_d  = '0;
      wu_d = '0;
      wv_d = '0;
    end
  end

  always_ff @(posedge clk_i) begin : output_regs
    coord_valid_o <= nonzero;
    face_o        <= nonzero ? g_div[LastStage].face_q : 3'd0;
    u_o           <= u_d;
    v_o           <= v_d;
    wu_o          <= wu_d;
    wv_o          <= wv_d;
  end

endmodule
