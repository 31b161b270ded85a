// cube4_gradient_ring: the gradient units of p pipelines connected near-
// neighbour in a ring (VolumePro §3.2, §5.1, Fig. 11; Cube-4 §5, "ABC
// gradient estimation" and "m < n").
//
// Function: pipeline k (cube4_gradient_unit) holds the samples with
// x = j*p + k of every partial beam j; it takes its x-1 column from pipeline
// k-1 and its x+1 column from pipeline k+1 (both their aligned links).
// Across partial beams the ring wraps: pipeline p-1 takes x+1 from pipeline
// 0's column of the next partial beam (link_now; zero after a beam's last),
// pipeline 0 takes x-1 from pipeline p-1's column of the previous partial
// beam (link_prev; zero before a beam's first). The inputs are
// cube4_interp_ring's outputs as they are (one valid, flag set, sample and
// tag per pipeline; all pipelines in lock step); each pipeline emits, for
// every sample S(x, y, s) of its columns, golden sample_gradient() of its
// 12-neighbourhood, the sample itself, its position (x, y), its flags and
// its slice's user tag, one slice, one beam and one sample behind the input.
// Stream format, tag layout, zero padding (one zero beam per slice made by
// the units, one zero slice per frame from the stream former), latency (4
// cycles after the step of beam y+1 of slice s+1 without stalls; a frame's
// last gradient B + 4 cycles after its zero slice's last sample) and
// preconditions: cube4_gradient_unit and docs/rtl-gradient.md.
//
// Handshake: valid-only, no back-pressure. Reset: control only. A valid_i
// in a unit's zero beam, or pipelines out of lock step, are protocol errors
// that the assertions of rtl/assert/ report in simulation.
//
// Parameters:
//   NumPipes                                       - p, pipelines (>= 1)
//   VoxelBits, WeightBits, GradientBits, GradientShift,
//   SupersamplingBits                              - as cube4_gradient
//   UserTagBits                                    - user part of the tag
//   MaxDim                                         - largest nx and ny
//   VoxelTagBits                                   - voxel tag width (bela
//                                                    §III; 0: none, vtag_o 0)
//   HasVoxelZ                                      - VolumePro's z gradient:
//                                                    gz from each pipeline's
//                                                    zdiff_i lane (the unit)
//   CtrlBits, TagBits, DimBits, VTagPortBits       - (derived) as the unit
`include "cube4_pkg.sv"

module cube4_gradient_ring #(
  parameter int unsigned  NumPipes          = cube4_pkg::NumPipes,
  parameter int unsigned  VoxelBits         = cube4_pkg::VoxelBits,
  parameter int unsigned  WeightBits        = cube4_pkg::WeightBits,
  parameter int unsigned  GradientBits      = cube4_pkg::GradientBits,
  parameter int unsigned  GradientShift     = cube4_pkg::GradientShift,
  parameter int unsigned  SupersamplingBits = cube4_pkg::SupersamplingBits,
  parameter int unsigned  UserTagBits       = 8,
  parameter int unsigned  MaxDim            = cube4_pkg::MaxDim,
  parameter int unsigned  VoxelTagBits      = cube4_pkg::VoxelTagBits,
  parameter bit           HasVoxelZ         = 1'b0,
  localparam int unsigned CtrlBits          = 4 * (WeightBits + 1) + SupersamplingBits + 2,
  localparam int unsigned TagBits           = CtrlBits + UserTagBits,
  localparam int unsigned DimBits           = $clog2(MaxDim + NumPipes),
  localparam int unsigned VTagPortBits      = VoxelTagBits > 0 ? VoxelTagBits : 1
) (
  input  logic                             clk_i,
  input  logic                             rst_ni,
  // Sample streams, pipeline k at bit k / [k*VoxelBits +:] / [k*TagBits +:]
  // / [k*VTagPortBits +:] (the samples' voxel tags).
  input  logic [NumPipes-1:0]              valid_i,
  input  logic [NumPipes-1:0]              beam_start_i,
  input  logic [NumPipes-1:0]              beam_end_i,
  input  logic [NumPipes-1:0]              slice_start_i,
  input  logic [NumPipes-1:0]              slice_end_i,
  input  logic [NumPipes*VoxelBits-1:0]    sample_i,
  input  logic [NumPipes*TagBits-1:0]      tag_i,
  input  logic [NumPipes*VTagPortBits-1:0] vtag_i,
  input  logic [NumPipes*(VoxelBits+1)-1:0] zdiff_i,
  // Gradient streams, pipeline k at bit k / [k*width +: width].
  output logic [NumPipes-1:0]              valid_o,
  output logic [NumPipes-1:0]              beam_start_o,
  output logic [NumPipes-1:0]              beam_end_o,
  output logic [NumPipes-1:0]              slice_start_o,
  output logic [NumPipes-1:0]              slice_end_o,
  output logic [NumPipes*VoxelBits-1:0]    sample_o,
  output logic [NumPipes*VTagPortBits-1:0] vtag_o,
  output logic [NumPipes*GradientBits-1:0] gx_o,
  output logic [NumPipes*GradientBits-1:0] gy_o,
  output logic [NumPipes*GradientBits-1:0] gz_o,
  output logic [NumPipes*DimBits-1:0]      x_o,
  output logic [NumPipes*DimBits-1:0]      y_o,
  output logic [NumPipes*UserTagBits-1:0]  tag_o
);

  localparam int unsigned LinkBits = HasVoxelZ ? VoxelBits : 5 * VoxelBits;

  // Links as packed vectors (yosys 0.23: no unpacked wire arrays).
  logic [NumPipes*LinkBits-1:0] link, link_now, link_prev;

  for (genvar k = 0; k < NumPipes; k++) begin : g_pipe
    logic [LinkBits-1:0] left_in, right_in;

    if (k == 0) begin : g_wrap_left
      assign left_in = link_prev[(NumPipes-1)*LinkBits +: LinkBits];
    end else begin : g_left
      assign left_in = link[(k-1)*LinkBits +: LinkBits];
    end
    if (k == NumPipes - 1) begin : g_wrap_right
      assign right_in = link_now[0 +: LinkBits];
    end else begin : g_right
      assign right_in = link[(k+1)*LinkBits +: LinkBits];
    end

    cube4_gradient_unit #(
      .NumPipes         (NumPipes),
      .PipeIndex        (k),
      .VoxelBits        (VoxelBits),
      .WeightBits       (WeightBits),
      .GradientBits     (GradientBits),
      .GradientShift    (GradientShift),
      .SupersamplingBits(SupersamplingBits),
      .UserTagBits      (UserTagBits),
      .MaxDim           (MaxDim),
      .VoxelTagBits     (VoxelTagBits),
      .HasVoxelZ        (HasVoxelZ)
    ) u_unit (
      .clk_i        (clk_i),
      .rst_ni       (rst_ni),
      .valid_i      (valid_i[k]),
      .beam_start_i (beam_start_i[k]),
      .beam_end_i   (beam_end_i[k]),
      .slice_start_i(slice_start_i[k]),
      .slice_end_i  (slice_end_i[k]),
      .sample_i     (sample_i[k*VoxelBits +: VoxelBits]),
      .tag_i        (tag_i[k*TagBits +: TagBits]),
      .vtag_i       (vtag_i[k*VTagPortBits +: VTagPortBits]),
      .zdiff_i      (zdiff_i[k*(VoxelBits+1) +: VoxelBits+1]),
      .link_o       (link[k*LinkBits +: LinkBits]),
      .link_now_o   (link_now[k*LinkBits +: LinkBits]),
      .link_prev_o  (link_prev[k*LinkBits +: LinkBits]),
      .link_left_i  (left_in),
      .link_right_i (right_in),
      .valid_o      (valid_o[k]),
      .beam_start_o (beam_start_o[k]),
      .beam_end_o   (beam_end_o[k]),
      .slice_start_o(slice_start_o[k]),
      .slice_end_o  (slice_end_o[k]),
      .sample_o     (sample_o[k*VoxelBits +: VoxelBits]),
      .vtag_o       (vtag_o[k*VTagPortBits +: VTagPortBits]),
      .gx_o         (gx_o[k*GradientBits +: GradientBits]),
      .gy_o         (gy_o[k*GradientBits +: GradientBits]),
      .gz_o         (gz_o[k*GradientBits +: GradientBits]),
      .x_o          (x_o[k*DimBits +: DimBits]),
      .y_o          (y_o[k*DimBits +: DimBits]),
      .tag_o        (tag_o[k*UserTagBits +: UserTagBits])
    );
  end

  // Only pipeline 0's current column and pipeline p-1's previous column
  // leave their units through the wrap; with p = 1 the aligned link has no
  // neighbour at all.
  logic unused_links;
  if (NumPipes > 1) begin : g_unused
    assign unused_links = ^{link_now[NumPipes*LinkBits-1:LinkBits],
                            link_prev[(NumPipes-1)*LinkBits-1:0]};
  end else begin : g_unused_p1
    assign unused_links = ^link;
  end

endmodule
