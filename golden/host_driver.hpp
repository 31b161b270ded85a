// Host driver: from a scene to the integer register values (docs/architecture.md).
// Floating point stops here; every value below is an integer of stated width.
#pragma once
#include "golden/registers.hpp"
#include "golden/scene.hpp"
#include "golden/view.hpp"
#include "golden/volume.hpp"

namespace cube4::golden {

struct HostProgram {
  ViewFactorisation view;
  Registers regs;
  EffectSet effects;
};

HostProgram program_host(const Scene& s, const Volume& vol);

// The frames x/y supersampling renders (VolumePro §4.1): for n =
// s.xy_supersampling, n² copies of s whose rays start at view.ray_offset +
// (i, j) / n base-plane pixels (each wrapped into [0, 1): the same grid of
// rays, the base plane's shift accounts for the wrap), i and j in 0..n-1,
// row by row; for n = 1 s itself. Their warped images, blended by
// blend_frames(), are the supersampled image: the hardware renders each one
// as an ordinary frame.
std::vector<Scene> xy_subframes(const Scene& s);

// A unit value in [0, 1] (clamped) as a bits-wide integer, rounded to
// nearest: 1 is 2^bits - 1. How every table, colour and opacity is made.
int64_t quantise_unit(double v, int bits);

// Pieces of program_host, exposed for tests and for the RTL testbenches.
std::vector<ClassEntry> build_classification(const Scene& s, double step_ratio);
std::vector<uint16_t> build_gm_lut(const Scene& s);
// Cube-map entry (face, u, v) as a direction in permuted space.
Vec3 map_direction(int face, int u, int v, int res);
std::vector<uint32_t> build_diffuse_map(const Scene& s, const ViewFactorisation& f);
std::vector<uint32_t> build_specular_map(const Scene& s, const ViewFactorisation& f);
CropRegs permute_cropping(const Cropping& c, const ViewFactorisation& f);
// The cut plane in permuted voxel coordinates, a·p in [dmin, dmax], |a| = 1.
struct PermutedCutPlane {
  Vec3 a{};
  double dmin = 0, dmax = 0, falloff = 0;
  bool keep_inside = true;
  // The real-valued counterpart of cut_factor(): 1 inside, linear ramp over
  // the falloff, 0 beyond; inverted when keeping the outside.
  double factor(double d) const;
};
PermutedCutPlane permute_cut_plane_real(const CutPlane& c, const ViewFactorisation& f);
// Throws InputError, naming the scene key, for a distance beyond its register.
CutRegs permute_cut_plane(const Scene& s, const ViewFactorisation& f);

// Fixed-point scale of cut-plane normals: components are round(n * 2^kCutNormalBits).
constexpr int kCutNormalBits = 10;

}  // namespace cube4::golden
