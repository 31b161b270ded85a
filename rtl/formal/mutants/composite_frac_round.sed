# file: rtl/cube4_composite.sv
# Planted bug: mul_frac maps every fraction f to f + 1 (instead of only
# f >= 1/2 gaining its top bit), so a product can exceed x: opacity grows
# past the remaining transparency and the cut can raise alpha.
s/f_unit   = {1'b0, f} + (A+1)'(f\[A-1\]);/f_unit   = {1'b0, f} + (A+1)'(1);/
