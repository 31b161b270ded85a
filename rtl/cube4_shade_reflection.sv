// cube4_shade_reflection: the reflection vector R = 2(N.E)N - (N.N)E of the
// unnormalised gradient N and the eye vector E, brought back to gradient
// width by reduce_vector(): the smallest common right shift s with
// max|R_i| >> s <= 2^(GradientBits-1)-1, applied to the magnitudes (signs
// kept). Bit-exact with golden reflection_vector() / reduce_vector()
// (golden/units/shade_reflection.hpp).
//
// s = max(0, bit_length(max|R_i|) - (GradientBits-1)), and
// bit_length(max|R_i|) = bit_length(|R_x| | |R_y| | |R_z|), so no magnitude
// comparison is needed: one OR and a priority encoder.
//
// Widths (any two's-complement inputs, -2^(b-1) included):
//   N.E: GradientBits+EyeBits+1 signed; N.N: 2*GradientBits unsigned;
//   R_i: 2*GradientBits+EyeBits+2 signed (|R_i| < 9*2^(2G+E-3)).
//
// Latency: 4 cycles (1: N.E and N.N; 2: R; 3: magnitudes and shift amount;
// 4: shift and sign). Fully pipelined, one vector per clock. Handshake:
// valid-only; valid_i travels with the data to valid_o. Only the valid
// registers are reset. eye_*_i is a frame register: change it only while no
// vector is in flight.
//
// Parameters (defaults = golden Precision): GradientBits, EyeBits.
`include "cube4_pkg.sv"

module cube4_shade_reflection #(
  parameter int unsigned GradientBits = cube4_pkg::GradientBits,
  parameter int unsigned EyeBits      = cube4_pkg::EyeBits
) (
  input  logic                           clk_i,
  input  logic                           rst_ni,
  // Frame register: the eye vector (golden Registers::eye).
  input  logic signed [EyeBits-1:0]      eye_x_i,
  input  logic signed [EyeBits-1:0]      eye_y_i,
  input  logic signed [EyeBits-1:0]      eye_z_i,
  // Gradient stream.
  input  logic                           valid_i,
  input  logic signed [GradientBits-1:0] x_i,
  input  logic signed [GradientBits-1:0] y_i,
  input  logic signed [GradientBits-1:0] z_i,
  output logic                           valid_o,
  output logic signed [GradientBits-1:0] x_o,
  output logic signed [GradientBits-1:0] y_o,
  output logic signed [GradientBits-1:0] z_o
);

  localparam int unsigned G         = GradientBits;
  localparam int unsigned E         = EyeBits;
  localparam int unsigned NeBits    = G + E + 1;      // signed N.E
  localparam int unsigned NnBits    = 2 * G + 1;      // N.N as a signed value
  localparam int unsigned RBits     = 2 * G + E + 2;  // signed R_i
  localparam int unsigned MagBits   = RBits - 1;      // |R_i|
  localparam int unsigned ShiftBits = $clog2(MagBits + 1);

  logic [3:0] valid_q;

  /////////////////////////
  // Stage 1: N.E, N.N   //
  /////////////////////////
  logic signed [NeBits-1:0] ne_d;
  logic signed [NnBits-1:0] nn_d;
  assign ne_d = NeBits'(x_i) * NeBits'(eye_x_i) + NeBits'(y_i) * NeBits'(eye_y_i)
              + NeBits'(z_i) * NeBits'(eye_z_i);
  assign nn_d = NnBits'(x_i) * NnBits'(x_i) + NnBits'(y_i) * NnBits'(y_i)
              + NnBits'(z_i) * NnBits'(z_i);

  logic signed [NeBits-1:0] ne_q;
  logic signed [NnBits-1:0] nn_q;
  logic signed [G-1:0]      nx_q, ny_q, nz_q;

  always_ff @(posedge clk_i) begin : stage1_regs
    ne_q <= ne_d;
    nn_q <= nn_d;
    nx_q <= x_i;
    ny_q <= y_i;
    nz_q <= z_i;
  end

  /////////////////////////////////
  // Stage 2: R = 2(N.E)N - (N.N)E //
  /////////////////////////////////
  logic signed [RBits-1:0] two_ne;
  logic signed [RBits-1:0] rx_d, ry_d, rz_d;
  assign two_ne = RBits'(ne_q) <<< 1;
  assign rx_d = two_ne * RBits'(nx_q) - RBits'(nn_q) * RBits'(eye_x_i);
  assign ry_d = two_ne * RBits'(ny_q) - RBits'(nn_q) * RBits'(eye_y_i);
  assign rz_d = two_ne * RBits'(nz_q) - RBits'(nn_q) * RBits'(eye_z_i);

  logic signed [RBits-1:0] rx_q, ry_q, rz_q;
  always_ff @(posedge clk_i) begin : stage2_regs
    rx_q <= rx_d;
    ry_q <= ry_d;
    rz_q <= rz_d;
  end

  ///////////////////////////////////////////
  // Stage 3: magnitudes, common shift     //
  ///////////////////////////////////////////
  logic [RBits-1:0]   rx_abs, ry_abs, rz_abs;
  logic [MagBits-1:0] mag_any;
  assign rx_abs  = rx_q[RBits-1] ? RBits'(-rx_q) : RBits'(rx_q);
  assign ry_abs  = ry_q[RBits-1] ? RBits'(-ry_q) : RBits'(ry_q);
  assign rz_abs  = rz_q[RBits-1] ? RBits'(-rz_q) : RBits'(rz_q);
  assign mag_any = rx_abs[MagBits-1:0] | ry_abs[MagBits-1:0] | rz_abs[MagBits-1:0];

  // |R_i| < 2^MagBits, so the top bit of each magnitude is always zero.
  logic unused_abs_msb;
  assign unused_abs_msb = ^{rx_abs[RBits-1], ry_abs[RBits-1], rz_abs[RBits-1]};

  logic [ShiftBits-1:0] bit_length, shift_d;
  always_comb begin : priority_encoder
    bit_length = '0;
    for (int unsigned i = 0; i < MagBits; i++) begin
      if (mag_any[i]) bit_length = ShiftBits'(i + 1);
    end
    shift_d = (bit_length > ShiftBits'(G - 1)) ? bit_length - ShiftBits'(G - 1) : '0;
  end

  logic [MagBits-1:0]   mx_q, my_q, mz_q;
  logic [2:0]           sign_q;
  logic [ShiftBits-1:0] shift_q;
  always_ff @(posedge clk_i) begin : stage3_regs
    mx_q    <= rx_abs[MagBits-1:0];
    my_q    <= ry_abs[MagBits-1:0];
    mz_q    <= rz_abs[MagBits-1:0];
    sign_q  <= {rx_q[RBits-1], ry_q[RBits-1], rz_q[RBits-1]};
    shift_q <= shift_d;
  end

  ////////////////////////////////
  // Stage 4: shift, apply sign //
  ////////////////////////////////
  // After the shift every magnitude fits G-1 bits.
  logic [MagBits-1:0] sx, sy, sz;
  assign sx = mx_q >> shift_q;
  assign sy = my_q >> shift_q;
  assign sz = mz_q >> shift_q;

  logic unused_shifted_msbs;
  assign unused_shifted_msbs = ^{sx[MagBits-1:G-1], sy[MagBits-1:G-1], sz[MagBits-1:G-1]};

  logic [G-1:0] px, py, pz;
  assign px = {1'b0, sx[G-2:0]};
  assign py = {1'b0, sy[G-2:0]};
  assign pz = {1'b0, sz[G-2:0]};

  always_ff @(posedge clk_i) begin : stage4_regs
    x_o <= sign_q[2] ? -px : px;
    y_o <= sign_q[1] ? -py : py;
    z_o <= sign_q[0] ? -pz : pz;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin : valid_regs
    if (!rst_ni) begin
      valid_q <= '0;
    end else begin
      valid_q <= {valid_q[2:0], valid_i};
    end
  end
  assign valid_o = valid_q[3];

endmodule
