// cube4_gradient_persp_homes: where, along one axis, the perspective
// gradient's operands of ray u have their homes (docs/perspective.md, "The
// plan for the ring's RTL"; docs/rtl-gradient-persp.md).
//
// Function: bit-exact with golden gradient_operand_homes()
// (golden/perspective_dataflow.hpp): the home cell (floor of the position)
// of ray u on slice k, of its neighbours u - 1 and u + 1 there, and of the
// two rays q, q + 1 of slices k - 1 and k + 1 around the point straight
// behind and ahead of it (q = floor(start + u * step), the realignment
// DDA), with the realigned point's weight between q and q + 1 (the top
// WeightBits of its fraction, golden realigned_ray()). A home is valid where its ray is one of its slice's rays along the
// axis [lo, hi) and the slice is present (the frame's first slice has none
// behind, its last none ahead); golden's kNoRow is valid = 0.
//
// A ray's home column depends on u alone and its home row on v alone, so the
// gradient ring asks this once per axis: along x for each lane's ray (which
// of the seven column packets holds each operand), along y once per beam
// (which rows the column stages read).
//
// Latency: 0 (combinational; the ring registers what it keeps).
//
// Widths (P = PosBits, F = FracBits, R = RayBits): positions, spacings and
// the DDAs P bits signed with F fraction bits; rays R bits signed; homes
// P - F bits signed. The ray u must be one of slice k's rays. A realigned q
// outside its slice's rays gives an invalid home whatever its width (it is
// compared at P - F bits, multiplied at R bits only once in range).
//
// Cost: five R x P multipliers (u by the spacing and by both steps, q by
// the neighbouring spacings); the ring's lanes could walk them as
// cube4_persp_lanes walks positions, a saving left to the ring.
//
// Parameters:
//   FracBits   - DDA fraction bits (golden Precision::dda_frac_bits, 20)
//   WeightBits - realigned weights' bits (cube4_pkg::WeightBits)
//   PosBits    - positions, signed (48, as cube4_persp_ray)
//   RayBits    - ray indices, signed (16, as cube4_persp_ray)
`include "cube4_pkg.sv"

module cube4_gradient_persp_homes #(
  parameter int unsigned  FracBits = cube4_pkg::FracBits,
  parameter int unsigned  WeightBits = cube4_pkg::WeightBits,
  parameter int unsigned  PosBits  = 48,
  parameter int unsigned  RayBits  = 16,
  localparam int unsigned HomeBits = PosBits - FracBits
) (
  input  logic signed [RayBits-1:0]    u_i,
  // Slice k along the axis.
  input  logic signed [PosBits-1:0]    spacing_i,
  input  logic signed [PosBits-1:0]    ray0_i,
  input  logic signed [RayBits-1:0]    rays_lo_i,
  input  logic signed [RayBits-1:0]    rays_hi_i,
  // Slice k - 1, and slice k's realignment into its rays.
  input  logic                         behind_present_i,
  input  logic signed [PosBits-1:0]    behind_spacing_i,
  input  logic signed [PosBits-1:0]    behind_ray0_i,
  input  logic signed [RayBits-1:0]    behind_lo_i,
  input  logic signed [RayBits-1:0]    behind_hi_i,
  input  logic signed [PosBits-1:0]    behind_start_i,
  input  logic signed [PosBits-1:0]    behind_step_i,
  // Slice k + 1, likewise.
  input  logic                         ahead_present_i,
  input  logic signed [PosBits-1:0]    ahead_spacing_i,
  input  logic signed [PosBits-1:0]    ahead_ray0_i,
  input  logic signed [RayBits-1:0]    ahead_lo_i,
  input  logic signed [RayBits-1:0]    ahead_hi_i,
  input  logic signed [PosBits-1:0]    ahead_start_i,
  input  logic signed [PosBits-1:0]    ahead_step_i,
  // The homes: ray u's, rays u - 1 and u + 1 (side [0], [1]), and rays q
  // and q + 1 of slices k - 1 and k + 1 ([0], [1]) with the weights between
  // them (whatever the homes' validity: a ray that misses reads zero).
  output logic signed [HomeBits-1:0]   home_o,
  output logic [1:0]                   side_valid_o,
  output logic [2*HomeBits-1:0]        side_o,
  output logic [1:0]                   behind_valid_o,
  output logic [2*HomeBits-1:0]        behind_o,
  output logic [WeightBits-1:0]        behind_weight_o,
  output logic [1:0]                   ahead_valid_o,
  output logic [2*HomeBits-1:0]        ahead_o,
  output logic [WeightBits-1:0]        ahead_weight_o
);

  function automatic logic signed [HomeBits-1:0] home_of(input logic signed [PosBits-1:0] pos);
    home_of = HomeBits'(pos >>> FracBits);
  endfunction

  // Whether ray a (HomeBits wide: a realigned q may lie far outside) is one
  // of the rays [lo, hi).
  function automatic logic among(input logic signed [HomeBits-1:0] a, input logic signed [RayBits-1:0] lo,
                                  input logic signed [RayBits-1:0] hi);
    among = a >= HomeBits'(lo) && a < HomeBits'(hi);
  endfunction

  // Slice k: ray u's position; its neighbours' lie a spacing either side.
  logic signed [PosBits-1:0]  pos;
  logic signed [HomeBits-1:0] u_wide;
  assign pos    = ray0_i + PosBits'(u_i) * spacing_i;
  assign u_wide = HomeBits'(u_i);

  assign home_o       = home_of(pos);
  assign side_valid_o = {among(u_wide + HomeBits'(1), rays_lo_i, rays_hi_i),
                         among(u_wide - HomeBits'(1), rays_lo_i, rays_hi_i)};
  assign side_o       = {home_of(pos + spacing_i), home_of(pos - spacing_i)};

  // A neighbouring slice: the realigned point (ray q and its weight), and
  // the homes of q and q + 1.
  localparam int unsigned Realigned = WeightBits + 2 + 2 * HomeBits;
  function automatic logic [Realigned-1:0] realigned(
      input logic present, input logic signed [PosBits-1:0] start, input logic signed [PosBits-1:0] step,
      input logic signed [PosBits-1:0] there_spacing, input logic signed [PosBits-1:0] there_ray0,
      input logic signed [RayBits-1:0] lo, input logic signed [RayBits-1:0] hi, input logic signed [RayBits-1:0] u);
    logic signed [PosBits-1:0]  point, q_pos;
    logic signed [HomeBits-1:0] q;
    point = start + PosBits'(u) * step;
    q     = home_of(point);
    q_pos = there_ray0 + PosBits'($signed(q[RayBits-1:0])) * there_spacing;
    realigned = {point[FracBits-1 -: WeightBits],
                 present && among(q + HomeBits'(1), lo, hi), present && among(q, lo, hi),
                 home_of(q_pos + there_spacing), home_of(q_pos)};
  endfunction

  assign {behind_weight_o, behind_valid_o, behind_o} =
      realigned(behind_present_i, behind_start_i, behind_step_i, behind_spacing_i, behind_ray0_i, behind_lo_i,
                behind_hi_i, u_i);
  assign {ahead_weight_o, ahead_valid_o, ahead_o} =
      realigned(ahead_present_i, ahead_start_i, ahead_step_i, ahead_spacing_i, ahead_ray0_i, ahead_lo_i, ahead_hi_i,
                u_i);

endmodule
