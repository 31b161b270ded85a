# file: rtl/cube4_composite.sv
# Planted bug: front-to-back colour sums wrap around instead of saturating.
s/add_sat = sum\[A\] ? {A{1'b1}} : sum\[A-1:0\];/add_sat = sum[A-1:0];/
