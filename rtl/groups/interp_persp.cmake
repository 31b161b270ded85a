# The perspective interpolation unit (`interp_persp`, docs/rtl-interp-persp.md):
# its column stage (cube4_interp_persp_column), its home stage
# (cube4_interp_persp_home) and the ring of them (cube4_interp_persp_ring,
# with its walks cube4_persp_lanes). One executable, test_rtl_interp_persp.
# Small delays (BeamDepth 32, SliceDepth 1024; rings of MaxDim 24) so that
# the tests fill them; the test files hold the same values.
cube4_rtl_test(test_rtl_interp_persp
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_interp_persp_column.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/test_interp_persp_home.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/test_interp_persp_ring.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/test_interp_persp_sva.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
cube4_rtl_variant(test_rtl_interp_persp cube4_interp_persp_column Vcube4_interp_persp_column
  SOURCES cube4_delay_ram.sv cube4_slice_store.sv cube4_box_taps.sv PARAMS BeamDepth=32 SliceDepth=1024)
cube4_rtl_variant(test_rtl_interp_persp cube4_interp_persp_column Vcube4_interp_persp_column_zdiff
  SOURCES cube4_delay_ram.sv cube4_slice_store.sv cube4_box_taps.sv PARAMS BeamDepth=32 SliceDepth=1024 HasZDiff=1'b1)
cube4_rtl_variant(test_rtl_interp_persp cube4_interp_persp_home Vcube4_interp_persp_home
  SOURCES cube4_box_taps.sv cube4_box_mean.sv cube4_lerp.sv)
# The second home stage of VolumePro's z gradient: signed voxel z differences.
cube4_rtl_variant(test_rtl_interp_persp cube4_interp_persp_home Vcube4_interp_persp_home_signed
  SOURCES cube4_box_taps.sv cube4_box_mean.sv cube4_lerp.sv PARAMS Signed=1'b1)
set(_persp_ring_sources cube4_delay_ram.sv cube4_slice_store.sv cube4_box_taps.sv cube4_box_mean.sv cube4_lerp.sv cube4_box_axis.sv
    cube4_persp_lanes.sv cube4_interp_persp_column.sv cube4_interp_persp_home.sv)
foreach(p 4 1 5 8)
  set(_prefix Vcube4_interp_persp_ring_p${p})
  if(p EQUAL 4)
    set(_prefix Vcube4_interp_persp_ring)
  endif()
  cube4_rtl_variant(test_rtl_interp_persp cube4_interp_persp_ring ${_prefix} SOURCES ${_persp_ring_sources}
    PARAMS NumPipes=${p} MaxDim=24)
endforeach()
# With 4-bit voxel tags (bela §III): the words {tag, value}, a tag per sample.
cube4_rtl_variant(test_rtl_interp_persp cube4_interp_persp_ring Vcube4_interp_persp_ring_t4
  SOURCES ${_persp_ring_sources} PARAMS NumPipes=4 MaxDim=24 VoxelTagBits=4)
# VolumePro's z gradient (HasZDiff): the voxel z differences filtered too.
cube4_rtl_variant(test_rtl_interp_persp cube4_interp_persp_ring Vcube4_interp_persp_ring_zdiff
  SOURCES ${_persp_ring_sources} PARAMS NumPipes=4 MaxDim=24 HasZDiff=1'b1)
cube4_rtl_variant(test_rtl_interp_persp cube4_interp_persp_ring Vcube4_interp_persp_ring_zdiff_p5
  SOURCES ${_persp_ring_sources} PARAMS NumPipes=5 MaxDim=24 HasZDiff=1'b1)
# As large as the MRI head (brainsmall, 128 x 128 x 84), for its frame.
cube4_rtl_variant(test_rtl_interp_persp cube4_interp_persp_ring Vcube4_interp_persp_ring_m128
  SOURCES ${_persp_ring_sources} PARAMS NumPipes=4 MaxDim=128)
target_compile_definitions(test_rtl_interp_persp PRIVATE CUBE4_BRAINSMALL="${CUBE4_BRAINSMALL}")
# The lane walk alone, for its assertion's test (test_interp_persp_sva.cpp).
cube4_rtl_variant(test_rtl_interp_persp cube4_persp_lanes Vcube4_persp_lanes_p4 SOURCES cube4_box_axis.sv PARAMS Pipes=4)
