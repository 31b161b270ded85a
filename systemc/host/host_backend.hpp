// What the host interface needs from the rest of the system model: a voxel
// memory to load, a frame to start, status to report and a pixel memory to
// read. The system model implements it; tests implement it with a golden
// renderer or a recorder. Kept this small so that the interface knows
// nothing of pipelines, memories or levels.
#pragma once
#include <array>
#include <cstdint>

#include "golden/registers.hpp"

namespace cube4::sysc {

struct HostBackend {
  virtual ~HostBackend() = default;
  // A new volume of nx*ny*nz voxels (object order, 1..max_dim each). Called
  // before the first voxel write or START after VOL_DIM changed.
  virtual void set_volume_dims(int nx, int ny, int nz) = 0;
  // One voxel at object coordinates, value < 2^voxel_bits. Never while busy().
  virtual void write_voxel(int x, int y, int z, uint16_t v) = 0;
  // Runs, or schedules, one frame with these register values (a copy: the
  // register file may be rewritten while the frame runs). Never while
  // busy(). May throw std::exception to refuse the frame (GENERIC_ERROR).
  virtual void start_frame(const golden::Registers& regs) = 0;
  virtual bool busy() const = 0;
  virtual uint64_t frames_done() const = 0;
  virtual uint64_t last_frame_cycles() const = 0;
  // The last frame's base plane (0 x 0 before the first frame).
  virtual int base_width() const = 0;
  virtual int base_height() const = 0;
  virtual std::array<uint16_t, 4> read_pixel(int u, int v) const = 0;  // premultiplied RGBA
};

}  // namespace cube4::sysc
