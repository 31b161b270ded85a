// Golden unit functions on hand-computed cases and properties. These are the
// functions the RTL must equal, so their corner behaviour is pinned here.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "golden/pipeline.hpp"

using namespace cube4::golden;

namespace {
const Precision kP = volumepro_precision();  // VolumePro widths
}

TEST(Fixed, RoundShiftRoundsHalfUp) {
  EXPECT_EQ(round_shift(5, 1), 3);    // 2.5 -> 3
  EXPECT_EQ(round_shift(-5, 1), -2);  // -2.5 -> -2
  EXPECT_EQ(round_shift(4, 1), 2);
  EXPECT_EQ(round_shift(-6, 2), -1);  // -1.5 -> -1
  EXPECT_EQ(round_shift(7, 0), 7);
}

TEST(Fixed, SaturationIsSymmetricAndNeverWraps) {
  EXPECT_EQ(sat_signed(1000, 8), 127);
  EXPECT_EQ(sat_signed(-1000, 8), -127);
  EXPECT_EQ(sat_signed(-128, 8), -127);
  EXPECT_EQ(sat_unsigned(-1, 12), 0);
  EXPECT_EQ(sat_unsigned(5000, 12), 4095);
}

TEST(Fixed, ExpandBitsKeepsTheEnds) {
  EXPECT_EQ(expand_bits(0, 8, 12), 0);
  EXPECT_EQ(expand_bits(255, 8, 12), 4095);
  EXPECT_EQ(expand_bits(0x80, 8, 12), 0x808);
  EXPECT_EQ(expand_bits(4095, 12, 16), 65535);
  EXPECT_EQ(expand_bits(0xABC, 12, 16), 0xABCA);
  EXPECT_EQ(expand_bits(15, 4, 12), 4095);
  for (int v = 0; v < 256; ++v) EXPECT_EQ(expand_bits(v, 8, 12) >> 4, v);
}

TEST(Fixed, MulFracFullIsIdentityZeroIsZeroAndNeverGrows) {
  for (int n : {8, 12, 16}) {
    const int64_t one = max_unsigned(n);
    for (int64_t x = 0; x < (int64_t{1} << 16); x += 7) {
      EXPECT_EQ(mul_frac(x, one, n), x) << "n=" << n << " x=" << x;
      EXPECT_EQ(mul_frac(x, 0, n), 0);
    }
  }
  for (int64_t x = 0; x <= 4095; x += 13)
    for (int64_t f = 0; f <= 4095; ++f) {
      const int64_t m = mul_frac(x, f, 12);
      ASSERT_LE(m, x);
      if (f > 0) {
        ASSERT_GE(m, mul_frac(x, f - 1, 12)) << "not monotonic at x=" << x << " f=" << f;
      }
      // Within one LSB of the exact product x*f/4095.
      ASSERT_LE(std::fabs(m - x * f / 4095.0), 1.0) << x << " " << f;
    }
}

TEST(Trilinear, LerpEndsReturnVoxelsExactly) {
  for (int a : {0, 1, 2048, 4095})
    for (int b : {0, 7, 4095}) {
      EXPECT_EQ(lerp(a, b, 0, 8), a);
      EXPECT_EQ(lerp(a, b, 256, 8), b);
    }
  EXPECT_EQ(lerp(100, 200, 128, 8), 150);
  EXPECT_EQ(lerp(0, 4095, 1, 8), 16);    // 15.996 -> 16
  EXPECT_EQ(lerp(4095, 0, 1, 8), 4079);  // 4095 - 15.996 -> 4079
}

TEST(Trilinear, ResultStaysBetweenItsVoxels) {
  std::mt19937 gen(7);
  for (int i = 0; i < 200000; ++i) {
    std::array<uint32_t, 8> v;
    for (auto& x : v) x = gen() & 4095;
    const uint32_t wx = gen() % 257, wy = gen() % 257, wz = gen() % 257;
    const uint32_t s = trilinear(v, wx, wy, wz, 8);
    ASSERT_GE(s, *std::min_element(v.begin(), v.end()));
    ASSERT_LE(s, *std::max_element(v.begin(), v.end()));
  }
}

TEST(Trilinear, WeightLimitsPickCorners) {
  const std::array<uint32_t, 8> v{10, 20, 30, 40, 50, 60, 70, 4095};
  EXPECT_EQ(trilinear(v, 0, 0, 0, 8), 10u);
  EXPECT_EQ(trilinear(v, 256, 0, 0, 8), 20u);
  EXPECT_EQ(trilinear(v, 0, 256, 0, 8), 30u);
  EXPECT_EQ(trilinear(v, 0, 0, 256, 8), 50u);
  EXPECT_EQ(trilinear(v, 256, 256, 256, 8), 4095u);
  const std::array<uint32_t, 8> full{4095, 4095, 4095, 4095, 4095, 4095, 4095, 4095};
  EXPECT_EQ(trilinear(full, 255, 255, 255, 8), 4095u);  // maximum voxels, maximum weights
  // x first: 0.5 between 0 and 1 rounds up to 1 before y and z see it.
  const std::array<uint32_t, 8> odd{0, 1, 0, 1, 0, 1, 0, 1};
  EXPECT_EQ(trilinear(odd, 128, 0, 0, 8), 1u);
}

