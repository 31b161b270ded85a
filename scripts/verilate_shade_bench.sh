#!/usr/bin/env bash
# Verilates cube4_shade_unit from the RTL folder RTL with
# tb/bench/verilator_threads_bench.cpp as its main (four instances in one
# context, clocked from a C++ loop with random samples and gradients) into
# OUT/Vshade, as the system verilates and compiles the unit (Verilator's
# -O3, X unique; the C++ at -O3 -march=x86-64-v2 -falign-functions=64, as
# systemc/CMakeLists.txt compiles it: Verilator's own makefile would
# otherwise compile the model at -Os, about 1.7x slower) plus any further
# Verilator options given. Shared by perf_verilator_threads.sh and
# perf_shade_unit.sh.
#   scripts/verilate_shade_bench.sh RTL OUT [verilator options...]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
r=$1
out=$2
shift 2
src=()
for unit in pkg udiv lerp mul_frac pipe_delay shade_magnitude shade_classify shade_cube_coord shade_reflection \
            shade_reflectance shade_phong shade shade_unit; do
  src+=("$r/cube4_$unit.sv")
done
verilator --cc --exe --build -j 2 -O3 --x-assign unique --x-initial unique "$@" -Wall -Wno-fatal -I"$r" \
  --top cube4_shade_unit --prefix Vshade -Mdir "$out" "${src[@]}" "$here/tb/bench/verilator_threads_bench.cpp" \
  -CFLAGS "-march=x86-64-v2 -falign-functions=64" -MAKEFLAGS OPT_FAST=-O3 -MAKEFLAGS OPT_SLOW=-O3 -MAKEFLAGS OPT_GLOBAL=-O3 \
  >"$out.log" 2>&1 || { echo "verilate_shade_bench: verilator failed on $r (log: $out.log)" >&2; exit 1; }
