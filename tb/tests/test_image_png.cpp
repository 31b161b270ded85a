// cube4's own PNG writer (tb/image_png.hpp) against OpenImageIO, which
// reads every image cube4 reads and wrote every PNG before it: random 8-bit
// RGB and 16-bit RGBA images of odd sizes read back bit for bit, the base
// plane's channel width is recorded, and a write that cannot complete is an
// error naming the file.
#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <unistd.h>
#include <vector>

#include "tb/image_png.hpp"

namespace {

using cube4::tb::ImagePixels;
using cube4::tb::write_png;
namespace fs = std::filesystem;

template <class T>
std::vector<T> read_back(const std::string& file, OIIO::TypeDesc type, int channels, OIIO::ImageSpec* spec) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(file, &config);
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  *spec = in->spec();
  std::vector<T> out(static_cast<size_t>(spec->width) * spec->height * channels);
  EXPECT_TRUE(in->read_image(0, 0, 0, channels, type, out.data())) << in->geterror();
  return out;
}

TEST(ImagePng, OpenImageIOReadsBackEveryValue) {
  std::mt19937 rng(20261203);
  const fs::path dir = fs::temp_directory_path() / ("cube4_png_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const auto& [w, h] : {std::pair{1, 1}, std::pair{37, 5}, std::pair{64, 129}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3);
    for (auto& v : rgb) v = static_cast<uint8_t>(rng());
    const std::string f8 = (dir / "rgb.png").string();
    ASSERT_EQ(write_png(f8, "rgb", {w, h, 3, ImagePixels::Format::U8, rgb.data()}), "");
    OIIO::ImageSpec spec;
    EXPECT_EQ(read_back<uint8_t>(f8, OIIO::TypeDesc::UINT8, 3, &spec), rgb);
    EXPECT_EQ(spec.nchannels, 3);

    std::vector<uint16_t> rgba(static_cast<size_t>(w) * h * 4);
    for (auto& v : rgba) v = static_cast<uint16_t>(rng());
    rgba[3] = 0;  // colour behind zero alpha: kept as it is (unassociated)
    const std::string f16 = (dir / "rgba.png").string();
    ASSERT_EQ(write_png(f16, "rgba", {w, h, 4, ImagePixels::Format::U16, rgba.data(), true, 12}), "");
    EXPECT_EQ(read_back<uint16_t>(f16, OIIO::TypeDesc::UINT16, 4, &spec), rgba);
    EXPECT_EQ(spec.get_int_attribute("cube4:channel_bits"), 12);
  }
  fs::remove_all(dir);
}

TEST(ImagePng, AWriteThatCannotCompleteIsAnError) {
  std::vector<uint8_t> rgb(64 * 64 * 3, 7);
  const ImagePixels px{64, 64, 3, ImagePixels::Format::U8, rgb.data()};
  const std::string full = write_png("/dev/full", "shown-name.png", px);
  EXPECT_NE(full.find("shown-name.png"), std::string::npos) << full;
  EXPECT_NE(full.find("No space"), std::string::npos) << full;
  const std::string missing = write_png("/nonexistent-folder/x.png", "x.png", px);
  EXPECT_NE(missing.find("x.png"), std::string::npos) << missing;
  EXPECT_NE(write_png("/tmp/unused.png", "f", {2, 2, 3, ImagePixels::Format::F32, rgb.data()}), "");
}

}  // namespace
