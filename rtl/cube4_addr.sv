// cube4_addr: address generation for Cube-4's skewed voxel memory.
//
// Function: bit-exact with golden beam_access() (golden/units/addr.hpp),
// which defines the layout, the traversal and the de-skew:
//   module(x, y, z) = (x + y + z) mod p
//   index(x, y, z)  = floor(x / p) + B_x * (y + P_y * z)
// in object coordinates of the volume padded to P_a = B_a * p,
// B_a = ceil(n_a / p). After start_i the unit walks the traversal given by
// perm_i/flip_i (permuted axis i walks object axis perm[i], backwards if
// flip[i]): slice by slice, beam by beam, partial beam by partial beam, and
// for each partial beam j of beam y of slice z (permuted coordinates)
// presents to every memory module m the index of the one voxel it holds,
// plus the de-skew: pipeline k's voxel (permuted x = j*p + k) comes from
// module (rotation_o + k) mod p, or (rotation_o - k) mod p if reverse_o.
//
// How: no multiplier or divider is used per beam. Each of the two outer
// axes keeps its object coordinate mod p (phase) and its share of the index
// (floor(o/p) for object x, stride * o otherwise), stepped by +-1. For the
// beam axis, module m's voxel has coordinate o = p*u' + t_m with
// t_m = (m - phase_y - phase_z) mod p and u' the partial beam's block u, or
// the next block (u+1) mod B when t_m < v (v = n mod p for a backwards beam
// axis, 0 otherwise): two running block shares gu/gu1 and a table
// st[t] = stride * t give index_m = g_y + g_z + (t_m < v ? gu1 : gu) + st[t_m].
// The per-frame constants (strides, start values) come from one shared
// multiplier in four setup cycles after start_i.
//
// Latency and handshake: start_i (a pulse) captures perm_i, flip_i, dim_i
// and begins a frame, also aborting one in progress; the registers must be
// valid in that cycle only. Setup takes 5 cycles; from the 6th cycle after
// start_i, every cycle with advance_i high issues one partial beam, which
// appears registered on the outputs with valid_o the next cycle (so with
// advance_i held high, valid_o first rises StartLatency = 7 cycles after
// start_i and stays high for B_{perm[0]} * n_{perm[1]} * n_{perm[2]}
// cycles). last_o marks the frame's last partial beam; busy_o is high from
// the cycle after start_i until that beam has been issued. A
// valid-only pipeline without back-pressure beyond advance_i.
// Walks for the system's stream (supersampling reads a slice S times; frames
// follow back to back): repeat_slice_i, sampled when a slice's last partial
// beam issues, walks that slice again from beam 0 instead of the next;
// again_i, sampled when the frame's last partial beam issues, starts the
// same frame over in the next cycle without setup (busy_o stays high). Only control
// state (FSM, valid) is reset.
//
// Preconditions: perm_i a permutation of {0, 1, 2}, every dim >= 1 and
// <= 2^DimBits - 1, NumPipes <= 2^DimBits.
//
// Parameters:
//   NumPipes  - p, memory modules = pipelines (4, as VolumePro)
//   DimBits   - width of each object dimension and position output (10)
//   IndexBits - width of a module index; the default holds any volume of
//               DimBits-wide dims
//   PipeBits  - (derived) width of a module number
`include "cube4_pkg.sv"

module cube4_addr #(
  parameter int unsigned  NumPipes  = cube4_pkg::NumPipes,
  parameter int unsigned  DimBits   = cube4_pkg::DimBits,
  parameter int unsigned  IndexBits = 3 * DimBits + 4 - $clog2(NumPipes + 1),
  localparam int unsigned PipeBits  = (NumPipes > 1) ? $clog2(NumPipes) : 1
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  input  logic                          start_i,
  input  logic                          advance_i,
  input  logic                          repeat_slice_i,  // with a slice's last partial beam
  input  logic                          again_i,         // with the frame's last partial beam
  input  logic [5:0]                    perm_i,     // perm[i] at [2*i +: 2]
  input  logic [2:0]                    flip_i,     // flip[i] at [i]
  input  logic [3*DimBits-1:0]          dim_i,      // object n_a at [a*DimBits +: DimBits]
  output logic                          busy_o,
  output logic                          valid_o,
  output logic [NumPipes*IndexBits-1:0] index_o,    // module m at [m*IndexBits +: IndexBits]
  output logic [PipeBits-1:0]           rotation_o,
  output logic                          reverse_o,
  output logic [DimBits-1:0]            beam_o,     // partial beam j
  output logic [DimBits-1:0]            y_o,        // beam (permuted y)
  output logic [DimBits-1:0]            z_o,        // slice (permuted z)
  output logic                          last_o
);

  localparam int unsigned P        = NumPipes;
  localparam int unsigned Log2P    = $clog2(NumPipes);
  localparam bit          Pow2     = (NumPipes & (NumPipes - 1)) == 0;
  localparam int unsigned I        = IndexBits;
  localparam int unsigned D        = DimBits;
  // Second multiplier operand: n - 1, p * (B - 1) or P_y = p * B.
  localparam int unsigned MulBits  = DimBits + PipeBits + 1;
  localparam logic [PipeBits-1:0] PMax = PipeBits'(NumPipes - 1);

  // ---------------------------------------------------------------------
  // Modulo-p helpers on values in [0, p).
  function automatic logic [PipeBits-1:0] add_mod(input logic [PipeBits-1:0] a,
                                                  input logic [PipeBits-1:0] b);
    logic [PipeBits:0] s;
    s = {1'b0, a} + {1'b0, b};
    if (s >= (PipeBits+1)'(NumPipes)) s = s - (PipeBits+1)'(NumPipes);
    add_mod = s[PipeBits-1:0];
  endfunction

  function automatic logic [PipeBits-1:0] sub_mod(input logic [PipeBits-1:0] a,
                                                  input logic [PipeBits-1:0] b);
    // a - b + p < p when a < b; PipeBits'(p) is 0 when p = 2^PipeBits and the
    // wrap-around of a - b is then already right.
    sub_mod = (a >= b) ? a - b : a - b + PipeBits'(NumPipes);
  endfunction

  // ---------------------------------------------------------------------
  // Control.
  typedef enum logic [1:0] {
    StIdle,
    StSetup,
    StRun
  } state_e;

  state_e            state_q, state_d;
  logic [2:0]        step_q, step_d;      // setup step 0 .. 4
  logic              issue;               // a partial beam is issued this cycle
  logic              frame_last;          // ... and it is the frame's last

  // Configuration, captured at start_i.
  logic [5:0]        perm_q;
  logic [2:0]        flip_q;
  logic [3*D-1:0]    n_q;                 // n_a
  logic [3*D-1:0]    div_q;               // floor((n_a - 1) / p) = B_a - 1
  logic [3*PipeBits-1:0] mod_q;           // (n_a - 1) mod p

  // Setup products and per-frame constants.
  logic [I-1:0]      sz_q;                // stride of object z: B_x * P_y
  logic [2*I-1:0]    gs_q;                // stride * (n - 1) of permuted axes 1, 2
  logic [I-1:0]      gutop_q;             // block share of block B_0 - 1
  logic [P*I-1:0]    st_q;                // st[t] = stride_0 * t (0 if axis 0 is x)
  logic [I-1:0]      sp0_q;               // block share step: 1 or stride_0 * p
  logic [I-1:0]      gus_q, gu1s_q;       // gu, gu1 at partial beam 0
  logic [PipeBits-1:0] v_q, c0_q;         // beam-axis window phase, pipeline-0 phase

  // Traversal state.
  logic [D-1:0]      j_q, y_q, z_q;
  logic [2*PipeBits-1:0] ph_q;            // object coordinate mod p, permuted axes 1, 2
  logic [2*I-1:0]    g_q;                 // index share, permuted axes 1, 2
  logic [I-1:0]      gu_q, gu1_q;         // index share of blocks u and (u+1) mod B_0

  // ---------------------------------------------------------------------
  // Division of the dims by p, at start_i (shift/mask when p = 2^k).
  logic [3*D-1:0]        div_d;
  logic [3*PipeBits-1:0] mod_d;

  for (genvar a = 0; a < 3; a++) begin : g_divmod
    logic [D-1:0] nm1;
    assign nm1 = dim_i[a*D +: D] - D'(1);
    if (Pow2) begin : g_pow2
      assign div_d[a*D +: D]               = nm1 >> Log2P;
      assign mod_d[a*PipeBits +: PipeBits] = PipeBits'(nm1 & D'(NumPipes - 1));
    end else begin : g_div
      assign div_d[a*D +: D]               = nm1 / D'(NumPipes);
      assign mod_d[a*PipeBits +: PipeBits] = PipeBits'(nm1 % D'(NumPipes));
    end
  end

  // ---------------------------------------------------------------------
  // Per permuted axis i: object axis, its dims and index stride. Packed
  // vectors, slice i (yosys 0.23 has neither packed multi-dimensional arrays
  // nor warning-free unpacked wire arrays).
  logic [5:0]            ax;
  logic [2:0]            isx;
  logic [2:0]            flp;
  logic [3*D-1:0]        n_ax, div_ax;
  logic [3*PipeBits-1:0] mod_ax;
  logic [3*I-1:0]        stride;
  logic [D:0]            bx, by;          // B_x, B_y

  assign bx  = {1'b0, div_q[0 +: D]} + (D+1)'(1);
  assign by  = {1'b0, div_q[D +: D]} + (D+1)'(1);
  assign flp = flip_q;

  for (genvar i = 0; i < 3; i++) begin : g_axis
    logic [1:0] a;
    assign a                             = perm_q[2*i +: 2];
    assign ax[2*i +: 2]                  = a;
    assign isx[i]                        = a == 2'd0;
    assign n_ax[i*D +: D]                = n_q[a*D +: D];
    assign div_ax[i*D +: D]              = div_q[a*D +: D];
    assign mod_ax[i*PipeBits +: PipeBits] = mod_q[a*PipeBits +: PipeBits];
    // Object x contributes floor(x / p): its "stride" per block is 1.
    assign stride[i*I +: I] = (a == 2'd2) ? sz_q : (a == 2'd1) ? I'(bx) : I'(1);
  end

  // Named slices used below.
  logic [I-1:0]        stride0, stride1, stride2;
  logic [D-1:0]        n1, n2, div0;
  logic [PipeBits-1:0] mod0;
  assign stride0 = stride[0 +: I];
  assign stride1 = stride[I +: I];
  assign stride2 = stride[2*I +: I];
  assign n1      = n_ax[D +: D];
  assign n2      = n_ax[2*D +: D];
  assign div0    = div_ax[0 +: D];
  assign mod0    = mod_ax[0 +: PipeBits];

  // ---------------------------------------------------------------------
  // Setup: one shared multiplier, steps 0 .. 3; step 4 derives the rest.
  logic [I-1:0]       mul_a, prod;
  logic [MulBits-1:0] mul_b;

  always_comb begin
    unique case (step_q)
      3'd0:    begin mul_a = I'(bx);    mul_b = MulBits'(by) * MulBits'(NumPipes); end  // B_x * P_y
      3'd1:    begin mul_a = stride1;   mul_b = MulBits'(n1) - MulBits'(1);       end
      3'd2:    begin mul_a = stride2;   mul_b = MulBits'(n2) - MulBits'(1);       end
      default: begin
        // Block share of block B_0 - 1: (B_0 - 1) for x, stride * p * (B_0 - 1) else.
        mul_a = stride0;
        mul_b = isx[0] ? MulBits'(div0) : MulBits'(div0) * MulBits'(NumPipes);
      end
    endcase
  end
  assign prod = mul_a * I'(mul_b);

  // Step-4 constants.
  logic [I-1:0]        sp0_d, gus_d, gu1s_d;
  logic [P*I-1:0]      st_d;
  logic [PipeBits-1:0] v_d, c0_d;

  assign sp0_d = isx[0] ? I'(1) : stride0 * I'(NumPipes);
  for (genvar t = 0; t < P; t++) begin : g_st
    assign st_d[t*I +: I] = isx[0] ? '0 : stride0 * I'(t);
  end
  assign v_d    = !flp[0] ? '0 : (mod0 == PMax) ? '0 : mod0 + PipeBits'(1);
  assign c0_d   = flp[0] ? mod0 : '0;
  // Forwards: u = j. Backwards: u = (floor(n/p) - 1 - j) mod B_0, which starts
  // at B_0 - 1 if p divides n (or B_0 = 1), else at B_0 - 2.
  assign gus_d  = !flp[0] ? '0
                : (v_d == '0 || div0 == '0) ? gutop_q : gutop_q - sp0_d;
  assign gu1s_d = !flp[0] ? sp0_d : (v_d == '0) ? '0 : gutop_q;

  // Start values of the outer-axis walkers (slice w: permuted axis w+1).
  logic [2*PipeBits-1:0] phs;
  logic [2*I-1:0]        gst;
  for (genvar w = 0; w < 2; w++) begin : g_start
    assign phs[w*PipeBits +: PipeBits] = flp[w+1] ? mod_ax[(w+1)*PipeBits +: PipeBits] : '0;
    assign gst[w*I +: I] = !flp[w+1] ? '0
                         : isx[w+1] ? I'(div_ax[(w+1)*D +: D]) : gs_q[w*I +: I];
  end

  // ---------------------------------------------------------------------
  // Addresses of the current partial beam.
  logic [PipeBits-1:0] s_yz;
  logic [I-1:0]        base;
  logic [P*I-1:0]      index_d;
  logic [PipeBits-1:0] rotation_d;

  assign s_yz = add_mod(ph_q[0 +: PipeBits], ph_q[PipeBits +: PipeBits]);
  assign base = g_q[0 +: I] + g_q[I +: I];

  for (genvar m = 0; m < P; m++) begin : g_module
    logic [PipeBits-1:0] t;
    assign t = sub_mod(PipeBits'(m), s_yz);
    assign index_d[m*I +: I] = base + ((t < v_q) ? gu1_q : gu_q) + st_q[t*I +: I];
  end
  assign rotation_d = add_mod(c0_q, s_yz);

  // ---------------------------------------------------------------------
  // Traversal step.
  logic last_j, last_y, last_z;
  assign last_j     = j_q == div0;               // B_0 - 1
  assign last_y     = y_q == n1 - D'(1);
  assign last_z     = z_q == n2 - D'(1);
  assign issue      = (state_q == StRun) && advance_i;
  // A slice repeated (repeat_slice_i with its last partial beam) is walked
  // again from beam 0; the frame ends after the last slice's last walk.
  assign frame_last = last_j && last_y && last_z && !repeat_slice_i;

  // One +-1 step of an outer-axis walker (slice w: permuted axis w+1).
  logic [2*PipeBits-1:0] ph_step;
  logic [2*I-1:0]        g_step;
  for (genvar w = 0; w < 2; w++) begin : g_walk
    logic [PipeBits-1:0] ph;
    logic [I-1:0]        g, inc;
    logic                wrap, back;
    assign ph   = ph_q[w*PipeBits +: PipeBits];
    assign g    = g_q[w*I +: I];
    assign back = flp[w+1];
    assign wrap = back ? (ph == '0) : (ph == PMax);
    assign inc  = isx[w+1] ? I'(wrap) : stride[(w+1)*I +: I];
    assign ph_step[w*PipeBits +: PipeBits] = back ? (wrap ? PMax : ph - PipeBits'(1))
                                                  : (wrap ? '0   : ph + PipeBits'(1));
    assign g_step[w*I +: I] = back ? g - inc : g + inc;
  end

  always_comb begin
    state_d = state_q;
    step_d  = step_q;
    if (start_i) begin
      state_d = StSetup;
      step_d  = '0;
    end else if (state_q == StSetup) begin
      step_d = step_q + 3'd1;
      if (step_q == 3'd4) state_d = StRun;
    end else if (issue && frame_last && !again_i) begin
      state_d = StIdle;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= StIdle;
      step_q  <= '0;
    end else begin
      state_q <= state_d;
      step_q  <= step_d;
    end
  end

  // Datapath registers (not reset: written before use in every frame).
  always_ff @(posedge clk_i) begin
    if (start_i) begin
      perm_q <= perm_i;
      flip_q <= flip_i;
      n_q    <= dim_i;
      div_q  <= div_d;
      mod_q  <= mod_d;
    end
    if (state_q == StSetup) begin
      unique case (step_q)
        3'd0: sz_q              <= prod;
        3'd1: gs_q[0 +: I]      <= prod;
        3'd2: gs_q[I +: I]      <= prod;
        3'd3: gutop_q           <= prod;
        default: begin
          st_q   <= st_d;
          sp0_q  <= sp0_d;
          gus_q  <= gus_d;
          gu1s_q <= gu1s_d;
          v_q    <= v_d;
          c0_q   <= c0_d;
          j_q    <= '0;
          y_q    <= '0;
          z_q    <= '0;
          ph_q   <= phs;
          g_q    <= gst;
          gu_q   <= gus_d;
          gu1_q  <= gu1s_d;
        end
      endcase
    end
    if (issue) begin
      if (!last_j) begin
        j_q <= j_q + D'(1);
        if (!flp[0]) begin
          gu_q  <= gu_q + sp0_q;
          gu1_q <= gu1_q + sp0_q;
        end else if (gu_q == '0) begin  // block 0 -> block B_0 - 1
          gu_q  <= gutop_q;
          gu1_q <= '0;
        end else begin
          gu_q  <= gu_q - sp0_q;
          gu1_q <= gu_q;
        end
      end else begin
        j_q   <= '0;
        gu_q  <= gus_q;
        gu1_q <= gu1s_q;
        if (!last_y) begin
          y_q                 <= y_q + D'(1);
          ph_q[0 +: PipeBits] <= ph_step[0 +: PipeBits];
          g_q[0 +: I]         <= g_step[0 +: I];
        end else begin
          y_q                 <= '0;
          ph_q[0 +: PipeBits] <= phs[0 +: PipeBits];
          g_q[0 +: I]         <= gst[0 +: I];
          if (frame_last) begin  // again_i: the next frame from its start
            z_q                        <= '0;
            ph_q[PipeBits +: PipeBits] <= phs[PipeBits +: PipeBits];
            g_q[I +: I]                <= gst[I +: I];
          end else if (!repeat_slice_i) begin
            z_q                        <= z_q + D'(1);
            ph_q[PipeBits +: PipeBits] <= ph_step[PipeBits +: PipeBits];
            g_q[I +: I]                <= g_step[I +: I];
          end
        end
      end
    end
  end

  // ---------------------------------------------------------------------
  // Output registers.
  logic valid_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= 1'b0;
    end else begin
      valid_q <= issue && !start_i;
    end
  end

  logic [P*I-1:0]      index_q;
  logic [PipeBits-1:0] rotation_q;
  logic                reverse_q, last_q;
  logic [D-1:0]        beam_q, y_out_q, z_out_q;
  always_ff @(posedge clk_i) begin
    if (issue) begin
      index_q    <= index_d;
      rotation_q <= rotation_d;
      reverse_q  <= flp[0];
      beam_q     <= j_q;
      y_out_q    <= y_q;
      z_out_q    <= z_q;
      last_q     <= frame_last;
    end
  end

  assign busy_o     = state_q != StIdle;
  assign valid_o    = valid_q;
  assign index_o    = index_q;
  assign rotation_o = rotation_q;
  assign reverse_o  = reverse_q;
  assign beam_o     = beam_q;
  assign y_o        = y_out_q;
  assign z_o        = z_out_q;
  assign last_o     = last_q;

  // The beam axis's n is only needed as B_0 - 1 (div0); ax is for waveforms.
  logic unused_axis;
  assign unused_axis = ^{n_ax[0 +: D], ax};

endmodule