TEST(Dda, SplitTruncatesAndFloors) {
  const int F = 20, W = 8;
  const SliceOffset a = dda_split((int64_t{3} << F) + (int64_t{1} << (F - 1)), F, W);
  EXPECT_EQ(a.integer, 3);
  EXPECT_EQ(a.weight, 128u);
  const SliceOffset b = dda_split(-1, F, W);  // just below zero
  EXPECT_EQ(b.integer, -1);
  EXPECT_EQ(b.weight, 255u);
  const SliceOffset c = dda_split((int64_t{1} << (F - W)) - 1, F, W);  // below one weight LSB
  EXPECT_EQ(c.weight, 0u);
}

TEST(Dda, ZWeightsForEverySupersampling) {
  for (int S = 1; S <= 8; ++S)
    for (int k = 0; k < 3 * S; ++k) {
      EXPECT_EQ(z_voxel_slice(k, S), k / S);
      EXPECT_EQ(z_weight(k, S, 8), static_cast<uint32_t>((k % S) * 256 / S));
    }
  EXPECT_EQ(z_weight(1, 3, 8), 85u);
  EXPECT_EQ(z_weight(2, 3, 8), 170u);
}

TEST(Dda, LongRunsDoNotDrift) {
  // The accumulated position equals start + k*step exactly, and its distance
  // from the real ray offset is bounded by the step's rounding times k: below
  // one weight LSB for up to 2^(F-W) - 1 slices (4095 with VolumePro's widths,
  // i.e. 8x supersampling of 511 voxels).
  const int F = kP.dda_frac_bits;
  const double shear = 0.7071067811865476, S = 8;
  const int64_t start = std::llround(0.3 * (1 << F));
  const int64_t step = std::llround(shear / S * (1 << F));
  int64_t acc = start;
  const int slices = (1 << (F - kP.weight_bits)) - 1;
  for (int k = 0; k < slices; ++k) {
    ASSERT_EQ(acc, dda_position(start, step, k));
    const double exact = 0.3 + k * shear / S;
    ASSERT_LE(std::fabs(acc / double(1 << F) - exact), (k + 1) * std::ldexp(0.5, -F)) << k;
    acc += step;
  }
  EXPECT_LT((slices + 1) * std::ldexp(0.5, -F), std::ldexp(1.0, -kP.weight_bits));
}

TEST(Dda, RealignCoversBothSides) {
  EXPECT_EQ(realign(100, 40, 8).base, 0);
  EXPECT_EQ(realign(100, 40, 8).weight, 60u);
  EXPECT_EQ(realign(40, 100, 8).base, -1);
  EXPECT_EQ(realign(40, 100, 8).weight, 196u);
  EXPECT_EQ(realign(7, 7, 8).weight, 0u);
}

TEST(Gradient, SaturatesInsteadOfWrapping) {
  Precision p;
  p.gradient_shift = 0;
  EXPECT_EQ(gradient_component(4095, p), 127);
  EXPECT_EQ(gradient_component(-4095, p), -127);
  EXPECT_EQ(gradient_component(128, p), 127);
  EXPECT_EQ(gradient_component(-128, p), -127);
  // Default shift 5: the largest 12-bit difference just fits.
  EXPECT_EQ(gradient_component(4095, kP), 127);  // 127.97 -> 128 -> saturated
  EXPECT_EQ(gradient_component(-4095, kP), -127);
  EXPECT_EQ(gradient_component(48, kP), 2);       // 1.5 -> 2
  EXPECT_EQ(gradient_component(-48, kP), -1);     // -1.5 -> -1 (half up)
}

TEST(Gradient, TwelveNeighbourhoodHandCase) {
  // x: (300 - 100), y: (50 - 250), z: ahead 400 behind 80, shift 5.
  const Gradient g = gradient_12n(100, 300, 250, 50, 80, 400, 1, kP);
  EXPECT_EQ(g, (Gradient{6, -6, 10}));  // 200/32 = 6.25, -200/32 = -6.25, 320/32 = 10
  // Supersampling scales the z difference to per-voxel units.
  EXPECT_EQ(gradient_12n(0, 0, 0, 0, 80, 400, 2, kP).z, 20);
  // The ABC sample at zero re-alignment weight is the aligned sample itself.
  EXPECT_EQ(abc_sample(123, 9, 9, 9, 0, 0, 8), 123u);
}

