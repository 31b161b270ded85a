// cube4_udiv: unsigned integer division, a combinational restoring divider.
//
// Function: quotient_o = dividend_i / divisor_i and remainder_o =
// dividend_i % divisor_i, truncating, exactly C++ unsigned integer division.
// One restoring step per dividend bit, most significant first: shift the
// next dividend bit into the partial remainder, subtract the divisor if it
// fits and set that quotient bit. A zero divisor (undefined in C++) gives an
// all-ones quotient and a don't-care remainder; it never produces X.
//
// Latency: 0 (combinational), DividendBits subtract-and-select steps deep.
// Handshake: none (pure function).
//
// Parameters:
//   DividendBits - width of dividend and quotient (16)
//   DivisorBits  - width of divisor and remainder (9)
module cube4_udiv #(
  parameter int unsigned DividendBits = 16,
  parameter int unsigned DivisorBits  = 9
) (
  input  logic [DividendBits-1:0] dividend_i,
  input  logic [DivisorBits-1:0]  divisor_i,
  output logic [DividendBits-1:0] quotient_o,
  output logic [DivisorBits-1:0]  remainder_o
);

  // The partial remainder is below the divisor before each shift, so
  // DivisorBits + 1 bits hold it after the shift.
  logic [DivisorBits:0] rem;

  always_comb begin
    rem        = '0;
    quotient_o = '0;
    for (int i = DividendBits - 1; i >= 0; i--) begin
      rem = {rem[DivisorBits-1:0], dividend_i[i]};
      if (rem >= {1'b0, divisor_i}) begin
        rem           = rem - {1'b0, divisor_i};
        quotient_o[i] = 1'b1;
      end
    end
    remainder_o = rem[DivisorBits-1:0];
  end

endmodule
