// cube4_slice_store: the interpolation units' slice store (VolumePro §3.1;
// docs/rtl-interp.md): one entry per voxel step of a pass, in stream order.
// A pass whose sample slice lies on a voxel slice (wz = 0, on_slice_i)
// streams that slice and writes it; the passes after it with wz > 0 stream
// the slice above and read it back, entry by entry, in the same order. The
// pass's last step ends the lap, so every pass starts at entry 0; flush
// beams carry no voxels and do not step it. cube4_interp_unit and
// cube4_interp_persp_column keep their slice z_voxel here.
//
// Function: rdata_o is, in each step, the wdata_i of the same step of the
// last pass that wrote (cube4_delay_ram with laps ended by pass_last_i).
// Latency: rdata_o is valid in the step's own cycle. Reset: the pointer.
//
// Parameters:
//   Width      - entry width (a voxel word, or more: cube4_interp_unit's
//                VolumePro z-gradient entry holds three slices)
//   SliceDepth - entries: the largest pass (ny * partial beams)
`include "cube4_pkg.sv"

module cube4_slice_store #(
  parameter int unsigned Width      = 12,
  parameter int unsigned SliceDepth = 16384
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             valid_i,
  input  logic             flush_i,
  input  logic             pass_last_i,  // the pass's last step
  input  logic             on_slice_i,   // the pass writes (wz = 0)
  input  logic [Width-1:0] wdata_i,
  output logic [Width-1:0] rdata_o
);

  localparam int unsigned DepthBits = $clog2(SliceDepth + 1);

  cube4_delay_ram #(
    .Width   (Width),
    .MaxDepth(SliceDepth)
  ) u_store (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .depth_i  (DepthBits'(SliceDepth)),
    .clear_i  (1'b0),
    .advance_i(valid_i && !flush_i),
    .last_i   (pass_last_i),
    .write_i  (on_slice_i),
    .wdata_i  (wdata_i),
    .rdata_o  (rdata_o)
  );

endmodule