TEST(Magnitude, NewtonRaphsonWithinOneOfFloorSqrt) {
  for (uint64_t q = 0; q <= 3 * 127 * 127; ++q) {
    const uint32_t r = newton_sqrt(q, kP.nr_iterations);
    const auto f = static_cast<uint32_t>(std::floor(std::sqrt(static_cast<double>(q))));
    ASSERT_TRUE(r == f || r == f + 1) << "q=" << q << " got " << r << " floor " << f;
  }
  EXPECT_EQ(gradient_magnitude({0, 0, 0}, kP), 0u);
  const uint32_t m = gradient_magnitude({127, -127, 127}, kP);
  EXPECT_TRUE(m == 219u || m == 220u) << m;  // VolumePro: 0..220
  Precision narrow = kP;
  narrow.magnitude_bits = 6;
  EXPECT_EQ(gradient_magnitude({127, 127, 127}, narrow), 63u);  // saturates
}

TEST(Classify, AlphaModulationEnds) {
  EXPECT_EQ(modulate_alpha(3000, gm_unit(255, kP), kP), 3000u);
  EXPECT_EQ(modulate_alpha(3000, gm_unit(0, kP), kP), 0u);
  EXPECT_EQ(gm_unit(255, kP), 4095u);
}

TEST(CubeMap, ZeroVectorIsInvalidAndGivesNoLight) {
  const CubeCoord c = cube_coordinates(0, 0, 0, kP);
  EXPECT_FALSE(c.valid);
  std::vector<uint32_t> map(384, 500);
  EXPECT_EQ(reflectance_lookup(map, c, kP), 0u);
}

TEST(CubeMap, EveryFaceCentreEdgeAndCorner) {
  const int res = kP.map_face_res;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {1, -1}) {
      int32_t v[3] = {0, 0, 0};
      v[axis] = 127 * sign;
      const CubeCoord centre = cube_coordinates(v[0], v[1], v[2], kP);
      EXPECT_EQ(centre.face, 2 * axis + (sign < 0));
      EXPECT_EQ(centre.u, 3u);  // 3.5 cells: between entries 3 and 4
      EXPECT_EQ(centre.wu, 128u);
      // Near the far edge in u and the near edge in v, (253*7*256)/254 and
      // (1*7*256)/254 truncated.
      v[face_axis_u(axis)] = 126;
      v[face_axis_v(axis)] = -126;
      const CubeCoord near_corner = cube_coordinates(v[0], v[1], v[2], kP);
      EXPECT_EQ(near_corner.face, 2 * axis + (sign < 0));
      EXPECT_EQ(near_corner.u, 6u);
      EXPECT_EQ(near_corner.wu, 248u);
      EXPECT_EQ(near_corner.v, 0u);
      EXPECT_EQ(near_corner.wv, 7u);
    }
  // Exactly on a cube edge or corner the lower axis wins the tie, and the far
  // edge is the last cell at full weight so that u+1 stays on the face.
  for (int sign : {1, -1}) {
    const CubeCoord corner = cube_coordinates(127 * sign, 127, -127, kP);
    EXPECT_EQ(corner.face, sign > 0 ? 0 : 1);
    EXPECT_EQ(corner.u, static_cast<uint32_t>(res - 2));
    EXPECT_EQ(corner.wu, 256u);
    EXPECT_EQ(corner.v, 0u);
    EXPECT_EQ(corner.wv, 0u);
  }
  EXPECT_EQ(cube_coordinates(5, 5, 5, kP).face, 0);
  EXPECT_EQ(cube_coordinates(1, -5, 5, kP).face, 3);
  EXPECT_EQ(cube_coordinates(0, 0, -1, kP).face, 5);
}

TEST(CubeMap, LookupAtGridPointsReturnsEntries) {
  std::vector<uint32_t> map(384);
  for (size_t i = 0; i < map.size(); ++i) map[i] = static_cast<uint32_t>(i * 37 % 4096);
  // Face +z, entry (u=1, v=2) sits at direction (-1 + 2/7, -1 + 4/7, 1).
  EXPECT_EQ(reflectance_lookup(map, cube_coordinates(-90, -54, 126, kP), kP), map[map_index(4, 1, 2, 8)]);
  EXPECT_EQ(reflectance_lookup(map, cube_coordinates(100, 100, 100, kP), kP), map[map_index(0, 7, 7, 8)]);
  std::vector<uint32_t> flat(384, 256);
  std::mt19937 gen(3);
  for (int i = 0; i < 10000; ++i) {
    const int32_t x = int32_t(gen() % 255) - 127, y = int32_t(gen() % 255) - 127, z = int32_t(gen() % 255) - 127;
    if (!x && !y && !z) continue;
    ASSERT_EQ(reflectance_lookup(flat, cube_coordinates(x, y, z, kP), kP), 256u);
  }
}

TEST(Reflection, MirrorsTheEyeAboutTheNormal) {
  const Eye e{0, 0, 127};
  const Gradient along = reflection_vector({0, 0, 127}, e, kP);
  EXPECT_EQ(along.x, 0);
  EXPECT_EQ(along.y, 0);
  EXPECT_GT(along.z, 100);
  // Normal at 45° in x-z: the eye (0,0,1) reflects to (1,0,0).
  const Gradient r = reflection_vector({90, 0, 90}, e, kP);
  EXPECT_GT(r.x, 100);
  EXPECT_EQ(r.y, 0);
  EXPECT_LE(std::abs(r.z), 1);
  EXPECT_EQ(reflection_vector({0, 0, 0}, e, kP), (Gradient{0, 0, 0}));
  EXPECT_LE(std::abs(reduce_vector(1 << 30, -(1 << 29), 3, 8).x), 127);
}

