# file: rtl/cube4_lerp.sv
# Planted bug: the rounding constant is 2^W instead of 2^(W-1), so the
# result is rounded up by a whole step: it can pass b (leaves [a, b]).
s/ProdBits'(1) << (WeightBits == 0 ? 0 : WeightBits - 1)/ProdBits'(1) << WeightBits/
