// cube4_persp_slice: the perspective weight generator's per-slice
// divisions, part of cube4_dda (the weight generator of both projections).
//
// Function: from sample slice k's positions, which cube4_dda's walks hold
// (the rays' spacing m and ray 0's position c, x and y, on slices k - 1, k
// and k + 1), computes the rest of what every sample of the slice shares
// (golden perspective_slice(), golden/perspective.hpp;
// docs/perspective.md): the rays inside the volume per axis (two ceiling
// divisions each), the box filter's reciprocal round(2^Q / E^2), the
// gradient's lateral reciprocal round(2^(R+F) / m_k), and the four
// realignment DDAs of the points straight behind and ahead (floor
// divisions by the neighbouring slices' spacings; zero without the
// neighbour: the first and the last slice). Bit-exact with the golden
// function.
//
// The twelve divisions share one serial restoring divider, one quotient
// bit per cycle (a load, DivBits steps and a store per division), meant to
// compute slice k + 1's constants while slice k streams: at the default
// widths a slice's constants take 841 cycles, and a slice of nx * ny / p
// voxel cycles lasts that long from 64 x 64 voxels at p = 4 (smaller
// slices would wait for it). The divisions are per-slice work, so a divider
// per division would buy area and nothing else.
//
// Latency: done_o is high for one cycle, 1 + 12 * (DivBits + 2) clock
// edges after the edge that samples start_i (DivBits = PosBits + FracBits;
// 841 at the defaults, tested); the results hold until the next start_i.
// The positions are read from the cycle after start_i until done_o and
// must hold meanwhile. start_i while busy_o is high starts over (the
// weight generator moved to another slice).
//
// Precondition: the slice's ray spacing m_k lies in [1, 4) (the camera
// refuses spacings above 3); its box extent then has WeightBits + 2 bits.
//
// Parameters:
//   FracBits   - DDA fraction bits (golden Precision::dda_frac_bits)
//   WeightBits - box weights' fraction (cube4_pkg::WeightBits)
//   VoxelBits  - sample width, which sets both reciprocals' precision
//   PosBits    - DDA registers and positions, signed (48)
//   DimBits    - volume size per axis (cube4_pkg::DimBits)
`include "cube4_pkg.sv"

module cube4_persp_slice #(
  parameter int unsigned FracBits   = cube4_pkg::FracBits,
  parameter int unsigned WeightBits = cube4_pkg::WeightBits,
  parameter int unsigned VoxelBits  = cube4_pkg::VoxelBits,
  parameter int unsigned PosBits    = 48,
  parameter int unsigned DimBits    = cube4_pkg::DimBits
) (
  input  logic                        clk_i,
  input  logic                        rst_ni,
  // Slice k's neighbourhood, from cube4_dda's walks (behind: k - 1,
  // ahead: k + 1; whether they are slices of the frame).
  input  logic signed [PosBits-1:0]   spacing_behind_i,
  input  logic signed [PosBits-1:0]   spacing_i,
  input  logic signed [PosBits-1:0]   spacing_ahead_i,
  input  logic signed [PosBits-1:0]   ray0_x_behind_i,
  input  logic signed [PosBits-1:0]   ray0_x_i,
  input  logic signed [PosBits-1:0]   ray0_x_ahead_i,
  input  logic signed [PosBits-1:0]   ray0_y_behind_i,
  input  logic signed [PosBits-1:0]   ray0_y_i,
  input  logic signed [PosBits-1:0]   ray0_y_ahead_i,
  input  logic                        has_behind_i,
  input  logic                        has_ahead_i,
  input  logic [DimBits-1:0]          dim_x_i,
  input  logic [DimBits-1:0]          dim_y_i,
  // Command.
  input  logic                        start_i,
  output logic                        busy_o,
  output logic                        done_o,
  // Slice k's constants.
  output logic signed [PosBits-1:0]   rays_x_lo_o,
  output logic signed [PosBits-1:0]   rays_x_hi_o,
  output logic signed [PosBits-1:0]   rays_y_lo_o,
  output logic signed [PosBits-1:0]   rays_y_hi_o,
  output logic [PosBits-1:0]          box_recip_o,
  output logic [PosBits-1:0]          lateral_recip_o,
  output logic signed [PosBits-1:0]   behind_start_x_o,
  output logic signed [PosBits-1:0]   behind_start_y_o,
  output logic signed [PosBits-1:0]   behind_step_o,
  output logic signed [PosBits-1:0]   ahead_start_x_o,
  output logic signed [PosBits-1:0]   ahead_start_y_o,
  output logic signed [PosBits-1:0]   ahead_step_o
);

  // golden box_recip_bits() and lateral_recip_bits().
  localparam int unsigned RecipQ = VoxelBits + 2 * WeightBits + 5;
  localparam int unsigned RecipR = VoxelBits + 2;
  // The widest dividend is a position difference or spacing shifted left
  // by FracBits; 2^(R+F) and 2^Q fit as well (checked below).
  localparam int unsigned DivBits = PosBits + FracBits;
  localparam int unsigned DivW    = DivBits + 1;  // dividends, signed
  localparam int unsigned Jobs    = 12;
  localparam int unsigned CountBits = $clog2(DivBits + 1);

  typedef enum logic [1:0] { RoundTrunc, RoundFloor, RoundCeil } round_e;

  logic signed [PosBits-1:0] m_here, m_behind, m_ahead;
  logic signed [PosBits-1:0] cx_here, cx_behind, cx_ahead, cy_here, cy_behind, cy_ahead;
  logic has_behind, has_ahead;
  assign m_here     = spacing_i;
  assign m_behind   = spacing_behind_i;
  assign m_ahead    = spacing_ahead_i;
  assign cx_here    = ray0_x_i;
  assign cx_behind  = ray0_x_behind_i;
  assign cx_ahead   = ray0_x_ahead_i;
  assign cy_here    = ray0_y_i;
  assign cy_behind  = ray0_y_behind_i;
  assign cy_ahead   = ray0_y_ahead_i;
  assign has_behind = has_behind_i;
  assign has_ahead  = has_ahead_i;

  // The box extent E = m >> (F - W) and its square. The ray spacing is
  // below 4 (the camera allows at most 3: the box filter's four taps), so
  // E has WeightBits + 2 bits and E^2 twice that: a small multiplier, not
  // a PosBits-square one.
  localparam int unsigned ExtentBits = WeightBits + 2;
  logic [ExtentBits-1:0]   extent;
  logic [2*ExtentBits-1:0] area;
  assign extent = m_here[FracBits-WeightBits +: ExtentBits];
  assign area   = extent * extent;

  logic signed [PosBits-1:0] m_half;
  assign m_half = m_here >>> 1;

  // ---- The job table: dividend (signed), divisor (positive), rounding.
  logic [3:0]                  job_q;
  logic signed [DivBits:0]     dividend;
  logic [PosBits-1:0]          divisor;
  round_e                      rounding;
  logic                        job_valid;  // a realignment job of a missing neighbour gives 0

  function automatic logic signed [DivBits:0] shifted(input logic signed [PosBits-1:0] v);
    shifted = DivW'(v) <<< FracBits;
  endfunction

  always_comb begin
    dividend  = '0;
    divisor   = PosBits'(m_here);
    rounding  = RoundCeil;
    job_valid = 1'b1;
    unique case (job_q)
      4'd0: dividend = -(DivW'(cx_here));
      4'd1: dividend = (DivW'($signed({1'b0, dim_x_i})) <<< FracBits) - DivW'(cx_here);
      4'd2: dividend = -(DivW'(cy_here));
      4'd3: dividend = (DivW'($signed({1'b0, dim_y_i})) <<< FracBits) - DivW'(cy_here);
      4'd4: begin  // round(2^Q / E^2) = (2^Q + E^2 / 2) / E^2
        dividend = (DivW'(1) <<< RecipQ) + DivW'(area[2*ExtentBits-1:1]);
        divisor  = PosBits'(area);
        rounding = RoundTrunc;
      end
      4'd5: begin  // round(2^(R+F) / m) = (2^(R+F) + m / 2) / m
        dividend = (DivW'(1) <<< (RecipR + FracBits)) + DivW'(m_half);
        rounding = RoundTrunc;
      end
      4'd6: begin dividend = shifted(cx_here - cx_behind); divisor = PosBits'(m_behind); rounding = RoundFloor; job_valid = has_behind; end
      4'd7: begin dividend = shifted(cy_here - cy_behind); divisor = PosBits'(m_behind); rounding = RoundFloor; job_valid = has_behind; end
      4'd8: begin dividend = shifted(m_here);              divisor = PosBits'(m_behind); rounding = RoundFloor; job_valid = has_behind; end
      4'd9: begin dividend = shifted(cx_here - cx_ahead);  divisor = PosBits'(m_ahead);  rounding = RoundFloor; job_valid = has_ahead; end
      4'd10: begin dividend = shifted(cy_here - cy_ahead); divisor = PosBits'(m_ahead);  rounding = RoundFloor; job_valid = has_ahead; end
      4'd11: begin dividend = shifted(m_here);             divisor = PosBits'(m_ahead);  rounding = RoundFloor; job_valid = has_ahead; end
      default: ;
    endcase
  end

  // ---- The serial divider: |dividend| / divisor, restoring, MSB first.
  logic                      running_q;
  logic                      dividing_q;
  logic [CountBits-1:0]      count_q;
  logic [DivBits-1:0]        num_q;      // |dividend|, shifted out MSB first
  logic [DivBits-1:0]        quot_q;
  logic [PosBits:0]          rem_q;      // below the divisor before each shift
  logic                      neg_q;
  logic [PosBits:0]          rem_shifted;
  logic                      fits;

  assign rem_shifted = {rem_q[PosBits-1:0], num_q[DivBits-1]};
  assign fits        = rem_shifted >= {1'b0, divisor};

  // The rounded, signed quotient of the finished division.
  logic signed [PosBits-1:0] result;
  logic                      inexact;
  assign inexact = rem_q != '0;
  always_comb begin
    logic signed [PosBits-1:0] q;
    q = PosBits'($signed({1'b0, quot_q}));
    unique case (rounding)
      RoundCeil:  result = neg_q ? -q : q + PosBits'(inexact);
      RoundFloor: result = neg_q ? -(q + PosBits'(inexact)) : q;
      default:    result = q;
    endcase
    if (!job_valid) result = '0;
  end

  logic [DivBits:0] magnitude;
  assign magnitude = dividend[DivBits] ? -dividend : dividend;
  // Dividends stay far from -2^DivBits (positions and spacings are PosBits
  // wide, shifted by FracBits), so a magnitude never needs the sign bit.
  logic unused_magnitude_sign;
  assign unused_magnitude_sign = magnitude[DivBits];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      running_q  <= 1'b0;
      dividing_q <= 1'b0;
      done_o     <= 1'b0;
      job_q      <= '0;
      count_q    <= '0;
      num_q      <= '0;
      quot_q     <= '0;
      rem_q      <= '0;
      neg_q      <= 1'b0;
    end else begin
      done_o <= 1'b0;
      if (start_i) begin
        running_q  <= 1'b1;
        dividing_q <= 1'b0;
        job_q      <= '0;
      end else if (!running_q) begin
        // idle
      end else if (!dividing_q) begin
        // Load the job's operands.
        num_q      <= magnitude[DivBits-1:0];
        neg_q      <= dividend[DivBits];
        quot_q     <= '0;
        rem_q      <= '0;
        count_q    <= CountBits'(DivBits);
        dividing_q <= 1'b1;
      end else if (count_q != '0) begin
        rem_q   <= fits ? rem_shifted - {1'b0, divisor} : rem_shifted;
        quot_q  <= {quot_q[DivBits-2:0], fits};
        num_q   <= num_q << 1;
        count_q <= count_q - 1'b1;
      end else begin
        dividing_q <= 1'b0;
        if (job_q == 4'(Jobs - 1)) begin
          running_q <= 1'b0;
          done_o    <= 1'b1;
        end
        job_q <= job_q + 1'b1;
      end
    end
  end

  // Results, stored as each job finishes.
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rays_x_lo_o <= '0; rays_x_hi_o <= '0; rays_y_lo_o <= '0; rays_y_hi_o <= '0;
      box_recip_o <= '0; lateral_recip_o <= '0;
      behind_start_x_o <= '0; behind_start_y_o <= '0; behind_step_o <= '0;
      ahead_start_x_o <= '0; ahead_start_y_o <= '0; ahead_step_o <= '0;
    end else if (running_q && dividing_q && count_q == '0 && !start_i) begin
      unique case (job_q)
        4'd0: rays_x_lo_o <= result;
        4'd1: rays_x_hi_o <= result;
        4'd2: rays_y_lo_o <= result;
        4'd3: rays_y_hi_o <= result;
        4'd4: box_recip_o <= result;
        4'd5: lateral_recip_o <= result;
        4'd6: behind_start_x_o <= result;
        4'd7: behind_start_y_o <= result;
        4'd8: behind_step_o <= result;
        4'd9: ahead_start_x_o <= result;
        4'd10: ahead_start_y_o <= result;
        4'd11: ahead_step_o <= result;
        default: ;
      endcase
    end
  end

  assign busy_o = running_q;

  // The reciprocals' dividends fit: 2^Q and 2^(R+F) are below 2^DivBits
  // for every width the golden model allows (Q <= 49, R + F <= 48, DivBits
  // = PosBits + FracBits >= 50).

endmodule
