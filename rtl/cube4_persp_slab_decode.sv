// cube4_persp_slab_decode: the run-length decoders of slab images for a
// perspective compositing ring (Cube-5 §5 in perspective; docs/rtl-rle-decode.md,
// "In perspective"). Bit-exact with golden: each request's pixel is the
// slab image's pixel behind the ray (the image decoded by golden
// RleDecoder, line by line; systemc/core/persp_polygon_pixels.hpp reads
// it so for the TLM unit).
//
// Why a unit of its own: a parallel pipeline meets the pixels of its slab
// line in order, one a cycle, so one decoder per pipeline reading its own
// line serves it (cube4_composite_unit). A perspective slice's rays are
// placed lane by lane by the cell walks: which lane holds the ray of rank x
// (its index in its row of the slice's rays, the slab image's column)
// depends on the camera. What does not: a step's rays lie in at most two
// rows of rays (the cells of one stream beam and the last cells of the beam
// before), each row's in rank order along the lanes, and a row's rays are
// consecutive ranks. So a row's rays in one step are at most NumPipes
// consecutive ranks, which fall on distinct slab lines (line l of a row
// holds the pixels x = l, l + p, ...: the parallel format, golden
// SlabImage). Two banks of NumPipes decoders (cube4_rle_decode), one bank
// for each of two consecutive rows, serve any step: lane i's request goes
// to the decoder of its row's bank and its rank's line, and its pixel
// comes back through a crossbar.
//
// Which bank and which line, without the rank: rows take the banks in
// turn, a row's first ray (req_first_i) switching to the other bank; each
// bank counts the line of its next ray (0 at the row's first, then + 1
// modulo NumPipes per ray, lane by lane). A row's last ray (req_last_i)
// tells the source to move the bank's lines on by two rows at the clock
// edge (line_o), so that the bank's next row (two rows on) is presented
// before its first ray: the source needs no lookahead. The bank's decoders
// start their new lines (start_i) in the first cycle the source shows them,
// the cycle after line_o, and again with a row's first ray (harmless when
// nothing was read since; it starts the frame's first two rows). A row's
// lines are not decoded to their end (the image may be wider than the
// rays); the start forgets the rest.
//
// Word source (outside: the slab memory): per decoder d = bank * NumPipes +
// line, cube4_rle_decode's window_i / avail_i / consume_o. Bank b's lines
// are those of rows b, b + 2, b + 4, ... of the frame's rows of rays in
// stream order (slice by slice, each slice's rows 0 .. its count - 1, frame
// after frame), line l of each; at reset bank 0 shows row 0's and bank 1
// row 1's.
//
// Requests (valid-only, no back-pressure): req_valid_i per lane, a sample
// that needs the slab pixel behind its ray; req_first_i: the ray is its
// row's first (rank 0); req_last_i: its row's last. Output: pixel_valid_o
// and the pixel per lane one cycle later (Latency 1, the decoders'
// register); error_o: a decoder's line ran out inside a flit since its
// last start (golden RleDecoder::error()).
//
// Preconditions: every ray of every row is requested once, in stream
// order (lane order within a cycle), with its row's first and last
// marked; at most two rows a cycle; NumPipes >= 1.
//
// Parameters:
//   NumPipes - pipelines p (lanes; decoders per bank)
`include "cube4_pkg.sv"

module cube4_persp_slab_decode #(
  parameter int unsigned  NumPipes = 4,
  localparam int unsigned WordBits = cube4_pkg::RleWordBits,
  localparam int unsigned Decoders = 2 * NumPipes,
  localparam int unsigned WinBits  = 5 * WordBits
) (
  input  logic                            clk_i,
  input  logic                            rst_ni,
  // Requests, per lane.
  input  logic [NumPipes-1:0]             req_valid_i,
  input  logic [NumPipes-1:0]             req_first_i,
  input  logic [NumPipes-1:0]             req_last_i,
  // The word source, per decoder (bank * NumPipes + line).
  input  logic [Decoders*WinBits-1:0]     window_i,
  input  logic [Decoders*3-1:0]           avail_i,
  output logic [Decoders*3-1:0]           consume_o,
  output logic [1:0]                      line_o,
  // Pixels, per lane (premultiplied R, G, B, A; blank = all zero).
  output logic [NumPipes-1:0]             pixel_valid_o,
  output logic [NumPipes*WordBits-1:0]    pixel_red_o,
  output logic [NumPipes*WordBits-1:0]    pixel_green_o,
  output logic [NumPipes*WordBits-1:0]    pixel_blue_o,
  output logic [NumPipes*WordBits-1:0]    pixel_alpha_o,
  output logic                            error_o
);

  localparam int unsigned P        = NumPipes;
  localparam int unsigned W        = WordBits;
  localparam int unsigned LineBits = P > 1 ? $clog2(P) : 1;
  localparam int unsigned DecBits  = $clog2(Decoders);

  // The bank of the latest row, and each bank's next line ({bank 1, bank 0}).
  logic                  bank_q, bank_d;
  logic [2*LineBits-1:0] line_q, line_d;

  logic [1:0]            start, first, switched_q;
  logic [Decoders-1:0]   next;
  logic [P*DecBits-1:0]  lane_decoder, lane_decoder_q;  // per lane: the decoder its request went to

  // Lane by lane, as the rays come in stream order.
  always_comb begin
    logic                  bank;
    logic [2*LineBits-1:0] line;
    logic [LineBits-1:0]   l;
    bank         = bank_q;
    l            = '0;
    line         = line_q;
    first        = '0;
    next         = '0;
    line_o       = '0;
    lane_decoder = '0;
    for (int unsigned i = 0; i < P; i++) begin
      if (req_valid_i[i]) begin
        if (req_first_i[i]) begin
          bank  = ~bank;
          line[32'(bank)*LineBits +: LineBits] = '0;
          first[bank] = 1'b1;
        end
        l = line[32'(bank)*LineBits +: LineBits];
        lane_decoder[i*DecBits +: DecBits] = DecBits'(bank) * DecBits'(P) + DecBits'(l);
        next[lane_decoder[i*DecBits +: DecBits]] = 1'b1;
        line[32'(bank)*LineBits +: LineBits] = l == LineBits'(P - 1) ? '0 : l + LineBits'(1);
        if (req_last_i[i]) line_o[bank] = 1'b1;
      end
    end
    bank_d = bank;
    line_d = line;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      bank_q <= 1'b1;  // the first row takes bank 0
      line_q <= '0;
    end else begin
      bank_q <= bank_d;
      line_q <= line_d;
    end
  end

  assign start = first | switched_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      pixel_valid_o <= '0;
      switched_q    <= '0;
    end else begin
      pixel_valid_o <= req_valid_i;
      switched_q    <= line_o;
    end
  end
  always_ff @(posedge clk_i) begin
    lane_decoder_q <= lane_decoder;
  end

  logic [Decoders*4*W-1:0] dec_pixel;
  logic [Decoders-1:0]     dec_error;
  for (genvar d = 0; d < Decoders; d++) begin : g_decoder
    logic unused_valid, unused_finished;  // the lane's own valid; lines end undecoded past the rays
    cube4_rle_decode u_decode (
      .clk_i        (clk_i),
      .rst_ni       (rst_ni),
      .start_i      (start[d / P]),
      .next_i       (next[d]),
      .window_i     (window_i[d*WinBits +: WinBits]),
      .avail_i      (avail_i[d*3 +: 3]),
      .consume_o    (consume_o[d*3 +: 3]),
      .pixel_valid_o(unused_valid),
      .pixel_red_o  (dec_pixel[(4*d+3)*W +: W]),
      .pixel_green_o(dec_pixel[(4*d+2)*W +: W]),
      .pixel_blue_o (dec_pixel[(4*d+1)*W +: W]),
      .pixel_alpha_o(dec_pixel[(4*d+0)*W +: W]),
      .error_o      (dec_error[d]),
      .finished_o   (unused_finished)
    );
  end

  // The crossbar: each lane's pixel from the decoder its request went to.
  for (genvar i = 0; i < P; i++) begin : g_lane
    logic [4*W-1:0] px;
    assign px = dec_pixel[4*W*lane_decoder_q[i*DecBits +: DecBits] +: 4*W];
    assign {pixel_red_o[i*W +: W], pixel_green_o[i*W +: W], pixel_blue_o[i*W +: W], pixel_alpha_o[i*W +: W]} = px;
  end

  assign error_o = |dec_error;

endmodule
