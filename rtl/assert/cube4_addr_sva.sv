// cube4_addr_sva: cube4_addr's preconditions and its one-access-per-module
// property (its header), as assertions bound to every address generator:
//   a_start_config           - with start_i, perm_i is a permutation of
//                              {0, 1, 2} and every dimension is at least 1;
//   a_one_access_per_module  - in every cycle with valid_o, pipeline k's
//                              voxel (permuted x = beam_o * p + k, y_o, z_o)
//                              lies in the module the de-skew gives it,
//                              (rotation_o +- k) mod p, so the p pipelines
//                              read p different modules, each once. With
//                              the skew module(x, y, z) = (x + y + z) mod p,
//                              and a backwards axis's object coordinate
//                              n - 1 - v (mod p, whatever its padding),
//                              that is rotation_o = (the sum of the partial
//                              beam's object coordinates at k = 0) mod p and
//                              reverse_o = flip[0]. The formal proofs
//                              (rtl/formal/addr_fv.sv) check it, bounded,
//                              for every traversal; this checks every frame
//                              a simulation runs, to its end.
//
// Simulation only: not part of the unit, never synthesised.
module cube4_addr_sva #(
  parameter int unsigned  NumPipes = 4,
  parameter int unsigned  DimBits  = 10,
  localparam int unsigned PipeBits = (NumPipes > 1) ? $clog2(NumPipes) : 1
) (
  input logic                  clk_i,
  input logic                  rst_ni,
  input logic                  start_i,
  input logic [5:0]            perm_i,
  input logic [3*DimBits-1:0]  dim_i,
  input logic                  valid_o,
  input logic [PipeBits-1:0]   rotation_o,
  input logic                  reverse_o,
  input logic [DimBits-1:0]    beam_o,
  input logic [DimBits-1:0]    y_o,
  input logic [DimBits-1:0]    z_o,
  // The frame's configuration as the unit captured it (by name).
  input logic [5:0]            perm_q,
  input logic [2:0]            flip_q,
  input logic [3*DimBits-1:0]  n_q
);

  logic [63:0] cycle;
  cube4_sva_cycle u_cycle (.clk_i, .rst_ni, .cycle_o(cycle));

  function automatic logic is_perm(input logic [5:0] p);
    is_perm = p[1:0] != 2'd3 && p[3:2] != 2'd3 && p[5:4] != 2'd3 &&
              p[1:0] != p[3:2] && p[1:0] != p[5:4] && p[3:2] != p[5:4];
  endfunction

  // Object coordinate mod p, as a signed sum term, of permuted axis i at
  // position v (the partial beam's pipeline 0 for the beam axis: j * p = 0).
  function automatic int term(input int i, input int v);
    int n;
    n    = int'(n_q[perm_q[2*i +: 2]*DimBits +: DimBits]);
    term = flip_q[i] ? n - 1 - v : v;
  endfunction

  int sum, module0;
  always_comb begin
    sum     = term(0, 0) + term(1, int'(y_o)) + term(2, int'(z_o));
    module0 = ((sum % int'(NumPipes)) + int'(NumPipes)) % int'(NumPipes);
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      a_start_config: assert (!start_i || (is_perm(perm_i) && dim_i[0 +: DimBits] != '0
                                           && dim_i[DimBits +: DimBits] != '0 && dim_i[2*DimBits +: DimBits] != '0))
        else $error("cube4_addr: cycle %0d: start with perm %0d %0d %0d (a permutation of 0 1 2?) and dims %0d x %0d x %0d (each >= 1?)",
                    cycle, perm_i[1:0], perm_i[3:2], perm_i[5:4], dim_i[0 +: DimBits], dim_i[DimBits +: DimBits],
                    dim_i[2*DimBits +: DimBits]);
      a_one_access_per_module: assert (!valid_o || (int'(rotation_o) == module0 && reverse_o == flip_q[0]))
        else $error("cube4_addr: cycle %0d: partial beam %0d, beam %0d, slice %0d: de-skew rotation %0d reverse %0d, but pipeline k's voxel is in module (%0d %s k) mod %0d",
                    cycle, beam_o, y_o, z_o, rotation_o, reverse_o, module0, flip_q[0] ? "-" : "+", NumPipes);
    end
  end

endmodule

bind cube4_addr cube4_addr_sva #(
  .NumPipes(NumPipes),
  .DimBits (DimBits)
) u_sva (.*);
