// The 2-D warp from base plane to final image (VolumePro's companion
// graphics card): bilinear resampling, transparent outside the base plane.
#include <cmath>
#include <stdexcept>

#include "golden/renderers.hpp"

namespace cube4::golden {

ImageF warp(const ImageF& base, double shift_x, double shift_y, const ViewFactorisation& f) {
  // Parallel projection: an affine map, inverted once. Perspective: a
  // projective one, the ray through each image pixel met with the base
  // plane (Lacroute's perspective warp; rays that never reach it see nothing).
  const Affine2 to_base = f.perspective ? Affine2{} : f.base_to_image(shift_x, shift_y).inverse();
  ImageF out;
  out.width = f.image_width;
  out.height = f.image_height;
  out.rgba.assign(static_cast<size_t>(out.width) * out.height * 4, 0.0f);
  // A base-plane pixel's four channels, transparent black outside it.
  static constexpr float kOutside[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  auto texel = [&](int u, int v) -> const float* {
    return u < 0 || v < 0 || u >= base.width || v >= base.height ? kOutside : base.pixel(u, v);
  };
  for (int Y = 0; Y < out.height; ++Y)
    for (int X = 0; X < out.width; ++X) {
      std::array<double, 2> uv{};
      if (f.perspective) {
        const auto hit = f.base_of_image(X, Y, shift_x, shift_y);
        if (!hit) continue;
        uv = *hit;
      } else {
        uv = to_base.apply(X, Y);
      }
      const double fu = std::floor(uv[0]), fv = std::floor(uv[1]);
      const int u = static_cast<int>(fu), v = static_cast<int>(fv);
      if (u < -1 || v < -1 || u >= base.width || v >= base.height) continue;
      const float tu = static_cast<float>(uv[0] - fu), tv = static_cast<float>(uv[1] - fv);
      const float *t00 = texel(u, v), *t10 = texel(u + 1, v), *t01 = texel(u, v + 1), *t11 = texel(u + 1, v + 1);
      float* px = out.pixel(X, Y);
      for (int c = 0; c < 4; ++c) {
        const float a = t00[c] + tu * (t10[c] - t00[c]);
        const float b = t01[c] + tu * (t11[c] - t01[c]);
        px[c] = a + tv * (b - a);
      }
    }
  return out;
}

ImageF blend_frames(const std::vector<ImageF>& frames) {
  if (frames.empty()) throw std::invalid_argument("blend_frames: no frames");
  ImageF out = frames.front();
  for (size_t i = 1; i < frames.size(); ++i) {
    if (frames[i].width != out.width || frames[i].height != out.height)
      throw std::invalid_argument("blend_frames: frames of different sizes");
    for (size_t k = 0; k < out.rgba.size(); ++k) out.rgba[k] += frames[i].rgba[k];
  }
  const float scale = 1.0f / static_cast<float>(frames.size());
  for (float& v : out.rgba) v *= scale;
  return out;
}

}  // namespace cube4::golden
