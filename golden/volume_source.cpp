// The scene's volume: dispatch on kind, path resolution and the overrides
// that apply whatever the source.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "golden/quantise.hpp"
#include "golden/volume_io.hpp"

namespace cube4::golden {

namespace {

constexpr const char* kBrainsmall = "/usr/share/doc/libvolpack1-dev/examples/brainsmall.den";

bool is_synthetic(const std::string& kind) {
  return kind == "sphere" || kind == "spheres" || kind == "field" || kind == "noise" || kind == "constant" ||
         kind == "single_voxel";
}

// Relative paths are relative to the scene file, so scenes can travel with
// their volumes; a scene built in code (scene_dir "") uses the working folder.
std::string resolve(const std::string& path, const std::string& scene_dir) {
  if (path.empty()) throw InputError("volume.file: a file volume needs a path");
  const std::filesystem::path p(path);
  if (p.is_absolute() || scene_dir.empty()) return path;
  return (std::filesystem::path(scene_dir) / p).lexically_normal().string();
}

void check_spacing(const Vec3& s) {
  for (double c : s)
    if (!(c > 0) || !std::isfinite(c)) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "(%g, %g, %g)", s[0], s[1], s[2]);
      throw InputError(std::string("volume.spacing: ") + buf + " must have finite components > 0");
    }
}

}  // namespace

Volume load_volume(const VolumeSource& src, int voxel_bits, const std::string& scene_dir, bool header_only) {
  check_voxel_bits(voxel_bits);
  // Checked before any file is read, so a bad override does not cost a load.
  if (src.spacing) check_spacing(*src.spacing);
  Volume v;
  if (src.kind == "den")
    v = load_den(resolve(src.path, scene_dir), src.quantisation, voxel_bits, header_only);
  else if (src.kind == "raw")
    v = load_raw(src, resolve(src.path, scene_dir), voxel_bits, header_only);
  else if (src.kind == "nifti")
    v = load_nifti(resolve(src.path, scene_dir), src.quantisation, voxel_bits, header_only);
  else if (is_synthetic(src.kind))
    v = make_synthetic(src, voxel_bits, header_only);
  else
    throw InputError("volume.kind: unknown volume kind '" + src.kind +
                     "' (expected den, raw, nifti, sphere, spheres, field, noise, constant or "
                     "single_voxel)");
  if (src.spacing) v.spacing = *src.spacing;
  v.bits = voxel_bits;
  return v;
}

void load_tags(const Scene& s, Volume& v, const std::string& scene_dir) {
  v.tags.clear();
  v.tag_source.clear();
  const TagSource& t = s.tags;
  if (s.precision.tag_bits == 0 || (t.file.empty() && t.label.empty()) || v.data.empty()) return;
  const int max = s.tag_count() - 1;
  v.tags.assign(v.size(), 0);
  if (!t.file.empty()) {
    const std::string path = resolve(t.file, scene_dir);
    const FdCloser fd{open_regular_file(path, "the tag file (tags.file)")};
    const size_t n = read_fd(fd.fd, v.tags.data(), v.tags.size(), path, "the tag file (tags.file)");
    uint8_t extra = 0;
    if (n != v.tags.size() || read_fd(fd.fd, &extra, 1, path, "the tag file (tags.file)") != 0)
      throw InputError(path + ": tags.file should hold one byte per voxel, " + std::to_string(v.size()) +
                       " for the " + std::to_string(v.dim[0]) + "x" + std::to_string(v.dim[1]) + "x" +
                       std::to_string(v.dim[2]) + " volume; it holds " + (n == v.tags.size() ? "more" : std::to_string(n)));
    for (size_t i = 0; i < v.tags.size(); ++i)
      if (v.tags[i] > max) {
        const size_t x = i % v.dim[0], y = i / v.dim[0] % v.dim[1], z = i / v.dim[0] / v.dim[1];
        throw InputError(path + ": tags.file: voxel (" + std::to_string(x) + "," + std::to_string(y) + "," +
                         std::to_string(z) + ") has tag " + std::to_string(v.tags[i]) + ", above " +
                         std::to_string(max) + " (\"precision.tag_bits\" = " + std::to_string(s.precision.tag_bits) +
                         ")");
      }
    v.tag_source = path;
  }
  for (const TagRule& r : t.label) {
    for (int z = 0; z < v.dim[2]; ++z)
      for (int y = 0; y < v.dim[1]; ++y)
        for (int x = 0; x < v.dim[0]; ++x) {
          bool in = false;
          if (r.kind == TagRule::Kind::Threshold) {
            const double u = static_cast<double>(v.at(x, y, z)) / v.max_value();
            in = u >= r.range[0] && u <= r.range[1];
          } else if (r.kind == TagRule::Kind::Box) {
            in = x >= r.lo[0] && x <= r.hi[0] && y >= r.lo[1] && y <= r.hi[1] && z >= r.lo[2] && z <= r.hi[2];
          } else {
            const double dx = x - r.center[0], dy = y - r.center[1], dz = z - r.center[2];
            in = dx * dx + dy * dy + dz * dz <= r.radius * r.radius;
          }
          if (in) v.tags[v.index(x, y, z)] = static_cast<uint8_t>(r.tag);
        }
    v.tag_source += (v.tag_source.empty() ? "" : " + ") + r.key;
  }
}

std::string default_brainsmall_path() {
  // Some installs compress documentation examples; load_den reads both.
  std::error_code ec;
  const std::string gz = std::string(kBrainsmall) + ".gz";
  if (!std::filesystem::exists(kBrainsmall, ec) && std::filesystem::exists(gz, ec)) return gz;
  return kBrainsmall;
}

}  // namespace cube4::golden
