// cube4_shade_cube_coord_sva: for coverage (scripts/coverage.sh), the
// cases the cube-map coordinate unit must be driven through: a valid
// direction on each of the six faces (c_face[f], golden cube_coordinates'
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

  for (genvar f = 0; f < 6; f++) begin : g_face
    c_face: cover property (@(posedge clk_i) valid_o && coord_valid_o && face_o == 3'(f));
  end
  c_no_face: cover property (@(posedge clk_i) valid_o && !coord_valid_o);

endmodule

bind cube4_shade_cube_coord cube4_shade_cube_coord_sva u_sva (.*);
