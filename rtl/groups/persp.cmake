# Perspective weight generator (`persp`): cube4_persp_slice, the per-slice
# constants of Cube-4's perspective projection (golden perspective_slice(),
# docs/perspective.md). One executable, test_rtl_persp
# (tb/rtl/test_persp_slice.cpp).
cube4_rtl_test(test_rtl_persp
  TOPS cube4_persp_slice
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_persp_slice.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
