# Perspective weight generator (`persp`, docs/rtl-persp.md): cube4_persp_slice,
# the per-slice constants of Cube-4's perspective projection (golden
# perspective_slice()), and cube4_persp_ray, the per-sample positions and
# weights along a beam. One executable, test_rtl_persp
# (tb/rtl/test_persp_slice.cpp, tb/rtl/test_persp_ray.cpp).
cube4_rtl_test(test_rtl_persp
  TOPS cube4_persp_slice cube4_persp_ray
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_persp_slice.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/test_persp_ray.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
