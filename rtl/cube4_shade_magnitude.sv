// cube4_shade_magnitude: gradient magnitude |g| by an integer Newton-Raphson
// square root (VolumePro §3.3).
//
// Function: bit-exact with golden gradient_magnitude()
// (golden/units/shade_magnitude.hpp):
//   q  = gx^2 + gy^2 + gz^2
//   x0 = 2^ceil(bitlength(q) / 2)            (>= sqrt(q))
//   x_{i+1} = (x_i + floor(q / x_i)) >> 1,   i = 0 .. NrIterations-1
//   magnitude = q == 0 ? 0 : min(x_NrIterations, 2^MagnitudeBits - 1)
// Inputs are two's complement; the full range, -2^(GradientBits-1)
// included, is accepted. The divisions are cube4_udiv restoring dividers.
//
// Latency: NrIterations + 1 cycles (4 by default), fully pipelined:
//   stage 0 registers q and x0 (squares, sum, leading-one detector), stage
//   i = 1 .. NrIterations registers x_i (one divider and adder each); the
//   zero test and saturation are combinational after the last register.
// Handshake: valid-only. valid_i travels with the data to valid_o; only the
//   valid pipeline is reset.
//
// Parameters:
//   GradientBits  - signed input component width (golden Precision::gradient_bits, 8)
//   MagnitudeBits - unsigned output width (Precision::magnitude_bits, 8)
//   NrIterations  - Newton-Raphson steps (Precision::nr_iterations, 3)
`include "cube4_pkg.sv"

module cube4_shade_magnitude #(
  parameter int unsigned GradientBits  = cube4_pkg::GradientBits,
  parameter int unsigned MagnitudeBits = cube4_pkg::MagnitudeBits,
  parameter int unsigned NrIterations  = cube4_pkg::NrIterations
) (
  input  logic                           clk_i,
  input  logic                           rst_ni,
  input  logic                           valid_i,
  input  logic signed [GradientBits-1:0] gx_i,
  input  logic signed [GradientBits-1:0] gy_i,
  input  logic signed [GradientBits-1:0] gz_i,
  output logic                           valid_o,
  output logic [MagnitudeBits-1:0]       magnitude_o
);

  localparam int unsigned Stages = NrIterations + 1;
  // |g| <= 2^(GradientBits-1), so q <= 3 * 2^(2*GradientBits-2) < 2^QBits.
  localparam int unsigned QBits  = 2 * GradientBits;
  // x0 <= 2^ceil(QBits/2) = 2^GradientBits, and Newton-Raphson from above
  // never exceeds its start value: XBits holds every x_i.
  localparam int unsigned XBits  = GradientBits + 1;
  localparam int unsigned BlBits = $clog2(QBits + 1);
  localparam int unsigned CmpBits = (XBits > MagnitudeBits) ? XBits : MagnitudeBits + 1;
  localparam logic [CmpBits-1:0] MaxM = CmpBits'((CmpBits'(1) << MagnitudeBits) - CmpBits'(1));

  // Valid pipeline: the only reset state.
  // Each pipeline is written as {registers, input} and shifted by one
  // slice, which also covers NrIterations = 0 (a single stage).
  logic [Stages-1:0] valid_q;
  logic [Stages:0]   valid_chain;
  assign valid_chain = {valid_q, valid_i};

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= '0;
    end else begin
      valid_q <= valid_chain[Stages-1:0];
    end
  end
  assign valid_o = valid_q[Stages-1];

  // Stage 0: sum of squares and the start value.
  logic [GradientBits-1:0] ax, ay, az;
  logic [QBits-1:0]        q_d;
  logic [BlBits-1:0]       bl;
  logic [XBits-1:0]        x0_d;

  // |v| as an unsigned GradientBits-bit value (|-2^(GradientBits-1)| fits).
  function automatic logic [GradientBits-1:0] abs_g(input logic signed [GradientBits-1:0] v);
    abs_g = v[GradientBits-1] ? GradientBits'(-v) : GradientBits'(v);
  endfunction

  assign ax  = abs_g(gx_i);
  assign ay  = abs_g(gy_i);
  assign az  = abs_g(gz_i);
  assign q_d = QBits'(ax) * QBits'(ax) + QBits'(ay) * QBits'(ay) + QBits'(az) * QBits'(az);

  always_comb begin
    bl = '0;
    for (int i = 0; i < QBits; i++) begin
      if (q_d[i]) bl = BlBits'(i + 1);
    end
    x0_d = XBits'(1) << ((bl + BlBits'(1)) >> 1);
  end

  // Stage i (0 .. NrIterations), a generate block each: q_q, x_q and
  // zero_q are the values after stage i. Not one flattened vector of all
  // stages: Verilator evaluates each stage's fields as words, not as
  // part-selects of a vector of several words (docs/performance.md).
  // Stages 1 .. NrIterations: x <- (x + q / x) >> 1.
  for (genvar i = 0; i < Stages; i++) begin : g_stage
    logic [QBits-1:0] q_q;
    logic [XBits-1:0] x_q;
    logic             zero_q;
    if (i == 0) begin : g_start
      always_ff @(posedge clk_i) begin
        q_q    <= q_d;
        x_q    <= x0_d;
        zero_q <= ~|q_d;
      end
    end else begin : g_nr
      logic [QBits-1:0] quot;
      logic [XBits-1:0] unused_rem;
      logic [QBits:0]   sum;
      cube4_udiv #(
        .DividendBits(QBits),
        .DivisorBits (XBits)
      ) u_div (
        .dividend_i (g_stage[i-1].q_q),
        .divisor_i  (g_stage[i-1].x_q),
        .quotient_o (quot),
        .remainder_o(unused_rem)
      );
      assign sum = (QBits+1)'(g_stage[i-1].x_q) + (QBits+1)'(quot);
      logic unused_sum;
      assign unused_sum = ^{sum[QBits:XBits+1], sum[0]};
      always_ff @(posedge clk_i) begin
        q_q    <= g_stage[i-1].q_q;
        // sum / 2 <= max(x_{i-1}, x0) fits XBits (see XBits above).
        x_q    <= sum[XBits:1];
        zero_q <= g_stage[i-1].zero_q;
      end
    end
  end

  // q of the last stage feeds no divider.
  logic unused_q;
  assign unused_q = ^{g_stage[Stages-1].q_q, valid_chain[Stages]};

  // Zero test and saturation.
  logic [CmpBits-1:0] x_last;
  assign x_last      = CmpBits'(g_stage[Stages-1].x_q);
  logic saturated;  // also the coverage checker's (rtl/assert)
  assign saturated   = x_last > MaxM;
  assign magnitude_o = g_stage[Stages-1].zero_q ? '0
                     : saturated        ? MaxM[MagnitudeBits-1:0]
                     :                    x_last[MagnitudeBits-1:0];

endmodule
