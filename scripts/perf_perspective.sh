#!/usr/bin/env bash
# What perspective costs the golden renderer, and what its threads buy:
# the perspective scenes (scenes/perspective_*.json) at --model fixed on
# one thread and on all cores, and the same view in parallel projection
# (the scene without "projection", "fov", "distance" and "eye") on one
# thread; the median frame time of `cube4 render --repeat N`. Writes the
# "perspective-speed" section of docs/performance.md.
#   scripts/perf_perspective.sh [repeats]     (default 11; CUBE4_BUILD: the build folder)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CUBE4_BUILD:-$here/build}
[ -n "${CUBE4_BUILD:-}" ] || "$here/scripts/setup.sh" >/dev/null
cube4=$build/tb/cube4
python=${CUBE4_PYTHON:-python3}
repeats=${1:-11}
cores=$(nproc)
pin=()
command -v taskset >/dev/null && pin=(taskset -c "$(( cores - 1 ))")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
results=$tmp/results.txt
: > "$results"
time_of() {  # scene threads [pinned]: the median frame time in ms
  local run=("$cube4" render "$1" -q --model fixed --threads "$2" --repeat "$repeats" --report "$tmp/r.json" -o "$tmp/o.png")
  if [ "${3:-}" = pinned ]; then "${pin[@]}" "${run[@]}"; else "${run[@]}"; fi
  "$python" -c "import json,sys; print(json.load(open(sys.argv[1]))['frame_ms']['median'])" "$tmp/r.json"
}
for scene in perspective_sphere perspective_head perspective_flyin perspective_sphere_box perspective_brain_probe; do
  src=$here/scenes/$scene.json
  "$python" "$here/scripts/scene_variant.py" "$src" "$tmp/$scene-parallel.json" \
    view.projection- view.fov- view.distance- view.eye-
  echo "perf_perspective: $scene..." >&2
  one=$(time_of "$src" 1 pinned)
  all=$(time_of "$src" 0)
  par=$(time_of "$tmp/$scene-parallel.json" 1 pinned)
  echo "$scene $one $all $par" >> "$results"
done
section=$("$python" - "$results" "$repeats" "$cores" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" <<'PY'
import sys, datetime
rows = [l.split() for l in open(sys.argv[1])]
repeats, cores, cpu = sys.argv[2:5]
print(f"Measured {datetime.date.today()} by `scripts/perf_perspective.sh {repeats}` on {cpu}: median frame time "
      f"of `cube4 render --model fixed --repeat {repeats}` (a frame includes the host's work and the warp), one "
      f"thread pinned to one core, and all {cores} cores; the same view in parallel projection on one thread.")
print()
print(f"| scene | perspective, 1 thread (ms) | perspective, {cores} threads (ms) | speed-up | parallel projection, 1 thread (ms) | perspective / parallel |")
print("|---|---:|---:|---:|---:|---:|")
for name, one, many, par in rows:
    one, many, par = float(one), float(many), float(par)
    print(f"| `scenes/{name}.json` | {one:.1f} | {many:.1f} | {one / many:.2f} | {par:.1f} | {one / par:.2f} |")
PY
)
printf '%s\n' "$section" | "$python" "$here/scripts/update_doc_section.py" "$here/docs/performance.md" perspective-speed
echo "perf_perspective: docs/performance.md updated" >&2
