#!/usr/bin/env bash
# How fast the verilated shading unit, the RTL level's most expensive unit,
# simulates now against an earlier revision's RTL, measured in one run:
# cube4_shade_unit verilated from REV's rtl/ and from this tree's
# (scripts/verilate_shade_bench.sh: four instances in one context, random
# samples and gradients, as the system verilates them), then each timed
# in turn on one pinned core, round by round, so that a drift of the
# machine's speed reaches both alike. Writes the "shade-unit-speed" section
# of docs/performance.md.
#   scripts/perf_shade_unit.sh [REV] [CYCLES] [ROUNDS]
# REV defaults to 20d16ba (before the dividers became branch-free to
# simulate), CYCLES to 100000, ROUNDS to 7.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
rev=${1:-20d16ba}
cycles=${2:-100000}
rounds=${3:-7}
command -v verilator >/dev/null || "$here/scripts/setup.sh" --packages-only >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/rev"
git -C "$here" archive "$rev" rtl | tar -x -C "$tmp/rev"
echo "perf_shade_unit: verilating $rev's and this tree's cube4_shade_unit..." >&2
"$here/scripts/verilate_shade_bench.sh" "$tmp/rev/rtl" "$tmp/old"
"$here/scripts/verilate_shade_bench.sh" "$here/rtl" "$tmp/new"
pin=()
command -v taskset >/dev/null && pin=(taskset -c "$(( $(nproc) - 1 ))")
for _ in $(seq "$rounds"); do
  "${pin[@]}" "$tmp/old/Vshade" 4 "$cycles" >> "$tmp/old.json"
  "${pin[@]}" "$tmp/new/Vshade" 4 "$cycles" >> "$tmp/new.json"
done
section=$(python3 - "$tmp" "$rev" "$cycles" "$rounds" "$(nproc)" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" \
  "$(git -C "$here" rev-parse --short HEAD)" <<'PY'
import json, statistics, sys, datetime
tmp, rev, cycles, rounds, cores, cpu, head = sys.argv[1:8]
def load(name):
    return [json.loads(line)["us_per_unit_cycle"] for line in open(f"{tmp}/{name}.json") if line.strip()]
old, new = load("old"), load("new")
if len(old) != int(rounds) or len(new) != int(rounds):
    sys.exit("perf_shade_unit: a run gave no result")
pairs = sorted(o / n for o, n in zip(old, new))
print(f"Measured {datetime.date.today()} by `scripts/perf_shade_unit.sh {rev} {cycles} {rounds}` on {cpu} ({cores} cores): "
      f"four `cube4_shade_unit`s in one context, {cycles} cycles of random samples and gradients, one pinned core, "
      f"the two builds taking turns; µs per unit and cycle, median (and smallest) of {rounds} runs.")
print()
print("| RTL | µs per unit and cycle | smallest |")
print("|---|---:|---:|")
print(f"| {rev} | {statistics.median(old):.3f} | {min(old):.3f} |")
print(f"| {head} (working tree) | {statistics.median(new):.3f} | {min(new):.3f} |")
print()
print(f"Speed-up, round by round: **{statistics.median(pairs):.2f}×** (median; {pairs[0]:.2f}× to {pairs[-1]:.2f}×).")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" shade-unit-speed
echo "perf_shade_unit: docs/performance.md updated" >&2
