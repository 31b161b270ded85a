// Meshes of the scene's "polygons" (golden/mesh, docs/scene.md): the built-in
// shapes against their tessellations' exact formulas, OBJ, PLY and STL files
// through assimp, the transform and its order, and every documented error,
// whose message must name the scene file, the key and the fault.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

#include "golden/errors.hpp"
#include "golden/mesh.hpp"
#include "golden/scene.hpp"
#include "golden/scene_io.hpp"

namespace cube4::golden {
namespace {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;
const char* const kFile = "m.json";

// Relative agreement to rounding: the formulas are exact for the tessellation.
void expect_close(double got, double want, const char* what) {
  EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::fabs(want))) << what;
}

void expect_point(const Vec3& got, const Vec3& want) {
  for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << "component " << k;
}

// A folder under the system temp folder, removed at the end of the test.
struct TempDir {
  TempDir() {
    path = fs::temp_directory_path() /
           ("cube4_test_mesh_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& bytes) const {
    std::ofstream((path / name).string(), std::ios::binary) << bytes;
    return (path / name).string();
  }
  fs::path path;
};

MeshSpec shape(MeshShape s) {
  MeshSpec m;
  m.key = "polygons[0]";
  m.shape = s;
  return m;
}

// Every vertex a triangle uses is one of `want`, and every one of `want` is used.
void expect_vertex_set(const Mesh& m, std::vector<Vec3> want) {
  std::vector<Vec3> got;
  for (const auto& t : m.triangles)
    for (uint32_t i : t) got.push_back(m.vertices[i]);
  std::sort(got.begin(), got.end());
  got.erase(std::unique(got.begin(), got.end()), got.end());
  std::sort(want.begin(), want.end());
  EXPECT_EQ(got, want);
}

// ---- built-in shapes ------------------------------------------------------

TEST(MeshShapes, Box) {
  MeshSpec s = shape(MeshShape::Box);
  s.size = {2, 3, 4};
  const Mesh m = load_mesh(s, kFile, "");
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_TRUE(is_closed(m));
  expect_close(surface_area(m), 2 * (2 * 3 + 3 * 4 + 4 * 2), "area");
  expect_close(enclosed_volume(m), 2 * 3 * 4, "volume");  // > 0: wound outwards
  const auto b = bounds(m);
  expect_point(b[0], {-1, -1.5, -2});
  expect_point(b[1], {1, 1.5, 2});
}

// The UV sphere's rings are regular n-gons at polar angles pi k / m; each
// band between two rings is a frustum of a regular n-gonal pyramid (its
// quads are planar trapezoids), the caps are pyramids. With rho_k, z_k the
// ring radii and heights (rho_0 = rho_m = 0), A = (n/2) sin(2 pi / n):
//   V = sum_k (z_k - z_k+1) / 3 · A · (rho_k² + rho_k rho_k+1 + rho_k+1²)
//   S = sum_k n · sin(pi/n) (rho_k + rho_k+1) · sqrt((z_k - z_k+1)² + cos²(pi/n) (rho_k - rho_k+1)²)
void check_sphere(double r, int n, int m) {
  SCOPED_TRACE("sphere r " + std::to_string(r) + " segments " + std::to_string(n) + " rings " + std::to_string(m));
  MeshSpec s = shape(MeshShape::Sphere);
  s.radius = r;
  s.segments = n;
  s.rings = m;
  const Mesh mesh = load_mesh(s, kFile, "");
  EXPECT_EQ(mesh.vertices.size(), size_t(n) * size_t(m - 1) + 2);
  EXPECT_EQ(mesh.triangles.size(), 2 * size_t(n) * size_t(m - 1));
  EXPECT_EQ(mesh.dropped_degenerate, 0u);
  EXPECT_TRUE(is_closed(mesh));
  for (const Vec3& v : mesh.vertices)
    EXPECT_NEAR(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), r, 1e-12 * r);
  const double a = 0.5 * n * std::sin(2 * kPi / n);
  double volume = 0, area = 0;
  for (int k = 0; k < m; ++k) {
    const double r0 = r * std::sin(kPi * k / m), r1 = r * std::sin(kPi * (k + 1) / m);
    const double z0 = r * std::cos(kPi * k / m), z1 = r * std::cos(kPi * (k + 1) / m);
    volume += (z0 - z1) / 3 * a * (r0 * r0 + r0 * r1 + r1 * r1);
    const double c = std::cos(kPi / n);
    area += n * std::sin(kPi / n) * (r0 + r1) * std::sqrt((z0 - z1) * (z0 - z1) + c * c * (r0 - r1) * (r0 - r1));
  }
  expect_close(enclosed_volume(mesh), volume, "volume");
  expect_close(surface_area(mesh), area, "area");
  // Below the sphere's 4/3 pi r³ and 4 pi r²: the polyhedron is inscribed.
  EXPECT_LT(volume, 4.0 / 3 * kPi * r * r * r);
  EXPECT_LT(area, 4 * kPi * r * r);
}

