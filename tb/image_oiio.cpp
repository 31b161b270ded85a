// libcube4_image_oiio.so: image files through OpenImageIO (tb/image_plugin.hpp).
#include <OpenImageIO/imageio.h>

#include <cstdint>

#include "tb/image_plugin.hpp"

namespace {

using cube4::tb::ImagePixels;

OIIO::TypeDesc type_of(ImagePixels::Format f) {
  switch (f) {
    case ImagePixels::Format::U8: return OIIO::TypeDesc::UINT8;
    case ImagePixels::Format::U16: return OIIO::TypeDesc::UINT16;
    default: return OIIO::TypeDesc::FLOAT;
  }
}

std::string write(const std::string& file, const std::string& shown, const ImagePixels& px) {
  OIIO::ImageSpec spec(px.width, px.height, px.channels, type_of(px.format));
  if (px.unassociated_alpha) spec.attribute("oiio:UnassociatedAlpha", 1);
  if (px.channel_bits > 0) spec.attribute("cube4:channel_bits", px.channel_bits);
  auto out = OIIO::ImageOutput::create(file);
  if (!out) return "cannot write '" + shown + "': " + OIIO::geterror();
  if (!out->open(file, spec) || !out->write_image(spec.format, px.data) || !out->close())
    return "cannot write '" + shown + "': " + out->geterror();
  auto in = OIIO::ImageInput::open(file);
  bool ok = in && in->spec().width == spec.width && in->spec().height == spec.height &&
            in->spec().nchannels == spec.nchannels;
  if (ok) {
    std::vector<float> back(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, back.data());
  }
  if (!ok)
    return "cannot write '" + shown + "': the file written does not read back whole (" +
           (in ? in->geterror() : OIIO::geterror()) + "; is the disk full?)";
  return {};
}

template <class T>
std::string read(const std::string& file, bool unassociated_alpha, OIIO::TypeDesc type, int* width, int* height,
                 int* channels, std::vector<T>* out) {
  OIIO::ImageSpec config;
  if (unassociated_alpha) config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(file, &config);
  if (!in) return OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  *width = spec.width;
  *height = spec.height;
  *channels = spec.nchannels;
  out->assign(static_cast<size_t>(spec.width) * spec.height * spec.nchannels, T{});
  if (!in->read_image(0, 0, 0, spec.nchannels, type, out->data())) return in->geterror();
  return {};
}

std::string read_f32(const std::string& file, bool unassociated_alpha, int* w, int* h, int* c, std::vector<float>* out) {
  return read(file, unassociated_alpha, OIIO::TypeDesc::FLOAT, w, h, c, out);
}
std::string read_u16(const std::string& file, bool unassociated_alpha, int* w, int* h, int* c,
                     std::vector<uint16_t>* out) {
  return read(file, unassociated_alpha, OIIO::TypeDesc::UINT16, w, h, c, out);
}

const cube4::tb::ImagePlugin kPlugin{cube4::tb::kImagePluginVersion, write, read_f32, read_u16};

}  // namespace

extern "C" const cube4::tb::ImagePlugin* cube4_image_plugin() { return &kPlugin; }
