// A hybrid (volume and polygon) scene as the RTL tests use it: the scene
// from JSON, its volume and meshes, the host's registers and the polygon
// images the host rasteriser makes for them (golden/polygons.hpp), which
// are what the polygon units receive.
#pragma once
#include <string>
#include <vector>

#include "golden/host_driver.hpp"
#include "golden/mesh.hpp"
#include "golden/polygons.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"

namespace cube4::rtl {

struct HybridScene {
  golden::Scene scene;
  golden::Volume volume;
  std::vector<golden::Mesh> meshes;
  golden::HostProgram host;
  golden::PolygonFrame frame;
};

// `name` labels the scene in parse errors; built-in shapes only (paths
// relative to the working folder).
inline HybridScene hybrid_scene(const std::string& json, const std::string& name) {
  HybridScene h;
  h.scene = golden::parse_scene(json, name);
  h.volume = golden::load_volume(h.scene.volume, h.scene.precision.voxel_bits, ".");
  h.meshes = golden::load_meshes(h.scene, ".");
  h.host = golden::program_host(h.scene, h.volume, h.meshes);
  h.frame = golden::rasterise_polygons(h.scene, h.meshes, h.host);
  return h;
}

}  // namespace cube4::rtl
