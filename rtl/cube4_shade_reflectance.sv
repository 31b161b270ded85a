// cube4_shade_reflectance: reflectance-map look-up, bit-exact with golden
// reflectance_lookup() (golden/units/shade_cube_map.hpp): the bilinear
// interpolation bilerp(m(u,v), m(u+1,v), m(u,v+1), m(u+1,v+1), wu, wv) of
// four map entries of face `face`, and 0 for an invalid coordinate (the zero
// vector). bilerp = lerp(lerp(m00, m10, wu), lerp(m01, m11, wu), wv) with
// lerp(a, b, w) = a + round_shift((b - a) * w, WeightBits) (golden
// interp.hpp): three cube4_lerp, the interpolation's lerp.
//
// The map: 6 * MapFaceRes^2 entries of MapBits, written by the host through
// a write port addressed like golden map_index() ((face*res + v)*res + u).
// Four entries per clock are read from four banks, bank b = (u mod 2) +
// 2*(v mod 2): the 2x2 neighbourhood (u..u+1, v..v+1) has exactly one entry
// in each bank. Bank address = (face*H + (v' >> 1))*H + (u' >> 1),
// H = ceil(MapFaceRes/2), where u' is u or u+1, whichever has the bank's
// parity. Each bank: 6*H^2 words, one write and one synchronous read port
// (for MapFaceRes = 8: 4 x 96 x 16 bits = 6144 bits, no waste). A write and
// a read of the same entry in one cycle returns the old entry. The map is a
// frame register: write it only while no look-up is in flight.
//
// Latency: 3 cycles (1: bank read, 2: the two lerps in u, 3: the lerp in v).
// Fully pipelined, one look-up per clock. Handshake: valid-only; valid_i
// travels with the data to valid_o. Only the valid registers are reset.
//
// Parameters (defaults = golden Precision): WeightBits, MapFaceRes, MapBits.
`include "cube4_pkg.sv"

module cube4_shade_reflectance #(
  parameter int unsigned WeightBits = cube4_pkg::WeightBits,
  parameter int unsigned MapFaceRes = cube4_pkg::MapFaceRes,
  parameter int unsigned MapBits    = cube4_pkg::MapBits
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  // Host write port: map_index() address.
  input  logic                                  we_i,
  input  logic [$clog2(6*MapFaceRes*MapFaceRes)-1:0] waddr_i,
  input  logic [MapBits-1:0]                    wdata_i,
  // Look-up stream: a golden CubeCoord.
  input  logic                                  valid_i,
  input  logic                                  coord_valid_i,
  input  logic [2:0]                            face_i,
  input  logic [$clog2(MapFaceRes)-1:0]         u_i,
  input  logic [$clog2(MapFaceRes)-1:0]         v_i,
  input  logic [WeightBits:0]                   wu_i,
  input  logic [WeightBits:0]                   wv_i,
  output logic                                  valid_o,
  output logic [MapBits-1:0]                    value_o
);

  localparam int unsigned Res       = MapFaceRes;
  localparam int unsigned CellBits  = $clog2(Res);
  localparam int unsigned AddrBits  = $clog2(6 * Res * Res);
  localparam int unsigned Half      = (Res + 1) / 2;
  localparam int unsigned BankDepth = 6 * Half * Half;
  localparam int unsigned BankBits  = $clog2(BankDepth);

  //////////////////////////
  // Write-address decode //
  //////////////////////////
  logic [2:0]          wface;
  logic [CellBits-1:0] wu, wv;
  if (Res == (1 << CellBits)) begin : g_waddr_pow2
    assign wu    = waddr_i[CellBits-1:0];
    assign wv    = waddr_i[2*CellBits-1:CellBits];
    assign wface = 3'(waddr_i[AddrBits-1:2*CellBits]);
  end else begin : g_waddr_div
    assign wu    = CellBits'(waddr_i % AddrBits'(Res));
    assign wv    = CellBits'((waddr_i / AddrBits'(Res)) % AddrBits'(Res));
    assign wface = 3'(waddr_i / AddrBits'(Res * Res));
  end

  logic [CellBits-1:0] wu_half, wv_half;
  assign wu_half = wu >> 1;
  assign wv_half = wv >> 1;

  logic [BankBits-1:0] wbank_addr;
  assign wbank_addr = (BankBits'(wface) * BankBits'(Half) + BankBits'(wv_half)) * BankBits'(Half)
                    + BankBits'(wu_half);

  /////////////////////////////
  // Stage 1: four bank reads //
  /////////////////////////////
  // Bank b = pu + 2*pv reads column (u >> 1) + (u odd and pu = 0), row alike.
  logic [4*MapBits-1:0] bank_rdata;

  for (genvar b = 0; b < 4; b++) begin : g_bank
    localparam logic Pu = 1'(b % 2);
    localparam logic Pv = 1'(b / 2);

    logic                u_next, v_next;
    logic [CellBits-1:0] col, row;
    assign u_next = u_i[0] & ~Pu;
    assign v_next = v_i[0] & ~Pv;
    assign col    = (u_i >> 1) + CellBits'(u_next);
    assign row    = (v_i >> 1) + CellBits'(v_next);

    logic [BankBits-1:0] raddr;
    assign raddr = (BankBits'(face_i) * BankBits'(Half) + BankBits'(row)) * BankBits'(Half)
                 + BankBits'(col);

    logic [MapBits-1:0] mem [BankDepth];
    logic [MapBits-1:0] rdata_q;

    always_ff @(posedge clk_i) begin : bank_write
      if (we_i && wu[0] == Pu && wv[0] == Pv) mem[wbank_addr] <= wdata_i;
    end

    always_ff @(posedge clk_i) begin : bank_read
      rdata_q <= mem[raddr];
    end

    assign bank_rdata[b*MapBits +: MapBits] = rdata_q;
  end

  logic                u_odd_q, v_odd_q, coord_valid_q;
  logic [WeightBits:0] wu_q, wv_q;
  always_ff @(posedge clk_i) begin : stage1_regs
    u_odd_q       <= u_i[0];
    v_odd_q       <= v_i[0];
    coord_valid_q <= coord_valid_i;
    wu_q          <= wu_i;
    wv_q          <= wv_i;
  end

  ////////////////////////////////////
  // Stage 2: un-rotate, lerps in u //
  ////////////////////////////////////
  // Entry (u+du, v+dv) sits in bank ((u+du) mod 2) + 2*((v+dv) mod 2).
  logic [MapBits-1:0] m00, m10, m01, m11;
  logic [1:0]         b00, b10, b01, b11;
  assign b00 = {v_odd_q, u_odd_q};
  assign b10 = {v_odd_q, ~u_odd_q};
  assign b01 = {~v_odd_q, u_odd_q};
  assign b11 = {~v_odd_q, ~u_odd_q};
  assign m00 = bank_rdata[b00*MapBits +: MapBits];
  assign m10 = bank_rdata[b10*MapBits +: MapBits];
  assign m01 = bank_rdata[b01*MapBits +: MapBits];
  assign m11 = bank_rdata[b11*MapBits +: MapBits];

  // The interpolation's lerp (cube4_lerp, golden lerp()) on map entries.
  logic [MapBits-1:0]  lo, hi;
  cube4_lerp #(.VoxelBits(MapBits), .WeightBits(WeightBits)) u_lerp_lo (
    .a_i(m00), .b_i(m10), .w_i(wu_q), .y_o(lo));
  cube4_lerp #(.VoxelBits(MapBits), .WeightBits(WeightBits)) u_lerp_hi (
    .a_i(m01), .b_i(m11), .w_i(wu_q), .y_o(hi));

  logic [MapBits-1:0]  lo_q, hi_q;
  logic                coord_valid_qq;
  logic [WeightBits:0] wv_qq;
  always_ff @(posedge clk_i) begin : stage2_regs
    lo_q           <= lo;
    hi_q           <= hi;
    coord_valid_qq <= coord_valid_q;
    wv_qq          <= wv_q;
  end

  ///////////////////////////
  // Stage 3: lerp in v    //
  ///////////////////////////
  logic [MapBits-1:0] value;
  cube4_lerp #(.VoxelBits(MapBits), .WeightBits(WeightBits)) u_lerp_v (
    .a_i(lo_q), .b_i(hi_q), .w_i(wv_qq), .y_o(value));

  always_ff @(posedge clk_i) begin : stage3_regs
    value_o <= coord_valid_qq ? value : '0;
  end

  logic [2:0] valid_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin : valid_regs
    if (!rst_ni) begin
      valid_q <= '0;
    end else begin
      valid_q <= {valid_q[1:0], valid_i};
    end
  end
  assign valid_o = valid_q[2];

endmodule
