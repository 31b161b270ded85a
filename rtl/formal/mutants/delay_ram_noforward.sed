# file: rtl/cube4_delay_ram.sv
# Planted bug: no write-to-read forwarding, so a lap of one entry reads the
# entry's old value (an underflow: the value of the lap before).
s/assign rdata_d = (we \&\& ptr_d == ptr_q) ? wdata_i : mem_q\[ptr_d\];/assign rdata_d = mem_q[ptr_d];/
