// Meshes: assimp for files, our own tessellations for the built-in shapes,
// the scene's transform, and the checks of docs/scene.md ("polygons").
#include "golden/mesh.hpp"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <nlohmann/json.hpp>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>

#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "golden/view.hpp"

namespace cube4::golden {
namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross3(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm3(const Vec3& a) { return std::hypot(a[0], a[1], a[2]); }  // no overflow

bool finite3(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

std::string show_point(const Vec3& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%g, %g, %g)", v[0], v[1], v[2]);
  return buf;
}

const char* shape_name(MeshShape s) {
  switch (s) {
    case MeshShape::Box: return "box";
    case MeshShape::Sphere: return "sphere";
    case MeshShape::Cylinder: return "cylinder";
    case MeshShape::Needle: return "needle";
    case MeshShape::Plane: return "plane";
  }
  return "shape";
}

// ---- built-in shapes ---------------------------------------------------------
// Every closed shape is wound counter-clockwise seen from outside.

using Tri = std::array<uint32_t, 3>;

void quad(std::vector<Tri>& t, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {  // a b c d counter-clockwise
  t.push_back({a, b, c});
  t.push_back({a, c, d});
}

// Centred on the origin; vertex i has corner bits x = i&1, y = i&2, z = i&4.
void make_box(const Vec3& size, Mesh& m) {
  for (uint32_t i = 0; i < 8; ++i)
    m.vertices.push_back({(i & 1 ? 0.5 : -0.5) * size[0], (i & 2 ? 0.5 : -0.5) * size[1],
                          (i & 4 ? 0.5 : -0.5) * size[2]});
  for (int a = 0; a < 3; ++a) {
    // u, v, a right-handed: corners (0,0) (1,0) (1,1) (0,1) in (u, v) run
    // counter-clockwise seen from +a.
    const uint32_t bu = 1u << ((a + 1) % 3), bv = 1u << ((a + 2) % 3), ba = 1u << a;
    const uint32_t c0 = 0, c1 = bu, c2 = bu | bv, c3 = bv;
    quad(m.triangles, c0 | ba, c1 | ba, c2 | ba, c3 | ba);  // +a face
    quad(m.triangles, c0, c3, c2, c1);                      // -a face, the other way round
  }
}

// A ring of n vertices at height z, radius rho, the first on +x.
uint32_t ring(Mesh& m, int n, double rho, double z) {
  const auto first = uint32_t(m.vertices.size());
  for (int j = 0; j < n; ++j) {
    const double phi = 2 * kPi * j / n;
    m.vertices.push_back({rho * std::cos(phi), rho * std::sin(phi), z});
  }
  return first;
}

// The band between ring `hi` (above) and ring `lo` (below), n quads.
void band(Mesh& m, int n, uint32_t hi, uint32_t lo) {
  for (uint32_t j = 0; j < uint32_t(n); ++j) {
    const uint32_t k = (j + 1) % uint32_t(n);
    quad(m.triangles, hi + j, lo + j, lo + k, hi + k);
  }
}

// A fan from `apex` to ring `r`; `above` says the apex is above the ring.
void fan(Mesh& m, int n, uint32_t apex, uint32_t r, bool above) {
  for (uint32_t j = 0; j < uint32_t(n); ++j) {
    const uint32_t k = (j + 1) % uint32_t(n);
    if (above) m.triangles.push_back({apex, r + j, r + k});
    else m.triangles.push_back({apex, r + k, r + j});
  }
}

// UV sphere about the origin: poles on ±z, rings-1 rings of `segments`
// vertices at polar angles pi·k/rings.
void make_sphere(double r, int segments, int rings, Mesh& m) {
  m.vertices.push_back({0, 0, r});
  std::vector<uint32_t> rs;
  for (int k = 1; k < rings; ++k) {
    const double theta = kPi * k / rings;
    rs.push_back(ring(m, segments, r * std::sin(theta), r * std::cos(theta)));
  }
  const auto south = uint32_t(m.vertices.size());
  m.vertices.push_back({0, 0, -r});
  fan(m, segments, 0, rs.front(), true);
  for (size_t k = 0; k + 1 < rs.size(); ++k) band(m, segments, rs[k], rs[k + 1]);
  fan(m, segments, south, rs.back(), false);
}

// Along +z from the origin: a prism of `length - tip` capped at z = 0, then
// (tip > 0) a cone to the point (0, 0, length), or (tip = 0) a flat top.
void make_round(double r, double length, double tip, int segments, Mesh& m) {
  const uint32_t bottom = ring(m, segments, r, 0);
  const uint32_t top = ring(m, segments, r, length - tip);
  const auto base_centre = uint32_t(m.vertices.size());
  m.vertices.push_back({0, 0, 0});
  const auto apex = uint32_t(m.vertices.size());
  m.vertices.push_back({0, 0, length});
  band(m, segments, top, bottom);
  fan(m, segments, base_centre, bottom, false);
  fan(m, segments, apex, top, true);
}

// ---- files --------------------------------------------------------------------

// The file's meshes (an OBJ group, a PLY or STL body each) placed by their
// nodes' transforms (the identity in OBJ, PLY and STL) and merged into one,
// with equal positions shared across meshes as JoinIdenticalVertices shares
// them within one, so that a closed surface split into groups stays closed.
struct Collector {
  const aiScene& sc;
  const std::string& path;
  Mesh& m;
  std::map<Vec3, uint32_t> index;
  size_t faces = 0;

  uint32_t vertex(const Vec3& p) {
    const auto [it, added] = index.emplace(p, uint32_t(m.vertices.size()));
    if (added) m.vertices.push_back(p);
    return it->second;
  }
  void node(const aiNode& n, const aiMatrix4x4& parent);
};

void Collector::node(const aiNode& n, const aiMatrix4x4& parent) {
  const aiMatrix4x4 t = parent * n.mTransformation;
  for (unsigned i = 0; i < n.mNumMeshes; ++i) {
    const aiMesh& mesh = *sc.mMeshes[n.mMeshes[i]];
    std::vector<uint32_t> at;
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      const Vec3 raw{p.x, p.y, p.z};
      if (!finite3(raw)) throw InputError(path + ": a vertex is " + show_point(raw) + ", not a finite point");
      const aiVector3D q = t * p;
      at.push_back(vertex({q.x, q.y, q.z}));
    }
    faces += mesh.mNumFaces;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines
      Tri tri{};
      for (int k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= mesh.mNumVertices)
          throw InputError(path + ": a face names vertex " + std::to_string(face.mIndices[k]) + " of " +
                           std::to_string(mesh.mNumVertices));
        tri[size_t(k)] = at[face.mIndices[k]];
      }
      m.triangles.push_back(tri);
    }
  }
  for (unsigned c = 0; c < n.mNumChildren; ++c) node(*n.mChildren[c], t);
}

