// The OpenImageIO half of image I/O (tb/image_io.hpp), in a module of its
// own, libcube4_image_oiio.so, which tb/image_io.cpp opens the first time
// an image is read or written. OpenImageIO brings some 260 shared
// libraries with it; a cube4 run that writes no image (cube4 info, plan,
// regress, a partial image) no longer loads them, which took about 0.35 s
// of every process (docs/performance.md, "Start-up").
//
// Errors come back as text, not exceptions: the module and the program
// are two objects, and the text is all the caller needs.
#pragma once
#include <string>
#include <vector>

namespace cube4::tb {

struct ImagePixels {
  enum class Format { U8, U16, F32 };
  int width = 0, height = 0, channels = 0;
  Format format = Format::F32;
  const void* data = nullptr;        // width·height·channels values of `format`
  bool unassociated_alpha = false;   // PNG: store the values as they are
  int channel_bits = 0;              // > 0: recorded as the attribute cube4:channel_bits
};

struct ImagePlugin {
  int version;  // kImagePluginVersion
  // Writes `file` and reads it back whole (OpenImageIO's PNG writer
  // reports success on a full disk); "" or why not, naming `shown`.
  std::string (*write)(const std::string& file, const std::string& shown, const ImagePixels& px);
  // Reads `file` into `out` as float (any format) or as 16-bit values;
  // "" or why not.
  std::string (*read_f32)(const std::string& file, bool unassociated_alpha, int* width, int* height, int* channels,
                          std::vector<float>* out);
  std::string (*read_u16)(const std::string& file, bool unassociated_alpha, int* width, int* height, int* channels,
                          std::vector<uint16_t>* out);
};

constexpr int kImagePluginVersion = 1;

}  // namespace cube4::tb

// The module's one exported symbol.
extern "C" const cube4::tb::ImagePlugin* cube4_image_plugin();
