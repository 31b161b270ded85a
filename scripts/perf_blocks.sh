#!/usr/bin/env bash
# What sub-cubes cost and buy (issue: bela §IV's worked examples, Cube-4's
# 1024³ at 30 Hz): writes the "blocks-cost" section of docs/performance.md.
#  1. bela §IV's two worked examples recomputed from its own formulas (frame
#     rate from the time to shade a voxel with 40 ns RAM, latency adding one
#     pass of the composition tree, storage of volume, voxel images, slab
#     buffers and frame buffer), beside the paper's figures.
#  2. The same volumes with cube4 machines as the object-space processors:
#     synthetic volumes rendered by `cube4 render --model tlm --blocks`
#     (machines loosely timed by the cycle model, which the RTL tests hold
#     to the cycle; the network's cycles from its model), with wall time and
#     peak memory (GNU time) of the run.
#  3. Cube-4's 1024³ at 30 Hz: the machines, pipelines and clock that reach
#     it in our model, checked by rendering a 1024³ volume that way.
#   scripts/perf_blocks.sh [--quick]   (--quick: 256³ only)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/scripts/setup.sh" >/dev/null
quick=0
[ "${1:-}" = "--quick" ] && quick=1
cube4=$here/build/tb/cube4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rows=$tmp/rows.txt
: > "$rows"

# One run: NAME N PIPES MHZ BLOCKS -> a row of figures.
run() {
  local name=$1 n=$2 pipes=$3 mhz=$4 blocks=$5
  cat > "$tmp/$name.json" <<JSON
{"volume": {"synthetic": "sphere", "size": [$n, $n, $n]}, "view": {"rotate": [20, 30, 0]},
 "shading": true, "pipelines": $pipes, "clock_mhz": $mhz, "output": {"width": 512, "height": 512}}
JSON
  echo "perf_blocks: $name ($n³, $blocks blocks of p = $pipes at $mhz MHz)..." >&2
  /usr/bin/time -f "%e %M" -o "$tmp/$name.time" "$cube4" render "$tmp/$name.json" --model tlm --blocks "$blocks" \
    --max-memory 20000 -q -o "$tmp/$name.png" --report "$tmp/$name-report.json"
  python3 - "$tmp/$name-report.json" "$tmp/$name.time" "$name" "$n" "$blocks" "$pipes" "$mhz" >> "$rows" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
wall, rss_kib = open(sys.argv[2]).read().split()[-2:]
s = r["system"]
mhz = float(sys.argv[7])
base = r["blocks"]["per_block"]
stored = max(b["stored_object"]["size"][0] * b["stored_object"]["size"][1] * b["stored_object"]["size"][2] for b in base)
print(sys.argv[3], sys.argv[4], sys.argv[5], s["machines"], sys.argv[6], sys.argv[7],
      s["per_machine"][0]["cycles_steady_state_interval"], s["network"]["cycles_steady_state_interval"],
      s["cycles_steady_state_interval"], s["cycles_per_frame"],
      "%.1f" % s["fps_steady_state"], "%.2f" % (s["cycles_per_frame"] / mhz / 1e3),
      stored, wall, "%.2f" % (int(rss_kib) / 1048576))
PY
}

run b256 256 4 125 2x2x2
run b256_25 256 4 25 2x2x2
if [ $quick = 0 ]; then
  run b1024 1024 4 125 8x8x8
  run c1024 1024 8 125 4x4x4
fi

section=$(python3 - "$rows" <<'PY'
import math, sys, datetime
print(f"Generated {datetime.date.today()} by `scripts/perf_blocks.sh`.")
print()
print("**bela §IV from its own formulas.** A voxel is shaded in T_S = 40 ns (the RAM), each of P object-space")
print("processors shades N³/P voxels a frame, so f = P / (N³ · 40 ns); the minimum latency adds to that frame one")
print("pass of the composition tree over the M² slab-buffer pixels at 40 ns each (T_C; log2 of the tree is")
print("negligible). Storage: volume N³·(8 + 4 tag bits); voxel images d·p·n·N²·w²·64 bits and slab buffers")
print("d·p·n·M²·64 bits (16-bit RGBA, d = 2: double buffered; the paper's figures give p·n = 2 for N = 256 and 8")
print("for N = 1024); frame buffer d·M²·24 bits. MB are 2^20 bytes.")
print()
print("| example | quantity | paper | from the formulas |")
print("|---|---|---:|---:|")
t = 40e-9
for N, M, P, w, pn, paper in [(256, 512, 8, 5, 2, ("12 Hz", "95 ms", "24", "50", "8", "1.5")),
                              (1024, 1024, 512, 3, 8, ("12 Hz (same rate)", "126 ms", "1536", "1152", "128", "6"))]:
    f = P / (N ** 3 * t)
    lat = 1 / f + M * M * t
    mb = lambda bits: bits / 8 / 2 ** 20
    name = f"N = {N}, M = {M}, {P} processors"
    print(f"| {name} | frame rate | {paper[0]} | {f:.1f} Hz |")
    print(f"| | latency | {paper[1]} | {lat * 1e3:.1f} ms ({lat * f:.2f} frames) |")
    print(f"| | volume | {paper[2]} MB | {mb(N ** 3 * 12):.0f} MB |")
    print(f"| | voxel images (w = {w}) | {paper[3]} MB | {mb(2 * pn * N * N * w * w * 64):.0f} MB |")
    print(f"| | slab buffers | {paper[4]} MB | {mb(2 * pn * M * M * 64):.0f} MB |")
    print(f"| | frame buffer | {paper[5]} MB | {mb(2 * M * M * 24):.1f} MB |")
print()
print("**cube4 machines as the object-space processors** (`cube4 render --model tlm --blocks`, synthetic sphere,")
print("shaded, view rotated 20°/30°): per machine the steady-state interval of its frame (the cycle model, held to")
print("the RTL by the system tests), the composition network's interval (one base-plane pixel per clock, the")
print("tree's depth added to the latency only), the frame interval with double-buffered pixel memories (the")
print("larger of the two), the first frame's latency, and the host run's wall time and peak memory (GNU time).")
print()
print("| run | volume | blocks | machines | p | MHz | machine interval | network interval | frame interval | latency (cycles) | frames/s | latency (ms) | largest stored block (voxels) | wall s | peak GiB |")
print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for r in (l.split() for l in open(sys.argv[1])):
    name, n, blocks, machines, p, mhz, mi, ni, fi, lat, fps, ms, stored, wall, gib = r
    print(f"| {name} | {n}³ | {blocks} | {machines} | {p} | {mhz} | {int(mi):,} | {int(ni):,} | {int(fi):,} | "
          f"{int(lat):,} | {fps} | {ms} | {int(stored):,} | {wall} | {gib} |")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" blocks-cost
echo "perf_blocks: docs/performance.md updated" >&2
