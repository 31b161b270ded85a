// Small helpers shared by the golden-model tests.
#pragma once
#include <string>

#include "golden/host_driver.hpp"
#include "golden/renderers.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"

namespace cube4::test {

struct Setup {
  golden::Scene scene;
  golden::Volume volume;
  golden::HostProgram host;
};

inline Setup setup(const std::string& json) {
  Setup s;
  s.scene = golden::parse_scene(json, "test.json");
  s.volume = golden::load_volume(s.scene.volume, s.scene.precision.voxel_bits, ".");
  s.host = golden::program_host(s.scene, s.volume);
  return s;
}

inline golden::ImageF final_fixed(const Setup& s) {
  const golden::BasePlane bp = golden::render_fixed(s.volume, s.host.regs);
  return golden::warp(bp.to_float(), bp.shift_x, bp.shift_y, s.host.view);
}

inline golden::ImageF final_float(const Setup& s) {
  const golden::BasePlaneF bp = golden::render_float(s.volume, s.scene, s.host.view);
  return golden::warp(bp.image, bp.shift_x, bp.shift_y, s.host.view);
}

struct ImageError {
  double psnr = 0;     // over RGB, peak 1
  double max_error = 0;
};

inline ImageError compare(const golden::ImageF& a, const golden::ImageF& b) {
  double se = 0, mx = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = static_cast<double>(a.rgba[i]) - b.rgba[i];
    se += d * d;
    mx = std::max(mx, std::fabs(d));
    ++n;
  }
  const double mse = se / n;
  return {mse == 0 ? 999.0 : 10 * std::log10(1.0 / mse), mx};
}

}  // namespace cube4::test
