// cube4_persp_stream: where a perspective ring's stream step is
// (docs/perspective.md, "The dataflow"): the pass, beam and partial beam
// of each step, and the last six beams, which the gradient and compositing
// rings (cube4_gradient_persp_ring, cube4_composite_persp_ring) place their
// samples, accumulators and the cells they form by.
//
// Function, for the step in valid_i's cycle (combinational: *_now_o) and
// the beams before it (registered at each beam's last step):
//   pass_start_o   the step starts a pass (its first step, not a flush)
//   pass_now_o     the step's pass, mod 4 (the stream's first pass is 0)
//   col_now_o      its partial beam j
//   beam_*_o[d]    beam d back, d = 0 (the step's own) .. 6: whether it is
//                  a pass's beam (not a flush beam), whether that pass has
//                  one before it in the stream (its beams form the cells
//                  of the pass before), whether it is its pass's last, its
//                  row in the pass and its pass mod 4. Reset: none of them
//                  a pass's beam.
//   ny_o           a pass's rows, counted at each pass's end (0 before)
// Stream flags as the interpolation ring's: slice_start_i marks every step
// of a pass's beam 0, beam_start_i / beam_end_i a beam's first and last
// partial beam, flush_i the beams after the stream's last pass.
//
// Parameters:
//   MaxDim    - the largest ny (rows) and, with NumPipes, partial beams
//   NumPipes  - pipelines p (ceil(MaxDim / p) partial beams at most)
`include "cube4_pkg.sv"

module cube4_persp_stream #(
  parameter int unsigned  MaxDim    = 256,
  parameter int unsigned  NumPipes  = 4,
  localparam int unsigned BeamDepth = (MaxDim + NumPipes - 1) / NumPipes,
  localparam int unsigned RowBits   = $clog2(MaxDim),
  localparam int unsigned ColBits   = BeamDepth > 1 ? $clog2(BeamDepth) : 1,
  localparam int unsigned Beams     = 7  // the step's own and six back
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,
  input  logic                       valid_i,
  input  logic                       beam_start_i,
  input  logic                       beam_end_i,
  input  logic                       slice_start_i,
  input  logic                       slice_end_i,
  input  logic                       flush_i,
  output logic                       pass_start_o,
  output logic [1:0]                 pass_now_o,
  output logic [ColBits-1:0]         col_now_o,
  output logic [Beams-1:0]           beam_real_o,
  output logic [Beams-1:0]           beam_after_first_o,
  output logic [Beams-1:0]           beam_last_row_o,
  output logic [Beams*RowBits-1:0]   beam_row_o,
  output logic [Beams*2-1:0]         beam_pass_o,
  output logic [RowBits:0]           ny_o
);

  assign pass_start_o = valid_i && slice_start_i && beam_start_i && !flush_i;

  logic [1:0] pass_q;
  assign pass_now_o = pass_start_o ? pass_q + 2'd1 : pass_q;

  // Passes started since reset, saturating at 2: whether the step's pass
  // has one before it. (A stream after another finds the zero pass there,
  // which has no rays.)
  logic [1:0] started_q;
  logic       after_first;
  assign after_first = pass_start_o ? started_q != 2'd0 : started_q == 2'd2;

  logic [RowBits-1:0] row_q, row_now;
  logic [ColBits-1:0] col_q;
  assign row_now   = slice_start_i ? '0 : row_q;
  assign col_now_o = beam_start_i ? '0 : col_q;

  // The beams back, each {real, after_first, last_row, row, pass}.
  localparam int unsigned BeamBits = 3 + RowBits + 2;
  logic [BeamBits-1:0]          beam_now;
  logic [(Beams-1)*BeamBits-1:0] beams_q;  // beam d back at [(d-1)*BeamBits]
  logic [Beams*BeamBits-1:0]     beams;
  assign beam_now = {!flush_i, after_first, slice_end_i, row_now, pass_now_o};
  assign beams    = {beams_q, beam_now};
  for (genvar d = 0; d < Beams; d++) begin : g_beam
    assign {beam_real_o[d], beam_after_first_o[d], beam_last_row_o[d], beam_row_o[d*RowBits +: RowBits],
            beam_pass_o[d*2 +: 2]} = beams[d*BeamBits +: BeamBits];
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      pass_q    <= 2'd3;  // the stream's first pass is pass 0
      started_q <= '0;
      row_q     <= '0;
      col_q     <= '0;
      ny_o      <= '0;
      beams_q   <= '0;
    end else begin
      pass_q <= pass_now_o;
      if (pass_start_o && started_q != 2'd2) started_q <= started_q + 2'd1;
      if (valid_i) begin
        col_q <= col_now_o + ColBits'(1);
        if (beam_end_i) begin
          row_q <= row_now + RowBits'(1);
          if (slice_end_i && !flush_i) ny_o <= (RowBits+1)'(row_now) + (RowBits+1)'(1);
          beams_q <= beams[0 +: (Beams-1)*BeamBits];
        end
      end
    end
  end

endmodule
