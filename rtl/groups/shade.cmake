# Shading (`shade`): the gradient magnitude cube4_shade_magnitude (with
# cube4_udiv) and the classification and shading datapath cube4_shade; one
# executable, test_rtl_shade (tb/rtl/test_shade_magnitude.cpp,
# test_shade.cpp). cube4_shade instantiates the five shade units (SOURCES);
# each of those is also verilated as a top of its own below, for its unit
# test (a file cannot be both a top and a SOURCE of one verilate() call:
# MODDUP).
set(_shade_units
  cube4_shade_classify
  cube4_shade_cube_coord
  cube4_shade_reflection
  cube4_shade_reflectance
  cube4_shade_phong)
set(_shade_sources cube4_lerp.sv cube4_mul_frac.sv cube4_pipe_delay.sv)
foreach(u ${_shade_units})
  list(APPEND _shade_sources ${u}.sv)
endforeach()

cube4_rtl_test(test_rtl_shade
  TOPS cube4_shade
  SOURCES ${_shade_sources}
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_shade.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/test_shade_magnitude.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/test_shade_sva.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

# The five shade units as tops, default widths.
foreach(u ${_shade_units})
  cube4_rtl_variant(test_rtl_shade ${u} V${u})
endforeach()
# The classifier with 2-bit voxel tags (bela §III).
cube4_rtl_variant(test_rtl_shade cube4_shade_classify Vcube4_shade_classify_t2 PARAMS VoxelTagBits=2)
cube4_rtl_variant(test_rtl_shade cube4_shade Vcube4_shade_t2 SOURCES ${_shade_sources} PARAMS VoxelTagBits=2)

# cube4_shade at other widths (tb/rtl/test_shade.cpp holds the same values):
# wide: odd colour/alpha/GmLUT ratios, a 5x5 map face, 3 quotient bits per
# divider stage; small: GmLUT wider than alpha, 2x2 map faces, no coefficient
# fraction bits, 1 quotient bit per stage.
cube4_rtl_variant(test_rtl_shade cube4_shade Vcube4_shade_wide SOURCES ${_shade_sources}
  PARAMS VoxelBits=10 WeightBits=6 GradientBits=10 MagnitudeBits=9 ColorBits=5 AlphaBits=14
         GmlutBits=10 MapFaceRes=5 MapBits=20 MapFracBits=11 CoefBits=12 CoefFracBits=9
         EyeBits=10 DivBitsPerStage=3)
cube4_rtl_variant(test_rtl_shade cube4_shade Vcube4_shade_small SOURCES ${_shade_sources}
  PARAMS VoxelBits=8 WeightBits=2 GradientBits=4 MagnitudeBits=4 ColorBits=8 AlphaBits=8
         GmlutBits=16 MapFaceRes=2 MapBits=8 MapFracBits=7 CoefBits=4 CoefFracBits=0
         EyeBits=4 DivBitsPerStage=1)
# Without shading hardware (the system's variant for scenes without shading).
cube4_rtl_variant(test_rtl_shade cube4_shade Vcube4_shade_noshade SOURCES ${_shade_sources} PARAMS HasShading=0)
# The gradient magnitude and its divider, default and other parameters
# (test_shade_magnitude.cpp holds the same values).
cube4_rtl_variant(test_rtl_shade cube4_udiv Vcube4_udiv)
cube4_rtl_variant(test_rtl_shade cube4_shade_magnitude Vcube4_shade_magnitude SOURCES cube4_udiv.sv cube4_pipe_delay.sv)
cube4_rtl_variant(test_rtl_shade cube4_shade_magnitude Vcube4_shade_magnitude_g10 SOURCES cube4_udiv.sv
  PARAMS GradientBits=10 MagnitudeBits=9 NrIterations=2)
cube4_rtl_variant(test_rtl_shade cube4_shade_magnitude Vcube4_shade_magnitude_n0 SOURCES cube4_udiv.sv PARAMS NrIterations=0)
