# Weight generator of both projections (`dda`, docs/rtl-dda.md): cube4_dda,
# golden slice_control() and perspective_slice() slice by slice. One
# executable, test_rtl_dda (tb/rtl/test_dda.cpp): the default widths, and a
# parallel-projection variant of other widths (W = 12 over a 32-bit DDA of
# 16 fraction bits, S up to 31, HasPerspective = 0), whose values
# test_dda.cpp holds too.
cube4_rtl_test(test_rtl_dda
  TOPS cube4_dda
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_dda.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

cube4_rtl_variant(test_rtl_dda cube4_dda Vcube4_dda_w12 PARAMS PosBits=32 FracBits=16 WeightBits=12 SupersamplingBits=5 HasPerspective=0)
