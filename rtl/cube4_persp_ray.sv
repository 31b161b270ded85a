// cube4_persp_ray: the perspective weight generator's per-sample part.
//
// Function: walks a beam of rays u = u0, u0 + 1, ... of row v on sample
// slice k, one ray per cycle, and gives each its position and weights
// (golden/perspective.hpp and golden/units/dda_perspective.hpp, bit for
// bit): the ray's position in x and y (ray_position(): what box_axis()
// takes), the voxel column, row and weights of the sample
// (sample_place(): for cropping and the cut plane), the voxel nearest to it
// (nearest_voxel(): for the tag), and the points straight behind and ahead
// in the neighbouring slices' ray grids (realigned_ray(): ray index and
// weight, for the gradient). Every value is an accumulator advanced by a
// per-slice step, so no multiplier is needed per sample; start_i loads the
// beam's first ray with one multiply per value.
//
// Latency: 1. In the cycle after start_i or advance_i the outputs describe
// ray u0 (start) or the next ray (advance); they hold otherwise. start_i
// takes precedence over advance_i.
//
// Parameters:
//   FracBits   - DDA fraction bits (golden Precision::dda_frac_bits, 20)
//   WeightBits - weights' fraction (cube4_pkg::WeightBits)
//   PosBits    - positions and DDA values, signed (48)
//   RayBits    - ray indices u, v, signed (16: base planes up to 32767 rays
//                a side); the beam start's multiplies are RayBits x PosBits
`include "cube4_pkg.sv"

module cube4_persp_ray #(
  parameter int unsigned FracBits   = cube4_pkg::FracBits,
  parameter int unsigned WeightBits = cube4_pkg::WeightBits,
  parameter int unsigned PosBits    = 48,
  parameter int unsigned RayBits    = 16
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,
  // The slice's constants (cube4_persp_slice).
  input  logic signed [PosBits-1:0]  spacing_i,
  input  logic signed [PosBits-1:0]  ray0_x_i,
  input  logic signed [PosBits-1:0]  ray0_y_i,
  input  logic signed [PosBits-1:0]  behind_start_x_i,
  input  logic signed [PosBits-1:0]  behind_start_y_i,
  input  logic signed [PosBits-1:0]  behind_step_i,
  input  logic signed [PosBits-1:0]  ahead_start_x_i,
  input  logic signed [PosBits-1:0]  ahead_start_y_i,
  input  logic signed [PosBits-1:0]  ahead_step_i,
  // The beam.
  input  logic                       start_i,
  input  logic signed [RayBits-1:0]  u0_i,
  input  logic signed [RayBits-1:0]  v_i,
  input  logic                       advance_i,
  // The current ray.
  output logic signed [PosBits-1:0]  pos_x_o,
  output logic signed [PosBits-1:0]  pos_y_o,
  output logic signed [PosBits-1:0]  column_o,      // floor(pos_x)
  output logic signed [PosBits-1:0]  row_o,         // floor(pos_y)
  output logic [WeightBits-1:0]      wx_o,
  output logic [WeightBits-1:0]      wy_o,
  output logic signed [PosBits-1:0]  nearest_x_o,
  output logic signed [PosBits-1:0]  nearest_y_o,
  output logic signed [PosBits-1:0]  behind_ray_x_o,
  output logic signed [PosBits-1:0]  behind_ray_y_o,
  output logic [WeightBits-1:0]      behind_wx_o,
  output logic [WeightBits-1:0]      behind_wy_o,
  output logic signed [PosBits-1:0]  ahead_ray_x_o,
  output logic signed [PosBits-1:0]  ahead_ray_y_o,
  output logic [WeightBits-1:0]      ahead_wx_o,
  output logic [WeightBits-1:0]      ahead_wy_o
);

  // The four accumulators that move along the beam, and the two that do not.
  logic signed [PosBits-1:0] pos_x_q, pos_y_q, behind_x_q, behind_y_q, ahead_x_q, ahead_y_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      pos_x_q    <= '0;
      pos_y_q    <= '0;
      behind_x_q <= '0;
      behind_y_q <= '0;
      ahead_x_q  <= '0;
      ahead_y_q  <= '0;
    end else if (start_i) begin
      pos_x_q    <= ray0_x_i + u0_i * spacing_i;
      pos_y_q    <= ray0_y_i + v_i * spacing_i;
      behind_x_q <= behind_start_x_i + u0_i * behind_step_i;
      behind_y_q <= behind_start_y_i + v_i * behind_step_i;
      ahead_x_q  <= ahead_start_x_i + u0_i * ahead_step_i;
      ahead_y_q  <= ahead_start_y_i + v_i * ahead_step_i;
    end else if (advance_i) begin
      pos_x_q    <= pos_x_q + spacing_i;
      behind_x_q <= behind_x_q + behind_step_i;
      ahead_x_q  <= ahead_x_q + ahead_step_i;
    end
  end

  // Integer part (floor) and the weight: the fraction's top WeightBits bits
  // (dda_split(), realigned_ray(): truncation).
  localparam int unsigned Drop = FracBits - WeightBits;

  function automatic logic signed [PosBits-1:0] whole(input logic signed [PosBits-1:0] v);
    whole = v >>> FracBits;
  endfunction
  // Waiver: a weight is a slice of the fraction; the other bits are the
  // integer part (whole()) and the truncated low fraction, unused by design.
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic logic [WeightBits-1:0] weight(input logic signed [PosBits-1:0] v);
    weight = v[FracBits-1:Drop];
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  // nearest_voxel(): floor(pos + 1/2).
  localparam logic signed [PosBits-1:0] Half = PosBits'(1) <<< (FracBits - 1);

  assign pos_x_o        = pos_x_q;
  assign pos_y_o        = pos_y_q;
  assign column_o       = whole(pos_x_q);
  assign row_o          = whole(pos_y_q);
  assign wx_o           = weight(pos_x_q);
  assign wy_o           = weight(pos_y_q);
  assign nearest_x_o    = whole(pos_x_q + Half);
  assign nearest_y_o    = whole(pos_y_q + Half);
  assign behind_ray_x_o = whole(behind_x_q);
  assign behind_ray_y_o = whole(behind_y_q);
  assign behind_wx_o    = weight(behind_x_q);
  assign behind_wy_o    = weight(behind_y_q);
  assign ahead_ray_x_o  = whole(ahead_x_q);
  assign ahead_ray_y_o  = whole(ahead_y_q);
  assign ahead_wx_o     = weight(ahead_x_q);
  assign ahead_wy_o     = weight(ahead_y_q);

endmodule
