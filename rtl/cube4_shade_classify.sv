// cube4_shade_classify: classification and gradient-magnitude modulation of
// opacity (VolumePro §3.4), bit-exact with golden/units/shade_classify.hpp and the
// classification part of golden shade_sample():
//   entry  = classification[{vtag, sample}]            (classify, class_address)
//   gm     = magnitude ? gm_unit(GmLUT[|g|]) : one       (gm_unit = expand_bits)
//   alpha  = gm_opacity ? modulate_alpha(entry.a, gm) : entry.a   (mul_frac)
//   rgb    = widen_color(entry.r, entry.g, entry.b)     (expand_bits)
// Outputs the widened colour, alpha, and gm (alpha_bits unit) for Phong.
//
// Voxel tags (bela §III; VoxelTagBits > 0): the sample's tag vtag_i widens
// the table's address to {tag, sample}; vtag_o is vtag_i delayed with the
// sample, for the tag's material in Phong. VoxelTagBits = 0: no tag
// hardware, vtag_o is 0.
//
// Tables: the classification RAM (2^(VoxelTagBits+VoxelBits) x (3*ColorBits+AlphaBits),
// word {r, g, b, a}, r in the top bits) and the GmLUT RAM
// (2^MagnitudeBits x GmlutBits), each with its own host write port and one
// synchronous read port (read by the sample, resp. by |g|). A write and a
// read of the same entry in one cycle returns the old entry. Tables and the
// mode inputs are frame registers: change them only while no sample is in
// flight.
//
// Latency: 2 cycles (1: RAM read, 2: alpha product). Fully pipelined, one
// sample per clock. Handshake: valid-only; valid_i travels with the data to
// valid_o. Only the valid registers are reset.
//
// Parameters (defaults = golden Precision): VoxelBits, MagnitudeBits,
// ColorBits, AlphaBits, GmlutBits, VoxelTagBits (tag_bits).
`include "cube4_pkg.sv"

module cube4_shade_classify #(
  parameter int unsigned VoxelBits     = cube4_pkg::VoxelBits,
  parameter int unsigned MagnitudeBits = cube4_pkg::MagnitudeBits,
  parameter int unsigned ColorBits     = cube4_pkg::ColorBits,
  parameter int unsigned AlphaBits     = cube4_pkg::AlphaBits,
  parameter int unsigned GmlutBits     = cube4_pkg::GmlutBits,
  parameter int unsigned VoxelTagBits  = cube4_pkg::VoxelTagBits
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  // Frame registers (golden Registers::magnitude, ::gm_opacity).
  input  logic                                 magnitude_i,
  input  logic                                 gm_opacity_i,
  // Host write ports.
  input  logic                                 class_we_i,
  input  logic [VoxelTagBits+VoxelBits-1:0]    class_waddr_i,
  input  logic [3*ColorBits+AlphaBits-1:0]     class_wdata_i,
  input  logic                                 gmlut_we_i,
  input  logic [MagnitudeBits-1:0]             gmlut_waddr_i,
  input  logic [GmlutBits-1:0]                 gmlut_wdata_i,
  // Sample stream.
  input  logic                                 valid_i,
  input  logic [VoxelBits-1:0]                 sample_i,
  input  logic [MagnitudeBits-1:0]             grad_mag_i,
  input  logic [(VoxelTagBits > 0 ? VoxelTagBits : 1)-1:0] vtag_i,
  output logic                                 valid_o,
  output logic [AlphaBits-1:0]                 red_o,
  output logic [AlphaBits-1:0]                 green_o,
  output logic [AlphaBits-1:0]                 blue_o,
  output logic [AlphaBits-1:0]                 alpha_o,
  output logic [AlphaBits-1:0]                 gm_o,
  output logic [(VoxelTagBits > 0 ? VoxelTagBits : 1)-1:0] vtag_o
);

  localparam int unsigned EntryBits   = 3 * ColorBits + AlphaBits;
  localparam int unsigned AddrBits    = VoxelTagBits + VoxelBits;
  localparam int unsigned ClassDepth  = 2 ** AddrBits;
  localparam int unsigned GmlutDepth  = 2 ** MagnitudeBits;
  localparam int unsigned ProdBits    = 2 * AlphaBits + 1;

  //////////////
  // Stage 1  //
  //////////////
  // RAMs with a synchronous read.
  logic [EntryBits-1:0] class_mem [ClassDepth];
  logic [GmlutBits-1:0] gmlut_mem [GmlutDepth];

  always_ff @(posedge clk_i) begin : class_write
    if (class_we_i) class_mem[class_waddr_i] <= class_wdata_i;
  end

  always_ff @(posedge clk_i) begin : gmlut_write
    if (gmlut_we_i) gmlut_mem[gmlut_waddr_i] <= gmlut_wdata_i;
  end

  logic [EntryBits-1:0] entry_q;
  logic [GmlutBits-1:0] gmlut_q;
  logic                 valid_q;

  // The table address: {tag, sample} with tags, the sample without.
  logic [AddrBits-1:0] class_raddr;
  if (VoxelTagBits > 0) begin : g_vtag
    logic [2*VoxelTagBits-1:0] vtag_q;
    assign class_raddr = {vtag_i, sample_i};
    always_ff @(posedge clk_i) begin : vtag_regs
      vtag_q <= {vtag_q[VoxelTagBits-1:0], vtag_i};
    end
    assign vtag_o = vtag_q[2*VoxelTagBits-1 -: VoxelTagBits];
  end else begin : g_no_vtag
    logic unused_vtag;
    assign unused_vtag = ^vtag_i;
    assign class_raddr = sample_i;
    assign vtag_o = '0;
  end

  always_ff @(posedge clk_i) begin : read_regs
    entry_q <= class_mem[class_raddr];
    gmlut_q <= gmlut_mem[grad_mag_i];
  end

  //////////////
  // Stage 2  //
  //////////////
  // gm_unit: expand_bits(GmLUT, GmlutBits -> AlphaBits), bit replication:
  // result bit (AlphaBits-1-i) is source bit (GmlutBits-1 - i mod GmlutBits).
  logic [AlphaBits-1:0] gm_expanded;
  for (genvar i = 0; i < AlphaBits; i++) begin : g_expand_gm
    assign gm_expanded[AlphaBits-1-i] = gmlut_q[GmlutBits-1-(i % GmlutBits)];
  end

  // With GmlutBits > AlphaBits expand_bits keeps only the top bits.
  logic unused_gmlut;
  assign unused_gmlut = ^gmlut_q;

  logic [AlphaBits-1:0] gm_unit;
  assign gm_unit = magnitude_i ? gm_expanded : {AlphaBits{1'b1}};

  // modulate_alpha = mul_frac(a, gm, AlphaBits):
  // (a * (gm + (gm >> (AlphaBits-1))) + 2^(AlphaBits-1)) >> AlphaBits.
  logic [AlphaBits-1:0] alpha_raw;
  logic [AlphaBits:0]   gm_frac;
  logic [ProdBits-1:0]  alpha_prod;
  logic [AlphaBits-1:0] alpha_d;

  assign alpha_raw  = entry_q[AlphaBits-1:0];
  assign gm_frac    = {1'b0, gm_unit} + {{AlphaBits{1'b0}}, gm_unit[AlphaBits-1]};
  assign alpha_prod = ProdBits'(alpha_raw) * ProdBits'(gm_frac)
                    + (ProdBits'(1) << (AlphaBits - 1));
  // The result never exceeds alpha_raw, so the top bit is always zero.
  assign alpha_d    = gm_opacity_i ? alpha_prod[2*AlphaBits-1:AlphaBits] : alpha_raw;

  logic unused_alpha_prod;
  assign unused_alpha_prod = ^{alpha_prod[ProdBits-1], alpha_prod[AlphaBits-1:0]};

  logic [3*ColorBits-1:0] color_q;
  logic [AlphaBits-1:0]   alpha_q;
  logic [AlphaBits-1:0]   gm_q;

  always_ff @(posedge clk_i) begin : stage2_regs
    color_q <= entry_q[EntryBits-1:AlphaBits];
    alpha_q <= alpha_d;
    gm_q    <= gm_unit;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin : valid_regs
    if (!rst_ni) begin
      valid_q <= 1'b0;
      valid_o <= 1'b0;
    end else begin
      valid_q <= valid_i;
      valid_o <= valid_q;
    end
  end

  // widen_color: expand_bits(c, ColorBits -> AlphaBits) is wiring only, so it
  // follows the register.
  logic [ColorBits-1:0] red_q, green_q, blue_q;
  assign {red_q, green_q, blue_q} = color_q;
  for (genvar i = 0; i < AlphaBits; i++) begin : g_expand_color
    assign red_o[AlphaBits-1-i]   = red_q[ColorBits-1-(i % ColorBits)];
    assign green_o[AlphaBits-1-i] = green_q[ColorBits-1-(i % ColorBits)];
    assign blue_o[AlphaBits-1-i]  = blue_q[ColorBits-1-(i % ColorBits)];
  end

  assign alpha_o = alpha_q;
  assign gm_o    = gm_q;

endmodule