TEST(MeshShapes, SphereMatchesItsTessellation) {
  check_sphere(5, 32, 16);  // the defaults
  check_sphere(1, 3, 2);    // the coarsest: two triangular pyramids
  check_sphere(2.5, 7, 5);
}

TEST(MeshShapes, SphereBoundsWithSegmentsAMultipleOfFour) {
  // Vertices at phi = 0, 90, 180, 270 degrees on the equator (even rings).
  MeshSpec s = shape(MeshShape::Sphere);
  s.radius = 5;
  const auto b = bounds(load_mesh(s, kFile, ""));
  expect_point(b[0], {-5, -5, -5});
  expect_point(b[1], {5, 5, 5});
}

// Cylinders and needles: 2n ring vertices and two centres; n side quads,
// a fan of n at each end. n a multiple of 4 puts ring vertices on ±x and ±y.
Mesh load_round(MeshShape kind, double r, double length, double tip, int n) {
  MeshSpec s = shape(kind);
  s.radius = r;
  s.length = length;
  s.tip = tip;
  s.segments = n;
  const Mesh m = load_mesh(s, kFile, "");
  EXPECT_EQ(m.vertices.size(), 2u * size_t(n) + 2);
  EXPECT_EQ(m.triangles.size(), 4u * size_t(n));
  EXPECT_TRUE(is_closed(m));
  const auto b = bounds(m);
  EXPECT_EQ(n % 4, 0) << "the bounds below need it";
  expect_point(b[0], {-r, -r, 0});
  expect_point(b[1], {r, r, length});
  return m;
}

// Regular n-gon of circumradius r: area A r² with A = (n/2) sin(2 pi / n),
// edge 2 r sin(pi / n).
TEST(MeshShapes, Cylinder) {
  const int n = 24;
  const Mesh m = load_round(MeshShape::Cylinder, 2, 6, 0, n);
  const double cap = 0.5 * n * std::sin(2 * kPi / n) * 4;
  expect_close(enclosed_volume(m), cap * 6, "volume");
  expect_close(surface_area(m), 2 * cap + n * 2 * 2 * std::sin(kPi / n) * 6, "area");
}

// The prism to length - tip, then a pyramid of height tip over the same n-gon;
// each of its faces has base 2 r sin(pi/n) and slant height
// sqrt(tip² + (r cos(pi/n))²).
TEST(MeshShapes, Needle) {
  const int n = 16;
  const double r = 0.5;
  const Mesh m = load_round(MeshShape::Needle, r, 10, 2, n);
  const double cap = 0.5 * n * std::sin(2 * kPi / n) * r * r;
  expect_close(enclosed_volume(m), cap * 8 + cap * 2 / 3, "volume");
  const double c = std::cos(kPi / n);
  const double cone = n * r * std::sin(kPi / n) * std::sqrt(2 * 2 + r * r * c * c);
  expect_close(surface_area(m), cap + n * 2 * r * std::sin(kPi / n) * 8 + cone, "area");
}

TEST(MeshShapes, NeedleTipDefaultsToAQuarterOfItsLength) {
  MeshSpec a = shape(MeshShape::Needle), b = shape(MeshShape::Needle);
  a.length = b.length = 8;
  b.tip = 2;
  EXPECT_EQ(enclosed_volume(load_mesh(a, kFile, "")), enclosed_volume(load_mesh(b, kFile, "")));
}

