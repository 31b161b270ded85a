// Small helpers shared by the golden-model tests.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "golden/host_driver.hpp"
#include "golden/mesh.hpp"
#include "golden/polygons.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "tb/image_error.hpp"

namespace cube4::test {

struct Setup {
  golden::Scene scene;
  golden::Volume volume;
  std::vector<golden::Mesh> meshes;  // the scene's polygons
  golden::HostProgram host;
};

// A scene from JSON (relative paths from the working folder) or from a
// file (relative paths from its folder).
inline Setup setup_parsed(golden::Scene scene, const std::string& dir) {
  Setup s;
  s.scene = std::move(scene);
  s.volume = golden::load_volume(s.scene.volume, s.scene.precision.voxel_bits, dir);
  golden::load_tags(s.scene, s.volume, dir);
  s.meshes = golden::load_meshes(s.scene, dir);
  s.host = golden::program_host(s.scene, s.volume, s.meshes);
  return s;
}
inline Setup setup(const std::string& json) { return setup_parsed(golden::parse_scene(json, "test.json"), "."); }
inline Setup setup_file(const std::string& path) {
  return setup_parsed(golden::load_scene(path), std::filesystem::path(path).parent_path().string());
}

inline golden::ImageF final_fixed(const Setup& s) {
  golden::FixedOptions opt;
  golden::PolygonFrame polygons;
  if (!s.meshes.empty()) {
    polygons = golden::rasterise_polygons(s.scene, s.meshes, s.host);
    opt.polygons = &polygons;
  }
  const golden::BasePlane bp = golden::render_fixed(s.volume, s.host.regs, opt);
  return golden::warp(bp.to_float(), bp.shift_x, bp.shift_y, s.host.view);
}

inline golden::ImageF final_float(const Setup& s) {
  const golden::BasePlaneF bp = golden::render_float(s.volume, s.scene, s.host.view, nullptr, {}, s.meshes);
  return golden::warp(bp.image, bp.shift_x, bp.shift_y, s.host.view);
}

inline golden::ImageF final_reference(const Setup& s) {
  golden::ReferenceOptions opt;
  opt.meshes = &s.meshes;
  return golden::render_reference(s.volume, s.scene, s.host.view, opt);
}

// A shaded sphere, a translucent box around it crossing the volume's
// faces, an opaque needle through it, a translucent ball in front: the
// hybrid scene of the polygon tests, seen by `view`.
inline std::string sphere_with_polygons(const std::string& view) {
  return R"({"volume": {"synthetic": "sphere", "size": [24, 24, 24]}, "view": )" + view + R"(,
      "output": {"width": 64, "height": 64}, "supersampling": 2,
      "polygons": [
        {"shape": "box", "size": [22, 22, 22], "transform": {"translate": [11.5, 11.5, 11.5], "rotate": [10, 20, 0]},
         "color": [0.2, 0.5, 1], "opacity": 0.3},
        {"shape": "needle", "radius": 1.5, "length": 40, "transform": {"translate": [-6, 10, 8], "rotate": [0, 80, 10]},
         "color": [0.9, 0.9, 0.9]},
        {"shape": "sphere", "radius": 5, "segments": 12, "rings": 6, "transform": {"translate": [12, 12, -4]},
         "color": [1, 0.3, 0.2], "opacity": 0.5, "lit": false}]})";
}

// An image's alpha-weighted centroid (x, y) and its total alpha: where the
// renderers draw things, compared across them.
inline std::array<double, 3> centroid(const golden::ImageF& img) {
  double sx = 0, sy = 0, sa = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double a = img.pixel(x, y)[3];
      sx += a * x;
      sy += a * y;
      sa += a;
    }
  return {sx / sa, sy / sa, sa};
}

using tb::ImageError;

// RGB comparison with the figures idiff reports (tb/image_error.hpp).
inline ImageError compare(const golden::ImageF& a, const golden::ImageF& b) { return tb::image_error(a, b); }

}  // namespace cube4::test
