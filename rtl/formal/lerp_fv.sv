// Formal harness for cube4_lerp (combinational, so a depth-1 BMC covers
// every input): the result never leaves [min(a, b), max(a, b)] (so the
// unit needs no saturation, as its header claims), both weight ends are
// exact, and it equals the independent reference lerp of
// cube4_ref_interp (golden lerp_t) for every a, b and w <= 2^W.
module lerp_fv #(
  parameter int unsigned VoxelBits  = 12,
  parameter int unsigned WeightBits = 8,
  // The reference's integer width (golden's T): the smallest that holds
  // (b - a) * w + 2^(W-1) by default; 32 is golden's int32_t.
  parameter int unsigned RefIntBits = VoxelBits + WeightBits + 2,
  parameter bit          CheckRange = 1'b1,
  parameter bit          CheckRef   = 1'b1
) (
  input logic                  clk_i,
  input logic [VoxelBits-1:0]  a_i,
  input logic [VoxelBits-1:0]  b_i,
  input logic [WeightBits:0]   w_i
);

  logic [VoxelBits-1:0] y, y_ref;

  cube4_lerp #(
    .VoxelBits (VoxelBits),
    .WeightBits(WeightBits)
  ) u_dut (
    .a_i,
    .b_i,
    .w_i,
    .y_o(y)
  );

  // The reference's voxel 0/1 pair with weight w in x and 0 in y and z is
  // exactly lerp(a, b, w): reuse it rather than write lerp a third time.
  cube4_ref_interp #(
    .VoxelBits (VoxelBits),
    .WeightBits(WeightBits),
    .IntBits   (RefIntBits)
  ) u_ref (
    .voxels_i({{6{VoxelBits'(0)}}, b_i, a_i}),
    .wx_i    (w_i),
    .wy_i    ('0),
    .wz_i    ('0),
    .sample_o(y_ref),
    .x_o     (),
    .y_o     ()
  );

  localparam logic [WeightBits:0] One = (WeightBits+1)'(1) << WeightBits;

  logic [VoxelBits-1:0] lo, hi;
  assign lo = (a_i < b_i) ? a_i : b_i;
  assign hi = (a_i < b_i) ? b_i : a_i;

  always_comb begin
    assume (w_i <= One);
    if (CheckRange) begin
      assert (lo <= y && y <= hi);
      if (w_i == '0) assert (y == a_i);
      if (w_i == One) assert (y == b_i);
    end
    if (CheckRef) assert (y == y_ref);
  end

  logic unused_clk;
  assign unused_clk = clk_i;

endmodule
