// cube4_shade_cube_coord_sva: for coverage (scripts/coverage.sh), the
// cases the cube-map coordinate unit must be driven through: a valid
// direction on each of the six faces (c_face_px .. c_face_nz, golden cube_coordinates'
// face order: +x, -x, +y, -y, +z, -z), and the zero vector, which has no
// face (c_no_face: coord_valid_o low).
//
// Simulation only: not part of the unit, never synthesised.
module cube4_shade_cube_coord_sva (
  input logic       clk_i,
  input logic       valid_o,
  input logic       coord_valid_o,
  input logic [2:0] face_o
);

  // One statement per face: verilator_coverage merges the iterations of a
  // generate loop into one point.
  logic on_face;
  assign on_face = valid_o && coord_valid_o;
  c_face_px: cover property (@(posedge clk_i) on_face && face_o == 3'd0);
  c_face_nx: cover property (@(posedge clk_i) on_face && face_o == 3'd1);
  c_face_py: cover property (@(posedge clk_i) on_face && face_o == 3'd2);
  c_face_ny: cover property (@(posedge clk_i) on_face && face_o == 3'd3);
  c_face_pz: cover property (@(posedge clk_i) on_face && face_o == 3'd4);
  c_face_nz: cover property (@(posedge clk_i) on_face && face_o == 3'd5);
  c_no_face: cover property (@(posedge clk_i) valid_o && !coord_valid_o);

endmodule

bind cube4_shade_cube_coord cube4_shade_cube_coord_sva u_sva (.*);
