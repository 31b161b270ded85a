// cube4_gradient_persp_column: one pipeline's column stage of the
// perspective gradient ring (docs/perspective.md, "The plan for the ring's
// RTL"; docs/rtl-gradient-persp.md). It keeps the samples that arrive on
// its lane in four slice stores and, once per step, reads its column's
// cells at the rows the beam's gradients need: one column packet.
//
// Function: for each read port i = 0 .. Reads-1,
//   packet_o[i] = the word last written at (store_i[i], row_i[i], col_i),
// or wdata_i where this step writes that entry (a gradient formed in the
// very step that forms one of its operands takes it from the beat). The
// write (we_i) stores wdata_i at (wstore_i, wrow_i, col_i) at the clock
// edge. Entries never written read as whatever they hold: the ring reads
// only rows the schedule has filled, and gates the operands of rays that
// miss their slice.
//
// Addressing: an entry is (store, row, partial beam); the ring's beams are
// ceil(nx/p) <= BeamDepth partial beams. The address {store, row, col} needs
// no multiplier; rows take MaxDim entries of 2^ceil(log2 BeamDepth) each.
//
// Latency: packet_o is combinational (the stores are read asynchronously,
// as cube4_delay_ram's); the write lands at the edge.
//
// Parameters:
//   Width     - a stored word: {voxel tag, sample}
//   Reads     - read ports (seven: three rows of slice k, two each of k -/+ 1)
//   MaxDim    - rows per store (the largest ny)
//   BeamDepth - partial beams per beam (ceil(MaxDim / p))
`include "cube4_pkg.sv"

module cube4_gradient_persp_column #(
  parameter int unsigned  Width     = 12,
  parameter int unsigned  Reads     = 7,
  parameter int unsigned  MaxDim    = 256,
  parameter int unsigned  BeamDepth = 64,
  localparam int unsigned RowBits   = $clog2(MaxDim),
  localparam int unsigned ColBits   = BeamDepth > 1 ? $clog2(BeamDepth) : 1,
  localparam int unsigned AddrBits  = 2 + RowBits + ColBits
) (
  input  logic                     clk_i,
  input  logic                     we_i,
  input  logic [1:0]               wstore_i,
  input  logic [RowBits-1:0]       wrow_i,
  input  logic [Width-1:0]         wdata_i,
  input  logic [ColBits-1:0]       col_i,
  input  logic [Reads*2-1:0]       store_i,
  input  logic [Reads*RowBits-1:0] row_i,
  output logic [Reads*Width-1:0]   packet_o
);

  logic [Width-1:0] mem_q [2**AddrBits];

  logic [AddrBits-1:0] waddr;
  assign waddr = {wstore_i, wrow_i, col_i};

  always_ff @(posedge clk_i) begin
    if (we_i) mem_q[waddr] <= wdata_i;
  end

  for (genvar i = 0; i < Reads; i++) begin : g_read
    logic [AddrBits-1:0] raddr;
    assign raddr = {store_i[i*2 +: 2], row_i[i*RowBits +: RowBits], col_i};
    assign packet_o[i*Width +: Width] = (we_i && raddr == waddr) ? wdata_i : mem_q[raddr];
  end

endmodule
