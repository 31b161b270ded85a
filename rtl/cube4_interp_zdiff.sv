// cube4_interp_zdiff: VolumePro's z gradient (§3.2), the central voxel
// differences in z interpolated to the sample with the sample's own weights.
//
// Function: bit-exact with golden interpolated_z_difference() of the eight
// voxel_z_difference()s (golden/units/gradient.hpp):
//   d[i]     = V(z+1) - V(z-1)  at corner i = 0..3 (the lower voxel slice)
//   d[i]     = V(z+2) - V(z)    at corner i = 4..7 (the upper voxel slice)
//   zdiff    = trilinear of d with wx, wy, wz, Cube-4's SFG order and
//              cube4_lerp's rounding (cube4_interp with Signed = 1)
// voxels_i holds the sample's own eight voxels as cube4_interp takes them
// (voxel i at (x + (i & 1), y + (i >> 1 & 1), z + (i >> 2))); outer_i the
// eight beyond them in z: outer i < 4 at (x + (i & 1), y + (i >> 1 & 1), z - 1),
// outer i >= 4 at the same x, y and z + 2. Voxels outside the volume are 0.
// zdiff_o is two's complement, VoxelBits + 1 wide: it lies between the
// corners' differences, so it needs no saturation.
//
// Latency: 3 cycles, fully pipelined (cube4_interp's; the differences are
// combinational in front of its first stage). Handshake: valid-only, as
// cube4_interp.
//
// Hardware cost against the 12-neighbourhood: this interpolator and the two
// voxel slices z - 1 and z + 2 beside the two the sample interpolates; no
// ahead/behind sample slices or re-alignment bilerps for z.
//
// Parameters:
//   VoxelBits  - voxel width (golden Precision::voxel_bits, 12)
//   WeightBits - weight fraction bits; weight ports are WeightBits+1 wide
//                (Precision::weight_bits, 8)
`include "cube4_pkg.sv"

module cube4_interp_zdiff #(
  parameter int unsigned VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned WeightBits = cube4_pkg::WeightBits
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic                   valid_i,
  input  logic [8*VoxelBits-1:0] voxels_i,
  input  logic [8*VoxelBits-1:0] outer_i,
  input  logic [WeightBits:0]    wx_i,
  input  logic [WeightBits:0]    wy_i,
  input  logic [WeightBits:0]    wz_i,
  output logic                   valid_o,
  output logic [VoxelBits:0]     zdiff_o
);

  localparam int unsigned DiffBits = VoxelBits + 1;

  // Corner i's difference: above minus below, both unsigned voxels.
  logic [8*DiffBits-1:0] diffs;
  for (genvar i = 0; i < 8; i++) begin : g_diff
    logic [VoxelBits-1:0] above, below;
    if (i < 4) begin : g_lower
      assign above = voxels_i[(i+4)*VoxelBits +: VoxelBits];
      assign below = outer_i[i*VoxelBits +: VoxelBits];
    end else begin : g_upper
      assign above = outer_i[i*VoxelBits +: VoxelBits];
      assign below = voxels_i[(i-4)*VoxelBits +: VoxelBits];
    end
    assign diffs[i*DiffBits +: DiffBits] = {1'b0, above} - {1'b0, below};
  end

  logic unused_vtag;

  cube4_interp #(
    .VoxelBits   (DiffBits),
    .WeightBits  (WeightBits),
    .VoxelTagBits(0),
    .Signed      (1'b1)
  ) u_interp (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .valid_i (valid_i),
    .voxels_i(diffs),
    .wx_i    (wx_i),
    .wy_i    (wy_i),
    .wz_i    (wz_i),
    .vtags_i (8'b0),
    .valid_o (valid_o),
    .sample_o(zdiff_o),
    .vtag_o  (unused_vtag)
  );

endmodule
