// The mesh loader (assimp behind golden::read_mesh_file) on arbitrary bytes,
// as OBJ, PLY or STL by the input's first byte: a scene may name any file.
#include <string>

#include "golden/errors.hpp"
#include "golden/mesh.hpp"
#include "tb/fuzz/fuzz_support.hpp"

namespace {

using namespace cube4;

// The first byte picks the format: 0 OBJ, 1 PLY, 2 STL (modulo 3).
fuzz::Bytes text(unsigned char format, const std::string& body) {
  fuzz::Bytes b{static_cast<unsigned char>(format)};
  b.insert(b.end(), body.begin(), body.end());
  return b;
}

}  // namespace

void cube4::fuzz::write_seeds(const std::string& dir) {
  fuzz::write_seed(dir, "tetra.obj", text(0, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"));
  fuzz::write_seed(dir, "quad.obj", text(0, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"));
  fuzz::write_seed(dir, "tri.ply", text(1, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                              "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                              "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  fuzz::write_seed(dir, "tri.stl", text(2, "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                              "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n"));
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const char* suffix = data[0] % 3 == 0 ? ".obj" : data[0] % 3 == 1 ? ".ply" : ".stl";
  const std::string& path = fuzz::scratch_file(suffix, data + 1, size - 1);
  try {
    golden::read_mesh_file(path, 5);  // a reader that hangs is an InputError after 5 s
  } catch (const golden::InputError&) {
  }
  return 0;
}
