// cube4_gradient_ring_sva: the ring's precondition that its pipelines run
// in lock step (cube4_gradient_unit's header: all pipelines see the same
// valid_i and flags), as an assertion bound to every cube4_gradient_ring:
//   a_lock_step - valid_i is all ones or all zeros, and in a valid cycle
//                 every flag is too. The ring takes one valid and flag set
//                 per pipeline only because cube4_interp_ring delivers
//                 them so; pipelines out of step would exchange columns of
//                 different partial beams over their links.
//
// Simulation only: not part of the ring, never synthesised.
module cube4_gradient_ring_sva #(
  parameter int unsigned NumPipes = 4
) (
  input logic                clk_i,
  input logic                rst_ni,
  input logic [NumPipes-1:0] valid_i,
  input logic [NumPipes-1:0] beam_start_i,
  input logic [NumPipes-1:0] beam_end_i,
  input logic [NumPipes-1:0] slice_start_i,
  input logic [NumPipes-1:0] slice_end_i
);

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  function automatic logic uniform(input logic [NumPipes-1:0] v);
    uniform = v == '0 || v == '1;
  endfunction

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_lock_step: assert (uniform(valid_i) && (valid_i == '0 || (uniform(beam_start_i) && uniform(beam_end_i)
                                                                 && uniform(slice_start_i) && uniform(slice_end_i))))
        else $error("cube4_gradient_ring: cycle %0d: pipelines out of lock step: valid_i %b, beam_start_i %b, beam_end_i %b, slice_start_i %b, slice_end_i %b",
                    cycle, valid_i, beam_start_i, beam_end_i, slice_start_i, slice_end_i);
    end
  end

endmodule

bind cube4_gradient_ring cube4_gradient_ring_sva #(.NumPipes(NumPipes)) u_sva (.*);
