# Perspective box filter (`interp_box`, Cube-4 §3): cube4_box_axis (one
# axis's first cell and four overlaps, combinational) and cube4_interp_box
# (the 4x4 weighted mean, pipelined, made of cube4_box_taps and
# cube4_box_mean), and below the interpolation unit's column stage. One executable, test_rtl_interp_box
# (tb/rtl/test_interp_box.cpp): both units at the default widths from
# cube4_rtl_test, and again at two other width sets (test_interp_box.cpp
# holds the same values): W = 6 with a 32-bit DDA of 16 fraction bits and
# 8-bit voxels, W = 10 with 16-bit voxels (the widest product, 57 bits).
cube4_rtl_test(test_rtl_interp_box
  TOPS cube4_box_axis cube4_interp_box
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_interp_box.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

cube4_rtl_variant(test_rtl_interp_box cube4_box_axis Vcube4_box_axis_w6 PARAMS DdaBits=32 FracBits=16 WeightBits=6)
cube4_rtl_variant(test_rtl_interp_box cube4_box_axis Vcube4_box_axis_w10 PARAMS WeightBits=10)
cube4_rtl_variant(test_rtl_interp_box cube4_interp_box Vcube4_interp_box_w6 PARAMS VoxelBits=8 WeightBits=6)
cube4_rtl_variant(test_rtl_interp_box cube4_interp_box Vcube4_interp_box_w10 PARAMS VoxelBits=16 WeightBits=10)

# The perspective interpolation unit's column stage (cube4_interp_persp_column:
# its slice store, row delay and the y stage of the box filter), small
# delays so the test fills them (test_interp_persp_column.cpp holds the
# same values).
cube4_rtl_variant(test_rtl_interp_box cube4_interp_persp_column Vcube4_interp_persp_column
  SOURCES cube4_delay_ram.sv cube4_box_taps.sv PARAMS BeamDepth=32 SliceDepth=1024)
target_sources(test_rtl_interp_box PRIVATE ${PROJECT_SOURCE_DIR}/tb/rtl/test_interp_persp_column.cpp)
# And its home stage (cube4_interp_persp_home: the row stage, the means and
# the z lerp).
cube4_rtl_variant(test_rtl_interp_box cube4_interp_persp_home Vcube4_interp_persp_home
  SOURCES cube4_box_taps.sv cube4_box_mean.sv cube4_lerp.sv)
target_sources(test_rtl_interp_box PRIVATE ${PROJECT_SOURCE_DIR}/tb/rtl/test_interp_persp_home.cpp)