std::string resolve(const std::string& path, const std::string& scene_dir) {
  const std::filesystem::path p(path);
  if (p.is_absolute() || scene_dir.empty()) return path;
  return (std::filesystem::path(scene_dir) / p).lexically_normal().string();
}

// The 3×3 linear part and the translation of a transform.
struct Affine {
  std::array<Vec3, 3> a{};  // rows
  Vec3 t{};
};

Affine affine_of(const MeshTransform& t) {
  Affine f;
  if (t.matrix) {
    const auto& m = *t.matrix;
    for (size_t i = 0; i < 3; ++i) {
      f.a[i] = {m[4 * i], m[4 * i + 1], m[4 * i + 2]};
      f.t[i] = m[4 * i + 3];
    }
    return f;
  }
  View v;
  v.rotate = t.rotate;
  const Mat3 r = rotation_of(v);  // about x, then y, then z: the view's convention
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 3; ++j) f.a[i][j] = r[i][j] * t.scale[j];
  f.t = t.translate;
  return f;
}

Vec3 transformed(const Affine& f, const Vec3& p) {
  return {dot3(f.a[0], p) + f.t[0], dot3(f.a[1], p) + f.t[1], dot3(f.a[2], p) + f.t[2]};
}

double determinant(const std::array<Vec3, 3>& a) { return dot3(a[0], cross3(a[1], a[2])); }

