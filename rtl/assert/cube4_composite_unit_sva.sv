// cube4_composite_unit_sva: the storage preconditions cube4_composite_unit's
// header states, and the read-after-write order of its ray slice store, as
// assertions bound to every instance (attached from here, so the unit's
// file carries none):
//   a_beam_fits        - a beam has at most BeamDepth partial beams
//                        (ceil(nx/p) <= BeamDepth): a longer one wraps the
//                        ray beam delay (FIFO overflow);
//   a_slice_fits       - a slice has at most SliceDepth samples
//                        (ny * ceil(nx/p) <= SliceDepth): more wrap the ray
//                        slice store onto rays not yet continued;
//   a_slice_read_written - a sample of slice k > 0 continues the ray stored
//                        at its entry by slice k - 1: the entry must be one
//                        slice k - 1 wrote (slices of a frame equally long;
//                        FIFO underflow otherwise);
//   a_ray_store_order  - the store writes a step's ray in the cycle after the
//                        step and only then (the datapath's result follows
//                        the accumulator input by one cycle): this is what
//                        puts every read of an entry for slice k before
//                        slice k's write of it, and the next slice's read
//                        after it (through the bypass when they meet).
// A failure prints the cycle (cube4_sva_cycle) and the values at fault.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_composite_unit_sva #(
  parameter int unsigned  BeamDepth  = 64,
  parameter int unsigned  SliceDepth = 16384,
  localparam int unsigned BeamBits   = $clog2(BeamDepth + 1),
  localparam int unsigned CountBits  = $clog2(SliceDepth + 1)
) (
  input logic clk_i,
  input logic rst_ni,
  input logic valid_i,
  input logic beam_end_i,
  input logic slice_end_i,
  input logic first_slice_i,
  // The ray storage's step (AccDelay cycles after the input) and the
  // datapath's result, the store's write (internal signals, by name).
  input logic step,
  input logic result_valid
);

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  // Partial beams of the current beam, samples of the current slice and of
  // the previous one (0 after reset), and the step of the cycle before.
  logic [BeamBits-1:0]  j_q;
  logic [CountBits-1:0] n_q, prev_q;
  logic                 step_q;
  logic                 slice_last;
  assign slice_last = slice_end_i && beam_end_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      j_q    <= '0;
      n_q    <= '0;
      prev_q <= '0;
      step_q <= 1'b0;
    end else begin
      step_q <= step;
      if (valid_i) begin
        j_q <= (beam_end_i || j_q == BeamBits'(BeamDepth)) ? '0 : j_q + BeamBits'(1);
        if (slice_last) begin
          n_q    <= '0;
          prev_q <= n_q + CountBits'(1);
        end else if (n_q != CountBits'(SliceDepth)) begin
          n_q <= n_q + CountBits'(1);
        end
      end
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_beam_fits: assert (!valid_i || j_q < BeamBits'(BeamDepth))
        else $error("cube4_composite_unit: cycle %0d: partial beam %0d of a beam, but the ray beam delay holds %0d (ceil(nx/p) <= BeamDepth)",
                    cycle, j_q, BeamDepth);
      a_slice_fits: assert (!valid_i || n_q < CountBits'(SliceDepth))
        else $error("cube4_composite_unit: cycle %0d: sample %0d of a slice, but the ray slice store holds %0d (ny * ceil(nx/p) <= SliceDepth)",
                    cycle, n_q, SliceDepth);
      a_slice_read_written: assert (!valid_i || first_slice_i || n_q < prev_q)
        else $error("cube4_composite_unit: cycle %0d: sample %0d of a slice continues a stored ray, but the slice before stored %0d",
                    cycle, n_q, prev_q);
      a_ray_store_order: assert (result_valid == step_q)
        else $error("cube4_composite_unit: cycle %0d: ray store written %0d, step in the cycle before %0d: a step's ray must be written in the next cycle",
                    cycle, result_valid, step_q);
    end
  end

endmodule

bind cube4_composite_unit cube4_composite_unit_sva #(
  .BeamDepth (BeamDepth),
  .SliceDepth(SliceDepth)
) u_sva (.*);
