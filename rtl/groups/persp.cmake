# Perspective weight generator (`persp`, docs/rtl-persp.md): cube4_persp_slice,
# the per-slice divisions of Cube-4's perspective projection (golden
# perspective_slice(); part of cube4_dda, which walks the positions it
# divides), and cube4_persp_ray, the per-sample positions and
# weights along a beam. One executable, test_rtl_persp
# (tb/rtl/test_persp_slice.cpp, tb/rtl/test_persp_ray.cpp).
cube4_rtl_test(test_rtl_persp
  TOPS cube4_persp_slice cube4_persp_ray
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_persp_slice.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/test_persp_ray.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

# The lane assignment of the perspective dataflow (cube4_persp_lanes,
# docs/perspective.md "The dataflow"), at p = 1, 4, 5 and 16: one
# executable, test_rtl_persp_lanes (tb/rtl/test_persp_lanes.cpp).
cube4_rtl_test(test_rtl_persp_lanes
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_persp_lanes.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
foreach(p 1 4 5 16)
  cube4_rtl_variant(test_rtl_persp_lanes cube4_persp_lanes Vcube4_persp_lanes_p${p} SOURCES cube4_box_axis.sv PARAMS Pipes=${p})
endforeach()
