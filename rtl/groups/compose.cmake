# Compositing node (`compose`): cube4_compose_node, one node of the image
# composition network (golden compose(), docs/rtl-compose.md), and the
# network's output stage cube4_compose_out (golden pixel_of()). One
# executable, test_rtl_compose (tb/rtl/test_compose.cpp,
# tb/rtl/test_compose_out.cpp): the default widths
# from cube4_rtl_test, other widths and Latency 1 verilated again below
# (test_compose.cpp holds the same values).
set(_compose_sources cube4_mul_frac.sv)

cube4_rtl_test(test_rtl_compose
  TOPS cube4_compose_node cube4_compose_out
  SOURCES ${_compose_sources} cube4_acc_to_pixel.sv
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_compose.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/test_compose_out.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/test_compose_sva.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

# 8-bit pixels without guard bits (bela's eight bits a channel).
cube4_rtl_variant(test_rtl_compose cube4_compose_node Vcube4_compose_node_a8 SOURCES ${_compose_sources}
  PARAMS VoxelBits=8 AlphaBits=8 AccGuardBits=0)
cube4_rtl_variant(test_rtl_compose cube4_compose_node Vcube4_compose_node_a12 SOURCES ${_compose_sources}
  PARAMS AlphaBits=12 AccGuardBits=4)
# Latency 1: the instance inside cube4_composite.
cube4_rtl_variant(test_rtl_compose cube4_compose_node Vcube4_compose_node_l1 SOURCES ${_compose_sources}
  PARAMS Latency=1)
# Latency 0: the blend node inside cube4_composite with polygons.
cube4_rtl_variant(test_rtl_compose cube4_compose_node Vcube4_compose_node_l0 SOURCES ${_compose_sources}
  PARAMS Latency=0)
# The output stage at the same other widths.
cube4_rtl_variant(test_rtl_compose cube4_compose_out Vcube4_compose_out_a12 SOURCES cube4_acc_to_pixel.sv
  PARAMS AlphaBits=12 AccGuardBits=4)
cube4_rtl_variant(test_rtl_compose cube4_compose_out Vcube4_compose_out_a8 SOURCES cube4_acc_to_pixel.sv
  PARAMS AlphaBits=8 AccGuardBits=0)
# The node's checker alone (tb/rtl/test_compose_sva.cpp drives its alpha
# invariant into a violation, which the node cannot produce).
cube4_rtl_variant(test_rtl_compose cube4_compose_node_sva Vcube4_compose_node_sva)
