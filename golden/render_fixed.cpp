// The bit-exact fixed-point renderer: the hardware's traversal (slice by
// slice, beam by beam, in permuted order) built only from the unit functions.
#include <algorithm>
#include <cmath>
#include <vector>

#include "golden/pipeline.hpp"
#include "golden/renderers.hpp"

namespace cube4::golden {
namespace {

// Address generation, functionally: permuted (x, y, z) -> voxel memory offset.
struct PermutedAccess {
  int64_t origin = 0;
  int64_t stride[3] = {0, 0, 0};
  PermutedAccess(const Volume& v, const Registers& r) {
    const int64_t object_stride[3] = {1, v.dim[0], int64_t{v.dim[0]} * v.dim[1]};
    for (int i = 0; i < 3; ++i) {
      stride[i] = object_stride[r.perm[i]] * (r.flip[i] ? -1 : 1);
      if (r.flip[i]) origin += (r.dim[i] - 1) * object_stride[r.perm[i]];
    }
  }
};

// A slice with a border of zeros: `pad` columns/rows before and after, so
// neighbours of edge samples read zero (the volume is surrounded by zeros).
struct Plane {
  int nx = 0, ny = 0, pad = 0, pitch = 0;
  std::vector<uint32_t> v;
  Plane(int nx_, int ny_, int pad_) : nx(nx_), ny(ny_), pad(pad_), pitch(nx_ + 2 * pad_),
      v(static_cast<size_t>(nx_ + 2 * pad_) * (ny_ + 2 * pad_), 0) {}
  uint32_t* row(int y) { return &v[static_cast<size_t>(y + pad) * pitch + pad]; }
  const uint32_t* row(int y) const { return &v[static_cast<size_t>(y + pad) * pitch + pad]; }
  uint32_t at(int x, int y) const { return row(y)[x]; }
  void clear() { std::fill(v.begin(), v.end(), 0u); }
};

void load_voxel_slice(const Volume& vol, const Registers& r, const PermutedAccess& a, int z, Plane& out) {
  if (z >= r.dim[2]) { out.clear(); return; }
  const uint16_t* base = vol.data.data() + a.origin + a.stride[2] * z;
  for (int y = 0; y < r.dim[1]; ++y) {
    const uint16_t* src = base + a.stride[1] * y;
    uint32_t* dst = out.row(y);
    if (a.stride[0] == 1) {
      for (int x = 0; x < r.dim[0]; ++x) dst[x] = src[x];
    } else {
      for (int x = 0; x < r.dim[0]; ++x) dst[x] = src[a.stride[0] * x];
    }
  }
}

// Interpolation unit over a whole sample slice: x, then y, then z per
// sample, i.e. trilinear() on each sample's eight voxels.
void interpolate_slice(const Plane& lo, const Plane& hi, const SliceControl& c, int w, Plane& out) {
  for (int y = 0; y < out.ny; ++y) {
    const uint32_t *a0 = lo.row(y), *a1 = lo.row(y + 1), *b0 = hi.row(y), *b1 = hi.row(y + 1);
    uint32_t* dst = out.row(y);
    for (int x = 0; x < out.nx; ++x) {
      dst[x] = trilinear({a0[x], a0[x + 1], a1[x], a1[x + 1], b0[x], b0[x + 1], b1[x], b1[x + 1]},
                         c.wx, c.wy, c.wz, w);
    }
  }
}

void gather_2x2(const Plane& s, int x, int y, const Realign& rx, const Realign& ry, std::array<uint32_t, 4>& out) {
  const int bx = x + rx.base, by = y + ry.base;
  out = {s.at(bx, by), s.at(bx + 1, by), s.at(bx, by + 1), s.at(bx + 1, by + 1)};
}

void write_pixel(BasePlane& bp, int u, int v, const RayAcc& a) {
  uint16_t* px = &bp.rgba[(static_cast<size_t>(v) * bp.width + u) * 4];
  px[0] = a.r; px[1] = a.g; px[2] = a.b; px[3] = a.a;
}

}  // namespace

BasePlane render_fixed(const Volume& vol, const Registers& r, RenderStats* stats, const Progress& progress,
                       SampleProbe* probe) {
  const int nx = r.dim[0], ny = r.dim[1], nz = r.dim[2];
  const int K = r.sample_slices();
  const int w = r.p.weight_bits;
  const int ix_last = r.x_offset(K - 1).integer, iy_last = r.y_offset(K - 1).integer;

  BasePlane bp;
  bp.width = r.base_width();
  bp.height = r.base_height();
  bp.bits = r.p.alpha_bits;
  bp.rgba.assign(static_cast<size_t>(bp.width) * bp.height * 4, 0);
  const double frac_one = std::ldexp(1.0, r.p.dda_frac_bits);
  bp.shift_x = ix_last - r.x_start / frac_one;
  bp.shift_y = iy_last - r.y_start / frac_one;

  const PermutedAccess access(vol, r);
  // Voxel slices zv and zv+1 (one extra zero column/row for x+1, y+1).
  Plane vox_lo(nx, ny, 1), vox_hi(nx, ny, 1);
  int loaded_z = -1;
  auto samples_of = [&](int k, Plane& out) {
    if (k < 0 || k >= K) { out.clear(); return; }
    const SliceControl c = slice_control(r, k);
    if (c.z_voxel != loaded_z) {
      if (c.z_voxel == loaded_z + 1 && loaded_z >= 0) {
        std::swap(vox_lo, vox_hi);
      } else {
        load_voxel_slice(vol, r, access, c.z_voxel, vox_lo);
      }
      load_voxel_slice(vol, r, access, c.z_voxel + 1, vox_hi);
      loaded_z = c.z_voxel;
    }
    interpolate_slice(vox_lo, vox_hi, c, w, out);
  };

  // Sample slices behind, current and ahead of the one being shaded.
  Plane behind(nx, ny, 1), current(nx, ny, 1), ahead(nx, ny, 1);
  samples_of(0, current);
  if (r.gradient) samples_of(1, ahead);
  std::vector<RayAcc> prev(static_cast<size_t>(nx) * ny), cur(prev.size());

  for (int k = 0; k < K; ++k) {
    const SliceControl c = slice_control(r, k);
    Neighbourhood n;
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx; ++x) {
        n.centre = current.at(x, y);
        if (r.gradient) {
          n.left = current.at(x - 1, y);
          n.right = current.at(x + 1, y);
          n.up = current.at(x, y - 1);
          n.down = current.at(x, y + 1);
          gather_2x2(behind, x, y, c.behind_x, c.behind_y, n.behind);
          gather_2x2(ahead, x, y, c.ahead_x, c.ahead_y, n.ahead);
        }
        const ShadedSample s = shade_sample(r, c, x, y, n);
        if (probe) probe->sample(x, y, c, n.centre, r.gradient ? sample_gradient(r, c, n) : Gradient{});
        const Predecessor pred = ray_predecessor(x, y, c.dx, c.dy);
        const RayAcc acc = pred.exists ? prev[static_cast<size_t>(pred.y) * nx + pred.x] : RayAcc{};
        cur[static_cast<size_t>(y) * nx + x] = blend(r.blend, acc, s, r.p);
      }
    }
    // Rays of slice k-1 with no successor in slice k left through a side face.
    if (k > 0) {
      const SliceControl pc = slice_control(r, k - 1);
      for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x)
          if (ray_leaves(x, y, c.dx, c.dy, nx, ny))
            write_pixel(bp, x - pc.ix + ix_last, y - pc.iy + iy_last, prev[static_cast<size_t>(y) * nx + x]);
    }
    std::swap(prev, cur);
    if (r.gradient) {
      std::swap(behind, current);
      std::swap(current, ahead);
      samples_of(k + 2, ahead);
    } else if (k + 1 < K) {
      samples_of(k + 1, current);
    }
    if (progress) progress(static_cast<double>(k + 1) / K);
  }
  // The rays still inside leave through the back face.
  const SliceControl last = slice_control(r, K - 1);
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x)
      write_pixel(bp, x - last.ix + ix_last, y - last.iy + iy_last, prev[static_cast<size_t>(y) * nx + x]);

  if (stats) {
    stats->samples = static_cast<uint64_t>(nx) * ny * K;
    stats->slices = K;
  }
  (void)nz;
  return bp;
}

ImageF BasePlane::to_float() const {
  ImageF f;
  f.width = width;
  f.height = height;
  f.rgba.resize(rgba.size());
  const float scale = 1.0f / static_cast<float>((1u << bits) - 1u);
  for (size_t i = 0; i < rgba.size(); ++i) f.rgba[i] = rgba[i] * scale;
  return f;
}

}  // namespace cube4::golden
