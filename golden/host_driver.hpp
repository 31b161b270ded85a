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
