#!/usr/bin/env bash
# The loosely timed TLM level against the golden renderer on large volumes
# (the goal: within 1.2x in time and in memory at every size): whole
# `cube4 render` processes on a synthetic sphere, --model fixed and
# --model tlm, one thread each, wall time and peak resident memory from
# /usr/bin/time. The TLM run programs the frame through the host interface,
# the volume mapped into voxel memory in place (HostInterface::map_volume,
# the bus time of its bursts annotated), and renders from there.
# Written to the "tlm-large" section of docs/performance.md.
#   scripts/perf_tlm_large.sh [size ...]     (default: 512 1024; CUBE4_BUILD: the build folder)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CUBE4_BUILD:-$here/build}
[ -n "${CUBE4_BUILD:-}" ] || "$here/scripts/setup.sh" >/dev/null
cube4=$build/tb/cube4
python=${CUBE4_PYTHON:-python3}
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(512 1024)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
results=$tmp/results.txt
: > "$results"
for n in "${sizes[@]}"; do
  printf '{"volume": {"synthetic": "sphere", "size": [%d, %d, %d]}, "output": {"width": 256, "height": 256}}\n' \
    "$n" "$n" "$n" > "$tmp/v$n.json"
  for model in fixed tlm; do
    echo "perf_tlm_large: ${n}^3 $model..." >&2
    /usr/bin/time -f "%e %M" -o "$tmp/time.txt" "$cube4" render "$tmp/v$n.json" --model $model -q --threads 1 \
      --max-memory 64000 -o "$tmp/o.png"
    echo "$n $model $(cat "$tmp/time.txt")" >> "$results"
  done
done
section=$("$python" - "$results" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" "$(nproc)" <<'PY'
import sys, datetime
rows = [l.split() for l in open(sys.argv[1])]
t = {(r[0], r[1]): (float(r[2]), float(r[3]) / 1024) for r in rows}
print(f"Measured {datetime.date.today()} by `scripts/perf_tlm_large.sh` on {sys.argv[2]} ({sys.argv[3]} cores): "
      "whole `cube4 render` processes, one thread, a synthetic sphere, 256×256 image; wall time and peak resident "
      "memory (`/usr/bin/time`).")
print()
print("| volume | fixed: s | fixed: MiB | tlm: s | tlm: MiB | tlm / fixed: time | memory |")
print("|---|---:|---:|---:|---:|---:|---:|")
for n in dict.fromkeys(r[0] for r in rows):
    (fs, fm), (ts, tm) = t[(n, "fixed")], t[(n, "tlm")]
    print(f"| {n}³ | {fs:.2f} | {fm:,.0f} | {ts:.2f} | {tm:,.0f} | {ts / fs:.2f} | {tm / fm:.2f} |")
PY
)
printf '%s\n' "$section" | "$python" "$here/scripts/update_doc_section.py" "$here/docs/performance.md" tlm-large
echo "perf_tlm_large: docs/performance.md updated" >&2
