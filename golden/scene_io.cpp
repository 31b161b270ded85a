// Scene JSON → Scene. Every key is read through Node / ObjectReader, so each
// error names the file, the key path ("lights[1].direction") and the value,
// and a key nobody asked for is an error rather than a silently ignored typo.
#include "golden/scene_io.hpp"

#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "golden/volume_io.hpp"

namespace cube4::golden {
namespace {

using json = nlohmann::json;

// An axis the scene does not crop keeps every voxel, whatever the volume's size.
constexpr int kWholeAxis = 1 << 30;
constexpr size_t kMaxLights = 16;

std::string fmt(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

// Values go into one-line messages: long values are cut short, and written
// only as far as shown, so a huge array costs no more than a short one.
void dump_prefix(const json& v, std::string& out, size_t max) {
  if (out.size() > max) return;
  if (v.is_array() || v.is_object()) {
    out += v.is_array() ? '[' : '{';
    bool first = true;
    for (auto it = v.begin(); it != v.end() && out.size() <= max; ++it) {
      if (!first) out += ',';
      first = false;
      if (v.is_object()) out += json(it.key()).dump() + ':';
      dump_prefix(*it, out, max);
    }
    out += v.is_array() ? ']' : '}';
    return;
  }
  std::string s = v.dump();
  if (s.size() > max) s.resize(max + 1);
  out += s;
}

std::string show(const json& v) {
  constexpr size_t kMax = 60;
  std::string s;
  dump_prefix(v, s, kMax);
  if (s.size() > kMax) s = s.substr(0, kMax - 3) + "...";
  return s;
}

std::string file_prefix(const std::string& file) {
  return (file.empty() ? std::string("scene") : file) + ": ";
}

std::string quoted_path(const std::string& path) {
  return path.empty() ? std::string("the scene") : "\"" + path + "\"";
}

// `shown` is the value as the message shows it.
[[noreturn]] void fail_value(const std::string& file, const std::string& path,
                             const std::string& shown, const std::string& problem) {
  throw InputError(file_prefix(file) + quoted_path(path) + " = " + shown + " " + problem);
}

[[noreturn]] void fail_missing(const std::string& file, const std::string& path,
                               const std::string& why) {
  throw InputError(file_prefix(file) + quoted_path(path) + " is missing; " + why);
}

std::string join_quoted(std::initializer_list<const char*> words) {
  std::string out;
  for (const char* w : words) out += (out.empty() ? "\"" : ", \"") + std::string(w) + "\"";
  return out;
}

// One JSON value and where it sits in the scene, with checked conversions.
class Node {
 public:
  Node(const json& v, std::string path, const std::string& file)
      : v_(&v), path_(std::move(path)), file_(&file) {}

  const json& value() const { return *v_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }

  [[noreturn]] void fail(const std::string& problem) const {
    fail_value(*file_, path_, show(*v_), problem);
  }

  Node member(const std::string& key, const json& v) const {
    return Node(v, path_.empty() ? key : path_ + "." + key, *file_);
  }
  Node element(size_t i) const {
    return Node((*v_)[i], path_ + "[" + std::to_string(i) + "]", *file_);
  }

  double number() const {
    if (!v_->is_number()) fail("should be a number");
    const double x = v_->get<double>();
    if (!std::isfinite(x)) fail("should be a finite number");
    return x;
  }
  double number_in(double lo, double hi) const {
    const double x = number();
    if (x < lo || x > hi) fail("is out of range " + fmt(lo) + ".." + fmt(hi));
    return x;
  }
  double at_least(double lo) const {
    const double x = number();
    if (x < lo) fail("should be >= " + fmt(lo));
    return x;
  }
  double positive() const {
    const double x = number();
    if (x <= 0) fail("should be > 0");
    return x;
  }

  // Integral floats (2.0) are accepted: JSON writers do not always keep the
  // distinction, and the value is unambiguous.
  int64_t integer(int64_t lo, int64_t hi) const {
    int64_t x = 0;
    if (v_->is_number_unsigned()) {
      const uint64_t u = v_->get<uint64_t>();
      x = u > uint64_t(std::numeric_limits<int64_t>::max()) ? std::numeric_limits<int64_t>::max()
                                                            : int64_t(u);
    } else if (v_->is_number_integer()) {
      x = v_->get<int64_t>();
    } else if (v_->is_number_float() && is_integral(v_->get<double>())) {
      x = int64_t(v_->get<double>());
    } else {
      fail("should be an integer");
    }
    if (x < lo || x > hi) fail("is out of range " + std::to_string(lo) + ".." + std::to_string(hi));
    return x;
  }
  int int_in(int lo, int hi) const { return int(integer(lo, hi)); }

  bool boolean() const {
    if (!v_->is_boolean()) fail("should be true or false");
    return v_->get<bool>();
  }
  std::string string() const {
    if (!v_->is_string()) fail("should be a string");
    return v_->get<std::string>();
  }
  std::string one_of(std::initializer_list<const char*> choices) const {
    const std::string s = string();
    for (const char* c : choices)
      if (s == c) return s;
    fail("is not one of " + join_quoted(choices));
  }

  // The elements of an array of min..max entries.
  std::vector<Node> elements(size_t min, size_t max) const {
    if (!v_->is_array()) fail("should be an array");
    const size_t n = v_->size();
    if (n < min || n > max) {
      if (min == max) fail("should have " + std::to_string(min) + " entries, not " + std::to_string(n));
      if (max == std::numeric_limits<size_t>::max())
        fail("has " + std::to_string(n) + " entries; at least " + std::to_string(min) + " " +
             (min == 1 ? "is" : "are") + " needed");
      fail("has " + std::to_string(n) + " entries; " + std::to_string(min) + ".." +
           std::to_string(max) + " are allowed");
    }
    std::vector<Node> out;
    for (size_t i = 0; i < n; ++i) out.push_back(element(i));
    return out;
  }

  Vec3 vec3() const {
    const auto e = elements(3, 3);
    return {e[0].number(), e[1].number(), e[2].number()};
  }
  Vec3 vec3_in(double lo, double hi) const {
    const auto e = elements(3, 3);
    return {e[0].number_in(lo, hi), e[1].number_in(lo, hi), e[2].number_in(lo, hi)};
  }
  Vec3 positive_vec3() const {
    const auto e = elements(3, 3);
    return {e[0].positive(), e[1].positive(), e[2].positive()};
  }
  // Directions: any length but zero.
  Vec3 direction() const {
    const Vec3 v = vec3();
    if (v[0] == 0 && v[1] == 0 && v[2] == 0) fail("is not a direction (all zero)");
    return v;
  }
  std::array<int, 3> int3(int lo, int hi) const {
    const auto e = elements(3, 3);
    return {e[0].int_in(lo, hi), e[1].int_in(lo, hi), e[2].int_in(lo, hi)};
  }

 private:
  static bool is_integral(double x) {
    return std::isfinite(x) && std::floor(x) == x && std::fabs(x) < 9.0e18;
  }

  const json* v_;
  std::string path_;
  const std::string* file_;
};

// Walks one JSON object: hands out members by name, remembers which names
// were asked for, and rejects every other key once the caller is done.
class ObjectReader {
 public:
  explicit ObjectReader(const Node& n) : node_(n) {
    if (!n.value().is_object()) n.fail("should be an object");
  }

  const Node& node() const { return node_; }

  std::optional<Node> get(const std::string& key) {
    known_.push_back(key);
    const auto it = node_.value().find(key);
    if (it == node_.value().end()) return std::nullopt;
    return node_.member(key, *it);
  }

  void reject_unknown() const {
    for (const auto& [key, value] : node_.value().items()) {
      if (std::find(known_.begin(), known_.end(), key) != known_.end()) continue;
      const std::string path = node_.path().empty() ? key : node_.path() + "." + key;
      throw InputError(file_prefix(node_.file()) + "unknown key \"" + path + "\" = " + show(value) +
                       " (expected one of: " + known_list() + ")");
    }
  }

  [[noreturn]] void fail_missing(const std::string& key, const std::string& why) const {
    golden::fail_missing(node_.file(), node_.path().empty() ? key : node_.path() + "." + key, why);
  }

 private:
  std::string known_list() const {
    std::string out;
    for (const auto& k : known_) out += (out.empty() ? "" : ", ") + k;
    return out;
  }

  Node node_;
  std::vector<std::string> known_;
};

// ---- JSON text ------------------------------------------------------------

// Scenes are a few levels deep; a limit keeps a hostile file (100,000 nested
// arrays) from costing stack anywhere a value is walked.
constexpr size_t kMaxDepth = 64;
// A scene is a few kilobytes; the limit refuses a huge file before reading it.
constexpr uint64_t kMaxSceneBytes = uint64_t{16} << 20;

// Where the parser is, kept outside the callback (nlohmann copies it) so
// that an error the parser itself raises can be reported with its key path.
struct ParsePosition {
  struct Frame {
    bool is_array;
    size_t index;
    std::string key;
    std::set<std::string> keys;
  };
  std::vector<Frame> frames;

  std::string path() const {
    std::string p;
    for (const Frame& f : frames) {
      if (f.is_array) p += "[" + std::to_string(f.index) + "]";
      else p += (p.empty() ? "" : ".") + f.key;
    }
    return p;
  }
};

// nlohmann keeps the last of two equal keys; a duplicate is almost always a
// copy-and-paste slip, so it is an error, reported with its key path.
class SceneShapeCheck {
 public:
  SceneShapeCheck(const std::string& file, ParsePosition& pos) : file_(&file), pos_(&pos) {}

  bool operator()(int depth, json::parse_event_t event, json& parsed) {
    using E = json::parse_event_t;
    auto& frames = pos_->frames;
    switch (event) {
      case E::object_start:
      case E::array_start:
        if (static_cast<size_t>(depth) >= kMaxDepth)
          throw InputError(file_prefix(*file_) + quoted_path(pos_->path()) + " is nested more than " +
                           std::to_string(kMaxDepth) + " levels deep; scenes need a few");
        frames.push_back({event == E::array_start, 0, "", {}});
        break;
      case E::key: on_key(parsed.get<std::string>()); break;
      case E::object_end:
      case E::array_end:
        frames.pop_back();
        element_done();
        break;
      case E::value: element_done(); break;
    }
    return true;
  }

 private:
  void on_key(const std::string& key) {
    ParsePosition::Frame& f = pos_->frames.back();
    f.key = key;
    if (!f.keys.insert(key).second)
      throw InputError(file_prefix(*file_) + "duplicate key \"" + pos_->path() + "\"");
  }
  void element_done() {
    auto& frames = pos_->frames;
    if (!frames.empty() && frames.back().is_array) ++frames.back().index;
  }

  const std::string* file_;
  ParsePosition* pos_;
};

json parse_json(const std::string& text, const std::string& file) {
  ParsePosition pos;
  try {
    return json::parse(text, SceneShapeCheck(file, pos));
  } catch (const json::parse_error& e) {
    // Drop nlohmann's "[json.exception.parse_error.101] " tag, keep its
    // "parse error at line L, column C: ..." and add the byte offset.
    std::string what = e.what();
    const auto tag_end = what.find("] ");
    if (tag_end != std::string::npos) what = what.substr(tag_end + 2);
    throw InputError(file_prefix(file) + "invalid JSON: " + what + " (byte " +
                     std::to_string(e.byte) + ")");
  } catch (const json::out_of_range& e) {
    // nlohmann: "number overflow parsing '1e309'" (406), the only range
    // error its parser raises.
    std::string what = e.what(), number = "the number";
    const auto q1 = what.find('\''), q2 = what.rfind('\'');
    if (q1 != std::string::npos && q2 > q1) {
      number = what.substr(q1 + 1, q2 - q1 - 1);
      if (number.size() > 40) number = number.substr(0, 37) + "...";
    }
    fail_value(file, pos.path(), number, "does not fit a double (largest about 1.8e308)");
  }
}

// ---- volume ---------------------------------------------------------------

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string format_from_extension(std::string path) {
  std::transform(path.begin(), path.end(), path.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  // Some installs gzip documentation examples (brainsmall.den.gz); the DEN loader reads both.
  if (ends_with(path, ".den") || ends_with(path, ".den.gz")) return "den";
  if (ends_with(path, ".raw")) return "raw";
  if (ends_with(path, ".nii") || ends_with(path, ".nii.gz")) return "nifti";
  return "";
}

void read_raw_layout(ObjectReader& r, VolumeSource& v) {
  const auto dim = r.get("dim");
  if (dim) v.dim = dim->int3(1, 4096);
  if (auto n = r.get("type"))
    v.type = n->one_of({"uint8", "uint12", "uint16", "int16", "uint32", "int32", "float32", "float64"});
  if (auto n = r.get("endian")) v.endian = n->one_of({"little", "big"});
  if (auto n = r.get("header")) v.header_bytes = uint64_t(n->integer(0, std::numeric_limits<int64_t>::max()));
  // Unknown keys are rejected by read_volume, which also reads "spacing" and "map".
  if (!dim) r.fail_missing("dim", "raw volumes need their size [x, y, z]");
}

void read_file_source(ObjectReader& r, const Node& file, VolumeSource& v) {
  v.path = file.string();
  if (v.path.empty()) file.fail("should name a file");
  if (auto f = r.get("format")) {
    v.kind = f->one_of({"den", "raw", "nifti"});
  } else {
    v.kind = format_from_extension(v.path);
    if (v.kind.empty())
      file.fail("has no known extension (.den, .den.gz, .raw, .nii, .nii.gz); give \"volume.format\"");
  }
  if (v.kind == "raw") read_raw_layout(r, v);
}

// Only the keys of the chosen synthetic kind are read, so a key of another
// kind ("radius" on "noise") is reported as unknown.
void read_synthetic_source(ObjectReader& r, const Node& kind, VolumeSource& v) {
  v.kind = kind.one_of({"sphere", "spheres", "field", "noise", "constant", "single_voxel"});
  if (auto n = r.get("size")) v.size = n->int3(1, 1024);
  if (v.kind == "sphere" || v.kind == "spheres") {
    if (auto n = r.get("radius")) v.radius = n->positive();
    if (auto n = r.get("center")) v.center = n->vec3();
  } else if (v.kind == "field") {
    if (auto n = r.get("field"))
      v.field = n->one_of({"marschner_lobb", "gaussian", "ramp_x", "ramp_y", "ramp_z"});
  } else if (v.kind == "noise") {
    if (auto n = r.get("seed")) v.seed = uint32_t(n->integer(0, std::numeric_limits<uint32_t>::max()));
  } else {
    if (auto n = r.get("value")) v.value = n->number_in(0, 1);
    if (v.kind == "single_voxel")
      if (auto n = r.get("at")) v.at = n->int3(0, 1023);
  }
}

Quantisation read_map(const Node& n) {
  Quantisation q;
  if (n.value().is_string()) {
    q.mode = n.one_of({"full", "minmax"}) == "full" ? Quantisation::Mode::Full
                                                     : Quantisation::Mode::MinMax;
    return q;
  }
  if (!n.value().is_array()) n.fail("should be \"full\", \"minmax\" or [lo, hi]");
  const auto e = n.elements(2, 2);
  q.mode = Quantisation::Mode::Window;
  q.lo = e[0].number();
  q.hi = e[1].number();
  if (q.hi <= q.lo) e[1].fail("should be greater than lo = " + fmt(q.lo));
  return q;
}

void read_volume(const Node& n, VolumeSource& v) {
  ObjectReader r(n);
  const auto file = r.get("file");
  const auto synthetic = r.get("synthetic");
  if (file && synthetic) n.fail("gives both \"file\" and \"synthetic\"; give one");
  if (file) read_file_source(r, *file, v);
  if (synthetic) read_synthetic_source(r, *synthetic, v);
  if (auto s = r.get("spacing")) v.spacing = s->positive_vec3();
  if (auto m = r.get("map")) v.quantisation = read_map(*m);
  r.reject_unknown();
  if (!file && !synthetic) n.fail("needs \"file\" or \"synthetic\"");
}

// ---- view and output ------------------------------------------------------

void read_view(const Node& n, View& v) {
  ObjectReader r(n);
  const auto rotate = r.get("rotate");
  const auto direction = r.get("direction");
  const auto up = r.get("up");
  const auto offset = r.get("ray_offset");
  const auto zoom = r.get("zoom");
  const auto look_at = r.get("look_at");
  const auto window = r.get("window");
  const auto projection = r.get("projection");
  const auto fov = r.get("fov");
  const auto distance = r.get("distance");
  const auto eye = r.get("eye");
  r.reject_unknown();
  if (rotate && direction) n.fail("gives both \"rotate\" and \"direction\"; give one");
  if (eye && (rotate || direction))
    eye->fail(std::string("and \"view.") + (rotate ? "rotate" : "direction") +
              "\" both set the viewing direction; give one");
  if (eye && distance) distance->fail("and \"view.eye\" both place the eye; give one");
  if (up && !direction && !eye) up->fail("needs \"view.direction\" or \"view.eye\" (it does not apply to \"rotate\")");
  if (projection)
    v.projection = projection->one_of({"parallel", "perspective"}) == "parallel" ? View::Projection::Parallel
                                                                                 : View::Projection::Perspective;
  for (const auto& only : {fov, distance, eye})
    if (only && !v.perspective()) only->fail("needs \"view.projection\": \"perspective\"");
  // Cube-4's box filter spans 1 + 2 tan(fov/2) voxels at most in the
  // furthest slice: three at 90 degrees, the limit of its extra stages.
  if (fov) {
    v.fov = fov->number();
    if (!(v.fov > 0 && v.fov < 90))
      fov->fail("is out of range: the field of view must be above 0 and below 90 degrees (Cube-4's box filter "
                "covers at most 1 + 2 tan(fov/2) < 3 voxels)");
  }
  if (distance) v.distance = distance->positive();
  if (eye) v.eye = eye->vec3();
  if (rotate) v.rotate = rotate->vec3();
  if (direction) v.direction = direction->direction();
  if (up) v.up = up->direction();
  if (offset) {
    const auto e = offset->elements(2, 2);
    for (size_t i = 0; i < 2; ++i) {
      v.ray_offset[i] = e[i].number();
      if (v.ray_offset[i] < 0 || v.ray_offset[i] >= 1) e[i].fail("is out of range [0, 1)");
    }
  }
  // Beyond 1/64 the volume is a few pixels; beyond 1024 a pixel is a small
  // fraction of a voxel: either way the image says nothing the range does not.
  if (zoom) v.zoom = zoom->number_in(1.0 / 64, 1024);
  if (look_at) v.look_at = look_at->vec3();
  if (window) {
    const auto e = window->elements(4, 4);
    for (size_t i = 0; i < 4; ++i) v.window[i] = e[i].number_in(-1, 1);
    if (!(v.window[2] > v.window[0])) e[2].fail("is not right of x0 = " + fmt(v.window[0]) + " (window [x0, y0, x1, y1])");
    if (!(v.window[3] > v.window[1])) e[3].fail("is not above y0 = " + fmt(v.window[1]) + " (window [x0, y0, x1, y1])");
  }
}

void read_output(const Node& n, Scene& s) {
  ObjectReader r(n);
  if (auto w = r.get("width")) s.width = w->int_in(1, 8192);
  if (auto h = r.get("height")) s.height = h->int_in(1, 8192);
  r.reject_unknown();
}

// ---- transfer functions ---------------------------------------------------

// Piecewise-linear tables: rows of `width` numbers in [0,1], the first (x)
// strictly increasing, at least one row.
std::vector<std::vector<double>> read_table(const Node& n, size_t width) {
  std::vector<std::vector<double>> rows;
  for (const Node& row : n.elements(1, std::numeric_limits<size_t>::max())) {
    std::vector<double> values;
    for (const Node& cell : row.elements(width, width)) values.push_back(cell.number_in(0, 1));
    if (!rows.empty() && values[0] <= rows.back()[0])
      row.element(0).fail("is not greater than the x before it (" + fmt(rows.back()[0]) +
                          "); x must increase strictly");
    rows.push_back(std::move(values));
  }
  return rows;
}

std::vector<ScalarPoint> read_scalar_table(const Node& n) {
  std::vector<ScalarPoint> out;
  for (const auto& row : read_table(n, 2)) out.push_back({row[0], row[1]});
  return out;
}

void read_transfer(const Node& n, Scene& s) {
  ObjectReader r(n);
  if (auto c = r.get("color"))
    for (const auto& row : read_table(*c, 4)) s.color.push_back({row[0], {row[1], row[2], row[3]}});
  if (auto o = r.get("opacity")) s.opacity = read_scalar_table(*o);
  r.reject_unknown();
}

// ---- lighting -------------------------------------------------------------

Light read_light(const Node& n) {
  ObjectReader r(n);
  Light l;
  const auto direction = r.get("direction");
  if (direction) l.direction = direction->direction();
  if (auto i = r.get("intensity")) l.intensity = i->at_least(0);
  r.reject_unknown();
  if (!direction) r.fail_missing("direction", "every light needs one");
  return l;
}

void read_lights(const Node& n, Scene& s) {
  // An empty list would be silently replaced by the default light.
  if (n.value().is_array() && n.value().empty())
    n.fail("has no lights; give at least one, or \"shading\": false for none");
  for (const Node& l : n.elements(1, kMaxLights)) s.lights.push_back(read_light(l));
}

void read_material(const Node& n, Material& m) {
  ObjectReader r(n);
  if (auto k = r.get("ke")) m.ke = k->number_in(0, 3.99);
  if (auto k = r.get("kd")) m.kd = k->number_in(0, 3.99);
  if (auto k = r.get("ks")) m.ks = k->number_in(0, 3.99);
  if (auto c = r.get("specular_color")) m.specular_color = c->vec3_in(0, 1);
  if (auto e = r.get("exponent")) m.exponent = e->number_in(1, 128);
  r.reject_unknown();
}

void read_gradient_modulation(const Node& n, GradientModulation& gm) {
  ObjectReader r(n);
  if (auto b = r.get("opacity")) gm.opacity = b->boolean();
  if (auto b = r.get("diffuse")) gm.diffuse = b->boolean();
  if (auto b = r.get("specular")) gm.specular = b->boolean();
  r.reject_unknown();
}

Blend read_blend(const Node& n) {
  const std::string b = n.one_of({"composite", "mip", "minip"});
  return b == "composite" ? Blend::Composite : b == "mip" ? Blend::Mip : Blend::MinIp;
}

// ---- cropping and cut plane -----------------------------------------------

std::array<int, 2> read_slab(const Node& n) {
  const auto e = n.elements(2, 2);
  const int lo = e[0].int_in(0, kWholeAxis);
  const int hi = e[1].int_in(0, kWholeAxis);
  if (hi < lo) e[1].fail("is less than lo = " + std::to_string(lo));
  return {lo, hi};
}

uint8_t read_combine(const Node& n) {
  const std::string c = n.one_of({"intersection", "union", "cross"});
  if (c == "intersection") return 0x80;  // in all three slabs
  if (c == "union") return 0xFE;         // in any slab
  return 0xE8;                           // in at least two slabs
}

void read_cropping(const Node& n, Cropping& c) {
  ObjectReader r(n);
  c.enabled = true;
  const char* axes[] = {"x", "y", "z"};
  for (size_t i = 0; i < 3; ++i) {
    const auto a = r.get(axes[i]);
    c.slab[i] = a ? read_slab(*a) : std::array<int, 2>{0, kWholeAxis};
  }
  const auto combine = r.get("combine");
  const auto mask = r.get("mask");
  const auto invert = r.get("invert");
  r.reject_unknown();
  if (combine && mask) n.fail("gives both \"combine\" and \"mask\"; give one");
  if (combine) c.mask = read_combine(*combine);
  if (mask) c.mask = uint8_t(mask->int_in(0, 255));
  if (invert && invert->boolean()) c.mask = uint8_t(~c.mask);
}

void read_cut_plane(const Node& n, CutPlane& c) {
  ObjectReader r(n);
  c.enabled = true;
  if (auto v = r.get("normal")) c.normal = v->direction();
  if (auto v = r.get("dmin")) c.dmin = v->number();
  if (auto v = r.get("dmax")) c.dmax = v->number();
  if (auto v = r.get("falloff")) c.falloff = v->at_least(0);
  if (auto v = r.get("keep")) c.keep_inside = v->one_of({"inside", "outside"}) == "inside";
  r.reject_unknown();
}

// ---- polygons -------------------------------------------------------------

constexpr size_t kMaxMeshes = 1024;

// A number (uniform) or [x, y, z], every factor > 0.
Vec3 read_scale(const Node& n) {
  if (n.value().is_number()) {
    const double s = n.positive();
    return {s, s, s};
  }
  if (!n.value().is_array()) n.fail("should be a number or [x, y, z]");
  return n.positive_vec3();
}

// [[a, b, c, tx], [d, e, f, ty], [g, h, i, tz], [0, 0, 0, 1]]: rows, affine,
// with an invertible 3×3 part.
std::array<double, 16> read_matrix(const Node& n) {
  std::array<double, 16> m{};
  const auto rows = n.elements(4, 4);
  for (size_t i = 0; i < 4; ++i) {
    const auto cells = rows[i].elements(4, 4);
    for (size_t j = 0; j < 4; ++j) m[4 * i + j] = cells[j].number();
  }
  if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1)
    rows[3].fail("should be [0, 0, 0, 1] (an affine transform)");
  const double det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
                     m[2] * (m[4] * m[9] - m[5] * m[8]);
  if (!(std::fabs(det) > 0) || !std::isfinite(det))
    n.fail("is singular (its 3x3 part has determinant " + fmt(det) + "); it would flatten the mesh");
  return m;
}

void read_transform(const Node& n, MeshTransform& t) {
  ObjectReader r(n);
  const auto scale = r.get("scale");
  const auto rotate = r.get("rotate");
  const auto translate = r.get("translate");
  const auto matrix = r.get("matrix");
  r.reject_unknown();
  if (matrix && (scale || rotate || translate))
    n.fail("gives \"matrix\" and \"scale\", \"rotate\" or \"translate\"; give the matrix alone");
  if (scale) t.scale = read_scale(*scale);
  if (rotate) t.rotate = rotate->vec3();
  if (translate) t.translate = translate->vec3();
  if (matrix) t.matrix = read_matrix(*matrix);
}

MeshShape read_shape(const Node& n) {
  const std::string s = n.one_of({"box", "sphere", "cylinder", "needle", "plane"});
  if (s == "box") return MeshShape::Box;
  if (s == "sphere") return MeshShape::Sphere;
  if (s == "cylinder") return MeshShape::Cylinder;
  return s == "needle" ? MeshShape::Needle : MeshShape::Plane;
}

// Only the keys of the chosen shape are read, so "radius" on a box is unknown.
void read_shape_parameters(ObjectReader& r, MeshSpec& m) {
  switch (m.shape) {
    case MeshShape::Box:
      if (auto n = r.get("size")) m.size = n->positive_vec3();
      return;
    case MeshShape::Plane:
      if (auto n = r.get("size")) {
        const auto e = n->elements(2, 2);
        m.size = {e[0].positive(), e[1].positive(), 0};
      } else {
        m.size = {1, 1, 0};
      }
      return;
    case MeshShape::Sphere:
      if (auto n = r.get("radius")) m.radius = n->positive();
      if (auto n = r.get("segments")) m.segments = n->int_in(3, 1024);
      if (auto n = r.get("rings")) m.rings = n->int_in(2, 1024);
      return;
    case MeshShape::Cylinder:
    case MeshShape::Needle:
      break;
  }
  if (auto n = r.get("radius")) m.radius = n->positive();
  if (auto n = r.get("length")) m.length = n->positive();
  if (auto n = r.get("segments")) m.segments = n->int_in(3, 1024);
  if (m.shape != MeshShape::Needle) return;
  m.tip = m.length / 4;
  if (auto n = r.get("tip")) {
    m.tip = n->positive();
    if (m.tip >= m.length) n->fail("should be less than the needle's length (" + fmt(m.length) + ")");
  }
}

MeshSpec read_mesh(const Node& n) {
  ObjectReader r(n);
  MeshSpec m;
  m.key = n.path();
  const auto file = r.get("file");
  const auto shape = r.get("shape");
  if (file && shape) n.fail("gives both \"file\" and \"shape\"; give one");
  if (file) {
    m.file = file->string();
    if (m.file.empty()) file->fail("should name a file");
  }
  if (shape) {
    m.shape = read_shape(*shape);
    read_shape_parameters(r, m);
  }
  if (auto t = r.get("transform")) read_transform(*t, m.transform);
  if (auto c = r.get("color")) m.color = c->vec3_in(0, 1);
  if (auto o = r.get("opacity")) m.opacity = o->number_in(0, 1);
  if (auto l = r.get("lit")) m.lit = l->boolean();
  r.reject_unknown();
  if (!file && !shape) n.fail("needs \"file\" or \"shape\"");
  return m;
}

// Rates in millions a second (clock in MHz), each above 0 and at most 10^6.
void read_polygon_engine(const Node& n, PolygonEngine& e) {
  ObjectReader r(n);
  const auto rate = [&](const char* key, double& out) {
    if (auto v = r.get(key)) {
      const double m = v->number();
      if (!(m > 0 && m <= 1e6)) v->fail("is out of range (0, 1000000] (millions a second)");
      out = m * 1e6;
    }
  };
  rate("fill_rate_m", e.fill_rate);
  rate("triangle_rate_m", e.triangle_rate);
  rate("dual_fill_rate_m", e.dual_fill_rate);
  rate("rle_clock_mhz", e.rle_clock_hz);
  if (auto v = r.get("connection")) {
    const std::string c = v->one_of({"rle", "dual", "ideal"});
    e.connection = c == "rle" ? PolygonConnection::Rle : c == "dual" ? PolygonConnection::Dual : PolygonConnection::Ideal;
  }
  r.reject_unknown();
}

void read_polygons(const Node& n, Scene& s) {
  for (const Node& m : n.elements(0, kMaxMeshes)) s.polygons.push_back(read_mesh(m));
}

// ---- voxel tags -----------------------------------------------------------

constexpr size_t kMaxTagRules = 256;

TagRule read_tag_rule(const Node& n) {
  ObjectReader r(n);
  TagRule t;
  t.key = n.path();
  const auto tag = r.get("tag");
  if (tag) t.tag = tag->int_in(0, 255);
  const auto threshold = r.get("threshold"), box = r.get("box"), sphere = r.get("sphere");
  r.reject_unknown();
  if (!tag) r.fail_missing("tag", "every rule gives its voxels one");
  if (!!threshold + !!box + !!sphere != 1)
    n.fail("should have exactly one of \"threshold\", \"box\", \"sphere\"");
  if (threshold) {
    const auto e = threshold->elements(2, 2);
    t.kind = TagRule::Kind::Threshold;
    t.range = {e[0].number_in(0, 1), e[1].number_in(0, 1)};
    if (t.range[1] < t.range[0]) threshold->fail("should be [lo, hi] with lo <= hi");
  } else if (box) {
    ObjectReader b(*box);
    t.kind = TagRule::Kind::Box;
    const auto lo = b.get("min"), hi = b.get("max");
    b.reject_unknown();
    if (!lo) b.fail_missing("min", "a box needs its first voxel");
    if (!hi) b.fail_missing("max", "a box needs its last voxel");
    t.lo = lo->int3(0, 1 << 20);
    t.hi = hi->int3(0, 1 << 20);
  } else {
    ObjectReader b(*sphere);
    t.kind = TagRule::Kind::Sphere;
    const auto c = b.get("center"), rad = b.get("radius");
    b.reject_unknown();
    if (!c) b.fail_missing("center", "a sphere needs one (voxel coordinates)");
    if (!rad) b.fail_missing("radius", "a sphere needs one (voxels)");
    t.center = c->vec3();
    t.radius = rad->positive();
  }
  return t;
}

// A class's material starts as the scene's (read before "tags").
void read_tag_class(const Node& n, const Material& base, TagSource& tags) {
  ObjectReader r(n);
  const auto tag = r.get("tag");
  TagClass c;
  c.key = n.path();
  if (auto t = r.get("color")) {
    c.color.emplace();
    for (const auto& row : read_table(*t, 4)) c.color->push_back({row[0], {row[1], row[2], row[3]}});
  }
  if (auto t = r.get("opacity")) c.opacity = read_scalar_table(*t);
  if (auto m = r.get("material")) read_material(*m, c.material.emplace(base));
  r.reject_unknown();
  if (!tag) r.fail_missing("tag", "every class is some tag's");
  const int t = tag->int_in(0, 255);
  if (tags.classes.count(t)) tag->fail("has a class already (" + tags.classes[t].key + ")");
  tags.classes[t] = std::move(c);
}

void read_tags(const Node& n, const Material& base, TagSource& tags) {
  ObjectReader r(n);
  tags.given = true;
  if (auto f = r.get("file")) tags.file = f->string();
  if (auto l = r.get("label"))
    for (const Node& e : l->elements(1, kMaxTagRules)) tags.label.push_back(read_tag_rule(e));
  if (auto c = r.get("classes"))
    for (const Node& e : c->elements(1, 256)) read_tag_class(e, base, tags);
  r.reject_unknown();
}

// ---- precision ------------------------------------------------------------

void read_precision(const Node& n, Precision& p) {
  ObjectReader r(n);
  for (const auto& f : kPrecisionFields)
    if (auto v = r.get(f.key)) p.*f.member = v->int_in(f.lo, f.hi);
  r.reject_unknown();
}

// ---- cross-field checks (finish_scene) ------------------------------------

void check_int(const Scene& s, const std::string& path, int x, int lo, int hi, const std::string& why) {
  if (x < lo || x > hi)
    fail_value(s.file, path, std::to_string(x), "is out of range " + std::to_string(lo) + ".." + std::to_string(hi) + why);
}

void check_precision(const Scene& s) {
  const Precision& p = s.precision;
  for (const auto& f : kPrecisionFields)
    check_int(s, std::string("precision.") + f.key, p.*f.member, f.lo, f.hi, "");
  check_int(s, "precision.dda_frac_bits", p.dda_frac_bits, p.weight_bits, 30,
            " (at least \"precision.weight_bits\")");
  check_int(s, "precision.map_frac_bits", p.map_frac_bits, 0, p.map_bits - 1,
            " (below \"precision.map_bits\")");
  check_int(s, "precision.coef_frac_bits", p.coef_frac_bits, 0, p.coef_bits - 1,
            " (below \"precision.coef_bits\")");
}

// Formatted like the JSON the user wrote ([0,0,-3], not [0.0,0.0,-3.0]).
template <class Array>
std::string show_array(const Array& v) {
  std::string out;
  for (const auto& x : v) out += (out.empty() ? "[" : ",") + fmt(x);
  return out + "]";
}

// The eye's direction waits for the volume (factorise_view): look_at's
// default is the volume's centre.
void check_view(const Scene& s) {
  if (!s.view.direction) return;
  const Vec3& d = *s.view.direction;
  const std::string d_key = "view.direction";
  const Vec3& u = s.view.up;
  const double dd = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const double uu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  if (dd == 0) fail_value(s.file, "view.direction", show_array(d), "is not a direction (all zero)");
  const Vec3 c{d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2], d[0] * u[1] - d[1] * u[0]};
  const double cc = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  // sin(angle) below 1e-6: no usable image "up" is left after projection.
  if (!(cc > 1e-6 * dd * uu))
    fail_value(s.file, "view.up", show_array(u),
               "is parallel to the viewing direction (\"" + d_key + "\" gives " + show_array(d) + "); give another up");
}

void check_volume(const Scene& s) {
  const VolumeSource& v = s.volume;
  if (v.kind != "single_voxel") return;
  for (size_t i = 0; i < 3; ++i)
    if (v.at[i] < 0 || v.at[i] >= v.size[i])
      fail_value(s.file, "volume.at", show_array(v.at),
                 "lies outside \"volume.size\" = " + show_array(v.size));
}

// Tags fit precision.tag_bits; the classification table's address
// {tag, value} has at most 16 bits (bela: 16 bits per voxel and tag).
void check_tags(const Scene& s) {
  const Precision& p = s.precision;
  const TagSource& t = s.tags;
  if (p.tag_bits > 0)
    check_int(s, "precision.tag_bits", p.tag_bits, 0, 16 - p.voxel_bits,
              " (\"precision.voxel_bits\" + tag_bits address the classification table, at most 16 bits)");
  if (t.given && p.tag_bits == 0)
    fail_value(s.file, "tags", "{...}", "needs \"precision.tag_bits\" >= 1 (it is 0: no tags)");
  const int max = s.tag_count() - 1;
  const std::string why = " (\"precision.tag_bits\" = " + std::to_string(p.tag_bits) + ")";
  for (const TagRule& r : t.label) check_int(s, r.key + ".tag", r.tag, 0, max, why);
  for (const auto& [tag, c] : t.classes) {
    check_int(s, c.key + ".tag", tag, 0, max, why);
    if (c.material && c.material->exponent != s.material.exponent)
      fail_value(s.file, c.key + ".material.exponent", fmt(c.material->exponent),
                 "differs from \"material.exponent\" = " + fmt(s.material.exponent) +
                     " (one specular map serves every tag)");
  }
}

void check_cut_plane(const Scene& s) {
  if (s.cut.enabled && s.cut.dmax < s.cut.dmin)
    fail_value(s.file, "cut_plane.dmax", fmt(s.cut.dmax),
               "is less than \"cut_plane.dmin\" = " + fmt(s.cut.dmin));
}

void fill_defaults(Scene& s) {
  if (s.color.empty()) s.color = {{0, {1, 1, 1}}, {1, {1, 1, 1}}};
  // brainsmall's skin starts near byte 24 (24/255 = 0.094): air stays clear.
  if (s.opacity.empty()) s.opacity = {{0, 0}, {0.094, 0}, {0.16, 0.6}, {1, 0.8}};
  if (s.gm_lut.empty()) s.gm_lut = {{0, 0}, {1, 1}};
  if (s.lights.empty()) s.lights = {Light{{0.3, 0.3, 1}, 1}};
}

}  // namespace

Scene parse_scene(const std::string& json_text, const std::string& file_name) {
  const json j = parse_json(json_text, file_name);
  Scene s;
  s.file = file_name;
  ObjectReader r(Node(j, "", s.file));
  const auto volume = r.get("volume");
  if (volume) read_volume(*volume, s.volume);
  if (auto n = r.get("view")) read_view(*n, s.view);
  if (auto n = r.get("output")) read_output(*n, s);
  if (auto n = r.get("transfer")) read_transfer(*n, s);
  if (auto n = r.get("gm_lut")) s.gm_lut = read_scalar_table(*n);
  if (auto n = r.get("lights")) read_lights(*n, s);
  if (auto n = r.get("material")) read_material(*n, s.material);
  if (auto n = r.get("shading")) s.shading = n->boolean();
  if (auto n = r.get("blend")) s.blend = read_blend(*n);
  if (auto n = r.get("gradient_modulation")) read_gradient_modulation(*n, s.gm);
  if (auto n = r.get("supersampling")) s.supersampling = n->int_in(1, 8);
  if (auto n = r.get("xy_supersampling")) s.xy_supersampling = n->int_in(1, 4);
  if (auto n = r.get("z_gradient"))
    s.z_gradient = n->one_of({"abc", "voxel_differences"}) == "abc" ? ZGradient::Abc : ZGradient::VoxelDifferences;
  if (auto n = r.get("cropping")) read_cropping(*n, s.cropping);
  if (auto n = r.get("cut_plane")) read_cut_plane(*n, s.cut);
  if (auto n = r.get("pipelines")) s.pipelines = n->int_in(1, 256);
  if (auto n = r.get("blocks")) s.blocks = n->int3(1, 4096);
  if (auto n = r.get("clock_mhz")) {
    s.clock_mhz = n->number();
    if (s.clock_mhz <= 0 || s.clock_mhz > 10000) n->fail("is out of range (0, 10000]");
  }
  if (auto n = r.get("precision")) read_precision(*n, s.precision);
  if (auto n = r.get("polygons")) read_polygons(*n, s);
  if (auto n = r.get("polygon_engine")) read_polygon_engine(*n, s.polygon_engine);
  if (auto n = r.get("tags")) read_tags(*n, s.material, s.tags);
  // Unknown keys first: a misspelt "volume" should be reported as such.
  r.reject_unknown();
  if (!volume) r.fail_missing("volume", "every scene needs one (\"file\" or \"synthetic\")");
  finish_scene(s);
  return s;
}

Scene load_scene(const std::string& path) {
  const FdCloser fd{open_regular_file(path, "the scene")};
  struct stat st {};
  if (::fstat(fd.fd, &st) == 0 && static_cast<uint64_t>(st.st_size) > kMaxSceneBytes)
    throw InputError(path + ": the scene is " + std::to_string(st.st_size) + " bytes, more than the " +
                     std::to_string(kMaxSceneBytes >> 20) + " MiB a scene may have");
  // Read to the end, not to st_size: /proc files and the like report 0.
  std::string text;
  char buf[1 << 16];
  for (size_t n = sizeof buf; n == sizeof buf && text.size() <= kMaxSceneBytes;) {
    n = read_fd(fd.fd, buf, sizeof buf, path, "the scene");
    text.append(buf, n);
  }
  if (text.size() > kMaxSceneBytes)
    throw InputError(path + ": the scene is more than the " + std::to_string(kMaxSceneBytes >> 20) +
                     " MiB a scene may have");
  return parse_scene(text, path);
}

Scene default_scene() {
  Scene s;
  s.volume.kind = "den";
  s.volume.path = default_brainsmall_path();
  s.view.rotate = {20, 60, 180};  // a three-quarter view of the face
  finish_scene(s);
  return s;
}

void finish_scene(Scene& s) {
  fill_defaults(s);
  check_precision(s);
  check_view(s);
  check_volume(s);
  check_cut_plane(s);
  check_tags(s);
}

}  // namespace cube4::golden
