# Interpolation (`interp`): the datapath cube4_interp (with cube4_lerp), the
# unit with its delay storage and near-neighbour links (cube4_delay_ram,
# cube4_interp_unit) inside cube4_interp_ring. One executable,
# test_rtl_interp: the datapath tests (tb/rtl/test_interp.cpp) and the ring's
# (tb/rtl/test_interp_ring.cpp). The default ring (p = 4, MaxDim = 256) from
# cube4_rtl_test; the other pipeline counts, the datapath at other widths and
# the building blocks as tops of their own verilated again below (a file
# cannot be both a top and a SOURCE of one verilate() call: MODDUP).
set(_interp_sources cube4_lerp.sv cube4_interp.sv cube4_delay_ram.sv cube4_slice_store.sv cube4_interp_unit.sv)

cube4_rtl_test(test_rtl_interp
  TOPS cube4_interp_ring
  SOURCES ${_interp_sources}
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_interp.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/test_interp_ring.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/test_interp_sva.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

# Rings of 1, 2 and 5 pipelines; the small MaxDim of p = 2 and p = 5 lets
# the tests fill the slice store to the last entry (test_interp_ring.cpp holds
# the same values).
cube4_rtl_variant(test_rtl_interp cube4_interp_ring Vcube4_interp_ring_p1 SOURCES ${_interp_sources}
  PARAMS NumPipes=1 MaxDim=24)
cube4_rtl_variant(test_rtl_interp cube4_interp_ring Vcube4_interp_ring_p2 SOURCES ${_interp_sources}
  PARAMS NumPipes=2 MaxDim=16)
cube4_rtl_variant(test_rtl_interp cube4_interp_ring Vcube4_interp_ring_p5 SOURCES ${_interp_sources}
  PARAMS NumPipes=5 MaxDim=12)
# With 4-bit voxel tags (bela §III): the words {tag, value} through storage
# and links, a tag per sample.
cube4_rtl_variant(test_rtl_interp cube4_interp_ring Vcube4_interp_ring_t4 SOURCES ${_interp_sources}
  PARAMS NumPipes=4 MaxDim=16 VoxelTagBits=4)
# The delay RAM alone: a depth that is no power of two, and a single entry.
cube4_rtl_variant(test_rtl_interp cube4_delay_ram Vcube4_delay_ram_d13 PARAMS Width=10 MaxDepth=13)
cube4_rtl_variant(test_rtl_interp cube4_delay_ram Vcube4_delay_ram_d1 PARAMS Width=10 MaxDepth=1)
# The datapath and its lerp as tops, default and other widths
# (test_interp.cpp holds the same values).
cube4_rtl_variant(test_rtl_interp cube4_lerp Vcube4_lerp)
cube4_rtl_variant(test_rtl_interp cube4_interp Vcube4_interp SOURCES cube4_lerp.sv)
cube4_rtl_variant(test_rtl_interp cube4_interp Vcube4_interp_w6 SOURCES cube4_lerp.sv PARAMS VoxelBits=8 WeightBits=6)
cube4_rtl_variant(test_rtl_interp cube4_interp Vcube4_interp_w10 SOURCES cube4_lerp.sv PARAMS VoxelBits=16 WeightBits=10)
# With 4-bit voxel tags (bela §III), at the default widths otherwise.
cube4_rtl_variant(test_rtl_interp cube4_interp Vcube4_interp_t4 SOURCES cube4_lerp.sv PARAMS VoxelTagBits=4)
