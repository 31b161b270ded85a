// cube4_gradient_unit_sva: the stream preconditions cube4_gradient_unit's
// header states, as assertions (bound to every instance below; compiled in
// by Verilator's --assert, docs/verification.md, "Assertions"):
//   a_zero_beam_idle - valid_i stays low in the B cycles of the unit's own
//                      zero beam after the zero slice: the unit has no
//                      back-pressure, so a sample there would be dropped;
//   a_beam_fits      - a beam has at most BeamDepth partial beams
//                      (ceil(nx/p) <= BeamDepth): a longer one wraps the
//                      beam delay onto its own first entries;
//   a_slice_fits     - a slice has at most SliceDepth samples
//                      (ny * ceil(nx/p) <= SliceDepth): a longer one
//                      overwrites the slice delay's oldest samples before
//                      they are read (the FIFO overflows).
// A failure prints the cycle (cube4_sva_cycle) and the values at fault;
// the simulator's prefix names the instance, so the pipeline.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_gradient_unit_sva #(
  parameter int unsigned  BeamDepth  = 64,
  parameter int unsigned  SliceDepth = 16384,
  parameter int unsigned  DimBits    = 9,
  localparam int unsigned BeamBits   = $clog2(BeamDepth + 1),
  localparam int unsigned CountBits  = $clog2(SliceDepth + 1)
) (
  input logic                clk_i,
  input logic                rst_ni,
  input logic                valid_i,
  input logic                slice_end_i,
  input logic                beam_end_i,
  // The unit's step control (internal signals, connected by name).
  input logic                zb_active,
  input logic [BeamBits-1:0] zb_left_q,
  input logic                step,
  input logic                step_in,
  input logic [BeamBits-1:0] j_step,
  input logic [DimBits-1:0]  y_step
);

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  // Input samples of the current slice so far (saturating: the first one
  // too many fires).
  logic [CountBits-1:0] samples_q;
  logic                 slice_last;
  assign slice_last = step_in && slice_end_i && beam_end_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      samples_q <= '0;
    end else begin
      if (slice_last) begin
        samples_q <= '0;
      end else if (step_in && samples_q != CountBits'(SliceDepth)) begin
        samples_q <= samples_q + CountBits'(1);
      end

      a_zero_beam_idle: assert (!(valid_i && zb_active))
        else $error("cube4_gradient_unit: cycle %0d: valid_i high in a zero-beam cycle (%0d of its steps left): the stream must leave B idle cycles after the zero slice",
                    cycle, zb_left_q);
      a_beam_fits: assert (!(step && j_step >= BeamBits'(BeamDepth)))
        else $error("cube4_gradient_unit: cycle %0d: partial beam %0d of beam %0d, but the beam delay holds %0d (ceil(nx/p) <= BeamDepth)",
                    cycle, j_step, y_step, BeamDepth);
      a_slice_fits: assert (!(step_in && samples_q >= CountBits'(SliceDepth)))
        else $error("cube4_gradient_unit: cycle %0d: sample %0d of a slice, but the slice delay holds %0d (ny * ceil(nx/p) <= SliceDepth)",
                    cycle, samples_q, SliceDepth);
    end
  end

endmodule

bind cube4_gradient_unit cube4_gradient_unit_sva #(
  .BeamDepth (BeamDepth),
  .SliceDepth(SliceDepth),
  .DimBits   (DimBits)
) u_sva (.*);
