// Sub-cubes: the block plan, the blocks' volumes and registers, and the
// composition of their partial images (golden/blocks.hpp).
#include "golden/blocks.hpp"

#include <algorithm>
#include <stdexcept>

#include "golden/errors.hpp"
#include "golden/slice_steps.hpp"
#include "golden/units/compose.hpp"

namespace cube4::golden {

namespace {

const char* const kAxis = "xyz";

// Object piece j of `count` along an axis of n voxels.
std::array<int, 2> piece(int n, int count, int j) {
  return {static_cast<int>(int64_t{j} * n / count), static_cast<int>(int64_t{j + 1} * n / count)};
}

void check_counts(const std::array<int, 3>& object_dim, const std::array<int, 3>& counts, const std::string& what) {
  int64_t total = 1;
  for (int a = 0; a < 3; ++a) {
    const int n = object_dim[a], c = counts[a];
    const std::string axis = std::string(what) + ": " + kAxis[a] + " ";
    if (c < 1) throw InputError(axis + std::to_string(c) + " blocks: give at least 1 along every axis");
    if (c > 1 && n / c < kMinBlockCore)
      throw InputError(axis + std::to_string(c) + " blocks of a volume " + std::to_string(n) +
                       " voxels long leave cores of " + std::to_string(n / c) + " voxels; each block needs at least " +
                       std::to_string(kMinBlockCore) + " (its border is up to 3 voxels): use at most " +
                       std::to_string(std::max(1, n / kMinBlockCore)) + " blocks along " + kAxis[a]);
    total *= c;
  }
  if (total > kMaxBlocks)
    throw InputError(what + ": " + std::to_string(total) + " blocks; at most " + std::to_string(kMaxBlocks));
}

// The volume's crop slab [lo, hi] in the block's coordinates (origin `at`),
// the same set of the block's voxels. Positions are never negative: a lower
// bound before the block becomes 0 and a slab wholly before it the empty
// slab [1, 0].
std::array<int32_t, 2> shift_slab(const std::array<int32_t, 2>& s, int at) {
  const int64_t lo = int64_t{s[0]} - at, hi = int64_t{s[1]} - at;
  if (hi < 0) return {1, 0};
  return {static_cast<int32_t>(std::max<int64_t>(lo, 0)), static_cast<int32_t>(hi)};
}

Registers block_registers(const Registers& whole, const Block& b, const std::string& what) {
  Registers r = whole;
  const Precision& p = whole.p;
  for (int i = 0; i < 3; ++i) r.dim[i] = b.store_hi[i] - b.store_lo[i];
  // The DDA restarted at the block's first sample slice: the same positions
  // less a whole number of voxels, so every slice keeps its weights and its
  // offset changes.
  const int kb = b.store_lo[2] * whole.supersampling;
  auto restart = [&](int64_t start, int64_t step) {
    const int64_t pos = dda_position(start, step, kb);
    return pos - ((pos >> p.dda_frac_bits) << p.dda_frac_bits);
  };
  if (whole.perspective) {
    // The volume's rays, indices kept: ray 0 and the spacing at slice kb,
    // positions from the block's origin.
    r.x_start = dda_position(whole.x_start, whole.x_step, kb) - (int64_t{b.store_lo[0]} << p.dda_frac_bits);
    r.y_start = dda_position(whole.y_start, whole.y_step, kb) - (int64_t{b.store_lo[1]} << p.dda_frac_bits);
    r.scale_start = whole.ray_spacing(kb);
  } else {
    r.x_start = restart(whole.x_start, whole.x_step);
    r.y_start = restart(whole.y_start, whole.y_step);
  }
  if (whole.crop_enabled)
    for (int i = 0; i < 3; ++i) r.crop.slab[i] = shift_slab(whole.crop.slab[i], b.store_lo[i]);
  if (whole.cut_enabled) {
    // d = A·X + B·Y + C·Z is linear: moving the origin moves the distances.
    const int64_t shift = (int64_t{whole.cut.a} * b.store_lo[0] + int64_t{whole.cut.b} * b.store_lo[1] +
                           int64_t{whole.cut.c} * b.store_lo[2]) *
                          (int64_t{1} << p.weight_bits);
    r.cut.dmin = whole.cut.dmin - shift;
    r.cut.dmax = whole.cut.dmax - shift;
    const int64_t limit = max_signed(p.cut_bits);
    for (const int64_t d : {r.cut.dmin, r.cut.dmax})
      if (d < -limit || d > limit)
        throw InputError(what + ": block " + std::to_string(b.index) + "'s cut-plane distance " + std::to_string(d) +
                         " does not fit the " + std::to_string(p.cut_bits) +
                         "-bit register (precision.cut_bits); use fewer blocks or a wider cut_bits");
  }
  bool border = false;
  for (int i = 0; i < 3; ++i) {
    r.window.range[i] = {b.core_lo[i] - b.store_lo[i], b.core_hi[i] - 1 - b.store_lo[i]};
    border |= b.core_lo[i] != b.store_lo[i] || b.core_hi[i] != b.store_hi[i];
  }
  // A block that stores nothing but its core (one block) composites all it
  // computes: no window, the volume's registers exactly.
  r.window_enabled = border;
  return r;
}

}  // namespace

BlockPlan plan_blocks(const Registers& whole, const std::array<int, 3>& object_dim, const std::array<int, 3>& counts,
                      const std::string& what) {
  check_counts(object_dim, counts, what);
  BlockPlan plan;
  plan.counts = counts;
  plan.whole = whole;
  // What the core's samples read beyond the core (golden/blocks.hpp), along
  // x and y (z is the parallel one's in perspective too).
  const int z_before = whole.gradient ? 1 : 0, z_after = whole.gradient ? 2 : 1;
  const int before = !whole.perspective ? z_before : whole.gradient ? 4 : 1;
  const int after = !whole.perspective ? z_after : whole.gradient ? 5 : 2;
  std::array<int, 3> pcount{};
  for (int i = 0; i < 3; ++i) pcount[i] = counts[static_cast<size_t>(whole.perm[i])];
  const int K = whole.sample_slices();
  const int ix_last = whole.x_offset(K - 1).integer, iy_last = whole.y_offset(K - 1).integer;
  for (int cz = 0; cz < pcount[2]; ++cz)
    for (int cy = 0; cy < pcount[1]; ++cy)
      for (int cx = 0; cx < pcount[0]; ++cx) {
        Block b;
        b.index = static_cast<int>(plan.blocks.size());
        b.cell = {cx, cy, cz};
        for (int i = 0; i < 3; ++i) {
          const int a = whole.perm[i], n = object_dim[a], c = pcount[i];
          const bool flip = whole.flip[i];
          const auto o = piece(n, c, flip ? c - 1 - b.cell[i] : b.cell[i]);
          b.core_lo[i] = flip ? n - o[1] : o[0];
          b.core_hi[i] = flip ? n - o[0] : o[1];
          b.store_lo[i] = std::max(b.core_lo[i] - (i == 2 ? z_before : before), 0);
          b.store_hi[i] = std::min(b.core_hi[i] + (i == 2 ? z_after : after), n);
          b.object_lo[a] = flip ? n - b.store_hi[i] : b.store_lo[i];
          b.object_dim[a] = b.store_hi[i] - b.store_lo[i];
        }
        b.regs = block_registers(whole, b, what);
        if (whole.perspective) {  // the same ray indices: origins apart by the rays before each's first
          b.u0 = whole.base_origin_x() - b.regs.base_origin_x();
          b.v0 = whole.base_origin_y() - b.regs.base_origin_y();
        } else {
          const int k_end = b.store_hi[2] * whole.supersampling - 1;
          b.u0 = b.store_lo[0] + ix_last - whole.x_offset(k_end).integer;
          b.v0 = b.store_lo[1] + iy_last - whole.y_offset(k_end).integer;
        }
        if (b.u0 < 0 || b.v0 < 0 || b.u0 + b.base_width() > whole.base_width() ||
            b.v0 + b.base_height() > whole.base_height())
          throw std::logic_error("plan_blocks: block " + std::to_string(b.index) +
                                 "'s base plane leaves the volume's");
        plan.blocks.push_back(std::move(b));
      }
  for (int q = 0; q < 4; ++q) {
    // Lexicographic by (z, ±y, ±x): front to back for a ray monotonic in
    // each coordinate, x and y in the quadrant's directions.
    const int sx = q & 1 ? -1 : 1, sy = q & 2 ? -1 : 1;
    auto key = [&](int i) {
      const std::array<int, 3>& c = plan.blocks[static_cast<size_t>(i)].cell;
      return std::array<int, 3>{c[2], sy * c[1], sx * c[0]};
    };
    std::vector<int>& order = plan.order[static_cast<size_t>(q)];
    for (int i = 0; i < static_cast<int>(plan.blocks.size()); ++i) order.push_back(i);
    if (whole.perspective) std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
  }
  return plan;
}

const std::vector<int>& BlockPlan::order_at(int u, int v) const {
  if (!whole.perspective) return order[0];
  // Ray (u - origin)'s step per slice along x: X_STEP + ray·SCALE_STEP.
  const auto backwards = [&](int pixel, int origin, int64_t step) {
    return static_cast<__int128>(step) + static_cast<__int128>(pixel - origin) * whole.scale_step < 0;
  };
  const int q = (backwards(u, whole.base_origin_x(), whole.x_step) ? 1 : 0) |
                (backwards(v, whole.base_origin_y(), whole.y_step) ? 2 : 0);
  return order[static_cast<size_t>(q)];
}

Volume block_volume(const Volume& vol, const Block& b) {
  Volume out;
  out.dim = b.object_dim;
  out.spacing = vol.spacing;
  out.bits = vol.bits;
  out.source = vol.source + " block " + std::to_string(b.index);
  out.tag_source = vol.tag_source;
  // The block's voxels, and their tags with them.
  auto copy = [&](const auto& from, auto& to) {
    to.resize(out.size());
    for (int z = 0; z < out.dim[2]; ++z)
      for (int y = 0; y < out.dim[1]; ++y) {
        const auto* src = &from[vol.index(b.object_lo[0], b.object_lo[1] + y, b.object_lo[2] + z)];
        std::copy(src, src + out.dim[0], &to[out.index(0, y, z)]);
      }
  };
  copy(vol.data, out.data);
  if (!vol.tags.empty()) copy(vol.tags, out.tags);
  return out;
}

BasePlane compose_blocks(const BlockPlan& plan, const std::vector<const BasePlane*>& partials, bool accumulators) {
  const size_t n = plan.blocks.size();
  if (partials.size() != n)
    throw std::invalid_argument("compose_blocks: " + std::to_string(partials.size()) + " partial images for " +
                                std::to_string(n) + " blocks");
  for (size_t i = 0; i < n; ++i) {
    const Block& b = plan.blocks[i];
    const BasePlane& part = *partials[i];
    if (part.width != b.base_width() || part.height != b.base_height() ||
        part.acc.size() != static_cast<size_t>(part.width) * part.height)
      throw std::invalid_argument("compose_blocks: block " + std::to_string(i) + "'s partial image is " +
                                  std::to_string(part.width) + "x" + std::to_string(part.height) +
                                  (part.acc.empty() ? " without accumulators" : "") + ", the plan's " +
                                  std::to_string(b.base_width()) + "x" + std::to_string(b.base_height()));
  }
  BasePlane out = empty_base_plane(plan.whole);
  if (accumulators) out.acc.assign(static_cast<size_t>(out.width) * out.height, RayAcc{});
  std::vector<RayAcc> px(n);
  for (int v = 0; v < out.height; ++v)
    for (int u = 0; u < out.width; ++u) {
      const std::vector<int>& order = plan.order_at(u, v);
      for (size_t i = 0; i < n; ++i) {
        const size_t k = static_cast<size_t>(order[i]);
        const Block& b = plan.blocks[k];
        const int bu = u - b.u0, bv = v - b.v0;
        const BasePlane& part = *partials[k];
        px[i] = bu >= 0 && bv >= 0 && bu < part.width && bv < part.height
                    ? part.acc[static_cast<size_t>(bv) * part.width + bu]
                    : RayAcc{};
      }
      const RayAcc ray = compose_tree(plan.whole.blend, px.data(), static_cast<int>(n), plan.whole.p);
      write_pixel(out, u, v, pixel_of(ray, plan.whole.p));
      if (accumulators) out.acc[static_cast<size_t>(v) * out.width + u] = ray;
    }
  return out;
}

BasePlane render_block_fixed(const Volume& block_vol, const Block& b, FixedOptions options) {
  options.accumulators = true;
  options.ranges = nullptr;  // the caller's ranges are another volume's
  return render_fixed(block_vol, b.regs, options);
}

BasePlane render_blocks_fixed(const Volume& vol, const BlockPlan& plan, const FixedOptions& options) {
  std::vector<BasePlane> parts;
  parts.reserve(plan.blocks.size());
  const double n = static_cast<double>(plan.blocks.size());
  RenderStats total;
  for (const Block& b : plan.blocks) {
    FixedOptions o = options;
    RenderStats stats;
    o.stats = &stats;
    if (options.progress) o.progress = [&, i = parts.size()](double f) { options.progress((i + f) / n); };
    parts.push_back(render_block_fixed(block_volume(vol, b), b, o));
    total.samples += stats.samples;
    total.slices = std::max(total.slices, stats.slices);
  }
  if (options.stats) *options.stats = total;
  std::vector<const BasePlane*> ptrs;
  for (const BasePlane& p : parts) ptrs.push_back(&p);
  return compose_blocks(plan, ptrs, options.accumulators);
}

}  // namespace cube4::golden
