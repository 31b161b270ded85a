# file: rtl/cube4_mul_frac.sv
# Planted bug: the compositor's shared multiplier maps every fraction f to
# f + 1 (instead of only f >= 1/2 gaining its top bit), so T * alpha can
# exceed alpha: opacity grows past the sample's contribution.
s/assign f_unit = {1'b0, f_i} + (FBits + 1)'(f_i\[FBits-1\]);/assign f_unit = {1'b0, f_i} + (FBits + 1)'(1);/
