// tb/image_error.hpp gives the figures OpenImageIO's compare (idiff -a)
// gives, so the explorer's errors and the accuracy scripts' agree.
#include "tb/image_error.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <random>

namespace cube4::tb {
namespace {

golden::ImageF random_image(int w, int h, uint32_t seed) {
  golden::ImageF img{w, h, std::vector<float>(static_cast<size_t>(w) * h * 4)};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (float& v : img.rgba) v = u(rng);
  return img;
}

OIIO::ImageBufAlgo::CompareResults oiio_compare(const golden::ImageF& a, const golden::ImageF& b, const PixelRect& r) {
  const OIIO::ImageSpec spec(a.width, a.height, 4, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf ia(spec, const_cast<float*>(a.rgba.data()));
  OIIO::ImageBuf ib(spec, const_cast<float*>(b.rgba.data()));
  return OIIO::ImageBufAlgo::compare(ia, ib, 0.0f, 0.0f, OIIO::ROI(r.x, r.x + r.width, r.y, r.y + r.height, 0, 1, 0, 3));
}

TEST(ImageError, EqualsOpenImageIOCompare) {
  const golden::ImageF a = random_image(37, 23, 1), b = random_image(37, 23, 2);
  for (const PixelRect& r : {PixelRect{0, 0, 37, 23}, PixelRect{5, 3, 10, 7}, PixelRect{36, 22, 1, 1}}) {
    const ImageError e = image_error(a, b, r);
    const OIIO::ImageBufAlgo::CompareResults o = oiio_compare(a, b, r);
    EXPECT_NEAR(e.psnr, o.PSNR, 1e-6 * o.PSNR);
    EXPECT_NEAR(e.mean_error, o.meanerror, 1e-9);
    EXPECT_FLOAT_EQ(e.max_error, o.maxerror);  // OpenImageIO keeps the maximum as a float
  }
}

TEST(ImageError, AlphaIsNotCompared) {
  golden::ImageF a = random_image(8, 8, 3), b = a;
  for (size_t i = 3; i < b.rgba.size(); i += 4) b.rgba[i] = 1.0f - b.rgba[i];
  const ImageError e = image_error(a, b);
  EXPECT_EQ(e.max_error, 0.0);
  EXPECT_TRUE(std::isinf(e.psnr));
}

TEST(ImageError, RefusesOtherSizesAndOutsideRegions) {
  const golden::ImageF a = random_image(8, 8, 4), b = random_image(8, 9, 5);
  EXPECT_THROW(image_error(a, b), std::invalid_argument);
  EXPECT_THROW(image_error(a, a, {4, 4, 5, 1}), std::invalid_argument);
  EXPECT_THROW(image_error(a, a, {-1, 0, 2, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace cube4::tb
