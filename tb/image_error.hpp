// The error of an image against a reference, over its R, G and B channels
// and optionally a rectangle of it: the figures OpenImageIO's
// ImageBufAlgo::compare (and so `idiff -a`) reports, with the same
// definitions, so that the explorer's numbers and the accuracy scripts'
// agree (tb/tests/test_image_error.cpp holds the two equal).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "golden/renderers.hpp"

namespace cube4::tb {

struct ImageError {
  double psnr = 0;        // dB over RGB, peak 1: 20·log10(1 / rms); +inf for equal images
  double mean_error = 0;  // mean |a − b| over the channel values
  double max_error = 0;   // largest |a − b|
};

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;  // width 0: the whole image
};

inline ImageError image_error(const golden::ImageF& a, const golden::ImageF& ref, PixelRect r = {}) {
  if (a.width != ref.width || a.height != ref.height)
    throw std::invalid_argument("image_error: images of " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                " and " + std::to_string(ref.width) + "x" + std::to_string(ref.height) + " pixels");
  if (r.width == 0) r = {0, 0, a.width, a.height};
  if (r.x < 0 || r.y < 0 || r.width <= 0 || r.height <= 0 || r.x + r.width > a.width || r.y + r.height > a.height)
    throw std::invalid_argument("image_error: region " + std::to_string(r.width) + "x" + std::to_string(r.height) +
                                " at (" + std::to_string(r.x) + ", " + std::to_string(r.y) + ") is not inside the " +
                                std::to_string(a.width) + "x" + std::to_string(a.height) + " image");
  double sum = 0, sum_sq = 0, max = 0;
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double d = std::fabs(static_cast<double>(a.pixel(x, y)[c]) - ref.pixel(x, y)[c]);
        sum += d;
        sum_sq += d * d;
        max = std::max(max, d);
      }
  const double n = 3.0 * r.width * r.height;
  const double rms = std::sqrt(sum_sq / n);
  return {rms > 0 ? 20 * std::log10(1 / rms) : std::numeric_limits<double>::infinity(), sum / n, max};
}

}  // namespace cube4::tb