TEST(Phong, NoLightGivesEmissiveAndUnitEmissiveIsIdentity) {
  ShadeCoefs k;
  k.ke = 1 << kP.coef_frac_bits;  // 1.0
  k.kd = 200;
  k.ks = 300;
  k.specular = {4095, 4095, 4095};
  const Rgb c{1000, 2000, 4095};
  // Zero gradient: the maps give Id = Is = 0, so only ke·colour remains.
  EXPECT_EQ(phong(c, 0, 0, 4095, 4095, k, kP), c);
  ShadeCoefs half;
  half.ke = 128;
  EXPECT_EQ(phong(c, 0, 0, 4095, 4095, half, kP), (Rgb{500, 1000, 2048}));
  // Saturation, not wrap-around, for a bright highlight.
  ShadeCoefs hot;
  hot.ks = 1023;
  hot.specular = {4095, 4095, 4095};
  EXPECT_EQ(phong(c, 0, 65535, 4095, 4095, hot, kP), (Rgb{4095, 4095, 4095}));
  // Modulation by a zero GmLUT value removes the diffuse and specular terms.
  EXPECT_EQ(phong(c, 300, 300, 0, 0, k, kP), c);
}

TEST(Composite, MonotonicAndNeverPastFullOpacity) {
  std::mt19937 gen(11);
  for (int ray = 0; ray < 2000; ++ray) {
    RayAcc acc;
    for (int i = 0; i < 300; ++i) {
      ShadedSample s;
      s.alpha = gen() % 4096;
      s.rgb = {static_cast<uint32_t>(gen() % 4096), static_cast<uint32_t>(gen() % 4096),
               static_cast<uint32_t>(gen() % 4096)};
      const RayAcc next = blend_front_to_back(acc, s, kP);
      ASSERT_GE(next.a, acc.a);
      ASSERT_LE(next.a, 4095);
      ASSERT_GE(next.r, acc.r);
      ASSERT_LE(next.r, 4095);
      acc = next;
    }
  }
}

TEST(Composite, WithoutGuardBitsIsVolumeProsTwoRoundings) {
  // acc_guard_bits = 0: premultiply() is mul_frac(c, α) and the accumulator
  // domain is the sample's, so the blend is VolumePro's
  // C += mul_frac(t, mul_frac(c, α)), α += mul_frac(t, α), exactly.
  std::mt19937 gen(12);
  for (int i = 0; i < 200000; ++i) {
    RayAcc acc;
    acc.a = gen() % 4096;
    acc.r = gen() % 4096;
    ShadedSample s;
    s.alpha = gen() % 4096;
    s.rgb = {static_cast<uint32_t>(gen() % 4096), 0, 0};
    const RayAcc next = blend_front_to_back(acc, s, kP);
    const int64_t t = 4095 - acc.a;
    ASSERT_EQ(next.r, static_cast<uint32_t>(sat_unsigned(acc.r + mul_frac(t, mul_frac(s.rgb[0], s.alpha, 12), 12), 12)));
    ASSERT_EQ(next.a, static_cast<uint32_t>(acc.a + mul_frac(t, s.alpha, 12)));
    ASSERT_EQ(pixel_of(next, kP).r, next.r);
  }
}

TEST(Composite, GuardBitsKeepSubLsbContributions) {
  // Defaults: one 16-bit LSB of α and a 10 % colour premultiply to 0.1 LSB,
  // which 16 bits round to zero; the accumulator keeps them.
  const Precision p;
  EXPECT_EQ(mul_frac(6554, 1, p.alpha_bits), 0);
  ShadedSample s;
  s.alpha = 1;
  s.rgb = {6554, 0, 0};
  EXPECT_EQ(premultiply(6554, 1, p), 26u);  // 6554 · 2^8 / 2^16 = 25.6
  RayAcc acc;
  for (int i = 0; i < 1000; ++i) acc = blend_front_to_back(acc, s, p);
  // 1000 samples of α = 1/65535: α ≈ 0.01514 of full scale; colour 0.1 of it.
  const double a = 1 - std::pow(1 - 1 / 65535.0, 1000);
  EXPECT_NEAR(pixel_of(acc, p).a / 65535.0, a, 1e-4);
  EXPECT_NEAR(pixel_of(acc, p).r / 65535.0, 0.1 * a, 1e-4);
}