[[noreturn]] void fail_key(const std::string& scene_file, const std::string& key, const std::string& rest) {
  throw InputError((scene_file.empty() ? std::string("scene") : scene_file) + ": \"" + key + "\"" + rest);
}

void drop_degenerate(Mesh& m) {
  std::vector<Tri> kept;
  for (const Tri& t : m.triangles)
    if (!degenerate(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]])) kept.push_back(t);
  m.dropped_degenerate += m.triangles.size() - kept.size();
  m.triangles = std::move(kept);
}

}  // namespace

bool degenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double e = std::max({norm3(sub(b, a)), norm3(sub(c, b)), norm3(sub(a, c))});
  // |(b - a) × (c - a)| is twice the area, = longest edge × its height; the
  // edges are divided by e first so that nothing overflows. e = 0 gives NaN:
  // degenerate.
  const Vec3 u = sub(b, a), w = sub(c, a);
  const Vec3 un{u[0] / e, u[1] / e, u[2] / e}, wn{w[0] / e, w[1] / e, w[2] / e};
  return !(norm3(cross3(un, wn)) > 1e-12);
}

Vec3 apply(const MeshTransform& t, const Vec3& p) { return transformed(affine_of(t), p); }

Mesh make_shape(const MeshSpec& spec) {
  Mesh m;
  m.source = shape_name(spec.shape);
  switch (spec.shape) {
    case MeshShape::Box: make_box(spec.size, m); break;
    case MeshShape::Sphere: make_sphere(spec.radius, spec.segments, spec.rings, m); break;
    case MeshShape::Cylinder: make_round(spec.radius, spec.length, 0, spec.segments, m); break;
    case MeshShape::Needle:
      make_round(spec.radius, spec.length, spec.tip > 0 ? spec.tip : spec.length / 4, spec.segments, m);
      break;
    case MeshShape::Plane:
      m.vertices = {{-0.5 * spec.size[0], -0.5 * spec.size[1], 0},
                    {0.5 * spec.size[0], -0.5 * spec.size[1], 0},
                    {0.5 * spec.size[0], 0.5 * spec.size[1], 0},
                    {-0.5 * spec.size[0], 0.5 * spec.size[1], 0}};
      quad(m.triangles, 0, 1, 2, 3);  // normal +z
      break;
  }
  return m;
}

namespace {
// assimp 5.2's PLY reader never returns on a header that lacks its
// end_header line (it seeks and reads on at the end of the file; found by
// tb/fuzz/fuzz_mesh). assimp picks the PLY reader by the "ply" magic
// whatever the file's extension, so every file that starts with it must
// show the line within the first 64 KiB (real headers are a few hundred
// bytes) before assimp sees it.
void check_ply_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(64 * 1024, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  if (head.rfind("ply", 0) != 0) return;
  for (size_t at = head.find("end_header"); at != std::string::npos; at = head.find("end_header", at + 1)) {
    const size_t end = at + 10;
    const bool line_start = at > 0 && head[at - 1] == '\n';
    const bool line_end = end < head.size() && (head[end] == '\n' || head[end] == '\r');
    if (line_start && line_end) return;
  }
  throw InputError(path + ": a PLY header without its end_header line in the first 64 KiB");
}

// The file through assimp, in this process.
Mesh read_with_assimp(const std::string& path) {
  Assimp::Importer importer;
  // Triangulate: polygons become triangles (points and lines stay, and are
  // skipped). JoinIdenticalVertices: shared corners become one vertex. Neither
  // removes degenerate triangles (aiProcess_FindDegenerates is not asked
  // for): they are dropped here, by the rule of degenerate().
  // aiProcess_ValidateDataStructure is left out: it reports a file without
  // vertices as "The mesh t contains no vertices", where "no triangles" is
  // the fault; face indices are checked below instead.
  const aiScene* sc = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (!sc || !sc->mRootNode)
    throw InputError(path + ": assimp cannot read it: " + std::string(importer.GetErrorString()));
  Mesh m;
  m.source = path;
  Collector c{*sc, path, m, {}, 0};
  c.node(*sc->mRootNode, aiMatrix4x4());
  if (m.triangles.empty())
    throw InputError(path + ": no triangles (" + std::to_string(m.vertices.size()) + " vertices and " +
                     std::to_string(c.faces) + (c.faces == 1 ? " point or line)" : " points or lines)"));
  drop_degenerate(m);
  if (m.triangles.empty())
    throw InputError(path + ": only degenerate triangles (all " + std::to_string(m.dropped_degenerate) +
                     " have zero area)");
  return m;
}

// assimp 5.2 aborts on some malformed files (an assertion in its
// post-processing, found by tb/fuzz/fuzz_mesh) and may not return on
// others, so it reads in a child process: a crash or a hang there is an
// InputError here, never the end of cube4. The child sends the mesh, or its
// InputError's message, through a pipe.
class Pipe {
 public:
  explicit Pipe(int fd) : fd_(fd) {}
  ~Pipe() { ::close(fd_); }
  bool put(const void* data, size_t n) {
    for (const char* p = static_cast<const char*>(data); n > 0;) {
      const ssize_t w = ::write(fd_, p, n);
      if (w <= 0) return false;
      p += w;
      n -= static_cast<size_t>(w);
    }
    return true;
  }
  // Everything until end of file, or false once `deadline` has passed.
  bool take_all(std::string& out, std::chrono::steady_clock::time_point deadline) {
    char buf[1 << 16];
    for (;;) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return false;
      pollfd pfd{fd_, POLLIN, 0};
      const int r = ::poll(&pfd, 1, static_cast<int>(std::min<int64_t>(left.count(), 1000)));
      if (r < 0 && errno != EINTR) return false;
      if (r <= 0) continue;
      const ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return true;
      out.append(buf, static_cast<size_t>(n));
    }
  }

