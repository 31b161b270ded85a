# file: rtl/cube4_addr.sv
# Planted bug: pipeline 0's phase ignores a backwards beam axis, so the
# de-skew rotation is wrong for every traversal with flip[0].
s/assign c0_d   = flp\[0\] ? mod0 : '0;/assign c0_d   = '0;/
