# Run-length decoder of slab images (`rle`, Cube-5 §5): cube4_rle_decode,
# one per pipeline (golden RleDecoder, docs/rtl-rle-decode.md). One
# executable, test_rtl_rle (tb/rtl/test_rle_decode.cpp).
cube4_rtl_test(test_rtl_rle
  TOPS cube4_rle_decode
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_rle_decode.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