TEST(MeshShapes, PlaneIsOneOpenQuadFacingPlusZ) {
  MeshSpec s = shape(MeshShape::Plane);
  s.size = {4, 2, 0};
  const Mesh m = load_mesh(s, kFile, "");
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.triangles.size(), 2u);
  EXPECT_FALSE(is_closed(m));
  expect_close(surface_area(m), 8, "area");
  for (const auto& t : m.triangles) {
    const Vec3 &p = m.vertices[t[0]], &q = m.vertices[t[1]], &r = m.vertices[t[2]];
    EXPECT_GT((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]), 0) << "normal +z";
  }
  const auto b = bounds(m);
  expect_point(b[0], {-2, -1, 0});
  expect_point(b[1], {2, 1, 0});
}

// ---- the transform ------------------------------------------------------------

TEST(MeshTransform, ScaleThenRotateThenTranslate) {
  MeshTransform t;
  t.scale = {2, 2, 2};
  t.rotate = {0, 0, 90};
  t.translate = {10, 0, 0};
  // (1,0,0) ×2 → (2,0,0), 90° about z → (0,2,0), + (10,0,0). Translating
  // before rotating would give (0,22,0); rotating before scaling the same as
  // here only because the scale is uniform, hence the next case.
  expect_point(apply(t, {1, 0, 0}), {10, 2, 0});
  MeshTransform u;
  u.scale = {1, 2, 3};
  u.rotate = {90, 0, 0};
  // (0,1,0) → (0,2,0) → 90° about x → (0,0,2); rotate first would give (0,0,3)·... = (0,0,3).
  expect_point(apply(u, {0, 1, 0}), {0, 0, 2});
}

TEST(MeshTransform, RotationAboutXThenYThenZ) {
  MeshTransform t;
  t.rotate = {90, 90, 0};
  // About x: (0,1,0) → (0,0,1); then about y: → (1,0,0). (y first: (0,0,1).)
  expect_point(apply(t, {0, 1, 0}), {1, 0, 0});
  MeshTransform u;
  u.rotate = {0, 90, 90};
  // About y: (0,0,1) → (1,0,0); then about z: → (0,1,0).
  expect_point(apply(u, {0, 0, 1}), {0, 1, 0});
}

