# file: rtl/cube4_interp.sv
# Planted bug: the z stage uses the y weight's delay line one stage early
# (wz1_q instead of wz2_q): the sample mixes weights of two input sets.
s/\.w_i(wz2_q),/.w_i(wz1_q),/
