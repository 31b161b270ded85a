// The renderers and the warp. The fixed-point renderer is the bit-exact
// specification; the float renderer is the same algorithm in real
// arithmetic; the reference is an independent image-order ray caster; the
// splat renderer is bela's energy projection, for comparison.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "golden/empty_space.hpp"
#include "golden/host_driver.hpp"
#include "golden/mesh.hpp"
#include "golden/pipeline.hpp"
#include "golden/polygon_frame.hpp"
#include "golden/splat_footprint.hpp"
#include "golden/volume.hpp"

namespace cube4::golden {

// Premultiplied RGBA, floats in [0, 1].
struct ImageF {
  int width = 0, height = 0;
  std::vector<float> rgba;
  float* pixel(int x, int y) { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
  const float* pixel(int x, int y) const { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
};

// A base-plane image. Ray u starts at permuted x = u - shift_x on the front face.
struct BasePlane {
  int width = 0, height = 0;
  int bits = 12;                 // channel width (alpha_bits)
  std::vector<uint16_t> rgba;    // premultiplied
  double shift_x = 0, shift_y = 0;
  // Each ray's accumulator, row by row, when asked for (FixedOptions::
  // accumulators; the system model's pixel memory keeps them too): the
  // partial image a block of a partitioned volume hands to the composition
  // network, which composes in the accumulator domain (golden/blocks.hpp).
  std::vector<RayAcc> acc;
  ImageF to_float() const;
};

struct BasePlaneF {
  ImageF image;
  double shift_x = 0, shift_y = 0;
};

using Progress = std::function<void(double fraction_done)>;

// Counts of what the renderer computed, for reports.
struct RenderStats {
  uint64_t samples = 0;         // samples computed (S * n^3 for the fixed renderer)
  uint64_t shaded = 0;          // fixed renderer: samples given a gradient and shading (those that could change a pixel)
  int slices = 0;               // sample slices
};

// Sees every sample the fixed renderer shades, with its gradient (zero when
// the scene needs none): for measurements such as the gradient error.
struct SampleProbe {
  virtual ~SampleProbe() = default;
  virtual void sample(int x, int y, const SliceControl& c, uint32_t value, const Gradient& g) = 0;
  // With tags: the sample's tag, just before sample() (samples without a
  // call have tag 0).
  virtual void tagged(int /*x*/, int /*y*/, const SliceControl& /*c*/, uint32_t /*tag*/) {}
  // The same sample after classification, shading, cropping and cut plane:
  // what the compositor receives (for compositor testbenches).
  virtual void shaded(int /*x*/, int /*y*/, const SliceControl& /*c*/, const ShadedSample& /*s*/) {}
};

// Perspective frames: the interpolation unit's samples, produced elsewhere
// (the system model's clocked or verilated interpolation ring,
// systemc/core/perspective_frame.hpp) for the renderer to take instead of
// computing its own; the gradient, shading and compositing stay golden's.
struct PerspectiveSamples {
  virtual ~PerspectiveSamples() = default;
  // Slice k's sample of ray (u, v), and its voxel tag (0 without tags), for
  // a ray that samples the slice. Called from any of the renderer's threads.
  virtual uint32_t sample(int k, int64_t u, int64_t v) const = 0;
  virtual uint32_t vtag(int k, int64_t u, int64_t v) const = 0;
};
// Likewise a perspective frame's gradients (the clocked gradient unit's,
// systemc/tlm/tlm_gradient_persp.hpp), for a ray that samples slice k.
struct PerspectiveGradients {
  virtual ~PerspectiveGradients() = default;
  virtual Gradient gradient(int k, int64_t u, int64_t v) const = 0;
};

// How render_fixed() runs; none of it but `polygons` (and `given_samples`
// or `given_gradients` that differ from golden's) changes the base plane.
struct FixedOptions {
  RenderStats* stats = nullptr;
  Progress progress;          // called from the calling thread
  SampleProbe* probe = nullptr;  // sees every sample, in traversal order: one thread, no skipping
  // Threads, each rendering a band of base-plane rows (0: one per core).
  int threads = 1;
  // Skip the samples that cannot change their ray (golden/empty_space.hpp),
  // using `ranges` if given (block_ranges() of this volume, to build it once
  // for many frames) or building them for the frame.
  bool skip_empty = true;
  const BlockRanges* ranges = nullptr;
  // Keep every ray's accumulator in BasePlane::acc.
  bool accumulators = false;
  // At the default precision, run the loops instantiated with the widths as
  // compile-time constants (DefaultPrecisionRegisters); false runs the
  // run-time-width loops, which give the same bits (tested), a little slower.
  bool constant_widths = true;
  // The frame's polygon images (Cube-5; golden/polygons.hpp), or none. This
  // one changes the base plane: it is hardware input, like the registers.
  const PolygonFrame* polygons = nullptr;
  // Perspective only: take each sample (and tag) from here, not from the
  // volume. The volume's voxels still serve VolumePro's z gradient.
  const PerspectiveSamples* given_samples = nullptr;
  // Perspective only: take each composited sample's gradient from here.
  const PerspectiveGradients* given_gradients = nullptr;
};

BasePlane render_fixed(const Volume& vol, const Registers& regs, const FixedOptions& options);
// Registers with `perspective` set: Cube-4's perspective (golden/perspective.hpp);
// render_fixed() calls it for them. `threads` take rows of rays (the same
// frame for any number); no empty-space skipping beyond the per-sample one.
BasePlane render_perspective(const Volume& vol, const Registers& regs, const FixedOptions& options);
BasePlane render_fixed(const Volume& vol, const Registers& regs, RenderStats* stats = nullptr,
                       const Progress& progress = {}, SampleProbe* probe = nullptr);
// What `threads` = 0 means.
int default_threads();
// With meshes (the scene's polygons, loaded), they are drawn too (Cube-5);
// the base plane then has polygon_margins() around it.
BasePlaneF render_float(const Volume& vol, const Scene& s, const ViewFactorisation& f,
                        RenderStats* stats = nullptr, const Progress& progress = {},
                        const std::vector<Mesh>& meshes = {});

// render_float() for a perspective view (f.perspective): render_perspective()'s
// algorithm in real arithmetic; render_float() calls it for such views.
BasePlaneF render_float_perspective(const Volume& vol, const Scene& s, const ViewFactorisation& f,
                                    RenderStats* stats = nullptr, const Progress& progress = {},
                                    const std::vector<Mesh>& meshes = {});

struct ReferenceOptions {
  double step = 0.25;  // ray step in units of the smallest voxel spacing
  // The scene's polygons, loaded (Cube-5): intersected exactly with every ray.
  const std::vector<Mesh>* meshes = nullptr;
};
ImageF render_reference(const Volume& vol, const Scene& s, const ViewFactorisation& f,
                        const ReferenceOptions& opt = {}, RenderStats* stats = nullptr,
                        const Progress& progress = {});

// bela's projection (§III.B–C) in double precision, object order: every
// voxel classified and shaded where it is and spread over the image by its
// footprint table, slice images composited front to back. A comparison
// renderer, not a hardware specification. Final image of the scene's size;
// "composite" scenes only (InputError otherwise); samples = voxels spread.
ImageF render_splat(const Volume& vol, const Scene& s, const ViewFactorisation& f, const SplatKernel& kernel = {},
                    RenderStats* stats = nullptr, const Progress& progress = {});

// Bilinear warp of a base plane onto the final image (transparent outside).
ImageF warp(const ImageF& base, double shift_x, double shift_y, const ViewFactorisation& f);
// The mean of equally sized images, channel by channel: the host's blend of
// the frames of x/y supersampling (xy_subframes(), golden/host_driver.hpp).
ImageF blend_frames(const std::vector<ImageF>& frames);

}  // namespace cube4::golden
