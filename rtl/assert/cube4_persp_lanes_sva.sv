// cube4_persp_lanes_sva: the spacing range cube4_persp_lanes' header states,
// as an assertion bound to every cube4_persp_lanes:
//   a_spacing_range - with start_i, the walk's spacing lies in [1, 4)
//                     voxels: below one voxel several rays share a cell
//                     and a lane, above four the box filter's four taps
//                     (cube4_box_axis's F+2-bit spacing) drop cells.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_persp_lanes_sva #(
  parameter int unsigned FracBits = 20,
  parameter int unsigned PosBits  = 48
) (
  input logic                      clk_i,
  input logic                      rst_ni,
  input logic                      start_i,
  input logic signed [PosBits-1:0] spacing_i
);

  localparam logic signed [PosBits-1:0] One  = PosBits'(1) << FracBits;
  localparam logic signed [PosBits-1:0] Four = PosBits'(4) << FracBits;

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_spacing_range: assert (!start_i || (spacing_i >= One && spacing_i < Four))
        else $error("cube4_persp_lanes: cycle %0d: a walk starts with spacing %0d (%0d fraction bits), outside [1, 4) voxels",
                    cycle, spacing_i, FracBits);
    end
  end

endmodule

bind cube4_persp_lanes cube4_persp_lanes_sva #(.FracBits(FracBits), .PosBits(PosBits)) u_sva (.*);