TEST(MeshTransform, MatrixRowsActOnColumns) {
  MeshTransform t;
  t.matrix = std::array<double, 16>{0, -1, 0, 5, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  expect_point(apply(t, {1, 0, 0}), {5, 1, 0});
  expect_point(apply(t, {0, 1, 2}), {4, 0, 2});
}

TEST(MeshTransform, AppliedToALoadedShape) {
  MeshSpec s = shape(MeshShape::Box);
  s.transform.scale = {2, 4, 6};
  s.transform.translate = {10, 20, 30};
  const Mesh m = load_mesh(s, kFile, "");
  const auto b = bounds(m);
  expect_point(b[0], {9, 18, 27});
  expect_point(b[1], {11, 22, 33});
  expect_close(enclosed_volume(m), 48, "volume");
}

TEST(MeshTransform, MirroringKeepsTheWindingOutwards) {
  MeshSpec s = shape(MeshShape::Box);
  s.transform.matrix = std::array<double, 16>{-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const Mesh m = load_mesh(s, kFile, "");
  EXPECT_TRUE(is_closed(m));
  expect_close(enclosed_volume(m), 1, "volume");
}

// ---- files ------------------------------------------------------------------

// A unit right tetrahedron, wound outwards: volume 1/6.
const std::vector<Vec3> kTetra{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

TEST(MeshFiles, ObjWithAQuadIsTriangulated) {
  TempDir d;
  // A tetrahedron, and a separate quad (two triangles) in another group.
  const std::string path = d.write("t.obj",
                                   "# tetrahedron\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                   "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
                                   "g quad\nv 5 0 0\nv 6 0 0\nv 6 1 0\nv 5 1 0\nf 5 6 7 8\n");
  const Mesh m = read_mesh_file(path);
  EXPECT_EQ(m.triangles.size(), 6u);
  std::vector<Vec3> all = kTetra;
  all.insert(all.end(), {{5, 0, 0}, {6, 0, 0}, {6, 1, 0}, {5, 1, 0}});
  expect_vertex_set(m, all);
  expect_close(surface_area(m), 1.5 + std::sqrt(3.0) / 2 + 1, "area");
}

TEST(MeshFiles, ObjTetrahedronIsClosed) {
  TempDir d;
  const std::string path =
      d.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const Mesh m = read_mesh_file(path);
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_TRUE(is_closed(m));
  expect_close(enclosed_volume(m), 1.0 / 6, "volume");
}

TEST(MeshFiles, AsciiPlyCubeOfQuads) {
  TempDir d;
  std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 6\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < 8; ++i)
    ply += std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " + std::to_string((i >> 2) & 1) + "\n";
  ply += "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
  const Mesh m = read_mesh_file(d.write("cube.ply", ply));
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_TRUE(is_closed(m));
  expect_close(enclosed_volume(m), 1, "volume");
  expect_close(surface_area(m), 6, "area");
}

TEST(MeshFiles, BinaryPly) {
  TempDir d;
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& v : kTetra) {
    const float xyz[3] = {float(v[0]), float(v[1]), float(v[2])};
    ply.append(reinterpret_cast<const char*>(xyz), sizeof xyz);  // little-endian hosts, as the format says
  }
  for (const auto& f : std::vector<std::array<int32_t, 3>>{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) {
    ply += char(3);
    ply.append(reinterpret_cast<const char*>(f.data()), 12);
  }
  const Mesh m = read_mesh_file(d.write("t.ply", ply));
  EXPECT_EQ(m.triangles.size(), 4u);
  expect_vertex_set(m, kTetra);
  EXPECT_TRUE(is_closed(m));
  expect_close(enclosed_volume(m), 1.0 / 6, "volume");
}

std::string ascii_stl(const std::vector<std::array<Vec3, 3>>& facets) {
  std::string s = "solid t\n";
  for (const auto& f : facets) {
    s += "facet normal 0 0 0\nouter loop\n";
    for (const Vec3& v : f)
      s += "vertex " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
    s += "endloop\nendfacet\n";
  }
  return s + "endsolid t\n";
}

std::string binary_stl(const std::vector<std::array<Vec3, 3>>& facets) {
  std::string s(80, '\0');
  std::memcpy(s.data(), "cube4 binary stl", 16);  // must not start with "solid"
  const auto n = uint32_t(facets.size());
  s.append(reinterpret_cast<const char*>(&n), 4);  // little-endian hosts only, as assimp
  for (const auto& f : facets) {
    float rec[12] = {0, 0, 0};
    for (size_t v = 0; v < 3; ++v)
      for (size_t k = 0; k < 3; ++k) rec[3 + 3 * v + k] = float(f[v][k]);
    s.append(reinterpret_cast<const char*>(rec), sizeof rec);
    s.append(2, '\0');  // attribute byte count
  }
  return s;
}

const std::vector<std::array<Vec3, 3>> kTetraFacets{{kTetra[0], kTetra[2], kTetra[1]},
                                                    {kTetra[0], kTetra[1], kTetra[3]},
                                                    {kTetra[0], kTetra[3], kTetra[2]},
                                                    {kTetra[1], kTetra[2], kTetra[3]}};

TEST(MeshFiles, AsciiStl) {
  TempDir d;
  const Mesh m = read_mesh_file(d.write("t.stl", ascii_stl(kTetraFacets)));
  EXPECT_EQ(m.triangles.size(), 4u);
  EXPECT_EQ(m.vertices.size(), 4u);  // joined
  expect_vertex_set(m, kTetra);
  EXPECT_TRUE(is_closed(m));
  expect_close(enclosed_volume(m), 1.0 / 6, "volume");
}

TEST(MeshFiles, BinaryStl) {
  TempDir d;
  const Mesh m = read_mesh_file(d.write("t.stl", binary_stl(kTetraFacets)));
  EXPECT_EQ(m.triangles.size(), 4u);
  EXPECT_EQ(m.vertices.size(), 4u);
  expect_vertex_set(m, kTetra);
  EXPECT_TRUE(is_closed(m));
  expect_close(enclosed_volume(m), 1.0 / 6, "volume");
}

TEST(MeshFiles, DegenerateTrianglesAreDropped) {
  TempDir d;
  // One real triangle, one with a repeated vertex, one of collinear vertices.
  const std::string path = d.write("d.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\nf 1 2 4\n");
  MeshSpec s;
  s.key = "polygons[0]";
  s.file = path;
  const Mesh m = load_mesh(s, kFile, "");
  EXPECT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.dropped_degenerate, 2u);
}

TEST(MeshFiles, DegenerateRule) {
  EXPECT_TRUE(degenerate({0, 0, 0}, {0, 0, 0}, {1, 0, 0}));
  EXPECT_TRUE(degenerate({0, 0, 0}, {1, 1, 1}, {2, 2, 2}));
  EXPECT_TRUE(degenerate({1, 1, 1}, {1, 1, 1}, {1, 1, 1}));
  EXPECT_TRUE(degenerate({0, 0, 0}, {1, 0, 0}, {0.5, 1e-13, 0}));  // height 1e-13 of the edge
  EXPECT_FALSE(degenerate({0, 0, 0}, {1, 0, 0}, {0.5, 1e-11, 0}));
  EXPECT_FALSE(degenerate({0, 0, 0}, {1e-6, 0, 0}, {0, 1e-6, 0}));  // small but not thin
}

// ---- scenes -----------------------------------------------------------------

TEST(MeshScenes, EveryKeyParses) {
  const Scene s = parse_scene(R"({"volume": {"synthetic": "constant"}, "polygons": [
      {"file": "a.obj", "transform": {"scale": 2, "rotate": [1, 2, 3], "translate": [4, 5, 6]},
       "color": [1, 0.5, 0], "opacity": 0.25, "lit": false},
      {"shape": "box", "size": [1, 2, 3], "transform": {"scale": [1, 2, 3]}},
      {"shape": "sphere", "radius": 4, "segments": 8, "rings": 6},
      {"shape": "cylinder", "radius": 2, "length": 5, "segments": 12},
      {"shape": "needle", "radius": 0.5, "length": 20, "tip": 3,
       "transform": {"matrix": [[1, 0, 0, 1], [0, 1, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]}},
      {"shape": "plane", "size": [7, 8]},
      {"shape": "needle", "length": 8}]})",
                              kFile);
  ASSERT_EQ(s.polygons.size(), 7u);
  const MeshSpec& f = s.polygons[0];
  EXPECT_EQ(f.key, "polygons[0]");
  EXPECT_EQ(f.file, "a.obj");
  EXPECT_EQ(f.transform.scale, (Vec3{2, 2, 2}));
  EXPECT_EQ(f.transform.rotate, (Vec3{1, 2, 3}));
  EXPECT_EQ(f.transform.translate, (Vec3{4, 5, 6}));
  EXPECT_FALSE(f.transform.matrix);
  EXPECT_EQ(f.color, (Vec3{1, 0.5, 0}));
  EXPECT_EQ(f.opacity, 0.25);
  EXPECT_FALSE(f.lit);
  EXPECT_EQ(s.polygons[1].shape, MeshShape::Box);
  EXPECT_EQ(s.polygons[1].size, (Vec3{1, 2, 3}));
  EXPECT_EQ(s.polygons[1].transform.scale, (Vec3{1, 2, 3}));
  EXPECT_TRUE(s.polygons[1].lit);                   // default
  EXPECT_EQ(s.polygons[1].opacity, 1);               // default: opaque
  EXPECT_EQ(s.polygons[1].color, (Vec3{1, 1, 1}));   // default: white
  EXPECT_EQ(s.polygons[2].shape, MeshShape::Sphere);
  EXPECT_EQ(s.polygons[2].radius, 4);
  EXPECT_EQ(s.polygons[2].segments, 8);
  EXPECT_EQ(s.polygons[2].rings, 6);
  EXPECT_EQ(s.polygons[3].shape, MeshShape::Cylinder);
  EXPECT_EQ(s.polygons[3].length, 5);
  EXPECT_EQ(s.polygons[4].tip, 3);
  ASSERT_TRUE(s.polygons[4].transform.matrix);
  EXPECT_EQ((*s.polygons[4].transform.matrix)[7], 2);
  EXPECT_EQ(s.polygons[5].size, (Vec3{7, 8, 0}));
  EXPECT_EQ(s.polygons[6].tip, 2);  // a quarter of the length
}

