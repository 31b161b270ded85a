#include "tb/image_io.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "golden/errors.hpp"
#include "golden/fixed.hpp"
#include "tb/image_plugin.hpp"
#include "tb/image_png.hpp"

namespace cube4::tb {
namespace {

namespace fs = std::filesystem;
using golden::InputError;
using Format = ImagePixels::Format;

// OpenImageIO is opened at the first image read or write
// (tb/image_plugin.hpp): CUBE4_IMAGE_PLUGIN names the module, else the one
// this build made.
const ImagePlugin& plugin() {
  static const ImagePlugin* loaded = [] {
    const char* env = std::getenv("CUBE4_IMAGE_PLUGIN");
    const std::string path = env && *env ? env : CUBE4_IMAGE_PLUGIN;
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw std::runtime_error("image support: cannot load " + path + ": " + ::dlerror());
    auto entry = reinterpret_cast<const ImagePlugin* (*)()>(::dlsym(handle, "cube4_image_plugin"));
    if (!entry) throw std::runtime_error("image support: " + path + " has no cube4_image_plugin()");
    const ImagePlugin* p = entry();
    if (p->version != kImagePluginVersion)
      throw std::runtime_error("image support: " + path + " is version " + std::to_string(p->version) +
                               ", this cube4 needs " + std::to_string(kImagePluginVersion));
    return p;
  }();
  return *loaded;
}

std::string extension_of(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

void check_extension(const std::string& path) {
  const std::string e = extension_of(path);
  if (e != ".png" && e != ".exr")
    throw InputError("output file '" + path + "': unsupported extension '" + e + "' (use .png or .exr)");
}

// Writes `file` (the OpenImageIO module checks that an EXR reads back
// whole; write_png checks its own writes); `shown` names the output in
// messages (the destination, not the temporary).
void write_checked(const std::string& file, const std::string& shown, const ImagePixels& px) {
  check_extension(file);
  // PNG in this process (libpng); EXR through OpenImageIO's module.
  const std::string error = extension_of(file) == ".png" ? write_png(file, shown, px) : plugin().write(file, shown, px);
  if (!error.empty()) throw InputError(error);
}

}  // namespace

void write_image(const std::string& path, const golden::ImageF& img, const std::string& shown_as) {
  const std::string& shown = shown_as.empty() ? path : shown_as;
  check_extension(path);
  if (extension_of(path) == ".exr") {
    write_checked(path, shown, {img.width, img.height, 4, Format::F32, img.rgba.data()});
    return;
  }
  // PNG: the premultiplied colour is the image over a black background.
  const size_t n = static_cast<size_t>(img.width) * img.height;
  std::vector<uint8_t> px(n * 3);
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      px[i * 3 + c] = static_cast<uint8_t>(std::lround(std::clamp(img.rgba[i * 4 + c], 0.0f, 1.0f) * 255.0f));
  write_checked(path, shown, {img.width, img.height, 3, Format::U8, px.data()});
}

void write_baseplane(const std::string& path, const golden::BasePlane& bp, const std::string& shown_as) {
  const std::string& shown = shown_as.empty() ? path : shown_as;
  check_extension(path);
  if (extension_of(path) == ".exr") {
    write_baseplane(path, bp.to_float(), shown);
    return;
  }
  std::vector<uint16_t> px(bp.rgba.size());
  for (size_t i = 0; i < px.size(); ++i)
    px[i] = static_cast<uint16_t>(golden::expand_bits(bp.rgba[i], bp.bits, 16));
  write_checked(path, shown, {bp.width, bp.height, 4, Format::U16, px.data(), true, bp.bits});
}

void write_baseplane(const std::string& path, const golden::ImageF& bp, const std::string& shown_as) {
  const std::string& shown = shown_as.empty() ? path : shown_as;
  check_extension(path);
  if (extension_of(path) == ".exr") {
    write_checked(path, shown, {bp.width, bp.height, 4, Format::F32, bp.rgba.data()});
    return;
  }
  std::vector<uint16_t> px(bp.rgba.size());
  for (size_t i = 0; i < px.size(); ++i)
    px[i] = static_cast<uint16_t>(std::lround(std::clamp(bp.rgba[i], 0.0f, 1.0f) * 65535.0f));
  write_checked(path, shown, {bp.width, bp.height, 4, Format::U16, px.data(), true});
}

golden::ImageF read_image(const std::string& path) {
  int w = 0, h = 0, c = 0;
  std::vector<float> px;
  const std::string error = plugin().read_f32(path, false, &w, &h, &c, &px);
  if (!error.empty()) throw InputError("cannot read image '" + path + "': " + error);
  golden::ImageF img;
  img.width = w;
  img.height = h;
  img.rgba.assign(static_cast<size_t>(w) * h * 4, 1.0f);
  for (size_t i = 0; i < static_cast<size_t>(w) * h; ++i)
    for (int k = 0; k < std::min(4, c); ++k) img.rgba[i * 4 + k] = px[i * c + k];
  return img;
}

golden::BasePlane read_baseplane_png(const std::string& path, int bits) {
  int w = 0, h = 0, c = 0;
  std::vector<uint16_t> px;
  const std::string error = plugin().read_u16(path, true, &w, &h, &c, &px);
  if (!error.empty()) throw InputError("cannot read base plane '" + path + "': " + error);
  if (c != 4) throw InputError("base plane '" + path + "' has " + std::to_string(c) + " channels, expected 4");
  golden::BasePlane bp;
  bp.width = w;
  bp.height = h;
  bp.bits = bits;
  bp.rgba.resize(px.size());
  for (size_t i = 0; i < px.size(); ++i) bp.rgba[i] = static_cast<uint16_t>(px[i] >> (16 - bits));
  return bp;
}

}  // namespace cube4::tb
