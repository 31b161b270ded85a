// cube4_shade_phong: the Phong combine of VolumePro §3.5,
//   RGB = (ke + kd*Id*Gd) * SampleRGB + ks*Is*Gs * SpecularColor,
// bit-exact with golden phong() (golden/units/shade_phong.hpp):
//   fd  = ke + round_shift(kd * mul_frac(Id, Gd, AlphaBits), MapFracBits)
//   fs  =      round_shift(ks * mul_frac(Is, Gs, AlphaBits), MapFracBits)
//   out = sat_unsigned(round_shift(c * fd, CoefFracBits)
//                      + round_shift(spec_c * fs, CoefFracBits), AlphaBits)
// with mul_frac(x, f, n) = (x * (f + (f >> (n-1))) + 2^(n-1)) >> n and
// round_shift(v, s) = (v + 2^(s-1)) >> s (v >= 0 throughout, so no signs);
// the two mul_frac are cube4_mul_frac, the compositor's.
//
// Widths: mul_frac(Id, Gd) <= Id: MapBits; fd < 2^(CoefBits+MapBits-MapFracBits+1);
// fs < 2^(CoefBits+MapBits-MapFracBits).
//
// Latency: 3 cycles (1: mul_frac of Id and Is; 2: fd and fs; 3: the colour
// products, sum and saturation). The colour travels with the sample (it is
// used in stage 3). Fully pipelined, one sample per clock. Handshake:
// valid-only; valid_i travels with the data to valid_o. Only the valid
// registers are reset. ke/kd/ks and the specular colour are frame registers:
// change them only while no sample is in flight.
//
// Parameters (defaults = golden Precision): AlphaBits, MapBits,
// MapFracBits, CoefBits, CoefFracBits.
`include "cube4_pkg.sv"

module cube4_shade_phong #(
  parameter int unsigned AlphaBits    = cube4_pkg::AlphaBits,
  parameter int unsigned MapBits      = cube4_pkg::MapBits,
  parameter int unsigned MapFracBits  = cube4_pkg::MapFracBits,
  parameter int unsigned CoefBits     = cube4_pkg::CoefBits,
  parameter int unsigned CoefFracBits = cube4_pkg::CoefFracBits
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  // Frame registers (golden ShadeCoefs).
  input  logic [CoefBits-1:0]  ke_i,
  input  logic [CoefBits-1:0]  kd_i,
  input  logic [CoefBits-1:0]  ks_i,
  input  logic [AlphaBits-1:0] spec_red_i,
  input  logic [AlphaBits-1:0] spec_green_i,
  input  logic [AlphaBits-1:0] spec_blue_i,
  // Sample stream.
  input  logic                 valid_i,
  input  logic [AlphaBits-1:0] red_i,
  input  logic [AlphaBits-1:0] green_i,
  input  logic [AlphaBits-1:0] blue_i,
  input  logic [MapBits-1:0]   id_i,
  input  logic [MapBits-1:0]   is_i,
  input  logic [AlphaBits-1:0] gd_i,
  input  logic [AlphaBits-1:0] gs_i,
  output logic                 valid_o,
  output logic [AlphaBits-1:0] red_o,
  output logic [AlphaBits-1:0] green_o,
  output logic [AlphaBits-1:0] blue_o
);

  localparam int unsigned A        = AlphaBits;
  localparam int unsigned FsBits   = CoefBits + MapBits - MapFracBits;
  localparam int unsigned FdBits   = FsBits + 1;
  localparam int unsigned KBits    = CoefBits + MapBits;                // kd * mul_frac
  localparam int unsigned CBits    = A + FdBits;                        // colour * factor
  localparam int unsigned SumBits  = CBits - CoefFracBits + 1;

  /////////////////////////////////////
  // Stage 1: mul_frac(Id, Gd), (Is, Gs) //
  /////////////////////////////////////
  logic [MapBits-1:0] md, ms;
  cube4_mul_frac #(.XBits(MapBits), .FBits(A)) u_diffuse (.x_i(id_i), .f_i(gd_i), .y_o(md));
  cube4_mul_frac #(.XBits(MapBits), .FBits(A)) u_specular (.x_i(is_i), .f_i(gs_i), .y_o(ms));

  logic [MapBits-1:0] md_q, ms_q;
  logic [3*A-1:0]     color_q;
  always_ff @(posedge clk_i) begin : stage1_regs
    md_q    <= md;
    ms_q    <= ms;
    color_q <= {red_i, green_i, blue_i};
  end

  ////////////////////////////////
  // Stage 2: fd and fs factors //
  ////////////////////////////////
  // round_shift(v, s) for v >= 0: (v + (2^s >> 1)) >> s (no rounding at s = 0).
  localparam logic [KBits-1:0] MapHalf = KBits'((64'd1 << MapFracBits) >> 1);

  logic [KBits-1:0]  kd_prod, ks_prod;
  logic [FsBits-1:0] kd_term, ks_term;
  assign kd_prod = KBits'(kd_i) * KBits'(md_q) + MapHalf;
  assign ks_prod = KBits'(ks_i) * KBits'(ms_q) + MapHalf;
  // The rounding addition cannot carry out: kd*md <= (2^C-1)(2^M-1).
  assign kd_term = FsBits'(kd_prod >> MapFracBits);
  assign ks_term = FsBits'(ks_prod >> MapFracBits);

  logic [FdBits-1:0] fd_q;
  logic [FsBits-1:0] fs_q;
  logic [3*A-1:0]    color_qq;
  always_ff @(posedge clk_i) begin : stage2_regs
    fd_q     <= FdBits'(kd_term) + FdBits'(ke_i);
    fs_q     <= ks_term;
    color_qq <= color_q;
  end

  ///////////////////////////////////////////////
  // Stage 3: colour products, sum, saturation //
  ///////////////////////////////////////////////
  localparam logic [CBits-1:0] CoefHalf = CBits'((64'd1 << CoefFracBits) >> 1);
  localparam logic [SumBits-1:0] AlphaMax = SumBits'((64'd1 << A) - 1);

  // The sum before saturation, red, green, blue: a signal, so that the
  // coverage checker (rtl/assert) sees each channel saturate.
  function automatic logic [SumBits-1:0] channel_sum(input logic [A-1:0]      c,
                                                    input logic [A-1:0]      spec,
                                                    input logic [FdBits-1:0] fd,
                                                    input logic [FsBits-1:0] fs);
    logic [CBits-1:0] diffuse, specular;
    diffuse     = CBits'(c) * CBits'(fd) + CoefHalf;
    specular    = CBits'(spec) * CBits'(fs) + CoefHalf;
    diffuse     = diffuse >> CoefFracBits;
    specular    = specular >> CoefFracBits;
    channel_sum = SumBits'(diffuse) + SumBits'(specular);
  endfunction

  // Channel ch (0 blue, 1 green, 2 red) in a generate block of its own:
  // three sums of up to 32 bits are words to Verilator, one vector of the
  // three is not (docs/performance.md).
  logic [3*A-1:0] spec_rgb;
  logic [2:0]     saturated;
  logic [3*A-1:0] colour_d;
  assign spec_rgb = {spec_red_i, spec_green_i, spec_blue_i};
  for (genvar ch = 0; ch < 3; ch++) begin : g_channel
    logic [SumBits-1:0] sum;
    assign sum                 = channel_sum(color_qq[ch*A +: A], spec_rgb[ch*A +: A], fd_q, fs_q);
    assign saturated[ch]       = sum > AlphaMax;
    assign colour_d[ch*A +: A] = saturated[ch] ? {A{1'b1}} : sum[A-1:0];
  end

  always_ff @(posedge clk_i) begin : stage3_regs
    {red_o, green_o, blue_o} <= colour_d;
  end

  logic [2:0] valid_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin : valid_regs
    if (!rst_ni) begin
      valid_q <= '0;
    end else begin
      valid_q <= {valid_q[1:0], valid_i};
    end
  end
  assign valid_o = valid_q[2];

endmodule
