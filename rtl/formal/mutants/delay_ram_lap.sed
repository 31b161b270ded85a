# file: rtl/cube4_delay_ram.sv
# Planted bug: the lap wraps one entry late (pointer reaches depth_i), so a
# lap of D steps delays by D + 1 and the pointer leaves [0, D).
s/({1'b0, ptr_q} + (PtrBits+1)'(1) == (PtrBits+1)'(depth_i))/({1'b0, ptr_q} == (PtrBits+1)'(depth_i))/
