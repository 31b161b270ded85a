// Block ranges and the frame's skip map (golden/empty_space.hpp).
#include "golden/empty_space.hpp"

#include "golden/units/dda.hpp"

namespace cube4::golden {

namespace {

constexpr int kB = BlockRanges::kBlock;

int block_count(int dim) { return (dim - 1) / kB + 1; }

// Min and max over the voxels kB·b .. kB·b + kB of one axis, for rows of
// `width` values `stride` apart: the reductions along y and z run over whole
// x rows at once, which the compiler vectorises.
void reduce_rows(const uint16_t* lo_in, const uint16_t* hi_in, size_t stride, int count, size_t width,
                 uint16_t* lo_out, uint16_t* hi_out) {
  std::copy(lo_in, lo_in + width, lo_out);
  std::copy(hi_in, hi_in + width, hi_out);
  for (int i = 1; i < count; ++i) {
    const uint16_t* __restrict l = lo_in + stride * static_cast<size_t>(i);
    const uint16_t* __restrict h = hi_in + stride * static_cast<size_t>(i);
    uint16_t* __restrict lo = lo_out;
    uint16_t* __restrict hi = hi_out;
    for (size_t x = 0; x < width; ++x) {
      lo[x] = std::min(lo[x], l[x]);
      hi[x] = std::max(hi[x], h[x]);
    }
  }
}

}  // namespace

BlockRanges block_ranges(const Volume& vol) {
  BlockRanges b;
  b.dim = vol.dim;
  for (int i = 0; i < 3; ++i) b.blocks[i] = vol.dim[i] > 0 ? block_count(vol.dim[i]) : 0;
  const size_t nx = static_cast<size_t>(vol.dim[0]);
  const int ny = vol.dim[1], nz = vol.dim[2];
  const int bx = b.blocks[0], by = b.blocks[1], bz = b.blocks[2];
  b.lo.assign(static_cast<size_t>(bx) * by * bz, 0);
  b.hi.assign(b.lo.size(), 0);
  if (vol.size() == 0) return b;
  auto voxels_of = [](int block, int dim) { return std::min(kB, dim - 1 - kB * block) + 1; };
  // y blocks of every z slice, then z blocks: rows of nx voxels.
  std::vector<uint16_t> ylo(nx * by * nz), yhi(ylo.size());
  for (int z = 0; z < nz; ++z)
    for (int j = 0; j < by; ++j) {
      const uint16_t* src = &vol.data[vol.index(0, kB * j, z)];
      uint16_t* lo = &ylo[(static_cast<size_t>(z) * by + j) * nx];
      reduce_rows(src, src, nx, voxels_of(j, ny), nx, lo, &yhi[lo - ylo.data()]);
    }
  std::vector<uint16_t> zlo(nx * by * bz), zhi(zlo.size());
  const size_t plane = nx * static_cast<size_t>(by);
  for (int k = 0; k < bz; ++k) {
    const size_t in = static_cast<size_t>(kB) * k * plane, out = k * plane;
    reduce_rows(&ylo[in], &yhi[in], plane, voxels_of(k, nz), plane, &zlo[out], &zhi[out]);
  }
  for (int k = 0; k < bz; ++k)
    for (int j = 0; j < by; ++j) {
      const size_t row = (static_cast<size_t>(k) * by + j) * nx;
      for (int i = 0; i < bx; ++i) {
        const size_t x0 = static_cast<size_t>(kB) * i, n = static_cast<size_t>(voxels_of(i, vol.dim[0]));
        uint16_t lo = *std::min_element(&zlo[row + x0], &zlo[row + x0 + n]);
        const uint16_t hi = *std::max_element(&zhi[row + x0], &zhi[row + x0 + n]);
        // A cell on a face reads the zero outside the volume.
        if (i == 0 || j == 0 || k == 0 || i == bx - 1 || j == by - 1 || k == bz - 1) lo = 0;
        b.lo[b.index(i, j, k)] = lo;
        b.hi[b.index(i, j, k)] = hi;
      }
    }
  return b;
}

SkipMap::SkipMap(const Registers& r, const BlockRanges* ranges)
    : nx_(r.dim[0]), ny_(r.dim[1]), nz_(r.dim[2]), supersampling_(r.supersampling), reach_(r.gradient ? 1 : 0) {
  if (!ranges || r.blend != BlendMode::Composite || nx_ <= 0 || ny_ <= 0 || nz_ <= 0) return;
  for (int i = 0; i < 3; ++i)
    if (ranges->dim[r.perm[i]] != r.dim[i]) return;  // not this volume's ranges
  // A value may change a ray if its table α is non-zero: prefix counts of
  // such values answer "any in [lo, hi]" in two reads.
  // With tags, visible under any tag: the ranges know values only.
  const size_t values = r.class_values();
  std::vector<uint32_t> visible_below(values + 1, 0);
  for (size_t v = 0; v < values; ++v) visible_below[v + 1] = visible_below[v] + r.value_visible(v);
  auto any_visible = [&](uint32_t lo, uint32_t hi) {
    if (hi >= values) return true;  // beyond the table: never skipped
    return visible_below[hi + 1] != visible_below[lo];
  };
  // The object block holding the cell whose lower corner is permuted
  // coordinate c along permuted axis `axis` (voxels c and c + 1; flipped,
  // object voxels d-1-c and d-2-c).
  auto cell_block = [&](int axis, int c) {
    const int d = r.dim[axis];
    const int o = r.flip[axis] ? d - 2 - c : c;
    return std::clamp(o < 0 ? 0 : o / kB, 0, ranges->blocks[r.perm[axis]] - 1);
  };
  by_.resize(static_cast<size_t>(ny_));
  bz_.resize(static_cast<size_t>(nz_));
  for (int y = 0; y < ny_; ++y) by_[static_cast<size_t>(y)] = cell_block(1, y);
  for (int z = 0; z < nz_; ++z) bz_[static_cast<size_t>(z)] = cell_block(2, z);
  // The cells of beam x in each x block: contiguous, in either order.
  const int bx_count = ranges->blocks[r.perm[0]];
  std::vector<Span> cells(static_cast<size_t>(bx_count));
  for (int x = 0; x < nx_; ++x) {
    Span& s = cells[static_cast<size_t>(cell_block(0, x))];
    s = hull(s, Span{x, x + 1});
  }
  by_count_ = ranges->blocks[r.perm[1]];
  const int bz_count = ranges->blocks[r.perm[2]];
  spans_.assign(static_cast<size_t>(by_count_) * bz_count, Span{});
  for (int k = 0; k < bz_count; ++k)
    for (int j = 0; j < by_count_; ++j) {
      Span& s = spans_[static_cast<size_t>(k) * by_count_ + j];
      for (int i = 0; i < bx_count; ++i) {
        std::array<int, 3> ob{};
        ob[static_cast<size_t>(r.perm[0])] = i;
        ob[static_cast<size_t>(r.perm[1])] = j;
        ob[static_cast<size_t>(r.perm[2])] = k;
        const size_t at = ranges->index(ob[0], ob[1], ob[2]);
        if (any_visible(ranges->lo[at], ranges->hi[at])) s = hull(s, cells[static_cast<size_t>(i)]);
      }
    }
  rows_.assign(static_cast<size_t>(bz_count) * ny_, Span{});
  for (int k = 0; k < bz_count; ++k)
    for (int y = 0; y < ny_; ++y) {
      Span& s = rows_[static_cast<size_t>(k) * ny_ + y];
      for (int v = std::max(y - reach_, 0); v <= std::min(y + reach_, ny_ - 1); ++v)
        s = hull(s, spans_[static_cast<size_t>(k) * by_count_ + by_[static_cast<size_t>(v)]]);
    }
  skipping_ = true;
}

Span SkipMap::samples_needed(int k, int y) const {
  if (!skipping_) return {0, nx_};
  const int K = nz_ * supersampling_, g = reach_;
  const int z0 = z_voxel_slice(std::max(k - g, 0), supersampling_);
  const int z1 = z_voxel_slice(std::min(k + g, K - 1), supersampling_);
  Span s;
  for (int z = z0; z <= z1; ++z) s = hull(s, rows(z, y));
  return grown(s, g, g);
}

Span SkipMap::voxels_needed(int z, int y) const {
  if (!skipping_) return {0, nx_};
  const int g = reach_;
  Span s;
  for (int v = std::max(z - 1 - g, 0); v <= std::min(z + g, nz_ - 1); ++v) s = hull(s, hull(rows(v, y - 1), rows(v, y)));
  return grown(s, g, g + 1);
}

}  // namespace cube4::golden
