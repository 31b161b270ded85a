# Perspective gradient ring (`gradient_persp`, docs/rtl-gradient-persp.md):
# cube4_gradient_persp_homes, where along one axis a ray's gradient
# operands have their homes (golden gradient_operand_homes()). One
# executable, test_rtl_gradient_persp (tb/rtl/test_gradient_persp_homes.cpp).
cube4_rtl_test(test_rtl_gradient_persp
  TOPS cube4_gradient_persp_homes
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_gradient_persp_homes.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
