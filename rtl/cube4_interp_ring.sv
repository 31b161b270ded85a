// cube4_interp_ring: the interpolation units of p pipelines connected near-
// neighbour in a ring (VolumePro §5.1, Fig. 11; Cube-4 §5 "m < n").
//
// Function: pipeline k (cube4_interp_unit) handles the voxels with
// x = j*p + k of every partial beam j; it takes the x+1 column from pipeline
// k+1's aligned link, and pipeline p-1 takes it from pipeline 0's link of the
// next partial beam (the wrap; zero after a beam's last partial beam). The
// stream control (valid, flags, weights, tag) is common and fans out to every
// pipeline, where it travels with the data; voxel_i carries one voxel per
// pipeline (the memory word {voxel tag, value} with voxel tags). Each
// pipeline emits the samples of its own columns:
// sample_o[k] = S(j*p + k, y) of the pass, with its own valid and flags (all
// pipelines run in lock step). Stream format (passes back to back, a flush
// beam after the last), latency (4 cycles without stalls) and
// preconditions: see
// cube4_interp_unit and docs/rtl-interp.md. nx not a multiple of p is padded
// by the stream with zero voxels (columns x >= nx produce samples of the
// padding).
//
// Handshake: valid-only, no back-pressure. Reset: control only.
//
// Parameters:
//   NumPipes              - p, pipelines (>= 1)
//   VoxelBits, WeightBits - widths (Precision defaults 12, 8)
//   TagBits               - stream-control tag travelling with the data
//   VoxelTagBits          - voxel tag width (bela §III; 0: none, vtag_o 0)
//   HasZDiff              - VolumePro's z gradient: each pipeline's zdiff_o
//                           lane beside its samples; the stream reads one
//                           slice ahead after a priming pass (prime_i;
//                           cube4_interp_unit, docs/rtl-interp-zdiff.md)
//   MaxDim                - largest nx and ny the delay storage holds
//   BeamDepth, SliceDepth - (derived) per-pipeline beam delay and slice store
//                           entries: ceil(MaxDim / p) and MaxDim * that
//   WordBits, VTagPortBits - (derived) voxel word and vtag_o lane widths
`include "cube4_pkg.sv"

module cube4_interp_ring #(
  parameter int unsigned  NumPipes   = cube4_pkg::NumPipes,
  parameter int unsigned  VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned  WeightBits = cube4_pkg::WeightBits,
  parameter int unsigned  TagBits    = 8,
  parameter int unsigned  MaxDim     = cube4_pkg::MaxDim,
  parameter int unsigned  VoxelTagBits = cube4_pkg::VoxelTagBits,
  parameter bit           HasZDiff   = 1'b0,
  localparam int unsigned BeamDepth  = (MaxDim + NumPipes - 1) / NumPipes,
  localparam int unsigned SliceDepth = MaxDim * BeamDepth,
  localparam int unsigned WordBits     = VoxelBits + VoxelTagBits,
  localparam int unsigned VTagPortBits = VoxelTagBits > 0 ? VoxelTagBits : 1
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  // Voxel stream: common control, one voxel word per pipeline ([k*WordBits +:]).
  input  logic                          valid_i,
  input  logic                          beam_start_i,
  input  logic                          beam_end_i,
  input  logic                          slice_start_i,
  input  logic                          slice_end_i,
  input  logic                          flush_i,
  input  logic                          prime_i,
  input  logic [NumPipes*WordBits-1:0]  voxel_i,
  input  logic [WeightBits:0]           wx_i,
  input  logic [WeightBits:0]           wy_i,
  input  logic [WeightBits:0]           wz_i,
  input  logic [TagBits-1:0]            tag_i,
  // Sample streams, pipeline k at bit k / [k*VoxelBits +:] /
  // [k*VTagPortBits +:] / [k*TagBits +:].
  output logic [NumPipes-1:0]           valid_o,
  output logic [NumPipes-1:0]           beam_start_o,
  output logic [NumPipes-1:0]           beam_end_o,
  output logic [NumPipes-1:0]           slice_start_o,
  output logic [NumPipes-1:0]           slice_end_o,
  output logic [NumPipes*VoxelBits-1:0] sample_o,
  output logic [NumPipes*VTagPortBits-1:0] vtag_o,
  output logic [NumPipes*(VoxelBits+1)-1:0] zdiff_o,
  output logic [NumPipes*TagBits-1:0]   tag_o
);

  localparam int unsigned LinkBits = 4 * WordBits + (HasZDiff ? 4 * VoxelBits : 0);

  // Links as packed vectors (yosys 0.23: no unpacked wire arrays).
  logic [NumPipes*LinkBits-1:0] link, link_now;

  for (genvar k = 0; k < NumPipes; k++) begin : g_pipe
    localparam bit Last = k == NumPipes - 1;
    logic [LinkBits-1:0] link_in;

    if (Last) begin : g_wrap
      assign link_in = link_now[0 +: LinkBits];
    end else begin : g_next
      assign link_in = link[(k+1)*LinkBits +: LinkBits];
    end

    cube4_interp_unit #(
      .VoxelBits (VoxelBits),
      .WeightBits(WeightBits),
      .TagBits   (TagBits),
      .BeamDepth (BeamDepth),
      .SliceDepth(SliceDepth),
      .WrapIn    (Last),
      .VoxelTagBits(VoxelTagBits),
      .HasZDiff  (HasZDiff)
    ) u_unit (
      .clk_i        (clk_i),
      .rst_ni       (rst_ni),
      .valid_i      (valid_i),
      .beam_start_i (beam_start_i),
      .beam_end_i   (beam_end_i),
      .slice_start_i(slice_start_i),
      .slice_end_i  (slice_end_i),
      .flush_i      (flush_i),
      .prime_i      (prime_i),
      .voxel_i      (voxel_i[k*WordBits +: WordBits]),
      .wx_i         (wx_i),
      .wy_i         (wy_i),
      .wz_i         (wz_i),
      .tag_i        (tag_i),
      .link_o       (link[k*LinkBits +: LinkBits]),
      .link_now_o   (link_now[k*LinkBits +: LinkBits]),
      .link_i       (link_in),
      .valid_o      (valid_o[k]),
      .beam_start_o (beam_start_o[k]),
      .beam_end_o   (beam_end_o[k]),
      .slice_start_o(slice_start_o[k]),
      .slice_end_o  (slice_end_o[k]),
      .sample_o     (sample_o[k*VoxelBits +: VoxelBits]),
      .vtag_o       (vtag_o[k*VTagPortBits +: VTagPortBits]),
      .zdiff_o      (zdiff_o[k*(VoxelBits+1) +: VoxelBits+1]),
      .tag_o        (tag_o[k*TagBits +: TagBits])
    );
  end

  // Pipeline 0's aligned column has no left neighbour, and only pipeline
  // 0's current column leaves its unit (the wrap).
  logic unused_links;
  if (NumPipes > 1) begin : g_unused
    assign unused_links = ^{link[0 +: LinkBits], link_now[NumPipes*LinkBits-1:LinkBits]};
  end else begin : g_unused_p1
    assign unused_links = ^link;
  end

endmodule
