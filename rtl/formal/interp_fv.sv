// Formal harness for cube4_interp: an equivalence miter against the
// independent reference cube4_ref_interp (golden trilinear()), plus the
// saturation property: every stage's result lies between the smallest and
// largest of the eight voxels it came from (so the sample never leaves the
// voxel range and needs no clamp). All inputs are free in every cycle,
// weights within [0, 2^W].
//
// Miter, stage by stage: golden trilinear() is lerp in x (four), then y
// (two), then z (one). Reference instance 1 computes the x lerps from the
// inputs; instance 2 the y lerps from the expected x results one cycle
// later, instance 3 the z lerp from the expected y results (the weights of
// the stages not used are 0, for which golden lerp is the identity). The
// unit's stage registers (probes: the unit has no ports for them) and its
// output must equal the expected values in every cycle once written: the
// unit's datapath registers run without enable, so sample_o is specified
// in every cycle, not only under valid_o. valid_o is checked against
// valid_i delayed, from reset.
//
// Proof: 1-induction (each stage a function of the previous one), in three
// proofs, one per stage (parameter Stage). z3 proves a few lerp levels per
// query in seconds to minutes; all seven in one induction step, or the
// output against one seven-lerp reference of the inputs three cycles
// back, gave no result in 5 minutes.
module interp_fv #(
  parameter int unsigned VoxelBits  = 12,
  parameter int unsigned WeightBits = 8,
  // The reference's integer width (golden's T): the smallest that holds
  // (b - a) * w + 2^(W-1) by default; 32 is golden's int32_t.
  parameter int unsigned RefIntBits = VoxelBits + WeightBits + 2,
  // Which group of assertions this proof proves (see FV_CHECK); 0: all.
  parameter int unsigned Stage      = 0
) (
  input logic                   clk_i,
  input logic                   rst_ni,
  input logic                   valid_i,
  input logic [8*VoxelBits-1:0] voxels_i,
  input logic [WeightBits:0]    wx_i,
  input logic [WeightBits:0]    wy_i,
  input logic [WeightBits:0]    wz_i
);

  localparam int unsigned V = VoxelBits;
  localparam int unsigned Latency = 3;
  localparam logic [WeightBits:0] One = (WeightBits+1)'(1) << WeightBits;

  logic         valid;
  logic [V-1:0] sample;

  cube4_interp #(
    .VoxelBits (VoxelBits),
    .WeightBits(WeightBits)
  ) u_dut (
    .clk_i,
    .rst_ni,
    .valid_i,
    .voxels_i,
    .wx_i,
    .wy_i,
    .wz_i,
    .valid_o (valid),
    .sample_o(sample)
  );

  // Expected stage results, each registered once per stage like the unit's
  // (the reference computes combinationally).
  logic [4*V-1:0]      x_ref, x_exp_q;
  logic [2*V-1:0]      y_ref, y_exp_q;
  logic [V-1:0]        z_ref, z_exp_q;
  logic [WeightBits:0] wy_exp_q, wz_exp1_q, wz_exp_q;

  cube4_ref_interp #(
    .VoxelBits (VoxelBits),
    .WeightBits(WeightBits),
    .IntBits   (RefIntBits)
  ) u_ref_x (
    .voxels_i,
    .wx_i,
    .wy_i    ('0),
    .wz_i    ('0),
    .sample_o(),
    .x_o     (x_ref),
    .y_o     ()
  );

  // Voxel 2i = expected x lerp i, odd voxels 0, wx = 0: the x lerps pass
  // the even voxels through, and y_o is golden's front/back.
  logic [8*V-1:0] y_in;
  for (genvar i = 0; i < 4; i++) begin : g_y_in
    assign y_in[2*i*V +: V]     = x_exp_q[i*V +: V];
    assign y_in[(2*i+1)*V +: V] = '0;
  end

  cube4_ref_interp #(
    .VoxelBits (VoxelBits),
    .WeightBits(WeightBits),
    .IntBits   (RefIntBits)
  ) u_ref_y (
    .voxels_i(y_in),
    .wx_i    ('0),
    .wy_i    (wy_exp_q),
    .wz_i    ('0),
    .sample_o(),
    .x_o     (),
    .y_o     (y_ref)
  );

  // Voxel 0 = front, voxel 4 = back, wx = wy = 0: the sample is the z lerp.
  cube4_ref_interp #(
    .VoxelBits (VoxelBits),
    .WeightBits(WeightBits),
    .IntBits   (RefIntBits)
  ) u_ref_z (
    .voxels_i({{3{V'(0)}}, y_exp_q[V +: V], {3{V'(0)}}, y_exp_q[0 +: V]}),
    .wx_i    ('0),
    .wy_i    ('0),
    .wz_i    (wz_exp_q),
    .sample_o(z_ref),
    .x_o     (),
    .y_o     ()
  );

  // Probes (connected by scripts/formal.sh): the unit's stage registers.
  logic [4*V-1:0]      probe_x_q;
  logic [2*V-1:0]      probe_y_q;
  logic [WeightBits:0] probe_wy_q, probe_wz1_q, probe_wz2_q;
  logic [Latency-1:0]  probe_valid_q;

  // Bounds of the eight voxels, delayed with their stage.
  logic [V-1:0] vmin, vmax;
  always_comb begin
    vmin = voxels_i[0 +: V];
    vmax = voxels_i[0 +: V];
    for (int unsigned i = 1; i < 8; i++) begin
      if (voxels_i[i*V +: V] < vmin) vmin = voxels_i[i*V +: V];
      if (voxels_i[i*V +: V] > vmax) vmax = voxels_i[i*V +: V];
    end
  end
  logic [Latency*V-1:0] min_q, max_q;

  // filled counts the cycles since the start of the trace, so that
  // registers no input of the trace has written yet are not compared.
  logic [Latency-1:0] valid_exp_q;
  logic [1:0]         filled_q = '0;
  logic               reset_seen_q = 1'b0;

  always_ff @(posedge clk_i) begin
    x_exp_q   <= x_ref;
    y_exp_q   <= y_ref;
    z_exp_q   <= z_ref;
    wy_exp_q  <= wy_i;
    wz_exp1_q <= wz_i;
    wz_exp_q  <= wz_exp1_q;
    min_q <= {min_q[0 +: (Latency-1)*V], vmin};
    max_q <= {max_q[0 +: (Latency-1)*V], vmax};
    if (filled_q != 2'(Latency)) filled_q <= filled_q + 2'd1;
  end

  // The valid pipeline, from the first reset on.
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      valid_exp_q  <= '0;
      reset_seen_q <= 1'b1;
    end else begin
      valid_exp_q <= {valid_exp_q[Latency-2:0], valid_i};
    end
  end

  // Stage s's bounds: min_q/max_q slot s-1.
  function automatic logic in_range(input logic [V-1:0] v, input int unsigned s);
    in_range = min_q[(s-1)*V +: V] <= v && v <= max_q[(s-1)*V +: V];
  endfunction

  // Stage group g is asserted by the proof of group g (Stage = g) and
  // assumed by those of later groups: assume-guarantee without a cycle, so
  // the three proofs together prove every group; Stage = 0 asserts all in
  // one proof (too slow for z3 at the default widths).
`define FV_CHECK(g, c) \
    if (Stage == 0 || Stage == g) assert (c); \
    else if (Stage > g) assume (c);

  always_comb begin
    assume (wx_i <= One);
    assume (wy_i <= One);
    assume (wz_i <= One);
    // Group 1: the x stage, the weight delays and the valid pipeline.
    if (filled_q >= 2'd1) begin
      `FV_CHECK(1, probe_x_q == x_exp_q)
      `FV_CHECK(1, probe_wy_q == wy_exp_q)
      `FV_CHECK(1, probe_wz1_q == wz_exp1_q)
      `FV_CHECK(1, wy_exp_q <= One && wz_exp1_q <= One)
      for (int unsigned i = 0; i < 4; i++) begin
        `FV_CHECK(1, in_range(probe_x_q[i*V +: V], 1))
      end
    end
    if (filled_q >= 2'd2) begin
      `FV_CHECK(1, probe_wz2_q == wz_exp_q)
      `FV_CHECK(1, wz_exp_q <= One)
    end
    if (reset_seen_q && rst_ni) begin
      `FV_CHECK(1, probe_valid_q == valid_exp_q)
      `FV_CHECK(1, valid == valid_exp_q[Latency-1])
    end
    // Group 2: the y stage.
    if (filled_q >= 2'd2) begin
      `FV_CHECK(2, probe_y_q == y_exp_q)
      for (int unsigned i = 0; i < 2; i++) begin
        `FV_CHECK(2, in_range(probe_y_q[i*V +: V], 2))
      end
    end
    // Group 3: the z stage, i.e. the sample.
    if (filled_q == 2'(Latency)) begin
      `FV_CHECK(3, sample == z_exp_q)
      `FV_CHECK(3, in_range(sample, 3))
    end
  end
`undef FV_CHECK

  // Traces start in reset, like the system does.
  always_comb if ($initstate) assume (!rst_ni);

endmodule
