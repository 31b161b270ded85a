#!/usr/bin/env bash
# What polygons cost the simulation (issue: Cube-5's hybrid frame at TLM
# within 1.5x of the same frame without polygons): each hybrid scene at
# --model tlm, and at fixed for comparison, with its polygons and with
# "polygons": [], on one core; the median frame time of `cube4 render
# --repeat N` (a frame includes the host's rasterisation of the polygon
# images, its registers and the warp). Written to the "polygon-speed"
# section of docs/performance.md.
#   scripts/perf_polygons.sh [repeats]     (default 9; CUBE4_BUILD: the build folder)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CUBE4_BUILD:-$here/build}
[ -n "${CUBE4_BUILD:-}" ] || "$here/scripts/setup.sh" >/dev/null
cube4=$build/tb/cube4
python=${CUBE4_PYTHON:-python3}
repeats=${1:-9}
pin=()
command -v taskset >/dev/null && pin=(taskset -c "$(( $(nproc) - 1 ))")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
results=$tmp/results.txt
: > "$results"
for scene in brain_probe brain_probe_translucent sphere_box; do
  src=$here/scenes/$scene.json
  # The same scene without its polygons.
  "$python" "$here/scripts/scene_variant.py" "$src" "$tmp/$scene-none.json" 'polygons=[]'
  for model in tlm fixed; do
    for which in with none; do
      file=$src
      [ $which = none ] && file=$tmp/$scene-none.json
      echo "perf_polygons: $scene $model ($which polygons)..." >&2
      "${pin[@]}" "$cube4" render "$file" -q --model $model --threads 1 --repeat "$repeats" \
        --report "$tmp/r.json" -o "$tmp/o.png"
      ms=$("$python" -c "import json,sys; print(json.load(open(sys.argv[1]))['frame_ms']['median'])" "$tmp/r.json")
      echo "$scene $model $which $ms" >> "$results"
    done
  done
done
"$python" - "$results" "$repeats" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" <<'PY' | "$python" "$here/scripts/update_doc_section.py" "$here/docs/performance.md" polygon-speed
import sys, datetime
rows = [l.split() for l in open(sys.argv[1])]
repeats, cpu = sys.argv[2], sys.argv[3]
t = {(r[0], r[1], r[2]): float(r[3]) for r in rows}
print(f"Measured {datetime.date.today()} by `scripts/perf_polygons.sh {repeats}` on {cpu}, one core: median frame "
      f"time of `cube4 render --repeat {repeats} --threads 1` (a frame: the host's rasterisation of the polygon "
      "images, the frame itself, the warp); the same scene with `\"polygons\": []` for comparison.")
print()
print("| scene | model | with polygons (ms) | without (ms) | ratio |")
print("|---|---|---:|---:|---:|")
for scene in dict.fromkeys(r[0] for r in rows):
    for model in ("tlm", "fixed"):
        w, n = t[(scene, model, "with")], t[(scene, model, "none")]
        print(f"| `scenes/{scene}.json` | {model} | {w:.1f} | {n:.1f} | {w / n:.2f} |")
PY
echo "perf_polygons: docs/performance.md updated" >&2
