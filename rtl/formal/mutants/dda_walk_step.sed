# file: rtl/cube4_dda_walk.sv
# Planted bug: an advance adds the step to the slice ahead's old value
# twice over (the new ahead is here + 2 * step), as a walk that forgot the
# shift would: slice k + 1 is wrong after the first advance.
s/ahead_q  <= ahead_q + step_i;/ahead_q  <= ahead_q + step_i + step_i;/