 private:
  int fd_;
};

template <class T>
bool put_vector(Pipe& p, const std::vector<T>& v) {
  const uint64_t n = v.size();
  return p.put(&n, sizeof n) && p.put(v.data(), n * sizeof(T));
}
template <class T>
bool get_vector(const std::string& in, size_t& at, std::vector<T>& v) {
  uint64_t n = 0;
  if (in.size() - at < sizeof n) return false;
  std::memcpy(&n, in.data() + at, sizeof n);
  at += sizeof n;
  if (n > (in.size() - at) / sizeof(T)) return false;
  v.resize(static_cast<size_t>(n));
  std::memcpy(v.data(), in.data() + at, static_cast<size_t>(n) * sizeof(T));
  at += static_cast<size_t>(n) * sizeof(T);
  return true;
}

Mesh read_in_child(const std::string& path, int seconds) {
  int fds[2];
  if (::pipe(fds) != 0) throw InputError(path + ": cannot start the mesh reader (pipe: " + std::strerror(errno) + ")");
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw InputError(path + ": cannot start the mesh reader (fork: " + std::strerror(errno) + ")");
  }
  if (pid == 0) {
    ::close(fds[0]);
    Pipe out(fds[1]);
    bool ok = true;
    try {
      const Mesh m = read_with_assimp(path);
      const char tag = 'M';
      const uint64_t dropped = m.dropped_degenerate;
      ok = out.put(&tag, 1) && out.put(&dropped, sizeof dropped) && put_vector(out, m.vertices) &&
           put_vector(out, m.triangles);
    } catch (const InputError& e) {
      const std::string msg = e.what();
      const char tag = 'E';
      ok = out.put(&tag, 1) && out.put(msg.data(), msg.size());
    } catch (...) {
      ok = false;
    }
    ::_exit(ok ? 0 : 1);  // no destructors, no atexit handlers of the parent's state
  }
  ::close(fds[1]);
  std::string in;
  bool finished;
  {
    Pipe from(fds[0]);
    finished = from.take_all(in, std::chrono::steady_clock::now() + std::chrono::seconds(seconds));
  }
  if (!finished) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!finished)
    throw InputError(path + ": assimp did not finish reading it in " + std::to_string(seconds) +
                     " s (a malformed file?)");
  if (WIFSIGNALED(status))
    throw InputError(path + ": assimp crashed reading it (signal " + std::to_string(WTERMSIG(status)) +
                     "): a malformed or unsupported file");
  if (!in.empty() && in[0] == 'E') throw InputError(in.substr(1));
  Mesh m;
  m.source = path;
  size_t at = 1;
  uint64_t dropped = 0;
  const bool complete = !in.empty() && in[0] == 'M' && in.size() >= 1 + sizeof dropped &&
                        (std::memcpy(&dropped, in.data() + 1, sizeof dropped), at += sizeof dropped, true) &&
                        get_vector(in, at, m.vertices) && get_vector(in, at, m.triangles) && at == in.size();
  if (!complete || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InputError(path + ": the mesh reader failed (exit status " + std::to_string(status) + ")");
  m.dropped_degenerate = static_cast<size_t>(dropped);
  return m;
}

}  // namespace

