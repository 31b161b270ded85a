#!/usr/bin/env bash
# What simulating only the scene's effects saves: scenes that need no
# gradients, shading or cut plane (unshaded MIP) run the system model as it
# runs them by default (no gradient unit, lean shading and compositing RTL)
# and with everything simulated anyway (--simulate-all), at RTL and with the
# TLM models clocked, one core. Writes the
# "effect-savings" section of docs/performance.md.
#   scripts/perf_effects.sh [frames]   (default 3)
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
scenes=(scenes/brain_mip.json scenes/sphere_mip.json)
i=0
for s in "${scenes[@]}"; do
  for m in rtl tlm-cycle; do
    for all in "" --simulate-all; do
      echo "perf_effects: $s $m ${all:-(skipping)}..." >&2
      "${pin[@]}" "$bench" "$here/$s" --model "$m" --frames "$frames" --warmup 1 $all > "$tmp/$i.json"
      echo "$s $m ${all:-skip}" > "$tmp/$i.name"
      i=$((i + 1))
    done
  done
done
section=$(python3 - "$tmp" "$i" <<'PY'
import json, sys, datetime
tmp, n = sys.argv[1], int(sys.argv[2])
runs = {}
for i in range(n):
    scene, model, mode = open(f"{tmp}/{i}.name").read().split()
    runs[(scene, model, mode)] = json.load(open(f"{tmp}/{i}.json"))
print(f"Measured {datetime.date.today()} by `scripts/perf_effects.sh` (one core, p = 4, median of the frames). "
      "Both columns give the same base plane (system test `MipWithUnneededGradientUnit`).")
print()
print("| scene | level | only what the scene needs: ms/frame (cycles) | everything (`--simulate-all`): ms/frame (cycles) | time saved |")
print("|---|---|---|---|---|")
for (scene, model, mode), r in sorted(runs.items()):
    if mode != "skip":
        continue
    a = runs[(scene, model, "--simulate-all")]
    s_ms, a_ms = r["ms"]["median"], a["ms"]["median"]
    print(f"| `{scene}` | {model} | {s_ms:.0f} ({r['cycles_per_frame']}) | {a_ms:.0f} ({a['cycles_per_frame']}) | "
          f"{100 * (1 - s_ms / a_ms):.0f} % |")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" effect-savings
echo "perf_effects: docs/performance.md updated" >&2
