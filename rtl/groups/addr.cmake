# Address generation (`addr`): the skewed-memory address generator cube4_addr.
# One executable, test_rtl_addr (tb/rtl/test_addr.cpp): p = 4 from
# cube4_rtl_test, p = 1, 2, 5, 8 verilated again below.
cube4_rtl_test(test_rtl_addr
  TOPS cube4_addr
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_addr.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/test_addr_sva.cpp
        ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)

foreach(p 1 2 5 8)
  cube4_rtl_variant(test_rtl_addr cube4_addr Vcube4_addr_p${p} PARAMS NumPipes=${p})
endforeach()
# The one-access-per-module checker alone (tb/rtl/test_addr_sva.cpp drives
# it into its violation: the unit cannot be).
cube4_rtl_variant(test_rtl_addr cube4_addr_sva Vcube4_addr_sva)
