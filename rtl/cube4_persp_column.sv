// cube4_persp_column: one pipeline's column stores of the perspective
// rings (docs/perspective.md, "The plan for the ring's RTL" and "The plan
// for the compositing ring"; docs/rtl-gradient-persp.md). The gradient ring
// keeps the samples that arrive on its lane in four stores (passes mod 4),
// the compositing ring its rays' accumulators in two (passes mod 2); once
// per step each pipeline reads its column's entries at the rows its beam
// needs: one column packet.
//
// Function: for each read port i = 0 .. Reads-1,
//   packet_o[i] = the word last written at (store_i[i], row_i[i], col_i),
// or wdata_i where this cycle writes that entry (a gradient formed in the
// very step that forms one of its operands takes it from the beat). The
// write (we_i) stores wdata_i at (wstore_i, wrow_i, wcol_i) at the clock
// edge. Entries never written read as whatever they hold: the rings read
// only entries their schedules have filled, and gate the operands of rays
// that miss their slice.
//
// Addressing: an entry is (store, row, partial beam); the rings' beams are
// ceil(nx/p) <= BeamDepth partial beams. The address {store, row, col} needs
// no multiplier; rows take MaxDim entries of 2^ceil(log2 BeamDepth) each.
//
// Latency: packet_o is combinational (the stores are read asynchronously,
// as cube4_delay_ram's); the write lands at the edge.
//
// Parameters:
//   Width     - a stored word
//   Reads     - read ports
//   StoreBits - log2 of the stores (2: four, 1: two)
//   MaxDim    - rows per store (the largest ny)
//   BeamDepth - partial beams per beam (ceil(MaxDim / p))
`include "cube4_pkg.sv"

module cube4_persp_column #(
  parameter int unsigned  Width     = 12,
  parameter int unsigned  Reads     = 7,
  parameter int unsigned  StoreBits = 2,
  parameter int unsigned  MaxDim    = 256,
  parameter int unsigned  BeamDepth = 64,
  localparam int unsigned RowBits   = $clog2(MaxDim),
  localparam int unsigned ColBits   = BeamDepth > 1 ? $clog2(BeamDepth) : 1,
  localparam int unsigned AddrBits  = StoreBits + RowBits + ColBits
) (
  input  logic                       clk_i,
  input  logic                       we_i,
  input  logic [StoreBits-1:0]       wstore_i,
  input  logic [RowBits-1:0]         wrow_i,
  input  logic [ColBits-1:0]         wcol_i,
  input  logic [Width-1:0]           wdata_i,
  input  logic [ColBits-1:0]         col_i,
  input  logic [Reads*StoreBits-1:0] store_i,
  input  logic [Reads*RowBits-1:0]   row_i,
  output logic [Reads*Width-1:0]     packet_o
);

  logic [Width-1:0] mem_q [2**AddrBits];

  logic [AddrBits-1:0] waddr;
  assign waddr = {wstore_i, wrow_i, wcol_i};

  always_ff @(posedge clk_i) begin
    if (we_i) mem_q[waddr] <= wdata_i;
  end

  for (genvar i = 0; i < Reads; i++) begin : g_read
    logic [AddrBits-1:0] raddr;
    assign raddr = {store_i[i*StoreBits +: StoreBits], row_i[i*RowBits +: RowBits], col_i};
    assign packet_o[i*Width +: Width] = (we_i && raddr == waddr) ? wdata_i : mem_q[raddr];
  end

endmodule
