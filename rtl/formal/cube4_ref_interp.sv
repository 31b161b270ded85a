// cube4_ref_interp: a second, independent statement of golden trilinear()
// (golden/units/interp.hpp, golden lerp_t) for the equivalence proof
// against cube4_interp. Written from the golden C++ only: plain signed
// integer arithmetic of one width IntBits throughout, as golden's lerp_t<T>
// for a signed T, floor shift (>>> on a signed value, like C++ >> on int),
// no pipeline. It is not meant to be synthesised; it is the specification
// in SV.
//
// Parameters: VoxelBits, WeightBits as cube4_interp; weights in
// [0, 2^WeightBits] are the precondition (the miter assumes it). IntBits is
// golden's T: any signed width that holds (b - a) * w + 2^(W-1), i.e.
// >= VoxelBits + WeightBits + 2 (golden uses int32_t and int64_t; the
// miters use the smallest, which z3 proves far faster: see
// docs/verification.md).
module cube4_ref_interp #(
  parameter int unsigned VoxelBits  = 12,
  parameter int unsigned WeightBits = 8,
  parameter int unsigned IntBits    = 32
) (
  input  logic [8*VoxelBits-1:0] voxels_i,
  input  logic [WeightBits:0]    wx_i,
  input  logic [WeightBits:0]    wy_i,
  input  logic [WeightBits:0]    wz_i,
  output logic [VoxelBits-1:0]   sample_o,
  // The intermediate lerps of golden's order (x: [i] = lerp(v[2i], v[2i+1]);
  // y: front, back), so that a miter can compare stage by stage.
  output logic [4*VoxelBits-1:0] x_o,
  output logic [2*VoxelBits-1:0] y_o
);

  typedef logic signed [IntBits-1:0] int_t;

  // golden lerp_t: a + (((b - a) * w + 2^(W-1)) >> W), C++ semantics on T.
  function automatic int_t ref_lerp(input int_t a, input int_t b, input int_t w);
    ref_lerp = a + (((b - a) * w + ($signed(IntBits'(1)) <<< (WeightBits - 1))) >>> WeightBits);
  endfunction

  function automatic int_t voxel(input int unsigned i);
    voxel = $signed(IntBits'(voxels_i[i*VoxelBits +: VoxelBits]));
  endfunction

  int_t wx, wy, wz, x0, x1, x2, x3, front, back, sample;
  always_comb begin
    wx     = $signed(IntBits'(wx_i));
    wy     = $signed(IntBits'(wy_i));
    wz     = $signed(IntBits'(wz_i));
    // bilerp(v00, v10, v01, v11) = lerp(lerp(v00, v10, wx), lerp(v01, v11, wx), wy)
    x0     = ref_lerp(voxel(0), voxel(1), wx);
    x1     = ref_lerp(voxel(2), voxel(3), wx);
    x2     = ref_lerp(voxel(4), voxel(5), wx);
    x3     = ref_lerp(voxel(6), voxel(7), wx);
    front  = ref_lerp(x0, x1, wy);
    back   = ref_lerp(x2, x3, wy);
    sample = ref_lerp(front, back, wz);
  end
  assign x_o = {x3[VoxelBits-1:0], x2[VoxelBits-1:0], x1[VoxelBits-1:0], x0[VoxelBits-1:0]};
  assign y_o = {back[VoxelBits-1:0], front[VoxelBits-1:0]};
  // golden casts the int64 result to uint32_t; the sample lies between the
  // voxels, so the low VoxelBits are all of it.
  assign sample_o = sample[VoxelBits-1:0];

  logic unused_msbs;
  assign unused_msbs = ^{sample[IntBits-1:VoxelBits], x0[IntBits-1:VoxelBits],
                         x1[IntBits-1:VoxelBits], x2[IntBits-1:VoxelBits],
                         x3[IntBits-1:VoxelBits], front[IntBits-1:VoxelBits],
                         back[IntBits-1:VoxelBits]};

endmodule
