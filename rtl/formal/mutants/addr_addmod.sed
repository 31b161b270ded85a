# file: rtl/cube4_addr.sv
# Planted bug: the modulo-p sum keeps s = p (off by one in the wrap test),
# so a module number p appears for p not a power of two.
s/if (s >= (PipeBits+1)'(NumPipes)) s = s - (PipeBits+1)'(NumPipes);/if (s > (PipeBits+1)'(NumPipes)) s = s - (PipeBits+1)'(NumPipes);/
