// cube4_shade: the classification-and-shading unit of one rendering
// pipeline, bit-exact with golden shade_sample() (golden/pipeline.hpp)
// without cropping and the cut plane (those act in cube4_composite):
//   value  = sample
//   (rgb, alpha, gm) = cube4_shade_classify(sample, |g|)   (magnitude, gm_opacity)
//   if shading:
//     Id  = reflectance(diffuse map,  cube_coordinates(g))
//     Is  = specular ? reflectance(specular map, cube_coordinates(R(g, eye))) : 0
//     rgb = phong(rgb, Id, Is, gm_diffuse ? gm : one, gm_specular ? gm : one)
//
// Structure (latencies with the default parameters):
//   specular path: reflection (4) -> cube_coord (7) -> reflectance (3) = 14
//   diffuse path:  cube_coord (7) -> reflectance (3), then Id delayed 4 = 14
//   classify (2):  sample and |g| delayed 12, so colour/alpha/gm arrive at 14
//   phong (3):     14 -> 17; alpha delayed 3, the sample value delayed 17.
// Shading off is phong with ke = 1.0 (2^CoefFracBits), kd = ks = 0, which
// returns the colour exactly (round_shift(c << CoefFracBits, CoefFracBits) = c,
// no saturation); specular off is ks = 0, which gives the same fs = 0 as golden
// Is = 0. So one phong serves all modes and the colour needs no bypass delay.
//
// Inputs: grad_*_i is the gradient unit's output (zero when the gradient unit
// is off, as golden Gradient{}), grad_mag_i its magnitude (golden
// gradient_magnitude(g)).
//
// Latency: Latency = 4 + (1 + ceil(($clog2(MapFaceRes)+WeightBits)/DivBitsPerStage))
// + 3 + 3 cycles = 17 with the defaults. Fully pipelined, one sample per
// clock, all internal delays balanced. Handshake: valid-only; valid_i travels
// with the data to valid_o. Only the valid registers are reset. Mode,
// coefficient and eye inputs and the four tables are frame registers: change
// them only while no sample is in flight.
//
// RAMs (defaults): classification 4096 x 36 = 147456 bits, GmLUT 256 x 8 =
// 2048 bits, diffuse and specular maps 4 banks x 96 x 16 = 6144 bits each.
//
// Parameters (defaults = golden Precision): VoxelBits, WeightBits,
// GradientBits, MagnitudeBits, ColorBits, AlphaBits, GmlutBits, MapFaceRes,
// MapBits, MapFracBits, CoefBits, CoefFracBits, EyeBits; DivBitsPerStage
// (cube_coord divider); SideBits (side_i travels to side_o with the sample,
// Latency cycles, for the system's per-sample position and tag);
// HasShading (0: no shading hardware, for machines and scenes without it;
// shading_i is then ignored and the unit equals golden with shading off);
// VoxelTagBits (golden tag_bits; 0: no tag hardware).
//
// Voxel tags (bela §III, VoxelTagBits > 0): vtag_i, the sample's tag, travels
// with it to the classifier, which reads its table at {tag, sample}
// (golden class_address); the tag leaves the classifier with the colour and
// reads the tag's material, {ke, kd, ks, spec r, g, b} (ke in the top bits),
// from a RAM of 2^VoxelTagBits entries with its own host write port
// (golden Registers::coefs_of(tag), the MATERIAL window). The material
// replaces ke_i .. spec_blue_i, each coefficient timed to the Phong stage
// that uses it. Without tags the mat_* and vtag_i ports are unused.
`include "cube4_pkg.sv"

module cube4_shade #(
  parameter int unsigned VoxelBits       = cube4_pkg::VoxelBits,
  parameter int unsigned WeightBits      = cube4_pkg::WeightBits,
  parameter int unsigned GradientBits    = cube4_pkg::GradientBits,
  parameter int unsigned MagnitudeBits   = cube4_pkg::MagnitudeBits,
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
  // 0: no reflectance maps, reflection or Phong hardware: the colour is the
  // classified colour (golden with shading off), same latency.
  parameter bit          HasShading      = 1'b1,
  parameter int unsigned VoxelTagBits    = cube4_pkg::VoxelTagBits
) (
  input  logic                                   clk_i,
  input  logic                                   rst_ni,
  // Frame registers: modes (golden Registers fields of the same names).
  input  logic                                   magnitude_i,
  input  logic                                   shading_i,
  input  logic                                   specular_i,
  input  logic                                   gm_opacity_i,
  input  logic                                   gm_diffuse_i,
  input  logic                                   gm_specular_i,
  // Frame registers: coefficients (golden ShadeCoefs) and eye vector.
  input  logic [CoefBits-1:0]                    ke_i,
  input  logic [CoefBits-1:0]                    kd_i,
  input  logic [CoefBits-1:0]                    ks_i,
  input  logic [AlphaBits-1:0]                   spec_red_i,
  input  logic [AlphaBits-1:0]                   spec_green_i,
  input  logic [AlphaBits-1:0]                   spec_blue_i,
  input  logic signed [EyeBits-1:0]              eye_x_i,
  input  logic signed [EyeBits-1:0]              eye_y_i,
  input  logic signed [EyeBits-1:0]              eye_z_i,
  // Host write ports: classification ({r, g, b, a}), GmLUT, and the
  // diffuse and specular maps (map_index() addresses).
  input  logic                                   class_we_i,
  input  logic [VoxelTagBits+VoxelBits-1:0]      class_waddr_i,
  input  logic [3*ColorBits+AlphaBits-1:0]       class_wdata_i,
  input  logic                                   gmlut_we_i,
  input  logic [MagnitudeBits-1:0]               gmlut_waddr_i,
  input  logic [GmlutBits-1:0]                   gmlut_wdata_i,
  input  logic                                   dmap_we_i,
  input  logic [$clog2(6*MapFaceRes*MapFaceRes)-1:0] dmap_waddr_i,
  input  logic [MapBits-1:0]                     dmap_wdata_i,
  input  logic                                   smap_we_i,
  input  logic [$clog2(6*MapFaceRes*MapFaceRes)-1:0] smap_waddr_i,
  input  logic [MapBits-1:0]                     smap_wdata_i,
  // Host write port: each tag's material (with tags only).
  input  logic                                   mat_we_i,
  input  logic [(VoxelTagBits > 0 ? VoxelTagBits : 1)-1:0] mat_waddr_i,
  input  logic [3*CoefBits+3*AlphaBits-1:0]      mat_wdata_i,
  // Sample stream.
  input  logic                                   valid_i,
  input  logic [VoxelBits-1:0]                   sample_i,
  input  logic signed [GradientBits-1:0]         grad_x_i,
  input  logic signed [GradientBits-1:0]         grad_y_i,
  input  logic signed [GradientBits-1:0]         grad_z_i,
  input  logic [MagnitudeBits-1:0]               grad_mag_i,
  input  logic [(VoxelTagBits > 0 ? VoxelTagBits : 1)-1:0] vtag_i,
  output logic                                   valid_o,
  output logic [AlphaBits-1:0]                   red_o,
  output logic [AlphaBits-1:0]                   green_o,
  output logic [AlphaBits-1:0]                   blue_o,
  output logic [AlphaBits-1:0]                   alpha_o,
  output logic [VoxelBits-1:0]                   value_o,
  // Bits that travel with the sample (the system's position and slice tag).
  input  logic [SideBits-1:0]                    side_i,
  output logic [SideBits-1:0]                    side_o
);

  localparam int unsigned CellBits   = $clog2(MapFaceRes);
  localparam int unsigned LatRefl    = 4;
  localparam int unsigned LatCube    = 1 + (CellBits + WeightBits + DivBitsPerStage - 1)
                                        / DivBitsPerStage;
  localparam int unsigned LatMap     = 3;
  localparam int unsigned LatClass   = 2;
  localparam int unsigned LatPhong   = 3;
  localparam int unsigned PhongIn    = LatRefl + LatCube + LatMap;  // phong inputs
  localparam int unsigned ClassDelay = PhongIn - LatClass;
  localparam int unsigned Latency    = PhongIn + LatPhong;
  localparam int unsigned A          = AlphaBits;
  localparam int unsigned VT         = VoxelTagBits > 0 ? VoxelTagBits : 1;

  /////////////////////////////////////////////
  // Classification, timed to meet Id and Is //
  /////////////////////////////////////////////
  // The sample travels to the output (value_o); classify taps it at ClassDelay.
  logic [VoxelBits-1:0]     class_sample, out_sample;
  logic [MagnitudeBits-1:0] class_mag;
  cube4_pipe_delay #(.Width(VoxelBits), .Depth(ClassDelay)) u_sample_to_class (
    .clk_i, .d_i(sample_i), .q_o(class_sample)
  );
  cube4_pipe_delay #(.Width(VoxelBits), .Depth(Latency - ClassDelay)) u_sample_to_out (
    .clk_i, .d_i(class_sample), .q_o(out_sample)
  );
  cube4_pipe_delay #(.Width(SideBits), .Depth(Latency)) u_side_delay (.clk_i, .d_i(side_i), .q_o(side_o));
  cube4_pipe_delay #(.Width(MagnitudeBits), .Depth(ClassDelay)) u_mag_delay (
    .clk_i, .d_i(grad_mag_i), .q_o(class_mag)
  );

  logic [ClassDelay-1:0] class_valid_delay_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin : class_valid_delay
    if (!rst_ni) begin
      class_valid_delay_q <= '0;
    end else begin
      class_valid_delay_q[0] <= valid_i;
      for (int unsigned k = 1; k < ClassDelay; k++) begin
        class_valid_delay_q[k] <= class_valid_delay_q[k-1];
      end
    end
  end

  logic         class_valid;
  logic [A-1:0] class_red, class_green, class_blue, class_alpha, gm;
  logic [VT-1:0] class_vtag_in, class_vtag;

  // The tag meets the sample at the classifier's tap.
  if (VoxelTagBits > 0) begin : g_vtag_delay
    cube4_pipe_delay #(.Width(VT), .Depth(ClassDelay)) u_vtag_delay (.clk_i, .d_i(vtag_i), .q_o(class_vtag_in));
  end else begin : g_no_vtag_delay
    logic unused_vtag_in;
    assign unused_vtag_in = ^vtag_i;
    assign class_vtag_in = '0;
  end

  cube4_shade_classify #(
    .VoxelTagBits  (VoxelTagBits),
    .VoxelBits     (VoxelBits),
    .MagnitudeBits (MagnitudeBits),
    .ColorBits     (ColorBits),
    .AlphaBits     (AlphaBits),
    .GmlutBits     (GmlutBits)
  ) u_classify (
    .clk_i,
    .rst_ni,
    .magnitude_i,
    .gm_opacity_i,
    .class_we_i,
    .class_waddr_i,
    .class_wdata_i,
    .gmlut_we_i,
    .gmlut_waddr_i,
    .gmlut_wdata_i,
    .valid_i    (class_valid_delay_q[ClassDelay-1]),
    .sample_i   (class_sample),
    .grad_mag_i (class_mag),
    .vtag_i     (class_vtag_in),
    .valid_o    (class_valid),
    .red_o      (class_red),
    .green_o    (class_green),
    .blue_o     (class_blue),
    .alpha_o    (class_alpha),
    .gm_o       (gm),
    .vtag_o     (class_vtag)
  );

  //////////////////////////////////////////////////////
  // Shading: reflectance maps (diffuse and specular), //
  // Phong. Absent when HasShading = 0.                 //
  //////////////////////////////////////////////////////
  if (HasShading) begin : g_shading
    ///////////////////////////////
    // Diffuse path: g -> Id     //
    ///////////////////////////////
    logic                  dcc_valid, dcc_coord_valid;
    logic [2:0]            dcc_face;
    logic [CellBits-1:0]   dcc_u, dcc_v;
    logic [WeightBits:0]   dcc_wu, dcc_wv;

    cube4_shade_cube_coord #(
      .GradientBits    (GradientBits),
      .WeightBits      (WeightBits),
      .MapFaceRes      (MapFaceRes),
      .DivBitsPerStage (DivBitsPerStage)
    ) u_diffuse_coord (
      .clk_i,
      .rst_ni,
      .valid_i,
      .x_i           (grad_x_i),
      .y_i           (grad_y_i),
      .z_i           (grad_z_i),
      .valid_o       (dcc_valid),
      .coord_valid_o (dcc_coord_valid),
      .face_o        (dcc_face),
      .u_o           (dcc_u),
      .v_o           (dcc_v),
      .wu_o          (dcc_wu),
      .wv_o          (dcc_wv)
    );

    logic               dmap_valid;
    logic [MapBits-1:0] id_early;

    cube4_shade_reflectance #(
      .WeightBits (WeightBits),
      .MapFaceRes (MapFaceRes),
      .MapBits    (MapBits)
    ) u_diffuse_map (
      .clk_i,
      .rst_ni,
      .we_i          (dmap_we_i),
      .waddr_i       (dmap_waddr_i),
      .wdata_i       (dmap_wdata_i),
      .valid_i       (dcc_valid),
      .coord_valid_i (dcc_coord_valid),
      .face_i        (dcc_face),
      .u_i           (dcc_u),
      .v_i           (dcc_v),
      .wu_i          (dcc_wu),
      .wv_i          (dcc_wv),
      .valid_o       (dmap_valid),
      .value_o       (id_early)
    );

    // Id waits for the reflection vector's latency.
    logic [MapBits-1:0] id;
    cube4_pipe_delay #(.Width(MapBits), .Depth(LatRefl)) u_id_delay (.clk_i, .d_i(id_early), .q_o(id));

    ////////////////////////////////////////
    // Specular path: g -> R -> Is        //
    ////////////////////////////////////////
    logic                           refl_valid;
    logic signed [GradientBits-1:0] refl_x, refl_y, refl_z;

    cube4_shade_reflection #(
      .GradientBits (GradientBits),
      .EyeBits      (EyeBits)
    ) u_reflection (
      .clk_i,
      .rst_ni,
      .eye_x_i,
      .eye_y_i,
      .eye_z_i,
      .valid_i,
      .x_i     (grad_x_i),
      .y_i     (grad_y_i),
      .z_i     (grad_z_i),
      .valid_o (refl_valid),
      .x_o     (refl_x),
      .y_o     (refl_y),
      .z_o     (refl_z)
    );

    logic                  scc_valid, scc_coord_valid;
    logic [2:0]            scc_face;
    logic [CellBits-1:0]   scc_u, scc_v;
    logic [WeightBits:0]   scc_wu, scc_wv;

    cube4_shade_cube_coord #(
      .GradientBits    (GradientBits),
      .WeightBits      (WeightBits),
      .MapFaceRes      (MapFaceRes),
      .DivBitsPerStage (DivBitsPerStage)
    ) u_specular_coord (
      .clk_i,
      .rst_ni,
      .valid_i       (refl_valid),
      .x_i           (refl_x),
      .y_i           (refl_y),
      .z_i           (refl_z),
      .valid_o       (scc_valid),
      .coord_valid_o (scc_coord_valid),
      .face_o        (scc_face),
      .u_o           (scc_u),
      .v_o           (scc_v),
      .wu_o          (scc_wu),
      .wv_o          (scc_wv)
    );

    logic               smap_valid;
    logic [MapBits-1:0] is_value;

    cube4_shade_reflectance #(
      .WeightBits (WeightBits),
      .MapFaceRes (MapFaceRes),
      .MapBits    (MapBits)
    ) u_specular_map (
      .clk_i,
      .rst_ni,
      .we_i          (smap_we_i),
      .waddr_i       (smap_waddr_i),
      .wdata_i       (smap_wdata_i),
      .valid_i       (scc_valid),
      .coord_valid_i (scc_coord_valid),
      .face_i        (scc_face),
      .u_i           (scc_u),
      .v_i           (scc_v),
      .wu_i          (scc_wu),
      .wv_i          (scc_wv),
      .valid_o       (smap_valid),
      .value_o       (is_value)
    );

    ///////////
    // Phong //
    ///////////
    // Modes as coefficients (see the header): shading off = identity.
    localparam logic [CoefBits-1:0] CoefOne = CoefBits'(64'd1 << CoefFracBits);

    // The sample's material: the frame registers, or with tags its tag's,
    // read as the sample enters Phong (class_vtag comes with the colour):
    // ke, kd, ks for Phong's stage 2, the specular colour a cycle later for
    // its stage 3.
    logic [CoefBits-1:0] ke_sel, kd_sel, ks_sel;
    logic [A-1:0]        spec_red_sel, spec_green_sel, spec_blue_sel;
    if (VoxelTagBits > 0) begin : g_material
      localparam int unsigned MatBits = 3 * CoefBits + 3 * A;
      logic [MatBits-1:0] mat_mem [2**VoxelTagBits];
      logic [MatBits-1:0] mat_q;
      logic [3*A-1:0]     spec_q;
      always_ff @(posedge clk_i) begin : mat_write
        if (mat_we_i) mat_mem[mat_waddr_i] <= mat_wdata_i;
      end
      always_ff @(posedge clk_i) begin : mat_read
        mat_q  <= mat_mem[class_vtag];
        spec_q <= mat_q[3*A-1:0];
      end
      assign {ke_sel, kd_sel, ks_sel} = mat_q[MatBits-1 -: 3*CoefBits];
      assign {spec_red_sel, spec_green_sel, spec_blue_sel} = spec_q;
      logic unused_frame_coefs;
      assign unused_frame_coefs = ^{ke_i, kd_i, ks_i, spec_red_i, spec_green_i, spec_blue_i};
    end else begin : g_frame_material
      assign {ke_sel, kd_sel, ks_sel} = {ke_i, kd_i, ks_i};
      assign {spec_red_sel, spec_green_sel, spec_blue_sel} = {spec_red_i, spec_green_i, spec_blue_i};
      logic unused_material;
      assign unused_material = ^{mat_we_i, mat_waddr_i, mat_wdata_i, class_vtag};
    end

    logic [CoefBits-1:0] ke_eff, kd_eff, ks_eff;
    assign ke_eff = shading_i ? ke_sel : CoefOne;
    assign kd_eff = shading_i ? kd_sel : '0;
    assign ks_eff = (shading_i && specular_i) ? ks_sel : '0;

    logic [A-1:0] gd, gs;
    assign gd = gm_diffuse_i ? gm : {A{1'b1}};
    assign gs = gm_specular_i ? gm : {A{1'b1}};

    cube4_shade_phong #(
      .AlphaBits    (AlphaBits),
      .MapBits      (MapBits),
      .MapFracBits  (MapFracBits),
      .CoefBits     (CoefBits),
      .CoefFracBits (CoefFracBits)
    ) u_phong (
      .clk_i,
      .rst_ni,
      .ke_i         (ke_eff),
      .kd_i         (kd_eff),
      .ks_i         (ks_eff),
      .spec_red_i   (spec_red_sel),
      .spec_green_i (spec_green_sel),
      .spec_blue_i  (spec_blue_sel),
      .valid_i      (smap_valid),
      .red_i        (class_red),
      .green_i      (class_green),
      .blue_i       (class_blue),
      .id_i         (id),
      .is_i         (is_value),
      .gd_i         (gd),
      .gs_i         (gs),
      .valid_o,
      .red_o,
      .green_o,
      .blue_o
    );

    // The valid chain runs through the specular path; the other units' valid
    // outputs carry the same information at their own times.
    logic unused_valids;
    assign unused_valids = ^{dmap_valid, class_valid};
  end else begin : g_no_shading
    // No reflectance-map hardware: the colour is the classified colour (what
    // phong returns with shading off), timed as the phong stage would.
    logic [LatPhong-1:0]       valid_delay_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin : valid_delay
      if (!rst_ni) begin
        valid_delay_q <= '0;
      end else begin
        valid_delay_q <= {valid_delay_q[LatPhong-2:0], class_valid};
      end
    end
    cube4_pipe_delay #(.Width(3 * A), .Depth(LatPhong)) u_rgb_delay (
      .clk_i, .d_i({class_red, class_green, class_blue}), .q_o({red_o, green_o, blue_o})
    );
    assign valid_o = valid_delay_q[LatPhong-1];
    // The shading registers, the gradient and the map write ports stay
    // ports, so that both variants connect alike.
    logic unused_shading_inputs;
    assign unused_shading_inputs = ^{shading_i, specular_i, gm_diffuse_i, gm_specular_i, ke_i, kd_i, ks_i,
                                     spec_red_i, spec_green_i, spec_blue_i, eye_x_i, eye_y_i, eye_z_i,
                                     dmap_we_i, dmap_waddr_i, dmap_wdata_i, smap_we_i, smap_waddr_i,
                                     smap_wdata_i, grad_x_i, grad_y_i, grad_z_i, gm,
                                     mat_we_i, mat_waddr_i, mat_wdata_i, class_vtag};
  end

  // Alpha waits for phong.
  cube4_pipe_delay #(.Width(A), .Depth(LatPhong)) u_alpha_delay (.clk_i, .d_i(class_alpha), .q_o(alpha_o));

  assign value_o = out_sample;

endmodule
