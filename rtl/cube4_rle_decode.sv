// cube4_rle_decode: one pipeline's run-length decoder of slab images
// (Cube-5 §5: "we replicate the decoding hardware for each pipeline"): the
// pipeline's encoded line of a beam back to one polygon pixel per cycle, in
// the order the pipeline meets its samples. Bit-exact with golden
// RleDecoder::next(), finished() and error() (golden/units/rle_decode.hpp,
// where the line format is defined; docs/rtl-rle-decode.md):
//   a pixel flit  R, G, B, A (not all zero)  4 words: that pixel
//   a run flit    0, 0, 0, 0, L              5 words: L + 1 blank pixels
//
// Word source: the line store is outside (a memory the host fills, or the
// system model's slab memory). It presents window_i, the line's next five
// words from the decoder's read position (word i at [i*16 +: 16]), and
// avail_i = min(5, words left in the line); words beyond avail_i are
// ignored. The decoder answers in the same cycle with consume_o (0, 4 or 5)
// and the source advances its read position by that at the clock edge, so a
// flit is decoded in the cycle it is presented: one pixel per cycle with no
// bubble between flits, runs included (a run's first pixel comes with its
// flit, the other L while the source waits). Five words because a run flit
// is five: the source is a word buffer of at least five words with a
// variable advance (or five interleaved banks).
//
// Control (valid-only, no back-pressure):
//   start_i : a new line begins this cycle: the run left over and the error
//             of the previous line are forgotten (golden: a new RleDecoder).
//             With next_i in the same cycle, its pixel is the new line's
//             first. The source presents the new line's words from then on.
//   next_i  : the next pixel of the line is wanted this cycle.
// Output: pixel_valid_o and pixel_*_o one cycle after next_i (a register,
// Latency = 1). error_o: since the last start_i, a next_i found fewer
// words than its flit needs (golden error(): a malformed line, or more
// pixels asked than it holds); such a pixel is blank and consumes nothing.
// finished_o (combinational): no error, no run left, and no word left
// (avail_i = 0): the line held exactly the pixels asked of it (golden
// finished()). Both are the state after the pixels asked so far.
// Reset: control only (run counter, error); the pixel register is not reset.
//
// Preconditions (rtl/assert/cube4_rle_decode_sva.sv): avail_i <= 5; the
// source advances by exactly consume_o (the window moves, the count drops);
// a line has at most 2^16 pixels per run word, as golden (kRleRunMax).
//
// Parameters: none but the format's word width (cube4_pkg::RleWordBits,
// golden's uint16_t words); pixels of fewer bits (AlphaBits < 16) use the
// low bits of their words.
`include "cube4_pkg.sv"

module cube4_rle_decode #(
  localparam int unsigned WordBits = cube4_pkg::RleWordBits
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  input  logic                  start_i,
  input  logic                  next_i,
  // The line's words at the read position, and how many lie in the line.
  input  logic [5*WordBits-1:0] window_i,
  input  logic [2:0]            avail_i,
  output logic [2:0]            consume_o,
  // Decoded pixel (premultiplied R, G, B, A; blank = all zero).
  output logic                  pixel_valid_o,
  output logic [WordBits-1:0]   pixel_red_o,
  output logic [WordBits-1:0]   pixel_green_o,
  output logic [WordBits-1:0]   pixel_blue_o,
  output logic [WordBits-1:0]   pixel_alpha_o,
  output logic                  error_o,
  output logic                  finished_o
);

  localparam int unsigned W = WordBits;

  logic [W-1:0] run_left_q, run_left_d, run_left;  // blank pixels of the run still to come
  logic         error_q, error_d, error;
  logic [4*W-1:0] pixel_d, flit_pixel;

  // The state this cycle's pixel continues: start_i forgets the last line's.
  assign run_left = start_i ? '0 : run_left_q;
  assign error    = start_i ? 1'b0 : error_q;

  // Words 0..3 of the window, as golden's Pixel{w[0], w[1], w[2], w[3]}:
  // red is the first word.
  assign flit_pixel = {window_i[0 +: W], window_i[W +: W], window_i[2*W +: W], window_i[3*W +: W]};

  always_comb begin
    run_left_d = run_left;
    error_d    = error;
    pixel_d    = '0;
    consume_o  = 3'd0;
    if (next_i) begin
      if (run_left != '0) begin
        run_left_d = run_left - W'(1);
      end else if (avail_i < 3'd4) begin
        error_d = 1'b1;  // the line ends inside a flit
      end else if (flit_pixel != '0) begin
        pixel_d   = flit_pixel;
        consume_o = 3'd4;
      end else if (avail_i < 3'd5) begin
        error_d = 1'b1;  // a run without its length word
      end else begin
        run_left_d = window_i[4*W +: W];  // this cycle's pixel is the run's first
        consume_o  = 3'd5;
      end
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      run_left_q    <= '0;
      error_q       <= 1'b0;
      pixel_valid_o <= 1'b0;
    end else begin
      run_left_q    <= run_left_d;
      error_q       <= error_d;
      pixel_valid_o <= next_i;
    end
  end

  always_ff @(posedge clk_i) begin
    {pixel_red_o, pixel_green_o, pixel_blue_o, pixel_alpha_o} <= pixel_d;
  end

  assign error_o    = error_q;
  assign finished_o = !error_q && run_left_q == '0 && avail_i == 3'd0;

endmodule
