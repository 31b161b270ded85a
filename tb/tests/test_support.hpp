// Small helpers shared by the golden-model tests.
#pragma once

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

using tb::ImageError;

// RGB comparison with the figures idiff reports (tb/image_error.hpp).
inline ImageError compare(const golden::ImageF& a, const golden::ImageF& b) { return tb::image_error(a, b); }

}  // namespace cube4::test
