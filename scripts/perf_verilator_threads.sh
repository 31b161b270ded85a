#!/usr/bin/env bash
# What Verilator's own options do to the simulation of the shading unit,
# the system's most expensive RTL (docs/performance.md): cube4_shade_unit
# verilated and compiled as the system does (-O3, --x-assign/--x-initial
# unique), with --x-assign/--x-initial fast instead, and with --threads 2;
# four instances in one context (p = 4) clocked from a C++ loop
# (tb/bench/verilator_threads_bench.cpp), alone and with a second copy of
# the same run beside it (two simulations on this machine's cores, as
# `ctest -j2` or a sweep runs them). Writes the "verilator-options" section
# of docs/performance.md.
#   scripts/perf_verilator_threads.sh [cycles]    (default 20000)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cycles=${1:-20000}
command -v verilator >/dev/null || "$here/scripts/setup.sh" --packages-only >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
declare -A opts=(
  [system]=""
  [x_fast]="--x-assign fast --x-initial fast"
  [threads2]="--threads 2"
)
for v in system x_fast threads2; do
  echo "perf_verilator_threads: verilating ($v: ${opts[$v]:-as the system})..." >&2
  # shellcheck disable=SC2086
  "$here/scripts/verilate_shade_bench.sh" "$here/rtl" "$tmp/$v" ${opts[$v]}
done
section=$(python3 - "$tmp" "$cycles" "$(nproc)" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" <<'PY'
import json, subprocess, sys, datetime
tmp, cycles, cores, cpu = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
def run(v, copies):
    procs = [subprocess.Popen([f"{tmp}/{v}/Vshade", "4", cycles], stdout=subprocess.PIPE, text=True) for _ in range(copies)]
    return max(json.loads(p.communicate()[0])["us_per_unit_cycle"] for p in procs)
names = {"system": "as the system verilates and compiles it (`-O3 --x-assign unique --x-initial unique`, C++ `-O3`)",
         "x_fast": "`--x-assign fast --x-initial fast`", "threads2": "`--threads 2`"}
print(f"Measured {datetime.date.today()} by `scripts/perf_verilator_threads.sh {cycles}` on {cpu} ({cores} cores): "
      f"four `cube4_shade_unit`s in one context, {cycles} cycles of random samples and gradients, µs per unit and cycle "
      "(the slower copy when two run at once).")
print()
print("| verilated | alone | two runs at once |")
print("|---|---:|---:|")
for v in ("system", "x_fast", "threads2"):
    print(f"| {names[v]} | {run(v, 1):.2f} | {run(v, 2):.2f} |")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" verilator-options
echo "perf_verilator_threads: docs/performance.md updated" >&2
