# The package (rtl/cube4_pkg.sv) against golden's widths: test_rtl_pkg
# (tb/rtl/test_pkg.cpp) reads the package's constants from a verilated
# cube4_lerp, the smallest model that reads it.
cube4_rtl_test(test_rtl_pkg
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_pkg.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
cube4_rtl_variant(test_rtl_pkg cube4_lerp Vpkg)
