# Datapath units: interpolation (cube4_lerp, cube4_trilinear), gradient,
# gradient magnitude (cube4_udiv inside), skewed-memory address generation.
# One executable, test_rtl_datapath; the default-width units come from
# cube4_rtl_test, the other parameter sets are verilated again below.
cube4_rtl_test(test_rtl_datapath
  TOPS cube4_trilinear cube4_gradient cube4_magnitude cube4_skew_addr
  SOURCES cube4_lerp.sv cube4_udiv.sv
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_datapath.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

# cube4_datapath_variant(<top> <prefix> [PARAMS <Name=value>...]): verilate
# rtl/<top>.sv once more into test_rtl_datapath as class <prefix>, with the
# top-level parameters overridden (-G), same flags as cube4_rtl_test.
function(cube4_datapath_variant top prefix)
  cmake_parse_arguments(A "" "" "PARAMS" ${ARGN})
  set(gparams)
  foreach(p ${A_PARAMS})
    list(APPEND gparams -G${p})
  endforeach()
  set(srcs)
  foreach(s cube4_lerp.sv cube4_udiv.sv)
    if(NOT s STREQUAL "${top}.sv")
      list(APPEND srcs ${CMAKE_CURRENT_SOURCE_DIR}/${s})
    endif()
  endforeach()
  verilate(test_rtl_datapath
    SOURCES ${srcs} ${CMAKE_CURRENT_SOURCE_DIR}/${top}.sv
    TOP_MODULE ${top}
    PREFIX ${prefix}
    INCLUDE_DIRS ${CMAKE_CURRENT_SOURCE_DIR}
    VERILATOR_ARGS -Wall --x-assign unique --x-initial unique -O3 ${gparams})
endfunction()

# Combinational building blocks as tops of their own.
cube4_datapath_variant(cube4_lerp Vcube4_lerp)
cube4_datapath_variant(cube4_udiv Vcube4_udiv)
# Non-default widths (the tests hold the same values: test_datapath.cpp).
cube4_datapath_variant(cube4_trilinear Vcube4_trilinear_w6 PARAMS VoxelBits=8 WeightBits=6)
cube4_datapath_variant(cube4_trilinear Vcube4_trilinear_w10 PARAMS VoxelBits=16 WeightBits=10)
cube4_datapath_variant(cube4_gradient Vcube4_gradient_v8
  PARAMS VoxelBits=8 WeightBits=6 GradientBits=8 GradientShift=1)
cube4_datapath_variant(cube4_gradient Vcube4_gradient_v16
  PARAMS VoxelBits=16 WeightBits=10 GradientBits=12 GradientShift=6)
cube4_datapath_variant(cube4_magnitude Vcube4_magnitude_g10
  PARAMS GradientBits=10 MagnitudeBits=9 NrIterations=2)
cube4_datapath_variant(cube4_magnitude Vcube4_magnitude_n0 PARAMS NrIterations=0)
# Skewed memory with p = 1, 2, 5, 8 pipelines (p = 4 is the default top).
foreach(p 1 2 5 8)
  cube4_datapath_variant(cube4_skew_addr Vcube4_skew_addr_p${p} PARAMS NumPipes=${p})
endforeach()

# Lint (Verilator -Wall, yosys synth) of every rtl/*.sv.
add_test(NAME rtl_lint COMMAND ${PROJECT_SOURCE_DIR}/scripts/lint_rtl.sh)
set_tests_properties(rtl_lint PROPERTIES LABELS rtl)