TEST(MeshScenes, AbsentOrEmptyMeansNoMeshes) {
  EXPECT_TRUE(parse_scene(R"({"volume": {"synthetic": "constant"}})", kFile).polygons.empty());
  EXPECT_TRUE(parse_scene(R"({"volume": {"synthetic": "constant"}, "polygons": []})", kFile).polygons.empty());
  EXPECT_TRUE(default_scene().polygons.empty());
}

TEST(MeshScenes, RelativeFilesResolveAgainstTheScenesFolder) {
  TempDir d;
  fs::create_directories(d.path / "meshes");
  d.write("meshes/t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string scene = d.write(
      "s.json", R"({"volume": {"synthetic": "constant"}, "polygons": [{"file": "meshes/t.obj"}, {"shape": "box"}]})");
  const Scene s = load_scene(scene);
  EXPECT_EQ(s.polygons[0].file, "meshes/t.obj");  // as written
  const auto meshes = load_meshes(s, d.path.string());
  ASSERT_EQ(meshes.size(), 2u);
  EXPECT_EQ(meshes[0].source, (d.path / "meshes/t.obj").string());
  EXPECT_EQ(meshes[0].triangles.size(), 1u);
  EXPECT_EQ(meshes[1].triangles.size(), 12u);
}

TEST(MeshScenes, ExampleSceneLoads) {
  const std::string dir = std::string(CUBE4_SOURCE_DIR) + "/scenes";
  const Scene s = load_scene(dir + "/brain_probe.json");
  ASSERT_EQ(s.polygons.size(), 2u);
  const auto meshes = load_meshes(s, dir);
  EXPECT_TRUE(is_closed(meshes[0]));
  EXPECT_GT(enclosed_volume(meshes[0]), 0);
  EXPECT_TRUE(is_closed(meshes[1]));
}