Mesh read_mesh_file(const std::string& path, int seconds) {
  require_regular_file(path, "the mesh");
  check_ply_header(path);
  return read_in_child(path, seconds);
}

Mesh load_mesh(const MeshSpec& spec, const std::string& scene_file, const std::string& scene_dir) {
  Mesh m;
  // What the messages call the mesh: the file or the shape as written.
  const std::string what_value =
      spec.file.empty() ? std::string("\"") + shape_name(spec.shape) + "\"" : nlohmann::json(spec.file).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (spec.file.empty()) {
    m = make_shape(spec);
  } else {
    try {
      m = read_mesh_file(resolve(spec.file, scene_dir));
    } catch (const InputError& e) {
      fail_key(scene_file, spec.key + ".file", " = " + what_value + " cannot be loaded: " + e.what());
    }
  }
  const Affine f = affine_of(spec.transform);
  for (Vec3& p : m.vertices) {
    const Vec3 q = transformed(f, p);
    if (!finite3(q))
      fail_key(scene_file, spec.key + ".transform",
               " takes the vertex " + show_point(p) + " of " + what_value + " to " + show_point(q) +
                   ", not a finite point");
    p = q;
  }
  // A mirroring transform would turn the triangles inside out.
  if (determinant(f.a) < 0)
    for (Tri& t : m.triangles) std::swap(t[1], t[2]);
  // A transform that flattens (a nearly singular matrix) can make more.
  drop_degenerate(m);
  if (m.triangles.empty())
    fail_key(scene_file, spec.key + ".transform",
             " makes every triangle of " + what_value + " degenerate (zero area)");
  m.key = spec.key;
  m.color = spec.color;
  m.opacity = spec.opacity;
  m.lit = spec.lit;
  return m;
}

std::vector<Mesh> load_meshes(const Scene& scene, const std::string& scene_dir) {
  std::vector<Mesh> out;
  for (const MeshSpec& s : scene.polygons) out.push_back(load_mesh(s, scene.file, scene_dir));
  return out;
}

double surface_area(const Mesh& m) {
  double a = 0;
  for (const Tri& t : m.triangles)
    a += 0.5 * norm3(cross3(sub(m.vertices[t[1]], m.vertices[t[0]]), sub(m.vertices[t[2]], m.vertices[t[0]])));
  return a;
}

double enclosed_volume(const Mesh& m) {
  double v = 0;
  for (const Tri& t : m.triangles)
    v += dot3(m.vertices[t[0]], cross3(m.vertices[t[1]], m.vertices[t[2]])) / 6;
  return v;
}

bool is_closed(const Mesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[size_t(k)], t[size_t((k + 1) % 3)]}];
  for (const auto& [edge, n] : directed) {
    const auto back = directed.find({edge.second, edge.first});
    if (n != 1 || back == directed.end() || back->second != 1) return false;
  }
  return !m.triangles.empty();
}

std::array<Vec3, 2> bounds(const Mesh& m) {
  std::array<Vec3, 2> b{};
  for (size_t i = 0; i < m.vertices.size(); ++i)
    for (size_t k = 0; k < 3; ++k) {
      if (i == 0 || m.vertices[i][k] < b[0][k]) b[0][k] = m.vertices[i][k];
      if (i == 0 || m.vertices[i][k] > b[1][k]) b[1][k] = m.vertices[i][k];
    }
  return b;
}

}  // namespace cube4::golden
