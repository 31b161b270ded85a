#!/usr/bin/env bash
# Simulation speed of the system model on brainsmall (the default scene,
# p = 4), one core, written to the "system-speed" section of
# docs/performance.md:
#   golden render_fixed()             the reference for the TLM level
#   tlm                               one loosely timed transaction per frame
#   tlm-cycle                         every unit's TLM model clocked, SystemC kernel
#   rtl, plain C++ loop               the verilated units without SystemC: the ceiling
#   rtl, SystemC kernel               what `cube4 render --model rtl` runs
#   mixed:UNIT                        each unit alone at RTL
#   scripts/perf_system.sh [frames]   (default 3)
# CUBE4_BUILD: a build directory already configured (skips the set-up).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ -z "${CUBE4_BUILD:-}" ]; then "$here/scripts/setup.sh" >/dev/null; fi
build=${CUBE4_BUILD:-$here/build}
frames=${1:-3}
bench=$build/tb/bench/bench_system
pin=()
command -v taskset >/dev/null && pin=(taskset -c "$(( $(nproc) - 1 ))")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
runs=("golden systemc" "tlm systemc" "tlm-cycle systemc" "tlm-cycle plain" "rtl plain" "rtl systemc"
      "mixed:interp systemc" "mixed:gradient systemc" "mixed:shade systemc" "mixed:composite systemc")
i=0
for r in "${runs[@]}"; do
  set -- $r
  echo "perf_system: $1 ($2)..." >&2
  fr=$frames
  case "$1" in golden|tlm) fr=$(( frames * 10 )) ;; esac
  "${pin[@]}" "$bench" --model "$1" --kernel "$2" --frames "$fr" --warmup 1 > "$tmp/$i.json"
  i=$((i + 1))
done
python3 - "$tmp" "${#runs[@]}" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" <<'PY' | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" system-speed
import json, sys, datetime
tmp, n, cpu = sys.argv[1], int(sys.argv[2]), sys.argv[3]
rows = [json.load(open(f"{tmp}/{i}.json")) for i in range(n)]
by = {(r["model"], r["kernel"]): r for r in rows}
print(f"Measured {datetime.date.today()} by `scripts/perf_system.sh` on {cpu}, one core, brainsmall "
      f"(128×128×84, default view), p = 4, {rows[0]['cycles_per_frame']} cycles per frame; median frame times.")
print()
print("| model | kernel | ms/frame | simulated cycles/s | samples/s |")
print("|---|---|---|---|---|")
for r in rows:
    clk = "" if r["clock_simulated"] else " (no clock: cycles from the cycle model)"
    kern = r["kernel"] if r["model"] not in ("golden", "tlm") else "–"
    print(f"| {r['model']} | {kern} | {r['ms']['median']:.1f} | {r['cycles_per_second']/1e6:.3g} M{clk} | "
          f"{r['samples_per_second']/1e6:.3g} M |")
g = by[("golden", "systemc")]["ms"]["median"]
t = by[("tlm", "systemc")]["ms"]["median"]
rp = by[("rtl", "plain")]["ms"]["median"]
rs = by[("rtl", "systemc")]["ms"]["median"]
tc = by[("tlm-cycle", "systemc")]["ms"]["median"]
tp = by[("tlm-cycle", "plain")]["ms"]["median"]
print()
print(f"- RTL level under SystemC against the same verilated units on a plain C++ loop (the ceiling): "
      f"**{rs/rp:.2f}×** (target: within 3×).")
print(f"- TLM level against the golden renderer: **{t/g:.2f}×** (target: within 2×). Clocked beat by beat "
      f"instead, the TLM models take {tc/g:.1f}× golden under SystemC ({tp/g:.1f}× on the plain loop).")
PY
echo "perf_system: docs/performance.md updated" >&2
