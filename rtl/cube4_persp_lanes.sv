// cube4_persp_lanes: the perspective weight generator's lane assignment
// (docs/perspective.md, "The dataflow"; docs/rtl-persp.md): for each step
// of a walk along one axis, which of the step's Pipes cells is a ray's
// home, which ray's, and that ray's box and weight.
//
// Function: bit-exact with golden home_lane(ray0, spacing, rays, cell, F, W)
// (golden/perspective_dataflow.hpp) for the cells j * Pipes + k, k = 0 ..
// Pipes-1, of step j = 0, 1, ... since start_i. Along x a step is a partial
// beam and lane k pipeline k (Pipes = p); along y a step is a beam, one lane
// (Pipes = 1), whose home row's ray the whole beam shares.
//
// How: rays are at least a cell apart and their homes rise with the ray, so
// the rays homed in a step's cells are consecutive and at most Pipes. The
// unit keeps the first ray not yet placed (u_q, at pos_q) and the step's
// first cell (base_q); candidate i = 0 .. Pipes-1 is ray u_q + i at pos_q +
// i * spacing, placed if it is one of the slice's rays and its home is
// below base_q + Pipes, in lane home - base_q. An advance moves u_q past
// the placed rays; their count selects i * spacing from the same table.
// No ray homed before base_q is left behind: rays_lo's position is not
// negative (rays_inside()), and a step places every ray homed in it.
//
// Latency: 1. In the cycle after start_i (step 0, from ray rays_lo_i) or
// advance_i (the next step) the outputs describe that step; they hold
// otherwise. start_i takes precedence. The slice's constants are taken at
// start_i and kept for the walk, so a ring may start a walk on one slice
// while it still shows the last step of another's.
//
// Widths (P = PosBits, F = FracBits, W = WeightBits, R = RayBits):
//   spacing_i, ray0_i  P bits, signed, F fraction (the slice's m_k, c_k)
//   rays_lo_i/hi_i     R bits, signed: the slice's rays [lo, hi)
//   ray_o              Pipes x R bits, signed
//   overlap_o          Pipes x 4 x (W+1) bits: cube4_box_axis's overlaps
//   box_left_o         Pipes bits: the box starts at home - 1 (else at home)
//   weight_o           Pipes x W bits: the position's fraction
//   The box's extent needs spacing below 4 voxels (F+2 bits), which the
//   camera guarantees (spacing at most 3).
//
// Parameters:
//   Pipes      - lanes per step (p along x, 1 along y)
//   FracBits   - DDA fraction bits (golden Precision::dda_frac_bits, 20)
//   WeightBits - weight and overlap fraction bits (cube4_pkg::WeightBits)
//   PosBits    - positions, signed (48, as cube4_persp_ray)
//   RayBits    - ray indices, signed (16, as cube4_persp_ray)
`include "cube4_pkg.sv"

module cube4_persp_lanes #(
  parameter int unsigned Pipes      = 4,
  parameter int unsigned FracBits   = cube4_pkg::FracBits,
  parameter int unsigned WeightBits = cube4_pkg::WeightBits,
  parameter int unsigned PosBits    = 48,
  parameter int unsigned RayBits    = 16
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  // The slice's constants along this axis.
  input  logic signed [PosBits-1:0]         spacing_i,
  input  logic signed [PosBits-1:0]         ray0_i,
  input  logic signed [RayBits-1:0]         rays_lo_i,
  input  logic signed [RayBits-1:0]         rays_hi_i,
  // The walk.
  input  logic                              start_i,
  input  logic                              advance_i,
  // The current step's lanes.
  output logic [Pipes-1:0]                  valid_o,
  output logic [Pipes*RayBits-1:0]          ray_o,
  output logic [Pipes-1:0]                  box_left_o,
  output logic [Pipes*4*(WeightBits+1)-1:0] overlap_o,
  output logic [Pipes*WeightBits-1:0]       weight_o
);

  localparam int unsigned LaneBits = $clog2(Pipes + 1);
  localparam int unsigned IntBits  = PosBits - FracBits;  // a position's cell, signed

  // The walk's state: the first ray not yet placed, its position, and the
  // step's first cell; the walk's slice: the spacing and the rays' end.
  logic signed [RayBits-1:0] u_q, u_d, hi_q;
  logic signed [PosBits-1:0] pos_q, pos_d, spacing_q;
  logic signed [IntBits-1:0] base_q, base_d;

  // i * spacing for i = 0 .. Pipes: the candidates' offsets and the
  // advances (constant multiples: shifts and adds). Flat vectors: yosys
  // 0.23 reads no multi-dimensional packed arrays and warns on unpacked
  // ones written in always_comb; the fields are two's complement.
  logic [(Pipes+1)*PosBits-1:0] multiple;
  for (genvar i = 0; i <= Pipes; i++) begin : g_multiple
    assign multiple[i*PosBits +: PosBits] = PosBits'(i) * spacing_q;
  end

  // Candidates: ray u_q + i, placed if a ray of the slice homed in the step.
  logic [Pipes-1:0]         placed;
  logic [Pipes*PosBits-1:0] cand_pos;
  logic [Pipes*IntBits-1:0] cand_lane;  // home - base_q
  logic [Pipes*RayBits-1:0] cand_ray;
  logic [LaneBits-1:0]      count;
  always_comb begin
    count = '0;
    for (int unsigned i = 0; i < Pipes; i++) begin
      cand_pos[i*PosBits +: PosBits]  = pos_q + multiple[i*PosBits +: PosBits];
      cand_ray[i*RayBits +: RayBits]  = u_q + RayBits'(i);
      cand_lane[i*IntBits +: IntBits] = IntBits'($signed(cand_pos[i*PosBits +: PosBits]) >>> FracBits) - base_q;
      placed[i] = $signed(cand_ray[i*RayBits +: RayBits]) < hi_q &&
                  $signed(cand_lane[i*IntBits +: IntBits]) < $signed(IntBits'(Pipes));
      // Homes rise with the ray: the placed candidates are a prefix.
      if (placed[i]) count = LaneBits'(i + 1);
    end
  end

  // The slice's first ray's position: one multiply per walk start.
  logic signed [PosBits-1:0] first_pos;
  assign first_pos = ray0_i + PosBits'(rays_lo_i) * spacing_i;

  always_comb begin
    u_d    = u_q;
    pos_d  = pos_q;
    base_d = base_q;
    if (start_i) begin
      u_d    = rays_lo_i;
      pos_d  = first_pos;
      base_d = '0;
    end else if (advance_i) begin
      u_d    = u_q + RayBits'(count);
      pos_d  = pos_q + multiple[count*PosBits +: PosBits];
      base_d = base_q + IntBits'(Pipes);
    end
  end

  // Reset only for a defined state before the first start (outputs are
  // meaningful only after one).
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      u_q    <= '0;
      pos_q  <= '0;
      base_q <= '0;
    end else begin
      u_q    <= u_d;
      pos_q  <= pos_d;
      base_q <= base_d;
    end
  end

  always_ff @(posedge clk_i) begin
    if (start_i) begin
      spacing_q <= spacing_i;
      hi_q      <= rays_hi_i;
    end
  end

  // Lane k takes the candidate homed in its cell (at most one: homes differ).
  for (genvar k = 0; k < Pipes; k++) begin : g_lane
    logic                      hit;
    logic signed [PosBits-1:0] pos;
    logic signed [RayBits-1:0] ray;
    always_comb begin
      hit = 1'b0;
      pos = '0;
      ray = '0;
      for (int unsigned i = 0; i <= k; i++) begin
        if (placed[i] && cand_lane[i*IntBits +: IntBits] == IntBits'(k)) begin
          hit = 1'b1;
          pos = cand_pos[i*PosBits +: PosBits];
          ray = cand_ray[i*RayBits +: RayBits];
        end
      end
    end

    logic signed [IntBits:0] first;
    cube4_box_axis #(
      .DdaBits   (PosBits),
      .FracBits  (FracBits),
      .WeightBits(WeightBits)
    ) u_box (
      .pos_i    (pos),
      .spacing_i(spacing_q[FracBits+1:0]),
      .first_o  (first),
      .overlap_o(overlap_o[k*4*(WeightBits+1) +: 4*(WeightBits+1)])
    );

    assign valid_o[k]                          = hit;
    assign ray_o[k*RayBits +: RayBits]          = ray;
    assign box_left_o[k]                        = first < (IntBits+1)'(pos >>> FracBits);
    assign weight_o[k*WeightBits +: WeightBits] = pos[FracBits-1 -: WeightBits];
  end


endmodule
