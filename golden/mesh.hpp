// Triangle meshes in volume (voxel) coordinates: the scene's "polygons"
// (docs/scene.md), the start of Cube-5's hybrid volume/polygon rendering.
// A MeshSpec (golden/scene.hpp) is what the scene says, parsed by scene_io;
// load_mesh turns it into a Mesh: read from a file through assimp (OBJ, PLY, STL, ...) or
// generated (box, sphere, cylinder, needle, plane), then transformed.
// The renderers draw them: the host rasteriser (golden/polygons.hpp) for the
// fixed renderer, the float and reference renderers themselves.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "golden/scene.hpp"

namespace cube4::golden {

struct Mesh {
  std::string key;                             // the scene's "polygons[i]", for messages
  std::string source;                          // resolved file path, or "box", "sphere", ...
  std::vector<Vec3> vertices;                  // volume coordinates
  std::vector<std::array<uint32_t, 3>> triangles;  // indices into vertices, counter-clockwise seen from outside
  size_t dropped_degenerate = 0;               // zero-area triangles left out
  Vec3 color{1, 1, 1};
  double opacity = 1;
  bool lit = true;
};

// A triangle is degenerate when its height on its longest edge is at most
// 1e-12 of that edge (repeated vertices and collinear ones included).
bool degenerate(const Vec3& a, const Vec3& b, const Vec3& c);

// The built-in shape alone, in local coordinates, before the transform.
Mesh make_shape(const MeshSpec& spec);
// Reads the file's triangles through assimp, in file coordinates (assimp
// reads them in single precision), and drops the degenerate ones.
// Throws InputError "<path>: <fault>".
// assimp reads in a child process (fork): a crash or a read that takes
// longer than `seconds` there is an InputError naming the file, here. A
// program of several threads should load its meshes before it starts the
// others (as cube4 does): the child must not inherit a lock another thread
// holds.
constexpr int kMeshReadSeconds = 300;  // far beyond any real file's read
Mesh read_mesh_file(const std::string& path, int seconds = kMeshReadSeconds);

// Loads or generates the mesh, transforms it, drops degenerate triangles and
// checks what is left. Errors are InputErrors naming the scene file, the key
// ("polygons[1].file") and the fault. `scene_dir` resolves relative paths
// ("" = the working folder).
Mesh load_mesh(const MeshSpec& spec, const std::string& scene_file, const std::string& scene_dir);
std::vector<Mesh> load_meshes(const Scene& scene, const std::string& scene_dir);

// p' = T · p for one point.
Vec3 apply(const MeshTransform& t, const Vec3& p);

// Geometry used by tests and reports.
double surface_area(const Mesh& m);
double enclosed_volume(const Mesh& m);   // signed, by the divergence theorem; > 0 when wound outwards
bool is_closed(const Mesh& m);           // every edge in exactly two triangles, in opposite directions
std::array<Vec3, 2> bounds(const Mesh& m);  // min, max corner

}  // namespace cube4::golden
