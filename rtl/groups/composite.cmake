# Compositing unit with its ray storage and ray alignment: cube4_composite
# (datapath), cube4_delay_ram (ray beam delay), cube4_composite_unit, inside
# cube4_composite_ring. One executable, test_rtl_composite_ring
# (tb/rtl/test_composite_ring.cpp): the default ring (p = 4, MaxDim = 256)
# from cube4_rtl_test, the other pipeline counts verilated again below.
set(_composite_ring_sources cube4_composite.sv cube4_delay_ram.sv cube4_composite_unit.sv)

cube4_rtl_test(test_rtl_composite_ring
  TOPS cube4_composite_ring
  SOURCES ${_composite_ring_sources}
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_composite_ring.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

# Rings of 1, 2 and 5 pipelines; small MaxDim values let the tests fill the
# ray slice store and the beam delay to their last entries
# (test_composite_ring.cpp holds the same values).
cube4_rtl_variant(test_rtl_composite_ring cube4_composite_ring Vcube4_composite_ring_p1 SOURCES ${_composite_ring_sources} PARAMS NumPipes=1 MaxDim=24)
cube4_rtl_variant(test_rtl_composite_ring cube4_composite_ring Vcube4_composite_ring_p2 SOURCES ${_composite_ring_sources} PARAMS NumPipes=2 MaxDim=16)
cube4_rtl_variant(test_rtl_composite_ring cube4_composite_ring Vcube4_composite_ring_p5 SOURCES ${_composite_ring_sources} PARAMS NumPipes=5 MaxDim=12)
