// Formal harness for cube4_delay_ram: the delay line neither overflows nor
// underflows.
//   - In every cycle, whatever depth_i, last_i and clear_i do, the pointer
//     stays inside the RAM (no write or read beyond MaxDepth).
//   - With a run-time depth D (depth_i constant, 1..MaxDepth; the frame
//     register use) and laps of D steps (last_i low): the pointer stays
//     below D, and a value written in step t is on rdata_o in step t + D
//     (not overwritten before: no overflow; not read before it is written
//     or after a newer write: no underflow), and again one lap later for
//     every lap without a write (re-reading a slice). The value followed
//     is picked by the solver (track_i), so this holds for every step.
// FIFO checks the second set (parameter Fifo = 1); Fifo = 0 leaves depth_i
// and last_i free and checks the first only.
//
// Proof: 1-induction, strengthened with invariants on the unit's state
// (probes: the pointer and the RAM entries): rdata_o holds the entry
// under the pointer, the followed value sits in its entry, and the pointer
// is the followed entry's plus the steps since.
module delay_ram_fv #(
  parameter int unsigned  Width     = 2,
  parameter int unsigned  MaxDepth  = 5,
  parameter bit           Fifo      = 1'b1,
  localparam int unsigned DepthBits = $clog2(MaxDepth + 1),
  localparam int unsigned PtrBits   = (MaxDepth > 1) ? $clog2(MaxDepth) : 1
) (
  input logic                 clk_i,
  input logic                 rst_ni,
  input logic [DepthBits-1:0] depth_i,
  input logic                 clear_i,
  input logic                 advance_i,
  input logic                 last_i,
  input logic                 write_i,
  input logic [Width-1:0]     wdata_i,
  input logic                 track_i
);

  logic [Width-1:0] rdata;

  cube4_delay_ram #(
    .Width   (Width),
    .MaxDepth(MaxDepth)
  ) u_dut (
    .clk_i,
    .rst_ni,
    .depth_i,
    .clear_i,
    .advance_i,
    .last_i,
    .write_i,
    .wdata_i,
    .rdata_o(rdata)
  );

  // Probes (connected by scripts/formal.sh).
  logic [PtrBits-1:0]        probe_ptr;
  logic [MaxDepth*Width-1:0] probe_mem;   // entry e at [e*Width +: Width]

  logic step;
  assign step = advance_i && !clear_i;

  // The value followed: written in a step with track_i, expected on rdata_o
  // whenever a multiple of D steps later; dropped on clear_i or once
  // overwritten. count: steps since its write, mod D.
  logic                 tracking_q = 1'b0;
  logic [Width-1:0]     tracked_q;
  logic [PtrBits-1:0]   tracked_ptr_q;
  logic [DepthBits-1:0] count_q;
  logic                 reset_seen_q = 1'b0, written_q = 1'b0;
  logic                 due;
  assign due = tracking_q && step && count_q == depth_i - DepthBits'(1);

  always_ff @(posedge clk_i) begin
    if (!rst_ni) reset_seen_q <= 1'b1;
    written_q <= rst_ni;  // a clock out of reset has loaded the read register
    if (!rst_ni || clear_i) begin
      tracking_q <= 1'b0;
    end else if (step) begin
      if (tracking_q) begin
        count_q <= due ? '0 : count_q + DepthBits'(1);
        if (due && write_i) tracking_q <= 1'b0;
      end else if (track_i && write_i) begin
        tracking_q    <= 1'b1;
        tracked_q     <= wdata_i;
        tracked_ptr_q <= probe_ptr;
        count_q       <= '0;
      end
    end
  end

  logic [DepthBits-1:0] depth_prev_q;
  always_ff @(posedge clk_i) depth_prev_q <= depth_i;

  function automatic logic [Width-1:0] entry(input logic [PtrBits-1:0] e);
    entry = probe_mem[e*Width +: Width];
  endfunction

  // (tracked_ptr + count + 1) mod D: where the pointer must be.
  logic [DepthBits:0] ptr_exp;
  always_comb begin
    ptr_exp = (DepthBits+1)'(tracked_ptr_q) + (DepthBits+1)'(count_q) + (DepthBits+1)'(1);
    if (ptr_exp >= (DepthBits+1)'(depth_i)) ptr_exp = ptr_exp - (DepthBits+1)'(depth_i);
  end

  always_comb begin
    if ($initstate) assume (!rst_ni);
    if (Fifo) begin
      assume (depth_i >= DepthBits'(1) && depth_i <= DepthBits'(MaxDepth));
      if (!$initstate) assume (depth_i == depth_prev_q);
      assume (!last_i);
    end
    if (reset_seen_q) begin
      assert (probe_ptr <= PtrBits'(MaxDepth - 1));
      // The read register shows the entry under the pointer, so a step
      // reads that entry and nothing else.
      if (written_q && rst_ni) assert (rdata == entry(probe_ptr));
      if (Fifo && rst_ni) begin
        assert (DepthBits'(probe_ptr) < depth_i);
        if (tracking_q) begin
          assert (count_q < depth_i);
          assert (DepthBits'(tracked_ptr_q) < depth_i);
          assert (entry(tracked_ptr_q) == tracked_q);
          assert ((DepthBits+1)'(probe_ptr) == ptr_exp);
        end
        // The property itself: the followed value comes out after D steps.
        if (due) assert (rdata == tracked_q);
      end
    end
  end

endmodule