TEST(Composite, PremultipliedColourNeverExceedsAlpha) {
  // Every α with full colour, and random colours: P <= to_acc(α), and full
  // colour at full α is full. Without premultiply()'s clamp the bit
  // replication of the colour carries P past to_acc(α) for α >= 1/2.
  const Precision p;
  int clamped = 0;
  for (uint32_t a = 0; a < 65536; ++a) {
    const uint32_t full = premultiply(65535, a, p);
    ASSERT_LE(full, to_acc(a, p)) << a;
    clamped += mul_frac(to_acc(65535, p), a, p.alpha_bits) > to_acc(a, p);
    ASSERT_LE(premultiply(a * 7919u % 65536, a, p), to_acc(a, p)) << a;
  }
  EXPECT_GT(clamped, 0) << "the clamp is needed somewhere, or the test proves nothing";
  EXPECT_EQ(premultiply(65535, 65535, p), to_acc(65535, p));
}

TEST(Composite, PixelOfScalesTheAccumulatorDomainExactlyEnough) {
  // Every accumulator value: monotonic, full -> full, 0 -> 0, and within
  // 1/2 + 2^-g LSB of the exact scaling v (2^n - 1) / (2^A - 1).
  const Precision p;
  const uint32_t full = static_cast<uint32_t>(max_unsigned(acc_bits(p)));
  const double scale = 65535.0 / full, limit = 0.5 + std::ldexp(1.0, -p.acc_guard_bits);
  uint16_t previous = 0;
  for (uint32_t v = 0; v <= full; ++v) {
    const uint16_t px = acc_to_pixel(v, p);
    ASSERT_GE(px, previous) << v;
    ASSERT_LE(std::fabs(px - v * scale), limit) << v;
    previous = px;
  }
  EXPECT_EQ(acc_to_pixel(full, p), 65535);
  EXPECT_EQ(acc_to_pixel(0, p), 0);
  EXPECT_EQ(acc_to_pixel(to_acc(12345, p), p), 12345);
}

TEST(Composite, DefaultWidthsMonotonicAndNeverPastFullOpacity) {
  const Precision p;
  const uint32_t full = static_cast<uint32_t>(max_unsigned(acc_bits(p)));
  std::mt19937 gen(13);
  for (int ray = 0; ray < 2000; ++ray) {
    RayAcc acc;
    for (int i = 0; i < 300; ++i) {
      ShadedSample s;
      s.alpha = gen() % 65536;
      s.rgb = {static_cast<uint32_t>(gen() % 65536), static_cast<uint32_t>(gen() % 65536),
               static_cast<uint32_t>(gen() % 65536)};
      const RayAcc next = blend_front_to_back(acc, s, p);
      ASSERT_GE(next.a, acc.a);
      ASSERT_LE(next.a, full);
      ASSERT_GE(next.r, acc.r);
      ASSERT_LE(next.r, full);
      ASSERT_LE(pixel_of(next, p).r, 65535);
      acc = next;
    }
  }
  // Full α stops the ray in the accumulator domain, as at 12 bits.
  ShadedSample opaque;
  opaque.alpha = 65535;
  opaque.rgb = {65535, 0, 100};
  const RayAcc stopped = blend_front_to_back(RayAcc{}, opaque, p);
  EXPECT_EQ(stopped.a, full);
  EXPECT_EQ(pixel_of(stopped, p).a, 65535);
  EXPECT_EQ(pixel_of(stopped, p).b, 100);
  opaque.rgb = {0, 65535, 65535};
  EXPECT_EQ(blend_front_to_back(stopped, opaque, p), stopped);
}

TEST(Composite, OpaqueSampleStopsTheRay) {
  ShadedSample s;
  s.alpha = 4095;
  s.rgb = {4095, 0, 100};
  RayAcc acc = blend_front_to_back(RayAcc{}, s, kP);
  EXPECT_EQ(acc, (RayAcc{4095, 0, 100, 4095, 0, false}));
  s.rgb = {0, 4095, 4095};
  EXPECT_EQ(blend_front_to_back(acc, s, kP), acc);
}

TEST(Composite, VeryLowOpacityOverHundredsOfSamples) {
  // α = 1 LSB for 300 samples: each step adds round((4095 - α_acc)/4096),
  // one while the remaining transparency is at least half. Float: 1-(1-1/4095)^300.
  ShadedSample s;
  s.alpha = 1;
  s.rgb = {4095, 4095, 4095};
  RayAcc acc;
  for (int i = 0; i < 300; ++i) acc = blend_front_to_back(acc, s, kP);
  EXPECT_EQ(acc.a, 300);
  const double exact = (1 - std::pow(1 - 1 / 4095.0, 300)) * 4095;
  // Bound derived in docs/fixed-point.md: at most N·acc/4095 + 0.5 LSB above.
  EXPECT_LE(acc.a - exact, 300.0 * 300 / 4095 / 2 + 0.5 + 1);
  // Never stuck at zero, never beyond half without larger α.
  for (int i = 0; i < 5000; ++i) acc = blend_front_to_back(acc, s, kP);
  EXPECT_EQ(acc.a, 2048);
}

