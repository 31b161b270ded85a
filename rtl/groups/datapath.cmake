# Datapath units: interpolation (cube4_lerp, cube4_trilinear), gradient,
# gradient magnitude (cube4_udiv inside), skewed-memory address generation.
# One executable, test_rtl_datapath; the default-width units come from
# cube4_rtl_test, the other parameter sets are verilated again below.
cube4_rtl_test(test_rtl_datapath
  TOPS cube4_trilinear cube4_gradient cube4_magnitude cube4_skew_addr
  SOURCES cube4_lerp.sv cube4_udiv.sv
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_datapath.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

# Combinational building blocks as tops of their own.
cube4_rtl_variant(test_rtl_datapath cube4_lerp Vcube4_lerp SOURCES cube4_lerp.sv cube4_udiv.sv)
cube4_rtl_variant(test_rtl_datapath cube4_udiv Vcube4_udiv SOURCES cube4_lerp.sv cube4_udiv.sv)
# Non-default widths (the tests hold the same values: test_datapath.cpp).
cube4_rtl_variant(test_rtl_datapath cube4_trilinear Vcube4_trilinear_w6 SOURCES cube4_lerp.sv cube4_udiv.sv PARAMS VoxelBits=8 WeightBits=6)
cube4_rtl_variant(test_rtl_datapath cube4_trilinear Vcube4_trilinear_w10 SOURCES cube4_lerp.sv cube4_udiv.sv PARAMS VoxelBits=16 WeightBits=10)
cube4_rtl_variant(test_rtl_datapath cube4_gradient Vcube4_gradient_v8 SOURCES cube4_lerp.sv cube4_udiv.sv
  PARAMS VoxelBits=8 WeightBits=6 GradientBits=8 GradientShift=1)
cube4_rtl_variant(test_rtl_datapath cube4_gradient Vcube4_gradient_v16 SOURCES cube4_lerp.sv cube4_udiv.sv
  PARAMS VoxelBits=16 WeightBits=10 GradientBits=12 GradientShift=6)
cube4_rtl_variant(test_rtl_datapath cube4_magnitude Vcube4_magnitude_g10 SOURCES cube4_lerp.sv cube4_udiv.sv
  PARAMS GradientBits=10 MagnitudeBits=9 NrIterations=2)
cube4_rtl_variant(test_rtl_datapath cube4_magnitude Vcube4_magnitude_n0 SOURCES cube4_lerp.sv cube4_udiv.sv PARAMS NrIterations=0)
# Skewed memory with p = 1, 2, 5, 8 pipelines (p = 4 is the default top).
foreach(p 1 2 5 8)
  cube4_rtl_variant(test_rtl_datapath cube4_skew_addr Vcube4_skew_addr_p${p} SOURCES cube4_lerp.sv cube4_udiv.sv PARAMS NumPipes=${p})
endforeach()

# Lint (Verilator -Wall, yosys synth) of every rtl/*.sv.
add_test(NAME rtl_lint COMMAND ${PROJECT_SOURCE_DIR}/scripts/lint_rtl.sh)
set_tests_properties(rtl_lint PROPERTIES LABELS rtl)
