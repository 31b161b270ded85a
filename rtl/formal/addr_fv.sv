// Formal harness for cube4_addr: in every cycle with valid_o, for
// every traversal (perm a permutation, any flip), every pipeline k's voxel
// (permuted x = beam_o * p + k, beam y_o, slice z_o) lies in the module the
// de-skew takes it from, (rotation_o +- k) mod p, and that module is
// presented that voxel's index: golden skew_address() of golden
// skew_object_coordinate(), written here from golden/units/addr.hpp. So
// the p pipelines read p different modules, each module once, at the
// right word: no module is addressed twice in a cycle. Also: rotation_o <
// p, reverse_o = flip[0], and the position is inside the traversal.
// start_i, advance_i, repeat_slice_i and again_i are free in every cycle;
// perm_i, flip_i and dim_i are free and must meet the preconditions only
// with start_i (every dim in [1, 2^DimBits - 1]).
//
// Proof: BMC from reset (the unit's traversal state is not reset and
// would need an inductive invariant per walker: see docs/verification.md).
module addr_fv #(
  parameter int unsigned NumPipes = 4,
  parameter int unsigned DimBits  = 3,
  // Also check the index presented to each module (multiplications of
  // symbolic dims: far slower for z3); 0 checks the modules only.
  parameter bit          CheckIndex = 1'b0
) (
  input logic                 clk_i,
  input logic                 rst_ni,
  input logic                 start_i,
  input logic                 advance_i,
  input logic                 repeat_slice_i,
  input logic                 again_i,
  input logic [5:0]           perm_i,
  input logic [2:0]           flip_i,
  input logic [3*DimBits-1:0] dim_i
);

  localparam int unsigned P         = NumPipes;
  localparam int unsigned D         = DimBits;
  localparam int unsigned IndexBits = 3 * DimBits + 4 - $clog2(NumPipes + 1);
  localparam int unsigned PipeBits  = (NumPipes > 1) ? $clog2(NumPipes) : 1;
  localparam int unsigned I         = IndexBits;
  // Wide enough for any coordinate, sum and index of the harness (padded
  // dims < 2^(D+1), indices < 2^(3D+3)); wider words cost z3 dearly.
  localparam int unsigned W         = 3 * DimBits + 3;

  logic                busy, valid, reverse, last;
  logic [P*I-1:0]      index;
  logic [PipeBits-1:0] rotation;
  logic [D-1:0]        beam, y, z;

  cube4_addr #(
    .NumPipes(NumPipes),
    .DimBits (DimBits)
  ) u_dut (
    .clk_i,
    .rst_ni,
    .start_i,
    .advance_i,
    .repeat_slice_i,
    .again_i,
    .perm_i,
    .flip_i,
    .dim_i,
    .busy_o    (busy),
    .valid_o   (valid),
    .index_o   (index),
    .rotation_o(rotation),
    .reverse_o (reverse),
    .beam_o    (beam),
    .y_o       (y),
    .z_o       (z),
    .last_o    (last)
  );

  // The frame's configuration, captured like the unit does.
  logic [5:0]     perm_q;
  logic [2:0]     flip_q;
  logic [3*D-1:0] n_q;
  always_ff @(posedge clk_i) begin
    if (start_i) begin
      perm_q <= perm_i;
      flip_q <= flip_i;
      n_q    <= dim_i;
    end
  end

  // Golden SkewLayout of the captured dims: n_a, B_a, P_a at [a*W +: W].
  logic [3*W-1:0] n_obj, b_obj, p_obj;
  for (genvar a = 0; a < 3; a++) begin : g_layout
    assign n_obj[a*W +: W] = W'(n_q[a*D +: D]);
    assign b_obj[a*W +: W] = (n_obj[a*W +: W] + W'(P - 1)) / W'(P);
    assign p_obj[a*W +: W] = b_obj[a*W +: W] * W'(P);
  end
  // The same per permuted axis i (object axis perm[i]).
  logic [3*W-1:0] n_ax, b_ax, p_ax;
  for (genvar i = 0; i < 3; i++) begin : g_axis
    assign n_ax[i*W +: W] = n_obj[perm_q[2*i +: 2]*W +: W];
    assign b_ax[i*W +: W] = b_obj[perm_q[2*i +: 2]*W +: W];
    assign p_ax[i*W +: W] = p_obj[perm_q[2*i +: 2]*W +: W];
  end

  // golden skew_object_coordinate(l, t, i, v) of axis i with n, P and flip.
  function automatic logic [W-1:0] object_coord(input logic flip, input logic [W-1:0] n,
                                                input logic [W-1:0] padded, input logic [W-1:0] v);
    logic signed [W+1:0] o;
    o = $signed({2'b0, n}) - 1 - $signed({2'b0, v});
    if (!flip) begin
      object_coord = v;
    end else begin
      object_coord = (o < 0) ? W'(o + $signed({2'b0, padded})) : W'(o);
    end
  endfunction

  // Lane k: its voxel's golden skew_address(), and the module the de-skew
  // takes it from.
  logic [P*W-1:0]        lane_module, lane_index;
  logic [P*PipeBits-1:0] hw_module;
  always_comb begin
    for (int unsigned k = 0; k < P; k++) begin
      logic [W-1:0] o0, o1, o2, ox, oy, oz;
      logic [W:0]   m;
      o0 = object_coord(flip_q[0], n_ax[0 +: W], p_ax[0 +: W], W'(beam) * W'(P) + W'(k));
      o1 = object_coord(flip_q[1], n_ax[W +: W], p_ax[W +: W], W'(y));
      o2 = object_coord(flip_q[2], n_ax[2*W +: W], p_ax[2*W +: W], W'(z));
      ox = (perm_q[1:0] == 2'd0) ? o0 : (perm_q[3:2] == 2'd0) ? o1 : o2;
      oy = (perm_q[1:0] == 2'd1) ? o0 : (perm_q[3:2] == 2'd1) ? o1 : o2;
      oz = (perm_q[1:0] == 2'd2) ? o0 : (perm_q[3:2] == 2'd2) ? o1 : o2;
      lane_module[k*W +: W] = (ox + oy + oz) % W'(P);
      lane_index[k*W +: W]  = ox / W'(P) + b_obj[0 +: W] * (oy + p_obj[W +: W] * oz);
      m = reverse ? {1'b0, W'(rotation)} + W'(P) - W'(k % P) : {1'b0, W'(rotation)} + W'(k);
      hw_module[k*PipeBits +: PipeBits] = PipeBits'(m % (W+1)'(P));
    end
  end

  function automatic logic is_perm(input logic [5:0] p);
    is_perm = p[1:0] != 2'd3 && p[3:2] != 2'd3 && p[5:4] != 2'd3 &&
              p[1:0] != p[3:2] && p[1:0] != p[5:4] && p[3:2] != p[5:4];
  endfunction

  logic reset_seen_q = 1'b0;
  always_ff @(posedge clk_i) if (!rst_ni) reset_seen_q <= 1'b1;

  always_comb begin
    if ($initstate) assume (!rst_ni);
    if (start_i) begin
      assume (is_perm(perm_i));
      for (int unsigned a = 0; a < 3; a++) assume (dim_i[a*D +: D] != '0);
    end
    if (reset_seen_q && rst_ni && valid) begin
      assert (rotation < PipeBits'(P) || P == (1 << PipeBits));
      assert (reverse == flip_q[0]);
      assert (W'(beam) < b_ax[0 +: W]);
      assert (W'(y) < n_ax[W +: W]);
      assert (W'(z) < n_ax[2*W +: W]);
      for (int unsigned k = 0; k < P; k++) begin
        // The voxel is in the module the de-skew reads for lane k ...
        assert (W'(hw_module[k*PipeBits +: PipeBits]) == lane_module[k*W +: W]);
        // ... which is presented its index.
        if (CheckIndex) begin
          assert (W'(index[hw_module[k*PipeBits +: PipeBits]*I +: I]) == lane_index[k*W +: W]);
        end
        // No two lanes share a module.
        for (int unsigned l = 0; l < k; l++) begin
          assert (hw_module[k*PipeBits +: PipeBits] != hw_module[l*PipeBits +: PipeBits]);
        end
      end
    end
  end

  logic unused_outputs;
  assign unused_outputs = ^{busy, last};

endmodule