TEST(Composite, MipAndMinIpKeepTheExtremeAndTheFirstTie) {
  auto sample = [](uint32_t v, uint32_t r) {
    ShadedSample s;
    s.value = v;
    s.alpha = 4095;
    s.rgb = {r, 0, 0};
    return s;
  };
  RayAcc mx, mn;
  for (auto [v, r] : std::vector<std::pair<uint32_t, uint32_t>>{{5, 1}, {9, 2}, {9, 3}, {2, 4}, {2, 5}}) {
    mx = blend(BlendMode::Mip, mx, sample(v, r), kP);
    mn = blend(BlendMode::MinIp, mn, sample(v, r), kP);
  }
  EXPECT_EQ(mx.value, 9);
  EXPECT_EQ(mx.r, 2);
  EXPECT_EQ(mn.value, 2);
  EXPECT_EQ(mn.r, 4);
  ShadedSample hidden = sample(4000, 7);
  hidden.visible = false;
  EXPECT_EQ(blend(BlendMode::Mip, mx, hidden, kP), mx);
}

// The compositing node (golden/units/compose.hpp) at the default widths
// (A = 24) and VolumePro's (A = 12).
namespace {
RayAcc random_partial_pixel(std::mt19937& gen, const Precision& p) {
  const uint32_t full = static_cast<uint32_t>(max_unsigned(acc_bits(p)));
  RayAcc x;
  x.a = gen() % (full + 1);
  const uint32_t cmax = gen() % 4 ? x.a : full;  // premultiplied, or any colour
  x.r = gen() % (cmax + 1);
  x.g = gen() % (cmax + 1);
  x.b = gen() % (cmax + 1);
  x.value = static_cast<uint16_t>(gen() % 4096);
  x.valid = gen() % 4 != 0;
  return x;
}
bool same_colour(const RayAcc& x, const RayAcc& y) { return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a; }
}  // namespace

TEST(Compose, OverWithAnEmptyOrOpaquePixelIsExact) {
  for (const Precision& p : {Precision{}, kP}) {
    const uint32_t full = static_cast<uint32_t>(max_unsigned(acc_bits(p)));
    std::mt19937 gen(21);
    for (int i = 0; i < 100000; ++i) {
      const RayAcc x = random_partial_pixel(gen, p);
      // Nothing behind: the front unchanged, value and selection included.
      ASSERT_EQ(compose_over(x, RayAcc{}, p), x);
      // Nothing in front: the back's colour and α (mul_frac(full, c) = c);
      // over carries the front's value and selection.
      ASSERT_TRUE(same_colour(compose_over(RayAcc{}, x, p), x));
      // An opaque front hides the back.
      RayAcc opaque = random_partial_pixel(gen, p);
      opaque.a = full;
      ASSERT_EQ(compose_over(opaque, x, p), opaque);
    }
  }
}

// What blend_changes_ray() lets a model skip leaves every ray exactly as it
// was, in every blend mode; what it keeps, compositing, is a sample with α.
TEST(Composite, SamplesThatCannotChangeARayLeaveItExactly) {
  for (const Precision& p : {Precision{}, kP}) {
    std::mt19937 gen(23);
    const uint32_t sample_full = static_cast<uint32_t>(max_unsigned(p.alpha_bits));
    for (int i = 0; i < 100000; ++i) {
      const RayAcc acc = random_partial_pixel(gen, p);
      ShadedSample s;
      auto channel = [&] { return static_cast<uint32_t>(gen() % (sample_full + 1)); };
      s.rgb = {channel(), channel(), channel()};
      s.alpha = i % 2 ? 0 : channel();
      s.value = static_cast<uint32_t>(gen() % 4096);
      s.visible = i % 3 != 0;
      for (const BlendMode mode : {BlendMode::Composite, BlendMode::Mip, BlendMode::MinIp}) {
        if (!blend_changes_ray(mode, s)) {
          ASSERT_EQ(blend(mode, acc, s, p), acc) << i;
        }
      }
      ASSERT_EQ(blend_changes_ray(BlendMode::Composite, s), s.visible && s.alpha != 0);
    }
  }
}

TEST(Compose, OverNeverPassesFullOpacityAndSaturatesColour) {
  for (const Precision& p : {Precision{}, kP}) {
    const uint32_t full = static_cast<uint32_t>(max_unsigned(acc_bits(p)));
    std::mt19937 gen(22);
    for (int i = 0; i < 100000; ++i) {
      const RayAcc f = random_partial_pixel(gen, p), b = random_partial_pixel(gen, p);
      const RayAcc r = compose_over(f, b, p);
      ASSERT_GE(r.a, f.a);
      ASSERT_LE(r.a, full);
      ASSERT_LE(r.a - f.a, full - f.a);  // at most the front's transparency
      for (auto [c, cf] : {std::pair{r.r, f.r}, std::pair{r.g, f.g}, std::pair{r.b, f.b}}) {
        ASSERT_GE(c, cf);
        ASSERT_LE(c, full);
      }
      ASSERT_EQ(r.value, f.value);
      ASSERT_EQ(r.valid, f.valid);
    }
    // Saturation: a full front colour over a full back at half opacity.
    const RayAcc f{full, full, 0, full / 2, 0, false}, b{full, 0, full, full, 0, false};
    const RayAcc r = compose_over(f, b, p);
    EXPECT_EQ(r.r, full);
    EXPECT_EQ(r.g, full);
    EXPECT_EQ(r.b, static_cast<uint32_t>(mul_frac(full - full / 2, full, acc_bits(p))));
    EXPECT_EQ(r.a, full);
  }
  // A hand case at VolumePro's widths: t = 4095 - 1000 = 3095,
  // mul_frac(3095, 2000, 12) = round(3095 · 2000 / 4096) = 1511 (1511.2).
  EXPECT_EQ(compose_over(RayAcc{500, 0, 0, 1000, 0, false}, RayAcc{2000, 0, 0, 2000, 0, false}, kP),
            (RayAcc{2011, 0, 0, 2511, 0, false}));
}

