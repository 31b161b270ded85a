// Small helpers shared by the golden-model tests.
#pragma once
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

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
  double psnr = 0;       // over RGB, peak 1
  double max_error = 0;
  double mean_error = 0;
};

// RGB comparison through OpenImageIO's ImageBufAlgo::compare (what idiff uses).
inline ImageError compare(const golden::ImageF& a, const golden::ImageF& b) {
  const OIIO::ImageSpec spec(a.width, a.height, 4, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf ia(spec, const_cast<float*>(a.rgba.data()));
  OIIO::ImageBuf ib(spec, const_cast<float*>(b.rgba.data()));
  const auto r = OIIO::ImageBufAlgo::compare(ia, ib, 0.0f, 0.0f, OIIO::ROI(0, a.width, 0, a.height, 0, 1, 0, 3));
  return {r.PSNR, r.maxerror, r.meanerror};
}

}  // namespace cube4::test
