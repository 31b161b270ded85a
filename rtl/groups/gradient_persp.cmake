# Perspective gradient ring (`gradient_persp`, docs/rtl-gradient-persp.md):
# cube4_gradient_persp_homes, where along one axis a ray's gradient
# operands have their homes (golden gradient_operand_homes()), and the ring
# cube4_gradient_persp_ring (its column stage cube4_persp_column,
# walks cube4_persp_lanes, datapath cube4_gradient). One executable,
# test_rtl_gradient_persp (tb/rtl/test_gradient_persp_homes.cpp,
# tb/rtl/test_gradient_persp_ring.cpp). Rings of MaxDim 24, as the
# perspective interpolation ring's tests (the test file holds the value).
cube4_rtl_test(test_rtl_gradient_persp
  TOPS cube4_gradient_persp_homes
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_gradient_persp_homes.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/test_gradient_persp_ring.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
set(_gradient_persp_sources cube4_lerp.sv cube4_gradient.sv cube4_box_axis.sv cube4_persp_lanes.sv
    cube4_gradient_persp_homes.sv cube4_persp_column.sv cube4_persp_stream.sv cube4_persp_cell_walks.sv)
foreach(p 4 1 5 8)
  set(_prefix Vcube4_gradient_persp_ring_p${p})
  if(p EQUAL 4)
    set(_prefix Vcube4_gradient_persp_ring)
  endif()
  cube4_rtl_variant(test_rtl_gradient_persp cube4_gradient_persp_ring ${_prefix} SOURCES ${_gradient_persp_sources}
    PARAMS NumPipes=${p} MaxDim=24)
endforeach()
# With 4-bit voxel tags (bela §III): the stored words {tag, value}.
cube4_rtl_variant(test_rtl_gradient_persp cube4_gradient_persp_ring Vcube4_gradient_persp_ring_t4
  SOURCES ${_gradient_persp_sources} PARAMS NumPipes=4 MaxDim=24 VoxelTagBits=4)
# VolumePro's z gradient (HasVoxelZ): each sample's z difference stored beside it.
cube4_rtl_variant(test_rtl_gradient_persp cube4_gradient_persp_ring Vcube4_gradient_persp_ring_vz
  SOURCES ${_gradient_persp_sources} PARAMS NumPipes=4 MaxDim=24 HasVoxelZ=1'b1)
cube4_rtl_variant(test_rtl_gradient_persp cube4_gradient_persp_ring Vcube4_gradient_persp_ring_vz_p5
  SOURCES ${_gradient_persp_sources} PARAMS NumPipes=5 MaxDim=24 HasVoxelZ=1'b1)