TEST(Compose, ExtremeTiesKeepTheFrontAndNothingSelectedLoses) {
  const RayAcc f{1, 2, 3, 4, 100, true}, b{5, 6, 7, 8, 100, true};
  for (bool maximum : {true, false}) {
    EXPECT_EQ(compose_extreme(f, b, maximum), f);  // a tie
    RayAcc unsel = b;
    unsel.valid = false;
    unsel.value = maximum ? 4095 : 0;
    EXPECT_EQ(compose_extreme(f, unsel, maximum), f);  // the back has nothing selected
    RayAcc none = f;
    none.valid = false;
    none.value = maximum ? 4095 : 0;
    EXPECT_EQ(compose_extreme(none, b, maximum), b);  // the front has nothing selected
    EXPECT_EQ(compose_extreme(none, unsel, maximum), none);
  }
  RayAcc hi = b;
  hi.value = 101;
  EXPECT_EQ(compose_extreme(f, hi, true), hi);
  EXPECT_EQ(compose_extreme(f, hi, false), f);
  EXPECT_EQ(compose_extreme(hi, f, false), f);
  // Mode 3 of the register is over, as in the compositor.
  EXPECT_EQ(compose(static_cast<BlendMode>(3), f, b, kP), compose_over(f, b, kP));
}

// The compositor's blend is the node with the sample behind: an invisible
// sample is the empty pixel, which changes no ray in any mode.
TEST(Compose, BlendOfAnInvisibleSampleLeavesTheRay) {
  std::mt19937 gen(23);
  for (const Precision& p : {Precision{}, kP})
    for (BlendMode mode : {BlendMode::Composite, BlendMode::Mip, BlendMode::MinIp})
      for (int i = 0; i < 20000; ++i) {
        const RayAcc acc = random_partial_pixel(gen, p);
        ShadedSample s;
        s.rgb = {static_cast<uint32_t>(gen() % 4096), 0, 4095};
        s.alpha = gen() % 4096;
        s.value = i % 4 == 0 ? acc.value : gen() % 4096;  // ties too: they keep the ray
        s.visible = false;
        ASSERT_EQ(blend(mode, acc, s, p), acc);
        s.visible = true;
        ASSERT_EQ(blend(mode, acc, s, p), compose(mode, acc, sample_pixel(s, p), p));
      }
}

TEST(Compose, UnderlayAndOverlayAreTheNodeWithALayer) {
  std::mt19937 gen(24);
  const Precision p;
  const uint32_t full = static_cast<uint32_t>(max_unsigned(acc_bits(p)));
  const RayAcc black{0, 0, 0, full, 0, false};
  for (int i = 0; i < 10000; ++i) {
    const RayAcc x = random_partial_pixel(gen, p);
    // An opaque black background: the pixel's colour, full opacity.
    const RayAcc u = underlay(BlendMode::Composite, x, black, p);
    EXPECT_EQ(u.r, x.r);
    EXPECT_EQ(u.g, x.g);
    EXPECT_EQ(u.b, x.b);
    EXPECT_EQ(u.a, full);
    // No overlay (an empty layer): the pixel's colour.
    EXPECT_TRUE(same_colour(overlay(BlendMode::Composite, RayAcc{}, x, p), x));
    const RayAcc glass = random_partial_pixel(gen, p);
    EXPECT_EQ(overlay(BlendMode::Composite, glass, x, p), compose_over(glass, x, p));
    EXPECT_EQ(underlay(BlendMode::Mip, x, glass, p), compose_extreme(x, glass, true));
  }
}

