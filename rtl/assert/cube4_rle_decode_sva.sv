// cube4_rle_decode_sva: the word source's contract of cube4_rle_decode's
// header, as assertions bound to every decoder:
//   a_avail_in_range   - avail_i counts the window's words: at most 5 (in
//                        the cycles the decoder may read it: start_i or
//                        next_i; an unused decoder's source may show
//                        anything);
//   a_source_advances  - within a line (no start_i) the source moves by
//                        exactly the words the decoder consumed in the
//                        cycle before: the words it still shows are the
//                        previous window's, shifted by consume_o, and a
//                        count below 5 drops by consume_o (a window of 5
//                        may stay full: more words follow). A source that
//                        lags, skips or refills a line would make the
//                        decoder read another flit than golden's;
//   a_consume_in_window - the decoder never takes more words than the
//                        window holds (its own invariant: the flit checks
//                        come first).
//
// Simulation only: not part of the unit, never synthesised.
module cube4_rle_decode_sva #(
  localparam int unsigned W = cube4_pkg::RleWordBits
) (
  input logic           clk_i,
  input logic           rst_ni,
  input logic           start_i,
  input logic           next_i,
  input logic [5*W-1:0] window_i,
  input logic [2:0]     avail_i,
  input logic [2:0]     consume_o
);

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  // The previous cycle's window, count and advance; seen_q: a line has
  // started since reset (before that the source shows nothing in particular).
  logic [5*W-1:0] window_q;
  logic [2:0]     avail_q, consume_q;
  logic           seen_q;
  always_ff @(posedge clk_i) begin
    window_q  <= window_i;
    avail_q   <= avail_i;
    consume_q <= consume_o;
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      seen_q <= 1'b0;
    end else if (start_i) begin
      seen_q <= 1'b1;
    end
  end

  // Words of the window still shown after the advance, compared one by one.
  logic [4:0] word_kept;
  logic       words_ok, count_ok;
  always_comb begin
    for (int unsigned i = 0; i < 5; i++) begin
      word_kept[i] = (i + 32'(consume_q) >= 32'(avail_q))
                  || (window_i[i*W +: W] == window_q[(i + 32'(consume_q))*W +: W]);
    end
  end
  assign words_ok = &word_kept;
  assign count_ok = (avail_q < 3'd5) ? (avail_i == avail_q - consume_q) : (avail_i >= 3'd5 - consume_q);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_avail_in_range: assert (!(start_i || next_i) || avail_i <= 3'd5)
        else $error("cube4_rle_decode: cycle %0d: avail_i %0d: a window holds five words", cycle, avail_i);
      // (After an out-of-range count, which a_avail_in_range reported, the
      // window has no defined advance.)
      a_source_advances: assert (!seen_q || start_i || avail_q > 3'd5 || (words_ok && count_ok))
        else $error("cube4_rle_decode: cycle %0d: the word source did not advance by the %0d words consumed: count %0d -> %0d, words kept %b",
                    cycle, consume_q, avail_q, avail_i, word_kept);
      a_consume_in_window: assert (consume_o <= avail_i)
        else $error("cube4_rle_decode: cycle %0d: consumed %0d of %0d words", cycle, consume_o, avail_i);
    end
  end

endmodule

bind cube4_rle_decode cube4_rle_decode_sva u_sva (.*);
