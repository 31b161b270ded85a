// cube4_shade_unit: one pipeline's shading stage as the system connects it,
// the gradient unit's output in, the compositing unit's input out:
//   |g|     = cube4_shade_magnitude(g)                      (MagLatency cycles)
//   shaded  = cube4_shade(sample, g, |g|)            (the shader's Latency)
// The sample, the gradient and the side bits wait MagLatency cycles so that
// they meet their magnitude at the shader; the shader carries the side bits
// to its output. Equals golden shade_sample() without cropping and the cut
// plane (those act in cube4_composite), given golden sample_gradient()'s g.
//
// Why a unit of its own: the magnitude feeds only the shader (GmLUT and the
// α/colour modulation), so the two are one stage of the pipeline; the
// system instantiates one per pipeline. It has no neighbour links.
//
// Latency: NrIterations + 1 + the shader's Latency (4 + 17 = 21 with the
// defaults). Fully pipelined, valid-only handshake, valid_i travels to
// valid_o. Frame registers and table write ports are the shader's (change
// them only with no sample in flight).
//
// Voxel tags (bela §III; VoxelTagBits > 0): vtag_i, the sample's tag (the
// gradient unit's vtag_o), waits for the magnitude with the sample and goes
// to cube4_shade, which classifies at {tag, sample} (class_waddr_i is that
// wide) and reads the tag's material (host port mat_*). Without tags vtag_i
// and mat_* are unused and there is no tag delay.
//
// Parameters: those of cube4_shade and cube4_shade_magnitude (NrIterations);
// SideBits, HasShading and VoxelTagBits as in cube4_shade; HasMagnitude (0: no magnitude
// unit, |g| = 0: equals golden when the magnitude is off, same latency).
// The system model runs HasShading = HasMagnitude = 0 for scenes without
// shading and gradient-magnitude modulation (docs/system.md).
`include "cube4_pkg.sv"

module cube4_shade_unit #(
  parameter int unsigned VoxelBits       = cube4_pkg::VoxelBits,
  parameter int unsigned WeightBits      = cube4_pkg::WeightBits,
  parameter int unsigned GradientBits    = cube4_pkg::GradientBits,
  parameter int unsigned MagnitudeBits   = cube4_pkg::MagnitudeBits,
  parameter int unsigned NrIterations    = cube4_pkg::NrIterations,
  parameter int unsigned ColorBits       = cube4_pkg::ColorBits,
  parameter int unsigned AlphaBits       = cube4_pkg::AlphaBits,
  parameter int unsigned GmlutBits       = cube4_pkg::GmlutBits,
  parameter int unsigned MapFaceRes      = cube4_pkg::MapFaceRes,
  parameter int unsigned MapBits         = cube4_pkg::MapBits,
  parameter int unsigned MapFracBits     = cube4_pkg::MapFracBits,
  parameter int unsigned CoefBits        = cube4_pkg::CoefBits,
  parameter int unsigned CoefFracBits    = cube4_pkg::CoefFracBits,
  parameter int unsigned EyeBits         = cube4_pkg::EyeBits,
  parameter int unsigned DivBitsPerStage = cube4_pkg::DivBitsPerStage,
  parameter int unsigned SideBits        = 1,
  parameter bit          HasShading      = 1'b1,
  // 0: no magnitude hardware (|g| reads 0; for scenes that use no GmLUT).
  parameter bit          HasMagnitude    = 1'b1,
  parameter int unsigned VoxelTagBits    = cube4_pkg::VoxelTagBits,
  localparam int unsigned MapAddrBits    = $clog2(6 * MapFaceRes * MapFaceRes),
  localparam int unsigned VTagPortBits   = VoxelTagBits > 0 ? VoxelTagBits : 1
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  // Frame registers (cube4_shade's).
  input  logic                              magnitude_i,
  input  logic                              shading_i,
  input  logic                              specular_i,
  input  logic                              gm_opacity_i,
  input  logic                              gm_diffuse_i,
  input  logic                              gm_specular_i,
  input  logic [CoefBits-1:0]               ke_i,
  input  logic [CoefBits-1:0]               kd_i,
  input  logic [CoefBits-1:0]               ks_i,
  input  logic [AlphaBits-1:0]              spec_red_i,
  input  logic [AlphaBits-1:0]              spec_green_i,
  input  logic [AlphaBits-1:0]              spec_blue_i,
  input  logic signed [EyeBits-1:0]         eye_x_i,
  input  logic signed [EyeBits-1:0]         eye_y_i,
  input  logic signed [EyeBits-1:0]         eye_z_i,
  // Host write ports (cube4_shade's).
  input  logic                              class_we_i,
  input  logic [VoxelTagBits+VoxelBits-1:0] class_waddr_i,
  input  logic [3*ColorBits+AlphaBits-1:0]  class_wdata_i,
  input  logic                              gmlut_we_i,
  input  logic [MagnitudeBits-1:0]          gmlut_waddr_i,
  input  logic [GmlutBits-1:0]              gmlut_wdata_i,
  input  logic                              dmap_we_i,
  input  logic [MapAddrBits-1:0]            dmap_waddr_i,
  input  logic [MapBits-1:0]                dmap_wdata_i,
  input  logic                              smap_we_i,
  input  logic [MapAddrBits-1:0]            smap_waddr_i,
  input  logic [MapBits-1:0]                smap_wdata_i,
  input  logic                              mat_we_i,
  input  logic [VTagPortBits-1:0]           mat_waddr_i,
  input  logic [3*CoefBits+3*AlphaBits-1:0] mat_wdata_i,
  // Gradient stream (the gradient unit's output; zero gradients when the
  // gradient unit is off).
  input  logic                              valid_i,
  input  logic [VoxelBits-1:0]              sample_i,
  input  logic signed [GradientBits-1:0]    grad_x_i,
  input  logic signed [GradientBits-1:0]    grad_y_i,
  input  logic signed [GradientBits-1:0]    grad_z_i,
  input  logic [VTagPortBits-1:0]           vtag_i,
  input  logic [SideBits-1:0]               side_i,
  // Shaded stream.
  output logic                              valid_o,
  output logic [AlphaBits-1:0]              red_o,
  output logic [AlphaBits-1:0]              green_o,
  output logic [AlphaBits-1:0]              blue_o,
  output logic [AlphaBits-1:0]              alpha_o,
  output logic [VoxelBits-1:0]              value_o,
  output logic [SideBits-1:0]               side_o
);

  // cube4_shade_magnitude's latency (its header).
  localparam int unsigned MagLatency = NrIterations + 1;
  localparam int unsigned Carried    = VoxelBits + 3 * GradientBits + SideBits;

  logic                     mag_valid;
  logic [MagnitudeBits-1:0] magnitude;

  if (HasMagnitude) begin : g_magnitude
    cube4_shade_magnitude #(
      .GradientBits  (GradientBits),
      .MagnitudeBits (MagnitudeBits),
      .NrIterations  (NrIterations)
    ) u_magnitude (
      .clk_i,
      .rst_ni,
      .valid_i,
      .gx_i        (grad_x_i),
      .gy_i        (grad_y_i),
      .gz_i        (grad_z_i),
      .valid_o     (mag_valid),
      .magnitude_o (magnitude)
    );
  end else begin : g_no_magnitude
    // valid waits as long as the magnitude would take.
    logic [MagLatency-1:0] valid_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin : valid_delay
      if (!rst_ni) begin
        valid_q <= '0;
      end else begin
        valid_q[0] <= valid_i;
        for (int unsigned k = 1; k < MagLatency; k++) valid_q[k] <= valid_q[k-1];
      end
    end
    assign mag_valid = valid_q[MagLatency-1];
    assign magnitude = '0;
  end

  // Sample, gradient and side bits wait for their magnitude. Not reset: the
  // magnitude's valid chain says when they mean something.
  logic [Carried-1:0] carried;
  cube4_pipe_delay #(.Width(Carried), .Depth(MagLatency)) u_carry_delay (
    .clk_i, .d_i({side_i, grad_z_i, grad_y_i, grad_x_i, sample_i}), .q_o(carried)
  );

  logic [VoxelBits-1:0]           sh_sample;
  logic signed [GradientBits-1:0] sh_gx, sh_gy, sh_gz;
  logic [SideBits-1:0]            sh_side;
  assign {sh_side, sh_gz, sh_gy, sh_gx, sh_sample} = carried;

  // The voxel tag waits likewise, in a delay of its own that exists only
  // with tags.
  logic [VTagPortBits-1:0] sh_vtag;
  if (VoxelTagBits > 0) begin : g_vtag
    cube4_pipe_delay #(.Width(VoxelTagBits), .Depth(MagLatency)) u_vtag_delay (
      .clk_i, .d_i(vtag_i), .q_o(sh_vtag)
    );
  end else begin : g_no_vtag
    assign sh_vtag = vtag_i;  // unused by cube4_shade without tags
  end

  cube4_shade #(
    .VoxelBits       (VoxelBits),
    .WeightBits      (WeightBits),
    .GradientBits    (GradientBits),
    .MagnitudeBits   (MagnitudeBits),
    .ColorBits       (ColorBits),
    .AlphaBits       (AlphaBits),
    .GmlutBits       (GmlutBits),
    .MapFaceRes      (MapFaceRes),
    .MapBits         (MapBits),
    .MapFracBits     (MapFracBits),
    .CoefBits        (CoefBits),
    .CoefFracBits    (CoefFracBits),
    .EyeBits         (EyeBits),
    .DivBitsPerStage (DivBitsPerStage),
    .SideBits        (SideBits),
    .HasShading      (HasShading),
    .VoxelTagBits    (VoxelTagBits)
  ) u_shader (
    .clk_i,
    .rst_ni,
    .magnitude_i,
    .shading_i,
    .specular_i,
    .gm_opacity_i,
    .gm_diffuse_i,
    .gm_specular_i,
    .ke_i,
    .kd_i,
    .ks_i,
    .spec_red_i,
    .spec_green_i,
    .spec_blue_i,
    .eye_x_i,
    .eye_y_i,
    .eye_z_i,
    .class_we_i,
    .class_waddr_i,
    .class_wdata_i,
    .gmlut_we_i,
    .gmlut_waddr_i,
    .gmlut_wdata_i,
    .dmap_we_i,
    .dmap_waddr_i,
    .dmap_wdata_i,
    .smap_we_i,
    .smap_waddr_i,
    .smap_wdata_i,
    .mat_we_i,
    .mat_waddr_i,
    .mat_wdata_i,
    .valid_i    (mag_valid),
    .sample_i   (sh_sample),
    .grad_x_i   (sh_gx),
    .grad_y_i   (sh_gy),
    .grad_z_i   (sh_gz),
    .grad_mag_i (magnitude),
    .vtag_i     (sh_vtag),
    .valid_o,
    .red_o,
    .green_o,
    .blue_o,
    .alpha_o,
    .value_o,
    .side_i     (sh_side),
    .side_o
  );

endmodule