// Tree and chain compose the same images; MIP/MinIP select without
// rounding, and ties keep the front in both, so there the two are equal.
// (Over rounds differently in each: docs/accuracy.md measures how much.)
TEST(Compose, TreeEqualsChainForMipAndMinIp) {
  std::mt19937 gen(25);
  const Precision p;
  for (int n : {1, 2, 3, 4, 5, 7, 8, 16, 33, 64})
    for (int i = 0; i < 2000; ++i) {
      std::vector<RayAcc> px(static_cast<size_t>(n));
      for (RayAcc& x : px) {
        x = random_partial_pixel(gen, p);
        x.value = static_cast<uint16_t>(gen() % 8);  // many ties
      }
      for (BlendMode mode : {BlendMode::Mip, BlendMode::MinIp})
        ASSERT_EQ(compose_tree(mode, px.data(), n, p), compose_chain(mode, px.data(), n, p)) << n;
    }
  const RayAcc two[] = {RayAcc{1, 2, 3, 400, 0, false}, RayAcc{50, 60, 70, 800, 0, false}};
  EXPECT_EQ(compose_tree(BlendMode::Composite, two, 2, kP), compose_over(two[0], two[1], kP));
  EXPECT_EQ(compose_chain(BlendMode::Composite, two, 0, kP), RayAcc{});
}

TEST(RayAlign, PredecessorsAndSideEntries) {
  EXPECT_EQ(predecessor_index(1, 1), 3);
  EXPECT_FALSE(ray_predecessor(0, 5, 1, 0).exists);
  EXPECT_FALSE(ray_predecessor(5, 0, 0, 1).exists);
  const Predecessor p = ray_predecessor(4, 6, 1, 1);
  EXPECT_TRUE(p.exists);
  EXPECT_EQ(p.x, 3);
  EXPECT_EQ(p.y, 5);
  EXPECT_TRUE(ray_leaves(9, 3, 1, 0, 10, 10));
  EXPECT_FALSE(ray_leaves(9, 3, 0, 0, 10, 10));
}

TEST(Crop, SlabBoundariesAreInclusive) {
  CropRegs c;
  c.slab = {{{2, 5}, {0, 9}, {3, 3}}};
  c.mask = 0x80;  // intersection
  EXPECT_TRUE(crop_visible(2, 0, 3, c));
  EXPECT_TRUE(crop_visible(5, 9, 3, c));
  EXPECT_FALSE(crop_visible(6, 0, 3, c));
  EXPECT_FALSE(crop_visible(1, 0, 3, c));
  EXPECT_FALSE(crop_visible(3, 3, 4, c));
  c.mask = 0xFE;  // union
  EXPECT_TRUE(crop_visible(9, 20, 3, c));
  EXPECT_FALSE(crop_visible(9, 20, 4, c));
}

TEST(CutPlane, InsideRampAndOutside) {
  CutRegs r;
  r.dmin = 1000;
  r.dmax = 2000;
  r.falloff = 400;
  r.inv_falloff = static_cast<uint64_t>(std::llround(4095.0 * (1 << kCutInvShift) / 400));
  EXPECT_EQ(cut_factor(1000, r, kP), 4095u);
  EXPECT_EQ(cut_factor(2000, r, kP), 4095u);
  EXPECT_EQ(cut_factor(600, r, kP), 0u);
  EXPECT_EQ(cut_factor(2400, r, kP), 0u);
  EXPECT_NEAR(cut_factor(800, r, kP), 2048, 1);
  EXPECT_NEAR(cut_factor(2100, r, kP), 3071, 1);
  for (int64_t d = 500; d < 1100; ++d) ASSERT_GE(cut_factor(d + 1, r, kP), cut_factor(d, r, kP));
  r.keep_inside = false;
  EXPECT_EQ(cut_factor(1500, r, kP), 0u);
  EXPECT_EQ(cut_factor(100, r, kP), 4095u);
  CutRegs hard;
  hard.dmin = -5;
  hard.dmax = 5;
  EXPECT_EQ(cut_factor(5, hard, kP), 4095u);
  EXPECT_EQ(cut_factor(6, hard, kP), 0u);
  EXPECT_EQ(cut_alpha(3000, 4095, kP), 3000u);
}

TEST(CubeMap, DivisionTableEqualsTheDivider) {
  for (int res : {4, 8, 16}) {
    const FacePositionTable table(127, res, kP.weight_bits);
    for (int m = 1; m <= 127; ++m)
      for (int s = -m; s <= m; ++s) {
        uint32_t c1 = 0, w1 = 0, c2 = 0, w2 = 0;
        face_position(s, m, res, kP.weight_bits, c1, w1);
        table(s, m, c2, w2);
        ASSERT_EQ(c1, c2) << s << "/" << m;
        ASSERT_EQ(w1, w2) << s << "/" << m;
      }
  }
}

TEST(Reflection, ReduceVectorUsesTheSmallestShift) {
  std::mt19937_64 gen(9);
  for (int i = 0; i < 200000; ++i) {
    const int64_t x = static_cast<int64_t>(gen() >> (gen() % 60)) * ((gen() & 1) ? 1 : -1);
    const Gradient g = reduce_vector(x, x / 3, -x / 7, 8);
    const int64_t m = x < 0 ? -x : x;
    int s = 0;
    while ((m >> s) > 127) ++s;  // the definition, spelled out
    ASSERT_EQ(g.x, x < 0 ? -((-x) >> s) : x >> s) << x;
  }
}
