// The scene's volume: dispatch on kind, path resolution and the overrides
// that apply whatever the source.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "golden/errors.hpp"
#include "golden/quantise.hpp"
#include "golden/volume_io.hpp"

namespace cube4::golden {

namespace {

constexpr const char* kBrainsmall = "/usr/share/doc/libvolpack1-dev/examples/brainsmall.den";

bool is_synthetic(const std::string& kind) {
  return kind == "sphere" || kind == "field" || kind == "noise" || kind == "constant" ||
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
                     "' (expected den, raw, nifti, sphere, field, noise, constant or "
                     "single_voxel)");
  if (src.spacing) v.spacing = *src.spacing;
  v.bits = voxel_bits;
  return v;
}

std::string default_brainsmall_path() {
  // Some installs compress documentation examples; load_den reads both.
  std::error_code ec;
  const std::string gz = std::string(kBrainsmall) + ".gz";
  if (!std::filesystem::exists(kBrainsmall, ec) && std::filesystem::exists(gz, ec)) return gz;
  return kBrainsmall;
}

}  // namespace cube4::golden
