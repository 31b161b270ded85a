// The RTL package (rtl/cube4_pkg.sv) against the C++ side: every unit's
// default width comes from the package, every golden default from
// golden::Precision{}, and the two must be the same numbers. Verilator
// exports the package's public constants as V<model>_cube4_pkg (here the
// model Vpkg, a verilated cube4_lerp, built only to read the package).
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "Vpkg_cube4_pkg.h"
#include "golden/precision.hpp"
#include "golden/units/composite_crop.hpp"
#include "golden/units/composite_cut_plane.hpp"
#include "golden/units/composite_polygon.hpp"
#include "golden/units/rle_decode.hpp"

namespace {

namespace g = cube4::golden;
using Pkg = Vpkg_cube4_pkg;

struct PackageWidth {
  const char* name;  // the parameter's name in the package and in the units
  long value;
};

// The package's golden-width constants, by the names kPrecisionFields gives
// as rtl_parameter.
constexpr PackageWidth kPackageWidths[] = {
    {"VoxelBits", Pkg::VoxelBits},       {"WeightBits", Pkg::WeightBits},
    {"GradientBits", Pkg::GradientBits}, {"GradientShift", Pkg::GradientShift},
    {"MagnitudeBits", Pkg::MagnitudeBits}, {"NrIterations", Pkg::NrIterations},
    {"ColorBits", Pkg::ColorBits},       {"AlphaBits", Pkg::AlphaBits},
    {"GmlutBits", Pkg::GmlutBits},       {"MapFaceRes", Pkg::MapFaceRes},
    {"MapBits", Pkg::MapBits},           {"MapFracBits", Pkg::MapFracBits},
    {"CoefBits", Pkg::CoefBits},         {"CoefFracBits", Pkg::CoefFracBits},
    {"EyeBits", Pkg::EyeBits},           {"CutBits", Pkg::CutBits},
    {"AccGuardBits", Pkg::AccGuardBits}, {"VoxelTagBits", Pkg::VoxelTagBits},
    {"FracBits", Pkg::FracBits},
};

TEST(RtlPackage, DefaultsAreGoldens) {
  const g::Precision golden{};
  int matched = 0;
  for (const g::PrecisionField& f : g::kPrecisionFields) {
    if (f.rtl_parameter == nullptr) continue;
    const PackageWidth* w = nullptr;
    for (const PackageWidth& p : kPackageWidths)
      if (std::strcmp(p.name, f.rtl_parameter) == 0) w = &p;
    ASSERT_NE(w, nullptr) << "precision field " << f.key << ": cube4_pkg has no " << f.rtl_parameter;
    EXPECT_EQ(w->value, golden.*f.member) << "cube4_pkg::" << f.rtl_parameter << " against golden " << f.key;
    ++matched;
  }
  // A package width that no precision field names is a width golden lacks.
  EXPECT_EQ(matched, static_cast<int>(sizeof kPackageWidths / sizeof kPackageWidths[0]));
}

// The widths the register map and the unit wrappers state in C++.
static_assert(Pkg::CutCoefBits == g::kCutCoefBits, "cut-plane a, b, c width");
static_assert(Pkg::PosBits == g::kPositionBits, "sample position width");
static_assert(Pkg::ZBits == g::kZBits && Pkg::ZFracBits == g::kZFracBits, "a ray's depth Z");
static_assert(Pkg::SliceBits + Pkg::ZFracBits == Pkg::ZBits, "k << ZFracBits fits Z for every k");
static_assert((1 << Pkg::RleWordBits) == g::kRleRunMax, "a slab line's word holds a run length less one");

}  // namespace
