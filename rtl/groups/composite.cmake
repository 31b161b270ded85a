# Compositing (`composite`): the datapath cube4_composite (its blend stage is
# cube4_compose_node) and the unit with its ray storage and ray alignment
# (cube4_delay_ram, cube4_composite_unit) inside cube4_composite_ring. One
# executable, test_rtl_composite: the datapath tests (tb/rtl/test_composite.cpp) and the ring's
# (tb/rtl/test_composite_ring.cpp); the default ring (p = 4, MaxDim = 256)
# from cube4_rtl_test, the other pipeline counts and the datapath's variants
# verilated again below.
set(_composite_ring_sources cube4_mul_frac.sv cube4_to_acc.sv cube4_compose_node.sv cube4_composite.sv cube4_delay_ram.sv
  cube4_acc_to_pixel.sv cube4_rle_decode.sv cube4_composite_unit.sv)

cube4_rtl_test(test_rtl_composite
  TOPS cube4_composite_ring
  SOURCES ${_composite_ring_sources}
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_composite.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/test_composite_ring.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/test_composite_sva.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

# Rings of 1, 2 and 5 pipelines; small MaxDim values let the tests fill the
# ray slice store and the beam delay to their last entries
# (test_composite_ring.cpp holds the same values).
cube4_rtl_variant(test_rtl_composite cube4_composite_ring Vcube4_composite_ring_p1 SOURCES ${_composite_ring_sources} PARAMS NumPipes=1 MaxDim=24)
cube4_rtl_variant(test_rtl_composite cube4_composite_ring Vcube4_composite_ring_p2 SOURCES ${_composite_ring_sources} PARAMS NumPipes=2 MaxDim=16)
cube4_rtl_variant(test_rtl_composite cube4_composite_ring Vcube4_composite_ring_p5 SOURCES ${_composite_ring_sources} PARAMS NumPipes=5 MaxDim=12)

# The datapath as a top, default and other widths.
cube4_rtl_variant(test_rtl_composite cube4_composite Vcube4_composite)
# cube4_composite at other widths (tb/rtl/test_composite.cpp).
cube4_rtl_variant(test_rtl_composite cube4_composite Vcube4_composite_narrow
  PARAMS VoxelBits=10 WeightBits=6 AlphaBits=14 CutBits=24 PosBits=12 CutCoefBits=12)
# VolumePro's compositor: 12-bit channels and no accumulator guard bits.
cube4_rtl_variant(test_rtl_composite cube4_composite Vcube4_composite_volumepro PARAMS AlphaBits=12 AccGuardBits=0)
# Without cut-plane hardware (the system's variant for scenes without one).
cube4_rtl_variant(test_rtl_composite cube4_composite Vcube4_composite_nocut PARAMS HasCutPlane=0)
# Without polygon hardware (the system's variant for scenes without polygons).
cube4_rtl_variant(test_rtl_composite cube4_composite Vcube4_composite_nopoly PARAMS HasPolygons=0)
# The unit's checker alone (tb/rtl/test_composite_sva.cpp drives its
# ray-store order invariant into a violation, which the unit cannot produce).
cube4_rtl_variant(test_rtl_composite cube4_composite_unit_sva Vcube4_composite_unit_sva)
