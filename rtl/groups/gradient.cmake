# Gradient (`gradient`): the datapath cube4_gradient and the unit with its
# sample storage and near-neighbour links, cube4_gradient_unit (inside
# cube4_gradient_ring, around cube4_gradient and cube4_delay_ram). One
# executable, test_rtl_gradient: the datapath tests (tb/rtl/test_gradient.cpp),
# the ring's (tb/rtl/test_gradient_ring.cpp) and the assertions'
# (tb/rtl/test_gradient_sva.cpp); the default ring (p = 4, MaxDim = 256)
# from cube4_rtl_test, rings of 1, 2 and 5 pipelines verilated again below,
# and interpolation rings of the same p and MaxDim whose tag carries the
# gradient ring's tag (the test chains them: voxels -> samples -> gradients).
# Each ring is verilated with its sources (a file cannot be both a top and a
# SOURCE of one verilate() call: MODDUP).
set(_gradient_sources cube4_lerp.sv cube4_gradient.sv cube4_delay_ram.sv cube4_gradient_unit.sv)
set(_gradient_interp_sources cube4_lerp.sv cube4_interp.sv cube4_delay_ram.sv cube4_slice_store.sv cube4_interp_unit.sv)

# The gradient ring's tag, with the ring's default UserTagBits 8.
cube4_gradient_tag_bits(_gradient_tag_bits 8)

cube4_rtl_test(test_rtl_gradient
  TOPS cube4_gradient_ring
  SOURCES ${_gradient_sources}
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_gradient.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/test_gradient_ring.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/test_gradient_sva.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
target_compile_definitions(test_rtl_gradient PRIVATE CUBE4_GRADIENT_TAG_BITS=${_gradient_tag_bits})

# Pipelines and storage as in interp.cmake (test_gradient_ring.cpp holds the
# same values); the small MaxDim of p = 2 and 5 lets a test fill the slice
# delay to its last entry.
foreach(_cfg "1;24" "2;16" "5;12")
  list(GET _cfg 0 _p)
  list(GET _cfg 1 _dim)
  cube4_rtl_variant(test_rtl_gradient cube4_gradient_ring Vcube4_gradient_ring_p${_p} SOURCES ${_gradient_sources}
    PARAMS NumPipes=${_p} MaxDim=${_dim})
endforeach()
foreach(_cfg "1;24" "2;16" "4;256" "5;12")
  list(GET _cfg 0 _p)
  list(GET _cfg 1 _dim)
  cube4_rtl_variant(test_rtl_gradient cube4_interp_ring Vcube4_interp_ring_g${_p} SOURCES ${_gradient_interp_sources}
    PARAMS NumPipes=${_p} MaxDim=${_dim} TagBits=${_gradient_tag_bits})
endforeach()
# With 4-bit voxel tags (bela §III), chained likewise.
cube4_rtl_variant(test_rtl_gradient cube4_gradient_ring Vcube4_gradient_ring_t4 SOURCES ${_gradient_sources}
  PARAMS NumPipes=4 MaxDim=16 VoxelTagBits=4)
cube4_rtl_variant(test_rtl_gradient cube4_interp_ring Vcube4_interp_ring_gt4 SOURCES ${_gradient_interp_sources}
  PARAMS NumPipes=4 MaxDim=16 TagBits=${_gradient_tag_bits} VoxelTagBits=4)
# With VolumePro's z gradient (interpolation ring HasZDiff, gradient ring
# HasVoxelZ), chained likewise at p = 4 and 1.
foreach(_cfg "1;24" "4;16")
  list(GET _cfg 0 _p)
  list(GET _cfg 1 _dim)
  cube4_rtl_variant(test_rtl_gradient cube4_gradient_ring Vcube4_gradient_ring_z${_p} SOURCES ${_gradient_sources}
    PARAMS NumPipes=${_p} MaxDim=${_dim} HasVoxelZ=1'b1)
  cube4_rtl_variant(test_rtl_gradient cube4_interp_ring Vcube4_interp_ring_gz${_p}
    SOURCES ${_gradient_interp_sources} cube4_interp_zdiff.sv
    PARAMS NumPipes=${_p} MaxDim=${_dim} TagBits=${_gradient_tag_bits} HasZDiff=1'b1)
endforeach()
# The datapath as a top, default and other widths (test_gradient.cpp holds the
# same values).
cube4_rtl_variant(test_rtl_gradient cube4_gradient Vcube4_gradient SOURCES cube4_lerp.sv)
cube4_rtl_variant(test_rtl_gradient cube4_gradient Vcube4_gradient_v8 SOURCES cube4_lerp.sv
  PARAMS VoxelBits=8 WeightBits=6 GradientBits=8 GradientShift=1)
cube4_rtl_variant(test_rtl_gradient cube4_gradient Vcube4_gradient_v16 SOURCES cube4_lerp.sv
  PARAMS VoxelBits=16 WeightBits=10 GradientBits=12 GradientShift=6)
# With perspective's lateral scale (HasPerspective), default and narrow widths.
cube4_rtl_variant(test_rtl_gradient cube4_gradient Vcube4_gradient_persp SOURCES cube4_lerp.sv PARAMS HasPerspective=1'b1)
cube4_rtl_variant(test_rtl_gradient cube4_gradient Vcube4_gradient_persp_v8 SOURCES cube4_lerp.sv
  PARAMS VoxelBits=8 WeightBits=6 GradientBits=8 GradientShift=1 HasPerspective=1'b1)
