// Perspective views the golden-level tests of the rings' plans share
// (test_gradient_persp.cpp, test_composite_persp.cpp).
#pragma once
#include <random>
#include <string>

namespace cube4::test {

// A perspective view of a sphere from random angles (as the perspective
// reach table's), the field of view 20 to 89 degrees, S 1 or 2: view n is
// the same in every test that asks for it.
inline std::string random_perspective_view(int n) {
  std::mt19937 rng(20261206u + static_cast<unsigned>(n));
  std::uniform_real_distribution<double> angle(-180, 180);
  const int fov = 20 + 20 * (n % 4) + (n % 8 >= 4 ? 9 : 0);
  const std::string rotate =
      std::to_string(angle(rng)) + ", " + std::to_string(angle(rng)) + ", " + std::to_string(angle(rng));
  return R"({"volume": {"synthetic": "sphere", "size": [24, 20, 16]}, "shading": true,
      "view": {"projection": "perspective", "fov": )" +
         std::to_string(fov) + R"(, "rotate": [)" + rotate + R"(]}, "output": {"width": 40, "height": 40},
      "supersampling": )" +
         std::to_string(1 + n % 2) + "}";
}

}  // namespace cube4::test
