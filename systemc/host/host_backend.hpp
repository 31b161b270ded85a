// What the host interface needs from the rest of the system model: a voxel
// memory to load, a frame to start, status to report and a pixel memory to
// read. The system model implements it; tests implement it with a golden
// renderer or a recorder. Kept this small so that the interface knows
// nothing of pipelines, memories or levels.
#pragma once
#include <array>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "golden/polygon_frame.hpp"
#include "golden/registers.hpp"
#include "golden/volume.hpp"
#include "systemc/host/register_map.hpp"

namespace cube4::sysc {

struct HostBackend {
  virtual ~HostBackend() = default;
  // Subvolume k (0 .. regmap::kSubvolumes - 1) becomes a volume of
  // nx*ny*nz voxels (object order, 1..max_dim each), all zero; the other
  // subvolumes keep theirs. Called before the first voxel access of k or a
  // START that renders k after its VOL_DIM changed.
  virtual void set_volume_dims(int k, int nx, int ny, int nz) = 0;
  // One voxel memory word of subvolume k at object coordinates: {tag,
  // value}, the tag above voxel_bits, < 2^(voxel_bits + tag_bits).
  // Never while busy().
  virtual void write_voxel(int k, int x, int y, int z, uint16_t v) = 0;
  // Voxels first .. first + count - 1 of subvolume k (object order, x
  // fastest; dims nx, ny), two 16-bit words per 32-bit word, low half first:
  // the VOLUME window's burst, already checked. By default write_voxel() per
  // voxel; a backend that stores the volume in object order does better.
  virtual void write_voxels(int k, uint64_t first, uint64_t count, const uint32_t* words, int nx, int ny) {
    int x = static_cast<int>(first % nx), y = static_cast<int>(first / nx % ny),
        z = static_cast<int>(first / nx / ny);
    for (uint64_t i = 0; i < count; ++i) {
      write_voxel(k, x, y, z, static_cast<uint16_t>(words[i / 2] >> (16 * (i % 2))));
      if (++x == nx) {
        x = 0;
        if (++y == ny) {
          y = 0;
          ++z;
        }
      }
    }
  }
  // Subvolume k (its dims already set) takes vol's voxels, checked to fit:
  // by default a copy through write_voxels(). A backend that can use the
  // host's buffer in place (until the frame ends or a voxel is written) does
  // better: HostInterface::map_volume.
  virtual void map_volume(int k, const golden::Volume& vol) {
    const uint64_t n = vol.data.size();
    std::vector<uint32_t> words(std::min<uint64_t>(n, uint64_t{1} << 20) / 2 + 1);
    for (uint64_t first = 0; first < n; first += 2 * (words.size() - 1)) {
      const uint64_t count = std::min<uint64_t>(n - first, 2 * (words.size() - 1));
      for (uint64_t i = 0; i < count; ++i) {
        const uint32_t w = regmap::voxel_word(vol, first + i);
        words[i / 2] = i % 2 ? words[i / 2] | w << 16 : w;
      }
      write_voxels(k, first, count, words.data(), vol.dim[0], vol.dim[1]);
    }
  }
  // Ends a map_volume(): subvolume k reads as cleared (as after a new VOL_DIM)
  // unless a write had made it the backend's own copy.
  virtual void unmap_volume(int /*k*/) {}
  virtual uint16_t read_voxel(int k, int x, int y, int z) const = 0;
  // Runs, or schedules, one frame of subvolume k with these register values
  // (a copy: the register file may be rewritten while the frame runs) and
  // these polygon images (Cube-5; nullptr: none), which live only for the
  // call: a backend that needs them later keeps a copy.
  // Never while busy(). May throw std::exception to refuse the frame
  // (GENERIC_ERROR).
  virtual void start_frame(const golden::Registers& regs, int k, const golden::PolygonFrame* polygons) = 0;
  virtual bool busy() const = 0;
  virtual uint64_t frames_done() const = 0;
  virtual uint64_t last_frame_cycles() const = 0;
  // The last frame's base plane (0 x 0 before the first frame).
  virtual int base_width() const = 0;
  virtual int base_height() const = 0;
  virtual std::array<uint16_t, 4> read_pixel(int u, int v) const = 0;  // premultiplied RGBA
};

}  // namespace cube4::sysc
