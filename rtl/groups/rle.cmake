# Run-length decoder of slab images (`rle`, Cube-5 §5): cube4_rle_decode,
# one per pipeline (golden RleDecoder, docs/rtl-rle-decode.md). One
# executable, test_rtl_rle (tb/rtl/test_rle_decode.cpp).
cube4_rtl_test(test_rtl_rle
  TOPS cube4_rle_decode
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_rle_decode.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
# The decoders of a perspective compositing ring: two banks of p
# cube4_rle_decode and their crossbar (docs/rtl-rle-decode.md, "In
# perspective"). One executable, test_rtl_persp_slab_decode
# (tb/rtl/test_persp_slab_decode.cpp), at p = 4, 1, 5 and 8.
cube4_rtl_test(test_rtl_persp_slab_decode
  TOPS cube4_persp_slab_decode
  SOURCES cube4_rle_decode.sv
  TESTS ${PROJECT_SOURCE_DIR}/tb/rtl/test_persp_slab_decode.cpp ${PROJECT_SOURCE_DIR}/tb/rtl/rtl_main.cpp)
foreach(p 1 5 8)
  cube4_rtl_variant(test_rtl_persp_slab_decode cube4_persp_slab_decode Vcube4_persp_slab_decode_p${p}
    SOURCES cube4_rle_decode.sv PARAMS NumPipes=${p})
endforeach()
