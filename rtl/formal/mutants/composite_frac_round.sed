# file: rtl/cube4_composite.sv
# Planted bug: the blend's mul_frac (accumulator domain) maps every fraction
# f to f + 1 (instead of only f >= 1/2 gaining its top bit), so
# T * alpha can exceed alpha: opacity grows past the sample's contribution.
s/f_unit       = {1'b0, f} + (AB+1)'(f\[AB-1\]);/f_unit       = {1'b0, f} + (AB+1)'(1);/
