#!/usr/bin/env bash
# What polygons cost the simulation (issue: Cube-5's hybrid frame at TLM
# within 1.5x of the same frame without polygons): each hybrid scene at
# --model tlm, and at fixed for comparison, with its polygons and with
# "polygons": [], on one core; the median frame time of `cube4 render
# --repeat N` (a frame includes the host's rasterisation of the polygon
# images, its registers and the warp). The two run back to back in each of
# R paired rounds, and the ratio is taken round by round (the machine's
# speed drifts between rounds more than within one); the table gives the
# median round and the range. Written to the "polygon-speed" section of
# docs/performance.md.
#   scripts/perf_polygons.sh [repeats] [rounds]   (defaults 9 and 5; CUBE4_BUILD: the build folder)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CUBE4_BUILD:-$here/build}
[ -n "${CUBE4_BUILD:-}" ] || "$here/scripts/setup.sh" >/dev/null
cube4=$build/tb/cube4
python=${CUBE4_PYTHON:-python3}
repeats=${1:-9}
rounds=${2:-5}
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
    for ((k = 0; k < rounds; k++)); do
      echo "perf_polygons: $scene $model, round $((k + 1)) of $rounds (with and without polygons)..." >&2
      for which in with none; do
        file=$src
        [ $which = none ] && file=$tmp/$scene-none.json
        "${pin[@]}" "$cube4" render "$file" -q --model $model --threads 1 --repeat "$repeats" \
          --report "$tmp/r.json" -o "$tmp/o.png"
        ms=$("$python" -c "import json,sys; print(json.load(open(sys.argv[1]))['frame_ms']['median'])" "$tmp/r.json")
        echo "$scene $model $k $which $ms" >> "$results"
      done
    done
  done
done
section=$("$python" - "$results" "$repeats" "$rounds" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" <<'PY'
import sys, datetime, statistics
rows = [l.split() for l in open(sys.argv[1])]
repeats, rounds, cpu = sys.argv[2], int(sys.argv[3]), sys.argv[4]
t = {(r[0], r[1], int(r[2]), r[3]): float(r[4]) for r in rows}
print(f"Measured {datetime.date.today()} by `scripts/perf_polygons.sh {repeats} {rounds}` on {cpu}, one core: median frame "
      f"time of `cube4 render --repeat {repeats} --threads 1` (a frame: the host's rasterisation of the polygon "
      "images, the frame itself, the warp), and the same scene with `\"polygons\": []` run right after it, in "
      f"{rounds} paired rounds; the round with the median ratio, and the range of the rounds' ratios.")
print()
print("| scene | model | with polygons (ms) | without (ms) | ratio | rounds' range |")
print("|---|---|---:|---:|---:|---:|")
for scene in dict.fromkeys(r[0] for r in rows):
    for model in ("tlm", "fixed"):
        pairs = sorted(((t[(scene, model, k, "with")] / t[(scene, model, k, "none")], k) for k in range(rounds)))
        ratio, k = pairs[len(pairs) // 2]
        w, n = t[(scene, model, k, "with")], t[(scene, model, k, "none")]
        print(f"| `scenes/{scene}.json` | {model} | {w:.2f} | {n:.2f} | {ratio:.2f} | {pairs[0][0]:.2f}–{pairs[-1][0]:.2f} |")
PY
)
printf '%s\n' "$section" | "$python" "$here/scripts/update_doc_section.py" "$here/docs/performance.md" polygon-speed
echo "perf_polygons: docs/performance.md updated" >&2
