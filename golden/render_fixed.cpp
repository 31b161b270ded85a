// The bit-exact fixed-point renderer: the hardware's traversal (slice by
// slice, beam by beam, in permuted order) built only from the unit functions.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "golden/permuted_volume.hpp"
#include "golden/pipeline.hpp"
#include "golden/renderers.hpp"

namespace cube4::golden {
namespace {

// A slice with a border of zeros: `pad` columns/rows before and after, so
// neighbours of edge samples read zero (the volume is surrounded by zeros).
struct Plane {
  int nx = 0, ny = 0, pad = 0, pitch = 0;
  std::vector<int32_t> v;
  Plane(int nx_, int ny_, int pad_) : nx(nx_), ny(ny_), pad(pad_), pitch(nx_ + 2 * pad_),
      v(static_cast<size_t>(nx_ + 2 * pad_) * (ny_ + 2 * pad_), 0) {}
  int32_t* row(int y) { return &v[static_cast<size_t>(y + pad) * pitch + pad]; }
  const int32_t* row(int y) const { return &v[static_cast<size_t>(y + pad) * pitch + pad]; }
  uint32_t at(int x, int y) const { return static_cast<uint32_t>(row(y)[x]); }
  void clear() { std::fill(v.begin(), v.end(), 0); }
};

void load_voxel_slice(const PermutedVolume& pv, int z, Plane& out) {
  for (int y = 0; y < out.ny; ++y) pv.load_beam(y, z, out.row(y));
}

// Interpolation unit over a whole sample slice: trilinear() for every
// sample, computed stage by stage across the slice (x lerps of each voxel
// row once, then y, then z) with the same lerp, so the values are those of
// trilinear() on each sample's eight voxels (tested). A stage whose weight
// is zero returns its first operand exactly, so it is not computed.
struct Interpolator {
  int nx, ny, w;
  std::vector<int32_t> tx, ty_lo, ty_hi;
  Interpolator(int nx_, int ny_, int w_) : nx(nx_), ny(ny_), w(w_),
      tx(static_cast<size_t>(nx_) * (ny_ + 1)), ty_lo(static_cast<size_t>(nx_) * ny_), ty_hi(ty_lo.size()) {}

  void bilinear(const Plane& v, int32_t wx, int32_t wy, std::vector<int32_t>& out) {
    // Locals, so that stores through int32_t pointers cannot alias them.
    const int nx = this->nx, ny = this->ny, w = this->w;
    for (int y = 0; y <= ny; ++y) {
      const int32_t* __restrict a = v.row(y);
      int32_t* __restrict t = &tx[static_cast<size_t>(y) * nx];
      if (wx == 0) {
        std::copy(a, a + nx, t);
      } else {
        for (int x = 0; x < nx; ++x) t[x] = lerp_t<int32_t>(a[x], a[x + 1], wx, w);
      }
    }
    for (int y = 0; y < ny; ++y) {
      const int32_t* __restrict t0 = &tx[static_cast<size_t>(y) * nx];
      const int32_t* __restrict t1 = t0 + nx;
      int32_t* __restrict o = &out[static_cast<size_t>(y) * nx];
      if (wy == 0) {
        std::copy(t0, t0 + nx, o);
      } else {
        for (int x = 0; x < nx; ++x) o[x] = lerp_t<int32_t>(t0[x], t1[x], wy, w);
      }
    }
  }

  void slice(const Plane& lo, const Plane& hi, const SliceControl& c, Plane& out) {
    const auto wx = static_cast<int32_t>(c.wx), wy = static_cast<int32_t>(c.wy), wz = static_cast<int32_t>(c.wz);
    const int nx = this->nx, ny = this->ny, w = this->w;
    bilinear(lo, wx, wy, ty_lo);
    if (wz != 0) bilinear(hi, wx, wy, ty_hi);
    for (int y = 0; y < ny; ++y) {
      const int32_t* __restrict a = &ty_lo[static_cast<size_t>(y) * nx];
      const int32_t* __restrict b = &ty_hi[static_cast<size_t>(y) * nx];
      int32_t* __restrict o = out.row(y);
      if (wz == 0) {
        std::copy(a, a + nx, o);
      } else {
        for (int x = 0; x < nx; ++x) o[x] = lerp_t<int32_t>(a[x], b[x], wz, w);
      }
    }
  }
};

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

