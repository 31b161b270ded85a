// The fixed-point renderer's work on one sample slice, in the pieces the
// units do it in: interpolation of a slice, the gradient neighbourhood of a
// sample, ray alignment and compositing of a slice, and the rays that leave.
// render_fixed() is a loop over these; the system model's transaction-level
// units call the same pieces (systemc/tlm/), so there is one copy of each.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "golden/permuted_volume.hpp"
#include "golden/pipeline.hpp"
#include "golden/renderers.hpp"

namespace cube4::golden {

// A slice with a border of zeros: `pad` columns/rows before and after, so
// neighbours of edge samples read zero (the volume is surrounded by zeros).
struct Plane {
  int nx = 0, ny = 0, pad = 0, pitch = 0;
  std::vector<int32_t> v;
  Plane() = default;
  Plane(int nx_, int ny_, int pad_) : nx(nx_), ny(ny_), pad(pad_), pitch(nx_ + 2 * pad_),
      v(static_cast<size_t>(nx_ + 2 * pad_) * (ny_ + 2 * pad_), 0) {}
  int32_t* row(int y) { return &v[static_cast<size_t>(y + pad) * pitch + pad]; }
  const int32_t* row(int y) const { return &v[static_cast<size_t>(y + pad) * pitch + pad]; }
  uint32_t at(int x, int y) const { return static_cast<uint32_t>(row(y)[x]); }
  void clear() { std::fill(v.begin(), v.end(), 0); }
};

void load_voxel_slice(const PermutedVolume& pv, int z, Plane& out);

// Interpolation unit over a whole sample slice: trilinear() for every
// sample, computed stage by stage across the slice (x lerps of each voxel
// row once, then y, then z) with the same lerp, so the values are those of
// trilinear() on each sample's eight voxels (tested). A stage whose weight
// is zero returns its first operand exactly, so it is not computed.
// lo, hi: voxel slices z_voxel and z_voxel + 1 with a border of at least 1.
class SliceInterp {
 public:
  SliceInterp(int nx, int ny, int weight_bits);
  void slice(const Plane& lo, const Plane& hi, const SliceControl& c, Plane& out);

 private:
  void bilinear(const Plane& v, int32_t wx, int32_t wy, std::vector<int32_t>& out);
  int nx_, ny_, w_;
  std::vector<int32_t> tx_, ty_lo_, ty_hi_;
};

// The 12-neighbourhood of sample (x, y) of slice c.k from the sample slices
// behind, current and ahead (borders of at least 1).
inline void gather_neighbourhood(const Plane& behind, const Plane& current, const Plane& ahead,
                                 const SliceControl& c, int x, int y, Neighbourhood& n) {
  auto gather_2x2 = [x, y](const Plane& s, const Realign& rx, const Realign& ry, std::array<uint32_t, 4>& out) {
    const int bx = x + rx.base, by = y + ry.base;
    out = {s.at(bx, by), s.at(bx + 1, by), s.at(bx, by + 1), s.at(bx + 1, by + 1)};
  };
  n.centre = current.at(x, y);
  n.left = current.at(x - 1, y);
  n.right = current.at(x + 1, y);
  n.up = current.at(x, y - 1);
  n.down = current.at(x, y + 1);
  gather_2x2(behind, c.behind_x, c.behind_y, n.behind);
  gather_2x2(ahead, c.ahead_x, c.ahead_y, n.ahead);
}

inline void write_pixel(BasePlane& bp, int u, int v, const Pixel& a) {
  uint16_t* px = &bp.rgba[(static_cast<size_t>(v) * bp.width + u) * 4];
  px[0] = a.r; px[1] = a.g; px[2] = a.b; px[3] = a.a;
}

// The compositing unit over whole slices: the ray store of the previous
// slice, ray alignment, blending, and the base-plane pixels of the rays
// that leave. Per slice, `shade(x, y, ray, out)` supplies the cropped and
// cut sample of (x, y) and returns false if it leaves `ray` exactly as it
// is (then `out` is not used), and `beam_may_change(y)` may return false
// for a beam none of whose samples changes its ray.
class SliceCompositor {
 public:
  SliceCompositor(const Registers& r, BasePlane& bp)
      : r_(r), bp_(bp), nx_(r.dim[0]), ny_(r.dim[1]), K_(r.sample_slices()),
        ix_last_(r.x_offset(K_ - 1).integer), iy_last_(r.y_offset(K_ - 1).integer),
        prev_(static_cast<size_t>(nx_) * ny_), cur_(prev_.size()) {}

  template <class Shade, class BeamMayChange>
  void slice(const SliceControl& c, Shade&& shade, BeamMayChange&& beam_may_change) {
    for (int y = 0; y < ny_; ++y) {
      RayAcc* out_row = &cur_[static_cast<size_t>(y) * nx_];
      // ray_predecessor() is the same for the whole beam from x = dx on.
      const Predecessor from = ray_predecessor(c.dx, y, c.dx, c.dy);
      if (!from.exists) {
        std::fill(out_row, out_row + nx_, RayAcc{});
      } else {
        const RayAcc* in_row = &prev_[static_cast<size_t>(from.y) * nx_ + from.x];
        std::fill(out_row, out_row + c.dx, RayAcc{});
        std::copy(in_row, in_row + nx_ - c.dx, out_row + c.dx);
      }
      if (!beam_may_change(y)) continue;
      ShadedSample s;
      for (int x = 0; x < nx_; ++x) {
        RayAcc& ray = out_row[x];
        if (shade(x, y, ray, s)) ray = blend(r_.blend, ray, s, r_.p);
      }
    }
    // Rays of slice k-1 with no successor in slice k left through a side
    // face; only the last dy beams and the last dx rays of a beam can.
    if (c.k > 0 && (c.dx | c.dy)) {
      const SliceControl pc = slice_control(r_, c.k - 1);
      for (int y = 0; y < ny_; ++y)
        for (int x = y >= ny_ - c.dy ? 0 : nx_ - c.dx; x < nx_; ++x)
          if (ray_leaves(x, y, c.dx, c.dy, nx_, ny_))
            write_pixel(bp_, x - pc.ix + ix_last_, y - pc.iy + iy_last_,
                        pixel_of(prev_[static_cast<size_t>(y) * nx_ + x], r_.p));
    }
    std::swap(prev_, cur_);
  }

  // After the last slice: the rays still inside leave through the back face.
  void finish() {
    const SliceControl last = slice_control(r_, K_ - 1);
    for (int y = 0; y < ny_; ++y)
      for (int x = 0; x < nx_; ++x)
        write_pixel(bp_, x - last.ix + ix_last_, y - last.iy + iy_last_,
                    pixel_of(prev_[static_cast<size_t>(y) * nx_ + x], r_.p));
  }

 private:
  const Registers& r_;
  BasePlane& bp_;
  int nx_, ny_, K_, ix_last_, iy_last_;
  std::vector<RayAcc> prev_, cur_;
};

// An empty base plane of the frame's size, with the warp's shift.
BasePlane empty_base_plane(const Registers& r);

}  // namespace cube4::golden
