// cube4_persp_slab_decode_sva: the request stream's contract of
// cube4_persp_slab_decode's header, as assertions bound to every unit:
//   a_row_open   - a request that is not its row's first goes to a bank
//                  whose row has started and not ended: a ray before its
//                  row's first or after its last would read another row's
//                  lines;
//   a_row_ended  - a row's first goes to a bank whose previous row ended
//                  (its last ray came): otherwise the memory never moved
//                  that bank's lines on, and the new row reads the old one's;
//   a_two_rows   - at most two rows a cycle (a third would need a third
//                  bank).
// The bank of each request is the unit's own choice (lane_decoder), so the
// checker follows the unit's bank rotation instead of computing it again.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_persp_slab_decode_sva #(
  parameter int unsigned  NumPipes = 4,
  localparam int unsigned Decoders = 2 * NumPipes,
  localparam int unsigned DecBits  = $clog2(Decoders)
) (
  input logic                         clk_i,
  input logic                         rst_ni,
  input logic [NumPipes-1:0]          req_valid_i,
  input logic [NumPipes-1:0]          req_first_i,
  input logic [NumPipes-1:0]          req_last_i,
  input logic [NumPipes*DecBits-1:0]  lane_decoder
);

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  // Whether each bank's row is open (started, not ended), lane by lane.
  logic [1:0] open_q, open_d;
  logic       not_open, not_ended;
  int unsigned rows;
  always_comb begin
    logic [1:0] open;
    logic       bank, seen;
    open      = open_q;
    bank      = 1'b0;
    not_open  = 1'b0;
    not_ended = 1'b0;
    rows      = 0;
    seen      = 1'b0;
    for (int unsigned i = 0; i < NumPipes; i++) begin
      if (req_valid_i[i]) begin
        bank = lane_decoder[i*DecBits +: DecBits] >= DecBits'(NumPipes);
        if (req_first_i[i]) begin
          not_ended  = not_ended | open[bank];
          open[bank] = 1'b1;
          rows       = rows + 1;
        end else begin
          not_open = not_open | !open[bank];
          if (!seen) rows = rows + 1;  // the cycle's oldest row, begun before it
        end
        if (req_last_i[i]) open[bank] = 1'b0;
        seen = 1'b1;
      end
    end
    open_d = open;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) open_q <= '0;
    else         open_q <= open_d;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_row_open: assert (!not_open)
        else $error("cube4_persp_slab_decode: cycle %0d: a ray before its row's first or after its last", cycle);
      a_row_ended: assert (!not_ended)
        else $error("cube4_persp_slab_decode: cycle %0d: a row starts on a bank whose row two back has not ended",
                    cycle);
      a_two_rows: assert (rows <= 2)
        else $error("cube4_persp_slab_decode: cycle %0d: rays of %0d rows in one cycle, at most two", cycle, rows);
    end
  end

endmodule

bind cube4_persp_slab_decode cube4_persp_slab_decode_sva #(.NumPipes(NumPipes)) u_sva (.*);