  const PermutedVolume access(vol, r.perm, r.flip);
  // Voxel slices zv and zv+1 (one extra zero column/row for x+1, y+1).
  Plane vox_lo(nx, ny, 1), vox_hi(nx, ny, 1);
  Interpolator interp(nx, ny, w);
  int loaded_z = -1;
  auto samples_of = [&](int k, Plane& out) {
    if (k < 0 || k >= K) { out.clear(); return; }
    const SliceControl c = slice_control(r, k);
    if (c.z_voxel != loaded_z) {
      if (c.z_voxel == loaded_z + 1 && loaded_z >= 0) {
        std::swap(vox_lo, vox_hi);
      } else {
        load_voxel_slice(access, c.z_voxel, vox_lo);
      }
      load_voxel_slice(access, c.z_voxel + 1, vox_hi);
      loaded_z = c.z_voxel;
    }
    interp.slice(vox_lo, vox_hi, c, out);
  };

  // Sample slices behind, current and ahead of the one being shaded.
  Plane behind(nx, ny, 1), current(nx, ny, 1), ahead(nx, ny, 1);
  samples_of(0, current);
  if (r.gradient) samples_of(1, ahead);
  std::vector<RayAcc> prev(static_cast<size_t>(nx) * ny), cur(prev.size());
  const bool may_skip = r.blend == BlendMode::Composite && probe == nullptr;
  // Up to 10-bit gradients a table of the cube-map divisions (1 MB at most)
  // is cheaper than dividing per sample.
  std::unique_ptr<FacePositionTable> faces;
  if (r.shading && r.p.gradient_bits <= 10)
    faces = std::make_unique<FacePositionTable>(static_cast<int>(max_signed(r.p.gradient_bits)), r.p.map_face_res,
                                                r.p.weight_bits);
  const uint16_t opaque = static_cast<uint16_t>(max_unsigned(r.p.alpha_bits));
  int32_t first_visible = 0;
  while (first_visible < static_cast<int32_t>(r.classification.size()) && r.classification[first_visible].a == 0)
    ++first_visible;

  for (int k = 0; k < K; ++k) {
    const SliceControl c = slice_control(r, k);
    Neighbourhood n;
    for (int y = 0; y < ny; ++y) {
      RayAcc* out_row = &cur[static_cast<size_t>(y) * nx];
      // Ray alignment for the whole beam: each ray's predecessor, or an
      // empty ray where it enters through a side face.
      // ray_predecessor() is the same for the whole beam from x = dx on.
      const Predecessor from = ray_predecessor(c.dx, y, c.dx, c.dy);
      if (!from.exists) {
        std::fill(out_row, out_row + nx, RayAcc{});
      } else {
        const RayAcc* in_row = &prev[static_cast<size_t>(from.y) * nx + from.x];
        std::fill(out_row, out_row + c.dx, RayAcc{});
        std::copy(in_row, in_row + nx - c.dx, out_row + c.dx);
      }
      // A composited sample whose classified α is zero, or that meets an
      // opaque ray, leaves the ray exactly as it is (α only shrinks on the
      // way through the pipeline, and blend_front_to_back adds nothing for
      // α = 0 or full α_acc), so its gradient and shading are not computed;
      // nor are those of a beam whose samples all classify below the first
      // non-zero α.
      const int32_t* samples = current.row(y);
      if (may_skip && *std::max_element(samples, samples + nx) < first_visible) continue;
      for (int x = 0; x < nx; ++x) {
        RayAcc& out = out_row[x];
        n.centre = static_cast<uint32_t>(samples[x]);
        if (may_skip && (r.classification[n.centre].a == 0 || out.a == opaque)) continue;
        if (r.gradient) {
          n.left = current.at(x - 1, y);
          n.right = current.at(x + 1, y);
          n.up = current.at(x, y - 1);
          n.down = current.at(x, y + 1);
          gather_2x2(behind, x, y, c.behind_x, c.behind_y, n.behind);
          gather_2x2(ahead, x, y, c.ahead_x, c.ahead_y, n.ahead);
        }
        const ShadedSample s = shade_sample(r, c, x, y, n, faces.get());
        if (probe) {
          probe->sample(x, y, c, n.centre, r.gradient ? sample_gradient(r, c, n) : Gradient{});
          probe->shaded(x, y, c, s);
        }
        out = blend(r.blend, out, s, r.p);
      }
    }
    // Rays of slice k-1 with no successor in slice k left through a side
    // face; only the last dy beams and the last dx rays of a beam can.
    if (k > 0 && (c.dx | c.dy)) {
      const SliceControl pc = slice_control(r, k - 1);
      for (int y = 0; y < ny; ++y)
        for (int x = y >= ny - c.dy ? 0 : nx - c.dx; x < nx; ++x)
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
