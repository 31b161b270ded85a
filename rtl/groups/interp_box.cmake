# Perspective box filter (`interp_box`, Cube-4 §3): cube4_box_axis (one
# axis's first cell and four overlaps, combinational) and cube4_interp_box
# (the 4x4 weighted mean, pipelined, made of cube4_box_taps and
# cube4_box_mean). One executable, test_rtl_interp_box
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
