// cube4_delay_ram: a delay line on a RAM array, the storage primitive of the
// beam and slice delays (VolumePro §3.1: "each of these is a data storage
// element sized so that when a newly calculated value is inserted, it
// emerges again at precisely the time needed").
//
// Function: a circular buffer of `depth` entries with one pointer. Every
// cycle with advance_i high is one step of the line: rdata_o shows the
// entry under the pointer (the value written there one lap earlier), the
// entry is overwritten with wdata_i if write_i is high (kept otherwise, so
// that a lap without writes reads the same lap again: re-reading a slice),
// and the pointer moves on, back to entry 0 after entry depth_i - 1, after
// entry MaxDepth - 1, or when last_i marks the step as the last of a lap
// (a lap length carried by the data stream's own end flags instead of a
// depth register). clear_i moves the pointer to entry 0 without a step
// (it wins over advance_i; nothing is written). So with write_i = 1 and a
// lap of D steps, rdata_o in step t is wdata_i of step t - D: a FIFO of D
// entries with one push and one pop per clock that never over- or
// underflows.
//
// RAM: one write port and one synchronous read port (1R1W, two-port SRAM).
// The read pointer runs one entry ahead of the write pointer: the entry for
// the next step is read in the cycle of the current step and held in the
// read register, so rdata_o is a register output. When the entry read is
// the one written in the same cycle (a lap of one entry) the write data is
// forwarded.
//
// Latency: rdata_o is valid in the step's own cycle (from the read register);
// a value written in step t is on rdata_o in the step one lap later, however
// many idle cycles lie between. The read register follows the pointer on
// every clock edge, so a step may directly follow a clear_i.
// Handshake: none (advance_i is the enable); the user knows which laps hold
// data. Reset: the pointer only; the RAM and the read register are not reset
// (rdata_o is meaningful once its entry has been written).
//
// Parameters:
//   Width    - entry width in bits
//   MaxDepth - RAM entries (>= 1); the run-time depth_i and the lap lengths
//              given by last_i must not exceed it
//   DepthBits, PtrBits - (derived) widths of depth_i and of the pointer
module cube4_delay_ram #(
  parameter int unsigned  Width     = 24,
  parameter int unsigned  MaxDepth  = 64,
  localparam int unsigned DepthBits = $clog2(MaxDepth + 1),
  localparam int unsigned PtrBits   = (MaxDepth > 1) ? $clog2(MaxDepth) : 1
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  input  logic [DepthBits-1:0] depth_i,    // run-time lap length, 1 .. MaxDepth
  input  logic                 clear_i,    // pointer to entry 0, no step
  input  logic                 advance_i,  // one step
  input  logic                 last_i,     // this step ends the lap
  input  logic                 write_i,    // the step overwrites its entry
  input  logic [Width-1:0]     wdata_i,
  output logic [Width-1:0]     rdata_o     // the entry of the current step
);

  logic [Width-1:0]   mem_q [MaxDepth];
  logic [PtrBits-1:0] ptr_q, ptr_d;
  logic [Width-1:0]   rdata_q, rdata_d;
  logic               wrap, we;

  // The pointer's last entry: depth_i - 1, the RAM's end, or last_i.
  assign wrap = last_i
             || ({1'b0, ptr_q} + (PtrBits+1)'(1) == (PtrBits+1)'(depth_i))
             || (ptr_q == PtrBits'(MaxDepth - 1));
  assign we   = advance_i && write_i && !clear_i;

  always_comb begin
    ptr_d = ptr_q;
    if (clear_i) begin
      ptr_d = '0;
    end else if (advance_i) begin
      ptr_d = wrap ? '0 : ptr_q + PtrBits'(1);
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ptr_q <= '0;
    end else begin
      ptr_q <= ptr_d;
    end
  end

  // Write port at the current pointer.
  always_ff @(posedge clk_i) begin
    if (we) begin
      mem_q[ptr_q] <= wdata_i;
    end
  end

  // Read port at the next pointer, every cycle, with write-to-read forwarding.
  assign rdata_d = (we && ptr_d == ptr_q) ? wdata_i : mem_q[ptr_d];

  always_ff @(posedge clk_i) begin
    rdata_q <= rdata_d;
  end
  assign rdata_o = rdata_q;

endmodule
