// bela's projection (bela §III.B–C) as a comparison renderer in double
// precision: object order, splatting. Not a hardware specification (bela's
// is not modelled bit for bit); it answers how energy projection compares
// with ray casting against the same reference (docs/accuracy.md).
//
// Voxel slices are taken front to back along the principal viewing axis of
// the shear-warp factorisation. Every voxel is classified and shaded at its
// own position (no interpolation: only the voxels are rendered, bela §III),
// its premultiplied RGBα spread over the image by the footprint table of the
// sub-pixel its centre of projection falls in. A slice's footprints add up
// to a slice image, which is composited under the image of the slices in
// front of it: voxels of one slice lie side by side, not one behind the
// other, so none may hide another. (Compositing every voxel image on its
// own, as bela's image assembler does, would: where the footprints of an
// opaque slice overlap, 1 - Π(1 - wᵢ) of each pixel would be covered
// instead of Σwᵢ = 1, and the slice would come out translucent.)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "golden/errors.hpp"
#include "golden/host_driver.hpp"
#include "golden/permuted_volume.hpp"
#include "golden/renderers.hpp"
#include "golden/shading_model.hpp"
#include "golden/splat_footprint.hpp"

namespace cube4::golden {
namespace {

// Pixels a slice touched, to composite and clear only those.
struct Rect {
  int x0, y0, x1, y1;  // inclusive; empty while x0 > x1
  void add(int x, int y) {
    x0 = std::min(x0, x); y0 = std::min(y0, y);
    x1 = std::max(x1, x); y1 = std::max(y1, y);
  }
};

}  // namespace

ImageF render_splat(const Volume& vol, const Scene& s, const ViewFactorisation& f, const SplatKernel& kernel,
                    RenderStats* stats, const Progress& progress) {
  const std::string where = s.file.empty() ? std::string("the default scene") : s.file;
  if (s.blend != Blend::Composite)
    throw InputError(where + ": \"blend\" = \"" + (s.blend == Blend::Mip ? "mip" : "minip") +
                     "\": the splat model composites only (bela's energy projection sums energy)");
  if (footprint_extent(f, kernel) > kMaxFootprintExtent) {
    char zoom[32];
    std::snprintf(zoom, sizeof zoom, "%g", s.view.zoom);
    throw InputError(where + ": \"view.zoom\" = " + zoom + ": a voxel's footprint would be wider than the " +
                     std::to_string(kMaxFootprintExtent) + " pixels the splat model spreads (" +
                     std::to_string(s.width) + "x" + std::to_string(s.height) + " image)");
  }
  const EffectSet e = effects_of(s);
  const double vmax = static_cast<double>(vol.max_value());
  const double gscale = std::ldexp(1.0, -s.precision.gradient_shift);
  // A slice stands for the ray between it and the next: the float model's
  // sample step at supersampling 1.
  const SampleShading shade(s, f, vmax, sample_step_ratio(f, 1));
  const CropRegs crop = permute_cropping(s.cropping, f);
  const PermutedCutPlane cut = permute_cut_plane_real(s.cut, f);
  const FootprintTables tables = footprint_tables(f, kernel);
  const int h = tables.extent / 2, w = tables.extent;

  // Centre of projection of permuted voxel (x, y, z): origin + x·ex + y·ey + z·ez.
  const auto origin = f.image_of(f.to_object({0, 0, 0}));
  auto step = [&](const Vec3& d) {
    const auto p = f.image_of(f.to_object(d));
    return std::array<double, 2>{p[0] - origin[0], p[1] - origin[1]};
  };
  const auto ex = step({1, 0, 0}), ey = step({0, 1, 0}), ez = step({0, 0, 1});

  const int W = s.width, H = s.height;
  std::vector<double> acc(static_cast<size_t>(W) * H * 4, 0.0), slice(acc.size(), 0.0);
  const PermutedVolume pv(vol, f.perm, f.flip);
  const int nx = f.pdim[0], ny = f.pdim[1], nz = f.pdim[2];
  uint64_t splats = 0;
  for (int z = 0; z < nz; ++z) {
    Rect touched{W, H, -1, -1};
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const double v = pv.at(x, y, z);
        const int tag = pv.tag_at(x, y, z);  // a splat is one voxel: its own tag
        // Transparent by classification: nothing to shade or spread.
        if (eval_piecewise(s.opacity_of(tag), v / vmax) == 0) continue;
        if (e.cropping && !crop_visible(x, y, z, crop)) continue;
        double fac = 1;
        if (e.cut_plane) {
          fac = cut.factor(cut.a[0] * x + cut.a[1] * y + cut.a[2] * z);
          if (fac == 0) continue;
        }
        Vec3 g{0, 0, 0};
        if (e.gradient)
          g = {(pv.at(x + 1, y, z) - pv.at(x - 1, y, z)) * gscale, (pv.at(x, y + 1, z) - pv.at(x, y - 1, z)) * gscale,
               (pv.at(x, y, z + 1) - pv.at(x, y, z - 1)) * gscale};
        const ShadedF sh = shade(v, g, tag);
        const double alpha = sh.alpha * fac;
        if (alpha == 0) continue;
        const double X = origin[0] + x * ex[0] + y * ey[0] + z * ez[0];
        const double Y = origin[1] + x * ex[1] + y * ey[1] + z * ez[1];
        const int px = static_cast<int>(std::floor(X + 0.5)), py = static_cast<int>(std::floor(Y + 0.5));
        if (px + h < 0 || py + h < 0 || px - h >= W || py - h >= H) continue;
        ++splats;
        const std::vector<double>& table = tables.weight[FootprintTables::subpixel(X - px, Y - py)];
        const double energy = alpha * tables.cell_area;
        const double premul[4] = {sh.rgb[0] * energy, sh.rgb[1] * energy, sh.rgb[2] * energy, energy};
        for (int j = -h; j <= h; ++j) {
          const int Yp = py + j;
          if (Yp < 0 || Yp >= H) continue;
          for (int i = -h; i <= h; ++i) {
            const int Xp = px + i;
            if (Xp < 0 || Xp >= W) continue;
            const double wt = table[static_cast<size_t>(j + h) * w + (i + h)];
            double* d = &slice[(static_cast<size_t>(Yp) * W + Xp) * 4];
            for (int c = 0; c < 4; ++c) d[c] += wt * premul[c];
          }
        }
        touched.add(std::max(0, px - h), std::max(0, py - h));
        touched.add(std::min(W - 1, px + h), std::min(H - 1, py + h));
      }
    for (int Yp = touched.y0; Yp <= touched.y1; ++Yp)
      for (int Xp = touched.x0; Xp <= touched.x1; ++Xp) {
        double* d = &slice[(static_cast<size_t>(Yp) * W + Xp) * 4];
        double* a = &acc[(static_cast<size_t>(Yp) * W + Xp) * 4];
        // Where the footprints' sum ripples above one, an opaque slice
        // would be more than opaque: it is scaled back to α = 1, its colour kept.
        const double t = (1 - a[3]) * (d[3] > 1 ? 1 / d[3] : 1.0);
        for (int c = 0; c < 4; ++c) {
          a[c] += t * d[c];
          d[c] = 0;
        }
      }
    if (progress) progress(static_cast<double>(z + 1) / nz);
  }
  ImageF img;
  img.width = W;
  img.height = H;
  img.rgba.assign(acc.begin(), acc.end());
  if (stats) {
    stats->samples = splats;
    stats->slices = nz;
  }
  return img;
}

}  // namespace cube4::golden
