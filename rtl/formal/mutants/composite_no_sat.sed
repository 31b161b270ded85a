# file: rtl/cube4_compose_node.sv
# Planted bug: front-to-back colour sums wrap around instead of saturating
# (the compositing node, cube4_composite's blend stage).
s/colour_saturated\[\([0-2]\)\] ? {AB{1'b1}} : colour_sum/colour_sum/