// ---- errors -----------------------------------------------------------------

std::string parse_error(const std::string& polygons) {
  try {
    parse_scene(R"({"volume": {"synthetic": "constant"}, "polygons": )" + polygons + "}", kFile);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

void expect_fragments(const std::string& msg, const std::string& file, std::initializer_list<std::string> fragments) {
  EXPECT_EQ(msg.rfind(file + ": ", 0), 0u) << msg;
  for (const auto& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "wanted '" << f << "' in: " << msg;
}

void expect_parse_error(const std::string& polygons, std::initializer_list<std::string> fragments) {
  SCOPED_TRACE("polygons: " + polygons);
  expect_fragments(parse_error(polygons), kFile, fragments);
}

TEST(MeshErrors, SceneKeysAndValues) {
  expect_parse_error(R"([{"shape": "box", "radius": 2}])", {"unknown key \"polygons[0].radius\" = 2", "size"});
  expect_parse_error(R"([{"file": "a.obj", "size": [1, 1, 1]}])", {"unknown key \"polygons[0].size\""});
  expect_parse_error(R"([{"shape": "box"}, {"shape": "box", "colour": [1, 1, 1]}])",
                     {"unknown key \"polygons[1].colour\"", "color"});
  expect_parse_error(R"([{"shape": "box", "transform": {"shear": 1}}])", {"unknown key \"polygons[0].transform.shear\""});
  expect_parse_error(R"([{"shape": "cone"}])",
                     {"\"polygons[0].shape\" = \"cone\" is not one of", "\"box\"", "\"needle\""});
  expect_parse_error(R"([{"shape": "box", "color": [1, 1.5, 0]}])", {"\"polygons[0].color[1]\" = 1.5", "0..1"});
  expect_parse_error(R"([{"shape": "box", "opacity": -0.1}])", {"\"polygons[0].opacity\" = -0.1", "0..1"});
  expect_parse_error(R"([{"shape": "box", "opacity": 2}])", {"\"polygons[0].opacity\" = 2", "0..1"});
  expect_parse_error(R"([{"shape": "box", "lit": 1}])", {"\"polygons[0].lit\" = 1", "true or false"});
  expect_parse_error(R"([{"file": "a.obj", "shape": "box"}])", {"\"polygons[0]\"", "both \"file\" and \"shape\""});
  expect_parse_error(R"([{"color": [1, 1, 1]}])", {"\"polygons[0]\"", "needs \"file\" or \"shape\""});
  expect_parse_error(R"([{"file": ""}])", {"\"polygons[0].file\" = \"\"", "should name a file"});
  expect_parse_error(R"({"shape": "box"})", {"\"polygons\"", "should be an array"});
  expect_parse_error(R"([{"shape": "sphere", "segments": 2}])", {"\"polygons[0].segments\" = 2", "3..1024"});
  expect_parse_error(R"([{"shape": "sphere", "rings": 1}])", {"\"polygons[0].rings\" = 1", "2..1024"});
  expect_parse_error(R"([{"shape": "sphere", "radius": 0}])", {"\"polygons[0].radius\" = 0", "> 0"});
  expect_parse_error(R"([{"shape": "needle", "length": 4, "tip": 4}])",
                     {"\"polygons[0].tip\" = 4", "less than the needle's length (4)"});
  expect_parse_error(R"([{"shape": "plane", "size": [1, 2, 3]}])", {"\"polygons[0].size\"", "2 entries"});
}

TEST(MeshErrors, Transforms) {
  expect_parse_error(R"([{"shape": "box", "transform": {"scale": 0}}])", {"\"polygons[0].transform.scale\" = 0", "> 0"});
  expect_parse_error(R"([{"shape": "box", "transform": {"scale": [1, -1, 1]}}])",
                     {"\"polygons[0].transform.scale[1]\" = -1", "> 0"});
  expect_parse_error(R"([{"shape": "box", "transform": {"rotate": [0, 0]}}])",
                     {"\"polygons[0].transform.rotate\"", "3 entries"});
  const std::string id = "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]";
  expect_parse_error(R"([{"shape": "box", "transform": {"matrix": )" + id + R"(, "translate": [1, 2, 3]}}])",
                     {"\"polygons[0].transform\"", "give the matrix alone"});
  expect_parse_error(R"([{"shape": "box", "transform": {"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]}}])",
                     {"\"polygons[0].transform.matrix[3]\" = [0,0,1,1]", "[0, 0, 0, 1]"});
  expect_parse_error(R"([{"shape": "box", "transform": {"matrix": [[1, 0, 0, 0], [2, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}}])",
                     {"\"polygons[0].transform.matrix\"", "singular", "determinant 0"});
  expect_parse_error(R"([{"shape": "box", "transform": {"matrix": [[1, 0, 0]]}}])",
                     {"\"polygons[0].transform.matrix\"", "4 entries"});
}

