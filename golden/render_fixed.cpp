// The bit-exact fixed-point renderer: the hardware's traversal (slice by
// slice, beam by beam, in permuted order) built only from the unit functions,
// in the slice steps of golden/slice_steps.hpp.
#include <algorithm>
#include <memory>
#include <vector>

#include "golden/slice_steps.hpp"

namespace cube4::golden {

BasePlane render_fixed(const Volume& vol, const Registers& r, RenderStats* stats, const Progress& progress,
                       SampleProbe* probe) {
  const int nx = r.dim[0], ny = r.dim[1];
  const int K = r.sample_slices();
  BasePlane bp = empty_base_plane(r);

  const PermutedVolume access(vol, r.perm, r.flip);
  // Voxel slices zv and zv+1 (one extra zero column/row for x+1, y+1).
  Plane vox_lo(nx, ny, 1), vox_hi(nx, ny, 1);
  SliceInterp interp(nx, ny, r.p.weight_bits);
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
  SliceCompositor compositor(r, bp);
  const bool may_skip = r.blend == BlendMode::Composite && probe == nullptr;
  // Up to 10-bit gradients a table of the cube-map divisions (1 MB at most)
  // is cheaper than dividing per sample.
  std::unique_ptr<FacePositionTable> faces;
  if (r.shading && r.p.gradient_bits <= 10)
    faces = std::make_unique<FacePositionTable>(static_cast<int>(max_signed(r.p.gradient_bits)), r.p.map_face_res,
                                                r.p.weight_bits);
  const uint32_t opaque = static_cast<uint32_t>(max_unsigned(acc_bits(r.p)));
  int32_t first_visible = 0;
  while (first_visible < static_cast<int32_t>(r.classification.size()) && r.classification[first_visible].a == 0)
    ++first_visible;

  for (int k = 0; k < K; ++k) {
    const SliceControl c = slice_control(r, k);
    Neighbourhood n;
    // A composited sample whose classified α is zero, or that meets an
    // opaque ray, leaves the ray exactly as it is (α only shrinks on the
    // way through the pipeline, and blend_front_to_back adds nothing for
    // α = 0 or full α_acc), so its gradient and shading are not computed;
    // nor are those of a beam whose samples all classify below the first
    // non-zero α.
    auto beam_may_change = [&](int y) {
      const int32_t* samples = current.row(y);
      return !may_skip || *std::max_element(samples, samples + nx) >= first_visible;
    };
    auto shade = [&](int x, int y, const RayAcc& ray, ShadedSample& s) {
      const uint32_t centre = current.at(x, y);
      if (may_skip && (r.classification[centre].a == 0 || ray.a == opaque)) return false;
      if (r.gradient) {
        gather_neighbourhood(behind, current, ahead, c, x, y, n);
      } else {
        n.centre = centre;
      }
      s = shade_sample(r, c, x, y, n, faces.get());
      if (probe) {
        probe->sample(x, y, c, n.centre, r.gradient ? sample_gradient(r, c, n) : Gradient{});
        probe->shaded(x, y, c, s);
      }
      return true;
    };
    compositor.slice(c, shade, beam_may_change);
    if (r.gradient) {
      std::swap(behind, current);
      std::swap(current, ahead);
      samples_of(k + 2, ahead);
    } else if (k + 1 < K) {
      samples_of(k + 1, current);
    }
    if (progress) progress(static_cast<double>(k + 1) / K);
  }
  compositor.finish();

  if (stats) {
    stats->samples = static_cast<uint64_t>(nx) * ny * K;
    stats->slices = K;
  }
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
