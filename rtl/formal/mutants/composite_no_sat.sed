# file: rtl/cube4_compose_node.sv
# Planted bug: front-to-back colour sums wrap around instead of saturating
# (the compositing node, cube4_composite's blend stage).
s/add_sat = sum\[AB\] ? {AB{1'b1}} : sum\[AB-1:0\];/add_sat = sum[AB-1:0];/
