#!/usr/bin/env bash
# Blocks as jobs, measured: a volume one RTL machine cannot hold (its rings
# keep 256 voxels along the permuted x and y) rendered at RTL as blocks,
# once in one process (`cube4 render --blocks`, the machines one after
# another) and once as one process per block run by GNU parallel
# (scripts/render_blocks.sh), the two base planes compared bit for bit, the
# wall times set side by side; writes the "block-jobs" section of
# docs/performance.md.
#   scripts/perf_block_jobs.sh [N] [AxBxC] [JOBS]   (default: 512 3x3x3, one job per core)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/scripts/setup.sh" >/dev/null
n=${1:-512} counts=${2:-3x3x3} jobs=${3:-$(nproc)}
cube4=$here/build/tb/cube4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/scene.json" <<JSON
{"volume": {"synthetic": "sphere", "size": [$n, $n, $n]}, "view": {"rotate": [20, 30, 0]},
 "shading": true, "output": {"width": 512, "height": 512}}
JSON
echo "perf_block_jobs: one process, $counts blocks of $n³ at RTL..." >&2
load0=$(cut -d' ' -f1 /proc/loadavg)
t0=$(date +%s.%N)
"$cube4" render "$tmp/scene.json" --model rtl --blocks "$counts" --no-check --max-memory 20000 -q \
  -o "$tmp/one.png" --baseplane "$tmp/one_bp.png" --report "$tmp/one.json"
t1=$(date +%s.%N)
echo "perf_block_jobs: $jobs jobs at a time..." >&2
"$here/scripts/render_blocks.sh" "$tmp/scene.json" "$counts" "$tmp/jobs.png" --model rtl -j "$jobs" \
  --baseplane "$tmp/jobs_bp.png" --work "$tmp/work"
t2=$(date +%s.%N)
load2=$(cut -d' ' -f1 /proc/loadavg)
cmp -s "$tmp/one_bp.png" "$tmp/jobs_bp.png" && same=yes || same=NO
section=$(python3 - "$tmp/one.json" "$t0" "$t1" "$t2" "$n" "$counts" "$jobs" "$same" "$(nproc)" "$load0" "$load2" <<'PY'
import json, sys, datetime
r = json.load(open(sys.argv[1]))
t0, t1, t2 = map(float, sys.argv[2:5])
n, counts, jobs, same, cores, load0, load2 = sys.argv[5:12]
s = r["system"]
cycles = sum(m["simulated_cycles"] for m in s["per_machine"])
print(f"Generated {datetime.date.today()} by `scripts/perf_block_jobs.sh {n} {counts} {jobs}` on {cores} cores "
      f"(1-minute load average {load0} at the start, {load2} at the end: other work on the machine slows both runs, "
      "the parallel one more when it leaves it fewer free cores).")
print()
print(f"A {n}³ sphere (shaded) at RTL, p = {s['pipelines_per_machine']}: no one machine holds it (the rings keep 256")
print(f"voxels along the permuted x and y), so it renders as {s['machines']} blocks ({counts}); {cycles:,} machine")
print(f"cycles simulated in all, plus the network's {s['network']['cycles']:,}.")
print()
print("| run | wall s | base plane |")
print("|---|---:|---|")
print(f"| one process, the machines one after another (`cube4 render --blocks {counts} --model rtl`) | {t1 - t0:.1f} | reference |")
print(f"| one process per block, {jobs} at a time (`scripts/render_blocks.sh -j {jobs}`) | {t2 - t1:.1f} | "
      f"{'identical, bit for bit' if same == 'yes' else 'DIFFERENT'} |")
print()
print(f"Speed-up {(t1 - t0) / (t2 - t1):.2f}× with {jobs} jobs; the jobs also pay a process start and a volume load each.")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" block-jobs
[ "$same" = yes ] || { echo "perf_block_jobs: the base planes differ" >&2; exit 1; }
