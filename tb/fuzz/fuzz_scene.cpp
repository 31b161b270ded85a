// The scene parser, and for scenes with a small synthetic volume the host
// driver's register conversions too (where out-of-range values once gave
// wrong images). Only InputError may come out.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "golden/errors.hpp"
#include "golden/host_driver.hpp"
#include "golden/input_file.hpp"
#include "golden/scene_io.hpp"
#include "golden/volume_io.hpp"
#include "tb/fuzz/fuzz_support.hpp"

namespace {

using namespace cube4;

}  // namespace

void cube4::fuzz::write_seeds(const std::string& dir) {
  const char* src = std::getenv("CUBE4_SOURCE");
  if (src)
    for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(src) / "scenes")) {
      std::ifstream in(e.path(), std::ios::binary);
      std::ostringstream t;
      t << in.rdbuf();
      const std::string s = t.str();
      fuzz::write_seed(dir, e.path().filename().string(), fuzz::Bytes(s.begin(), s.end()));
    }
  // Small synthetic scenes reach program_host.
  const char* synthetic[] = {
      R"({"volume": {"synthetic": "sphere", "size": [8, 8, 8]}, "cut_plane": {"normal": [1, 0, 0], "dmin": 2, "dmax": 5, "falloff": 1}})",
      R"({"volume": {"synthetic": "noise", "size": [6, 5, 4]}, "blend": "mip", "view": {"rotate": [10, 20, 30]}})",
      R"({"volume": {"synthetic": "field", "size": [8, 8, 8]}, "material": {"ke": 0.2, "kd": 0.7, "ks": 0.5}, "lights": [{"direction": [1, 1, 1], "intensity": 2}]})",
      R"({"volume": {"synthetic": "constant", "size": [4, 4, 4]}, "cropping": {"x": [1, 2], "combine": "union"}, "supersampling": 2})",
      R"({"volume": {"synthetic": "single_voxel", "size": [4, 4, 4], "at": [1, 2, 3]}, "view": {"direction": [0, 0, -1], "up": [0, 1, 0]}})",
      R"({"volume": {"file": "v.raw", "dim": [2, 2, 2], "type": "uint16", "spacing": [1, 1, 2], "map": [0, 100]}})",
  };
  int i = 0;
  for (const char* s : synthetic)
    fuzz::write_seed(dir, "synthetic" + std::to_string(i++) + ".json", fuzz::Bytes(s, s + std::char_traits<char>::length(s)));
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const golden::Scene s = golden::parse_scene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
    const auto& z = s.volume.size;
    const bool small_synthetic = s.volume.kind != "den" && s.volume.kind != "raw" && s.volume.kind != "nifti" &&
                                 static_cast<long>(z[0]) * z[1] * z[2] <= 16 * 16 * 16;
    if (small_synthetic) {
      const golden::Volume v = golden::load_volume(s.volume, s.precision.voxel_bits, "");
      golden::program_host(s, v);
    }
  } catch (const golden::InputError&) {
  }
  return 0;
}
