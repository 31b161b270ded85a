// cube4_dda_walk: one of the weight generator's DDAs over the sample
// slices (golden dda_position(): start + k * step), held for three slices
// at once, k - 1, k and k + 1, because the realignment of the gradient's
// neighbourhood reads the slices behind and ahead of the current one.
// cube4_dda walks the rays' offset in x and y with it, and in perspective
// frames the rays' spacing m_k too.
//
// Accumulators rather than a product k * step: the unit is three adders,
// and a position is start + k * step exactly, for any run length, as long
// as it fits PosBits signed (the system checks slices -1 .. K + 1 from the
// registers before the frame).
//
// Timing: start_i loads slice 0's three positions (start - step, start,
// start + step), advance_i moves them one slice; the outputs show the new
// slice from that clock edge on. start_i wins over advance_i.
// Reset: none (the positions are loaded by start_i; cube4_dda's valid_o
// says whether they have been).
//
// Parameters:
//   PosBits - positions, signed
module cube4_dda_walk #(
  parameter int unsigned PosBits = 48
) (
  input  logic                      clk_i,
  input  logic signed [PosBits-1:0] start_i,
  input  logic signed [PosBits-1:0] step_i,
  input  logic                      load_i,
  input  logic                      advance_i,
  output logic signed [PosBits-1:0] behind_o,
  output logic signed [PosBits-1:0] here_o,
  output logic signed [PosBits-1:0] ahead_o
);

  logic signed [PosBits-1:0] behind_q, here_q, ahead_q;

  always_ff @(posedge clk_i) begin
    if (load_i) begin
      behind_q <= start_i - step_i;
      here_q   <= start_i;
      ahead_q  <= start_i + step_i;
    end else if (advance_i) begin
      behind_q <= here_q;
      here_q   <= ahead_q;
      ahead_q  <= ahead_q + step_i;
    end
  end

  assign behind_o = behind_q;
  assign here_o   = here_q;
  assign ahead_o  = ahead_q;

endmodule
