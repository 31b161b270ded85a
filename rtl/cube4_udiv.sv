// cube4_udiv: unsigned integer division, a combinational restoring divider.
//
// Function: quotient_o = dividend_i / divisor_i and remainder_o =
// dividend_i % divisor_i, truncating, exactly C++ unsigned integer division.
// One restoring step per dividend bit, most significant first: shift the
// next dividend bit into the partial remainder, subtract the divisor, and
// keep the difference and set that quotient bit if it did not borrow. A
// zero divisor (undefined in C++) never borrows: an all-ones quotient and a
// don't-care remainder; it never produces X.
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

  // Each step is one subtractor, whose borrow is the quotient bit, and a
  // multiplexer keeping the difference when it did not borrow. Written as
  // a select rather than an if (rem >= divisor) with a second subtraction:
  // verilated, that if became a branch on the data, which the host
  // mispredicts about every other step: about a tenth of the verilated
  // shading unit's time (docs/performance.md, "The dividers' branches").
  logic [DivisorBits+1:0] diff;
  logic                   fits;

  always_comb begin
    rem        = '0;
    quotient_o = '0;
    for (int i = DividendBits - 1; i >= 0; i--) begin
      rem           = {rem[DivisorBits-1:0], dividend_i[i]};
      diff          = {1'b0, rem} - {2'b0, divisor_i};
      fits          = !diff[DivisorBits+1];
      rem           = fits ? diff[DivisorBits:0] : rem;
      quotient_o[i] = fits;
    end
    remainder_o = rem[DivisorBits-1:0];
  end

endmodule
