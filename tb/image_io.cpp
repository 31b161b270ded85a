#include "tb/image_io.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "golden/errors.hpp"
#include "golden/fixed.hpp"

namespace cube4::tb {
namespace {

namespace fs = std::filesystem;
using golden::InputError;

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

// Writes `file` and reads it back: OpenImageIO's PNG writer does not report
// a failed write (a full disk gives a truncated file and success), so the
// file only counts as written once it decodes to the same size. `shown`
// names the output in messages (the destination, not the temporary).
void write_checked(const std::string& file, const std::string& shown, OIIO::ImageSpec spec, const void* pixels) {
  check_extension(file);
  auto out = OIIO::ImageOutput::create(file);
  if (!out) throw InputError("cannot write '" + shown + "': " + OIIO::geterror());
  if (!out->open(file, spec) || !out->write_image(spec.format, pixels) || !out->close())
    throw InputError("cannot write '" + shown + "': " + out->geterror());
  auto in = OIIO::ImageInput::open(file);
  bool ok = in && in->spec().width == spec.width && in->spec().height == spec.height &&
            in->spec().nchannels == spec.nchannels;
  if (ok) {
    std::vector<float> px(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data());
  }
  if (!ok)
    throw InputError("cannot write '" + shown + "': the file written does not read back whole (" +
                     (in ? in->geterror() : OIIO::geterror()) + "; is the disk full?)");
}

}  // namespace

void write_image(const std::string& path, const golden::ImageF& img, const std::string& shown_as) {
  const std::string& shown = shown_as.empty() ? path : shown_as;
  check_extension(path);
  if (extension_of(path) == ".exr") {
    OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::FLOAT);
    write_checked(path, shown, spec, img.rgba.data());
    return;
  }
  // PNG: the premultiplied colour is the image over a black background.
  const size_t n = static_cast<size_t>(img.width) * img.height;
  std::vector<uint8_t> px(n * 3);
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      px[i * 3 + c] = static_cast<uint8_t>(std::lround(std::clamp(img.rgba[i * 4 + c], 0.0f, 1.0f) * 255.0f));
  OIIO::ImageSpec spec(img.width, img.height, 3, OIIO::TypeDesc::UINT8);
  write_checked(path, shown, spec, px.data());
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
  OIIO::ImageSpec spec(bp.width, bp.height, 4, OIIO::TypeDesc::UINT16);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  spec.attribute("cube4:channel_bits", bp.bits);
  write_checked(path, shown, spec, px.data());
}

void write_baseplane(const std::string& path, const golden::ImageF& bp, const std::string& shown_as) {
  const std::string& shown = shown_as.empty() ? path : shown_as;
  check_extension(path);
  if (extension_of(path) == ".exr") {
    OIIO::ImageSpec spec(bp.width, bp.height, 4, OIIO::TypeDesc::FLOAT);
    write_checked(path, shown, spec, bp.rgba.data());
    return;
  }
  std::vector<uint16_t> px(bp.rgba.size());
  for (size_t i = 0; i < px.size(); ++i)
    px[i] = static_cast<uint16_t>(std::lround(std::clamp(bp.rgba[i], 0.0f, 1.0f) * 65535.0f));
  OIIO::ImageSpec spec(bp.width, bp.height, 4, OIIO::TypeDesc::UINT16);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  write_checked(path, shown, spec, px.data());
}

golden::ImageF read_image(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw InputError("cannot read image '" + path + "': " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  golden::ImageF img;
  img.width = spec.width;
  img.height = spec.height;
  std::vector<float> px(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()))
    throw InputError("cannot read image '" + path + "': " + in->geterror());
  img.rgba.assign(static_cast<size_t>(img.width) * img.height * 4, 1.0f);
  for (size_t i = 0; i < static_cast<size_t>(img.width) * img.height; ++i)
    for (int c = 0; c < std::min(4, spec.nchannels); ++c) img.rgba[i * 4 + c] = px[i * spec.nchannels + c];
  return img;
}

golden::BasePlane read_baseplane_png(const std::string& path, int bits) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) throw InputError("cannot read base plane '" + path + "': " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels != 4) throw InputError("base plane '" + path + "' has " + std::to_string(spec.nchannels) + " channels, expected 4");
  golden::BasePlane bp;
  bp.width = spec.width;
  bp.height = spec.height;
  bp.bits = bits;
  std::vector<uint16_t> px(static_cast<size_t>(spec.width) * spec.height * 4);
  if (!in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT16, px.data()))
    throw InputError("cannot read base plane '" + path + "': " + in->geterror());
  bp.rgba.resize(px.size());
  for (size_t i = 0; i < px.size(); ++i) bp.rgba[i] = static_cast<uint16_t>(px[i] >> (16 - bits));
  return bp;
}

}  // namespace cube4::tb
