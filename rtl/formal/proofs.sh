# The proofs scripts/formal.sh runs (sourced by it):
# proof <name> <group> <kind> <K> <top> "<files>" "<Param=value ...>" [probe=signal ...]
# group quick: default ctest suite; slow: ctest label slow; bug: a planted
# bug that the proof must catch (kind bug).

# mem_probes <width> <depth>: probe_mem slices onto the RAM entries of u_dut.mem_q.
mem_probes() {
  local w=$1 d=$2 e
  for ((e = 0; e < d; e++)); do
    echo "probe_mem[$((e * w + w - 1)):$((e * w))]=\\u_dut.mem_q[$e]"
  done
}

# cube4_lerp: range and equivalence, combinational.
proof lerp                 quick bmc 1 lerp_fv "rtl/cube4_lerp.sv $F/cube4_ref_interp.sv $F/lerp_fv.sv" "+noincr"
INTERP_PROBES="probe_x_q=u_dut.x_q probe_y_q=u_dut.y_q probe_wy_q=u_dut.wy_q probe_wz1_q=u_dut.wz1_q probe_wz2_q=u_dut.wz2_q probe_valid_q=u_dut.valid_q"
# cube4_interp: equivalence with the reference, range; pipelined.
INTERP_FILES="rtl/cube4_lerp.sv rtl/cube4_interp.sv $F/cube4_ref_interp.sv $F/interp_fv.sv"
# Quick: 6-bit voxels, 3-bit weights (the lerp proof covers the default
# widths); slow: the default widths (12, 8).
proof interp_v6_x       quick ind 1 interp_fv "$INTERP_FILES" "VoxelBits=6 WeightBits=3 Stage=1 +noincr" $INTERP_PROBES
proof interp_v6_y       quick ind 1 interp_fv "$INTERP_FILES" "VoxelBits=6 WeightBits=3 Stage=2 +noincr" $INTERP_PROBES
proof interp_v6_z       quick ind 1 interp_fv "$INTERP_FILES" "VoxelBits=6 WeightBits=3 Stage=3 +noincr" $INTERP_PROBES
proof interp_x          slow  ind 1 interp_fv "$INTERP_FILES" "Stage=1 +noincr" $INTERP_PROBES
proof interp_y          slow  ind 1 interp_fv "$INTERP_FILES" "Stage=2 +noincr" $INTERP_PROBES
proof interp_z          slow  ind 1 interp_fv "$INTERP_FILES" "Stage=3 +noincr" $INTERP_PROBES
# cube4_dda_walk: the weight generator's DDAs hold slices k - 1, k, k + 1
# exactly, start + k * step, for any run of commands (8-bit quick, the
# 48-bit default slow).
proof dda_walk_p8          quick ind 1 dda_walk_fv "rtl/cube4_dda_walk.sv $F/dda_walk_fv.sv" "PosBits=8 +noincr"
proof dda_walk             slow  ind 1 dda_walk_fv "rtl/cube4_dda_walk.sv $F/dda_walk_fv.sv" "PosBits=48 +noincr"
proof bug_dda_walk_step    bug   bug 4 dda_walk_fv "$F/mutants/dda_walk_step.sed $F/dda_walk_fv.sv" "PosBits=8 +noincr"
# cube4_delay_ram: pointer bound with free inputs; FIFO with constant depth.
DR_FILES="rtl/cube4_delay_ram.sv $F/delay_ram_fv.sv"
proof delay_ram_ptr_d5      quick ind 1 delay_ram_fv "$DR_FILES" "MaxDepth=5 Fifo=0" probe_ptr=u_dut.ptr_q $(mem_probes 2 5)
proof delay_ram_fifo_d5     quick ind 1 delay_ram_fv "$DR_FILES" "MaxDepth=5" probe_ptr=u_dut.ptr_q $(mem_probes 2 5)
proof delay_ram_fifo_d4     quick ind 1 delay_ram_fv "$DR_FILES" "MaxDepth=4" probe_ptr=u_dut.ptr_q $(mem_probes 2 4)
proof delay_ram_fifo_d8     slow  ind 1 delay_ram_fv "$DR_FILES" "MaxDepth=8" probe_ptr=u_dut.ptr_q $(mem_probes 2 8)
proof bug_delay_ram_lap     bug   bug 16 delay_ram_fv "$F/mutants/delay_ram_lap.sed $F/delay_ram_fv.sv" "MaxDepth=5" probe_ptr=u_dut.ptr_q $(mem_probes 2 5)
proof bug_delay_ram_noforward bug bug 16 delay_ram_fv "$F/mutants/delay_ram_noforward.sed $F/delay_ram_fv.sv" "MaxDepth=5" probe_ptr=u_dut.ptr_q $(mem_probes 2 5)
# cube4_composite: saturation limits (alpha and colours never wrap).
CO_FILES="rtl/cube4_mul_frac.sv rtl/cube4_to_acc.sv rtl/cube4_compose_node.sv rtl/cube4_pipe_delay.sv rtl/cube4_composite.sv $F/composite_fv.sv"
CO_PROBES="probe_alpha_q=u_dut.alpha_q probe_cut_alpha_q=u_dut.cut_alpha_q probe_pre_alpha_q=u_dut.pre_alpha_q probe_pre_red_q=u_dut.pre_red_q probe_pre_green_q=u_dut.pre_green_q probe_pre_blue_q=u_dut.pre_blue_q"
# Quick at 8-bit samples and 4 guard bits (the same datapath, parametric);
# slow at the default 16 + 8 (about 90 s on two loaded cores).
CO_NARROW="AlphaBits=8 AccGuardBits=4 +noincr"
proof composite_sat_a8g4    quick ind 1 composite_fv "$CO_FILES" "$CO_NARROW" $CO_PROBES
proof composite_sat         slow  ind 1 composite_fv "$CO_FILES" "+noincr" $CO_PROBES
proof bug_composite_frac_round bug bug 10 composite_fv "$F/mutants/composite_frac_round.sed rtl/cube4_to_acc.sv rtl/cube4_compose_node.sv rtl/cube4_pipe_delay.sv rtl/cube4_composite.sv $F/composite_fv.sv" "$CO_NARROW" $CO_PROBES
proof bug_composite_no_sat  bug   bug 10 composite_fv "rtl/cube4_mul_frac.sv rtl/cube4_to_acc.sv $F/mutants/composite_no_sat.sed rtl/cube4_pipe_delay.sv rtl/cube4_composite.sv $F/composite_fv.sv" "$CO_NARROW" $CO_PROBES
# cube4_addr: conflict-free, correct addresses for every traversal.
ADDR_FILES="rtl/cube4_addr.sv $F/addr_fv.sv"
# z3 gets nowhere on this model (no answer for the first cycle in 5
# minutes), yosys's SAT solver proves it: +yosys-sat.
# BMC depth: the first output beat is 9 cycles after reset (reset, start,
# 7 cycles of setup and latency); cost grows steeply with depth (p = 4: 3 s
# at 10, 42 s at 13, no answer in 200 s at 16).
# Quick: the powers of two (seconds); p not a power of two (dividers,
# ~45 s each at depth 11) and depth 13 are slow.
for p in 1 2 3 4 5 6 7 8; do
  case $p in 1|2|4|8) g=quick ;; *) g=slow ;; esac
  proof addr_p$p             $g bmc 11 addr_fv "$ADDR_FILES" "NumPipes=$p +yosys-sat"
  proof addr_p${p}_k13       slow  bmc 13 addr_fv "$ADDR_FILES" "NumPipes=$p +yosys-sat"
done
proof bug_addr_rotation     bug   bug 16 addr_fv "$F/mutants/addr_rotation.sed $F/addr_fv.sv" "NumPipes=4 +yosys-sat"
proof bug_addr_addmod       bug   bug 16 addr_fv "$F/mutants/addr_addmod.sed $F/addr_fv.sv" "NumPipes=5 +yosys-sat"
proof bug_lerp_half         bug   bug 1 lerp_fv "$F/mutants/lerp_half.sed $F/cube4_ref_interp.sv $F/lerp_fv.sv" "+noincr"
proof bug_interp_weight  bug   bug 5 interp_fv "rtl/cube4_lerp.sv $F/mutants/interp_weight.sed $F/cube4_ref_interp.sv $F/interp_fv.sv" "VoxelBits=6 WeightBits=3 Stage=3 +noincr" $INTERP_PROBES
