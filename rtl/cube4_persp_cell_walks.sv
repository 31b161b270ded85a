// cube4_persp_cell_walks: the rays of the cells a perspective ring forms
// (docs/perspective.md, "The gradient ring's schedule" and "The plan for
// the compositing ring"). The gradient and compositing rings work, in beam
// b of the stream, on the cells of row b - 5 of the pass before: the y walk
// gives that row's ray (one a beam), the x walk the rays of its cells,
// p a step (cube4_persp_lanes, along y with one lane and along x with p).
//
// Function: in the steps of a beam whose cell row is a pass's (next_forms_i
// at the previous beam's last step), row_*_o describe that row and lane
// k's lane_*_o at step j the cell j*p + k of the row: whether a ray of the
// pass has its home there, the ray, and its position's weight (the sample's
// fraction: the compositor's place, cube4_persp_lanes' weight_o). Both walks
// start at the previous beam's last step (valid_i && beam_end_i), on the
// next row's pass's constants: the y walk where that row is the pass's
// first (next_row_zero_i), else it advances a row; the x walk at every beam
// (then advances a partial beam each valid step). They start only on a
// pass's constants (next_forms_i: the row is a pass's and that pass has one
// before it), which the walks' checkers hold to their ranges.
//
// Parameters: NumPipes (p), FracBits, WeightBits, PosBits, RayBits - as
// cube4_persp_lanes.
`include "cube4_pkg.sv"

module cube4_persp_cell_walks #(
  parameter int unsigned NumPipes   = 4,
  parameter int unsigned FracBits   = cube4_pkg::FracBits,
  parameter int unsigned WeightBits = cube4_pkg::WeightBits,
  parameter int unsigned PosBits    = 48,
  parameter int unsigned RayBits    = 16
) (
  input  logic                             clk_i,
  input  logic                             rst_ni,
  input  logic                             valid_i,
  input  logic                             beam_end_i,
  // The next beam's cell row: a pass's (after the stream's first), and its first.
  input  logic                             next_forms_i,
  input  logic                             next_row_zero_i,
  // That row's pass's constants.
  input  logic signed [PosBits-1:0]        spacing_i,
  input  logic signed [PosBits-1:0]        ray0_x_i,
  input  logic signed [PosBits-1:0]        ray0_y_i,
  input  logic signed [RayBits-1:0]        rays_x_lo_i,
  input  logic signed [RayBits-1:0]        rays_x_hi_i,
  input  logic signed [RayBits-1:0]        rays_y_lo_i,
  input  logic signed [RayBits-1:0]        rays_y_hi_i,
  // The current beam's cell row, and the step's cells.
  output logic                             row_valid_o,
  output logic [RayBits-1:0]               row_ray_o,
  output logic [WeightBits-1:0]            row_weight_o,
  output logic [NumPipes-1:0]              lane_valid_o,
  output logic [NumPipes*RayBits-1:0]      lane_ray_o,
  output logic [NumPipes*WeightBits-1:0]   lane_weight_o
);

  logic beam_last, y_start, x_start;
  assign beam_last = valid_i && beam_end_i;
  assign y_start   = beam_last && next_forms_i && next_row_zero_i;
  assign x_start   = beam_last && next_forms_i;

  logic [0:0]                  y_valid, y_unused_left;
  logic [4*(WeightBits+1)-1:0] y_unused_box;
  cube4_persp_lanes #(
    .Pipes     (1),
    .FracBits  (FracBits),
    .WeightBits(WeightBits),
    .PosBits   (PosBits),
    .RayBits   (RayBits)
  ) u_walk_y (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .spacing_i (spacing_i),
    .ray0_i    (ray0_y_i),
    .rays_lo_i (rays_y_lo_i),
    .rays_hi_i (rays_y_hi_i),
    .start_i   (y_start),
    .advance_i (beam_last && !y_start),
    .valid_o   (y_valid),
    .ray_o     (row_ray_o),
    .box_left_o(y_unused_left),
    .overlap_o (y_unused_box),
    .weight_o  (row_weight_o)
  );
  assign row_valid_o = y_valid[0];

  logic [NumPipes-1:0]                  x_unused_left;
  logic [NumPipes*4*(WeightBits+1)-1:0] x_unused_box;
  cube4_persp_lanes #(
    .Pipes     (NumPipes),
    .FracBits  (FracBits),
    .WeightBits(WeightBits),
    .PosBits   (PosBits),
    .RayBits   (RayBits)
  ) u_walk_x (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .spacing_i (spacing_i),
    .ray0_i    (ray0_x_i),
    .rays_lo_i (rays_x_lo_i),
    .rays_hi_i (rays_x_hi_i),
    .start_i   (x_start),
    .advance_i (valid_i && !x_start),
    .valid_o   (lane_valid_o),
    .ray_o     (lane_ray_o),
    .box_left_o(x_unused_left),
    .overlap_o (x_unused_box),
    .weight_o  (lane_weight_o)
  );

  // Unused by design: the boxes are the interpolation ring's business.
  logic unused_boxes;
  assign unused_boxes = ^{y_unused_left, y_unused_box, x_unused_left, x_unused_box};

endmodule