// A scene naming one mesh file, loaded from its folder.
struct FileCase {
  TempDir dir;
  std::string scene;
  FileCase(const std::string& mesh_name, const std::string& bytes) {
    if (!bytes.empty() || mesh_name != "missing.obj") dir.write(mesh_name, bytes);
    scene = dir.write("s.json", R"({"volume": {"synthetic": "constant"}, "polygons": [{"shape": "box"}, {"file": ")" +
                                    mesh_name + R"("}]})");
  }
  std::string error() const {
    try {
      load_meshes(load_scene(scene), dir.path.string());
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

void expect_file_error(const std::string& name, const std::string& bytes, std::initializer_list<std::string> fragments) {
  SCOPED_TRACE("mesh " + name);
  const FileCase c(name, bytes);
  const std::string msg = c.error();
  expect_fragments(msg, c.scene, {"\"polygons[1].file\" = \"" + name + "\""});
  expect_fragments(msg, c.scene, {(c.dir.path / name).string()});
  expect_fragments(msg, c.scene, fragments);
}

TEST(MeshErrors, MissingFile) {
  FileCase c("missing.obj", "");
  fs::remove(c.dir.path / "missing.obj");
  const std::string msg = c.error();
  expect_fragments(msg, c.scene,
                   {"\"polygons[1].file\" = \"missing.obj\" cannot be loaded", (c.dir.path / "missing.obj").string(),
                    "No such file or directory"});
}

TEST(MeshErrors, DirectoryIsNotAMesh) {
  FileCase c("sub", "");
  fs::remove(c.dir.path / "sub");
  fs::create_directories(c.dir.path / "sub");
  expect_fragments(c.error(), c.scene, {"\"polygons[1].file\" = \"sub\"", "directory"});
}

TEST(MeshErrors, UnreadableFilesCarryAssimpsMessage) {
  // assimp's own words for each fault, after "assimp cannot read it: ".
  expect_file_error("bad.xyzq", "hello", {"assimp cannot read it", "No suitable reader found"});
  expect_file_error("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", {"assimp cannot read it", "index out of range"});
  expect_file_error("bad.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nend_header\n",
                    {"assimp cannot read it", "ply"});
}

// A PLY header without end_header made assimp 5.2 read forever (found by
// fuzz_mesh): it is refused before assimp sees it, under any extension.
TEST(MeshErrors, PlyHeaderWithoutEndHeaderIsRefusedNotHung) {
  const std::string truncated =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty _header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_file_error("hang.ply", truncated, {"a PLY header without its end_header line"});
  expect_file_error("hang.obj", truncated, {"a PLY header without its end_header line"});
  expect_file_error("split.ply", "ply\nformat ascii 1.0\nelement vertex 3\nxend_header\n",
                    {"a PLY header without its end_header line"});
}

// A PLY file that makes assimp 5.2 abort in its triangulation (found by
// fuzz_mesh): the reader runs in a child process, so cube4 reports it.
TEST(MeshErrors, ACrashInAssimpIsAnErrorNotTheEnd) {
  expect_file_error("crash.ply",
                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nprsperty float y\nproperty float z\n"
                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0ist uchar int vertex_i\n",
                    {"assimp crashed reading it (signal 6)", "a malformed or unsupported file"});
}

TEST(MeshErrors, NoTriangles) {
  expect_file_error("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n", {"no triangles (3 vertices and 2 points or lines)"});
  expect_file_error("empty.stl", "solid t\nendsolid t\n", {"no triangles"});
}

TEST(MeshErrors, NonFiniteVertices) {
  expect_file_error("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", {"(nan, 0, 0)", "not a finite point"});
  expect_file_error("inf.obj", "v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n", {"(1, inf, 0)", "not a finite point"});
}

TEST(MeshErrors, OnlyDegenerateTriangles) {
  expect_file_error("deg.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n",
                    {"cannot be loaded", "only degenerate triangles", "all 2 have zero area"});
}

TEST(MeshErrors, TransformBeyondADouble) {
  TempDir d;
  d.write("big.obj", "v 0 0 0\nv 1e30 0 0\nv 0 1e30 0\nf 1 2 3\n");  // floats in assimp
  const std::string scene = d.write(
      "s.json", R"({"volume": {"synthetic": "constant"}, "polygons": [{"file": "big.obj", "transform": {"scale": 1e300}}]})");
  try {
    load_meshes(load_scene(scene), d.path.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    expect_fragments(e.what(), scene, {"\"polygons[0].transform\"", "\"big.obj\"", "(1e+30, 0, 0)", "inf", "not a finite point"});
  }
}

TEST(MeshErrors, TransformThatFlattensEverything) {
  // Invertible, so the scene accepts it, but it squashes y by 1e-20: both
  // triangles of the plane become slivers of relative height 1e-20.
  MeshSpec s = shape(MeshShape::Plane);
  s.transform.matrix = std::array<double, 16>{1, 0, 0, 0, 0, 1e-20, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  try {
    load_mesh(s, kFile, "");
    FAIL() << "no error";
  } catch (const InputError& e) {
    expect_fragments(e.what(), kFile, {"\"polygons[0].transform\"", "\"plane\"", "degenerate"});
  }
  // Size alone does not make a triangle degenerate: the rule is about shape.
  MeshSpec tiny = shape(MeshShape::Box);
  tiny.transform.scale = {1e-300, 1e-300, 1e-300};
  EXPECT_EQ(load_mesh(tiny, kFile, "").triangles.size(), 12u);
}

}  // namespace
}  // namespace cube4::golden
