# VolumePro's z gradient (`interp_zdiff`, VolumePro §3.2): cube4_interp_zdiff,
# the voxel z differences interpolated to the sample (cube4_interp with
# Signed = 1 behind eight subtractors). One executable, test_rtl_interp_zdiff
# (tb/rtl/test_interp_zdiff.cpp): the default widths, and again at 8-bit
# voxels with 6-bit weights and at the widest, 16-bit voxels with 14-bit
# weights (test_interp_zdiff.cpp holds the same values).
cube4_rtl_test(test_rtl_interp_zdiff
  TOPS cube4_interp_zdiff
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_interp_zdiff.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

cube4_rtl_variant(test_rtl_interp_zdiff cube4_interp_zdiff Vcube4_interp_zdiff_v8 PARAMS VoxelBits=8 WeightBits=6)
cube4_rtl_variant(test_rtl_interp_zdiff cube4_interp_zdiff Vcube4_interp_zdiff_v16 PARAMS VoxelBits=16 WeightBits=14)
