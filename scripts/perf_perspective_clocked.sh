#!/usr/bin/env bash
# What a clocked perspective frame costs to simulate: the perspective scenes
# at --model mixed:interp (the interpolation ring verilated, its weight
# generator too; every unit after it clocked TLM on the SystemC schedule)
# and mixed:interp,gradient (the gradient ring verilated too) and rtl (every
# unit verilated), and the same view in parallel projection at the same
# levels, with --check; the median
# of N runs' frame time and the report's simulated cycles per wall second.
# Writes the "perspective-clocked-speed" section of docs/performance.md.
#   scripts/perf_perspective_clocked.sh [runs]   (default 5; CUBE4_BUILD: the build folder)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CUBE4_BUILD:-$here/build}
[ -n "${CUBE4_BUILD:-}" ] || "$here/scripts/setup.sh" >/dev/null
cube4=$build/tb/cube4
python=${CUBE4_PYTHON:-python3}
runs=${1:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
results=$tmp/results.txt
: > "$results"
measure() {  # scene projection name model: one line of results
  local walls=() rate=
  for _ in $(seq "$runs"); do
    "$cube4" render "$1" -q --model "$4" --check --report "$tmp/r.json" -o "$tmp/o.png"
    walls+=("$("$python" -c "import json,sys; print(json.load(open(sys.argv[1]))['wall_seconds'])" "$tmp/r.json")")
  done
  "$python" - "$tmp/r.json" "$2" "$3" "$4" "${walls[@]}" >> "$results" <<'PY'
import json, statistics, sys
r = json.load(open(sys.argv[1]))
wall = statistics.median(float(w) for w in sys.argv[5:])
s = r["system"]
print(sys.argv[3], sys.argv[2], sys.argv[4], s["simulated_cycles"], f"{wall:.3f}", f"{s['simulated_cycles'] / wall:.0f}",
      r["samples"], sep="\t")
PY
}
for scene in perspective_sphere perspective_head; do
  src=$here/scenes/$scene.json
  "$python" "$here/scripts/scene_variant.py" "$src" "$tmp/$scene-parallel.json" \
    view.projection- view.fov- view.distance- view.eye-
  for model in mixed:interp mixed:interp,gradient rtl; do
    echo "perf_perspective_clocked: $scene at $model..." >&2
    measure "$src" perspective "$scene" "$model"
    measure "$tmp/$scene-parallel.json" parallel "$scene" "$model"
  done
done
section=$("$python" - "$results" "$runs" "$(nproc)" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" <<'PY'
import sys, datetime
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1])]
runs, cores, cpu = sys.argv[2:5]
print(f"Measured {datetime.date.today()} by `scripts/perf_perspective_clocked.sh {runs}` on {cpu} ({cores} cores): "
      f"`cube4 render --model M --check`, the median of {runs} runs' frame time (the report's "
      f"`wall_seconds`: the verilated models' set-up, the clocked frame and the check's "
      f"golden frame; not the volume's load) and the simulated clock cycles per wall second it gives.")
print()
print("| scene | projection | M | simulated cycles | wall (s) | cycles / s | samples |")
print("|---|---|---|---:|---:|---:|---:|")
for scene, projection, model, cycles, wall, rate, samples in rows:
    print(f"| `scenes/{scene}.json` | {projection} | {model} | {int(cycles):,} | {float(wall):.2f} | {int(rate):,} | "
          f"{int(samples):,} |")
PY
)
printf '%s\n' "$section" | "$python" "$here/scripts/update_doc_section.py" "$here/docs/performance.md" perspective-clocked-speed
echo "perf_perspective_clocked: docs/performance.md updated" >&2
