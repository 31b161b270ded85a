# Perspective compositing ring (`composite_persp`, docs/perspective.md, "The
# plan for the compositing ring"): cube4_composite_persp_ring (its column
# stores cube4_persp_column, walks cube4_persp_lanes, datapath
# cube4_composite). One executable, test_rtl_composite_persp
# (tb/rtl/test_composite_persp_ring.cpp), rings of MaxDim 24 and Reach 3 at
# p = 4 (with polygon hardware), 1 and 5 (without) (the test file holds the
# values).
cube4_rtl_test(test_rtl_composite_persp
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_composite_persp_ring.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
set(_composite_persp_sources cube4_box_axis.sv cube4_persp_lanes.sv cube4_persp_column.sv cube4_persp_stream.sv cube4_persp_cell_walks.sv cube4_composite.sv
    cube4_compose_node.sv cube4_mul_frac.sv cube4_to_acc.sv cube4_acc_to_pixel.sv)
foreach(p 4 1 5)
  set(_prefix Vcube4_composite_persp_ring_p${p})
  set(_polygons 1'b0)
  if(p EQUAL 4)
    set(_prefix Vcube4_composite_persp_ring)
    set(_polygons 1'b1)
  endif()
  cube4_rtl_variant(test_rtl_composite_persp cube4_composite_persp_ring ${_prefix} SOURCES ${_composite_persp_sources}
    PARAMS NumPipes=${p} MaxDim=24 Reach=3 HasPolygons=${_polygons})
endforeach()
