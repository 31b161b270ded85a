#!/usr/bin/env bash
# Cube-5's polygon traffic (§5-6), measured on our hybrid scenes: renders
# each at the fixed level and reads the report's polygon_traffic (golden
# polygon_traffic(): slab lines as the run-length connection sends them,
# against plain RGBA slab images), and sets beside them the paper's
# arithmetic for 256^3 at 30 Hz; writes the "polygon-traffic" section of
# docs/performance.md. Then the two connections' frame times (golden
# connection_times(): the scenes' reports, and Fig. 16/17's bars from
# tb/bench/cube5_connections) into its "cube5-connections" section.
#   scripts/polygon_traffic.sh        (CUBE4_BUILD: the build folder, default build/)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CUBE4_BUILD:-$here/build}
[ -n "${CUBE4_BUILD:-}" ] || "$here/scripts/setup.sh" >/dev/null
python=${CUBE4_PYTHON:-python3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for scene in brain_probe brain_probe_translucent sphere_box; do
  echo "polygon_traffic: $scene..." >&2
  "$build/tb/cube4" render "$here/scenes/$scene.json" --model fixed -q -o "$tmp/$scene.png" --report "$tmp/$scene.json"
done
# The system model's frames with each connection (the polygon source's
# waits; loosely timed TLM, which adds the same waits the clocked and RTL
# runs simulate).
for scene in brain_probe brain_probe_translucent sphere_box; do
  for connection in rle dual ideal; do
    echo "polygon_traffic: $scene at tlm, connection $connection..." >&2
    "$python" "$here/scripts/scene_variant.py" "$here/scenes/$scene.json" "$tmp/$scene-$connection.json" \
      "polygon_engine.connection=\"$connection\""
    "$build/tb/cube4" render "$tmp/$scene-$connection.json" --model tlm -q -o "$tmp/o.png" \
      --report "$tmp/$scene-$connection.r.json"
  done
done
# Cube-5 Fig. 16/17's volume-only rates: 256^3 and 512^3 with four
# pipelines at 133 MHz, from the cycle model (loosely timed TLM).
for n in 256 512; do
  echo "polygon_traffic: volume-only ${n}^3 at p = 4, 133 MHz..." >&2
  printf '{"volume": {"synthetic": "sphere", "size": [%d, %d, %d]}, "pipelines": 4, "clock_mhz": 133}\n' $n $n $n \
    > "$tmp/volume$n.json"
  "$build/tb/cube4" render "$tmp/volume$n.json" --model tlm -q -o "$tmp/volume$n.png" --report "$tmp/volume$n.r.json"
done
section=$("$python" - "$tmp" <<'PY'
import json, sys, datetime
tmp = sys.argv[1]
print(f"Measured {datetime.date.today()} by `scripts/polygon_traffic.sh`: each scene's first frame at p = 4, "
      "16-bit RGBA channels (8 bytes a pixel), as `cube4 render --report` gives it (`polygon_traffic`).")
print()
print("| scene | slabs | flits | run-length bytes | plain slab bytes | ratio | front/back/Z bytes | slice cycles | run-length connection cycles | slabs over their slice |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for scene in ("brain_probe", "brain_probe_translucent", "sphere_box"):
    t = json.load(open(f"{tmp}/{scene}.json"))["polygon_traffic"]
    print(f"| scenes/{scene}.json | {t['slabs']} | {t['flits']:,} | {t['rle_bytes']:,} | {t['raw_bytes']:,} | "
          f"{t['raw_bytes'] / t['rle_bytes']:.1f}x | {t['image_bytes']:,} | {t['slice_cycles']:,} | "
          f"{t['rle_cycles']:,} | {t['slabs_over_slice']} |")
print()
# Cube-5 §6's arithmetic for 256^3 at 30 Hz with 8-bit RGBA slab images.
slabs, side, fps = 256, 256, 30
raw = slabs * side * side * 4
print(f"Cube-5's figures from the same formulas: 256 slabs of 256 x 256 8-bit RGBA pixels are "
      f"{raw / 2**20:.0f} MiB a frame without encoding, {raw * fps / 2**30:.2f} GiB/s at 30 Hz, and a slab has "
      f"{1e6 / fps / slabs:.0f} µs (1/30 s over 256 slices) to arrive: the paper's 64 MB, 1.9 GB/s and 130 µs. "
      f"At the run-length buffer's 200 MHz those {1e6 / fps / slabs:.1f} µs are {200e6 / fps / slabs:,.0f} flits, "
      "not the paper's 27,300 (which 210 MHz would give): the paper's one inconsistent figure here.")
print()
print("Fig. 16/17's volume-only rates (four pipelines at 133 MHz), from our cycle model at `--model tlm` on a "
      "synthetic sphere of each size (the cycles do not depend on the content):")
print()
print("| volume | cycles, a lone frame | frames/s | cycles a frame, frames back to back | frames/s | the paper |")
print("|---|---:|---:|---:|---:|---|")
for n, paper in ((256, "30 Hz"), (512, "under 4 Hz")):
    s = json.load(open(f"{tmp}/volume{n}.r.json"))["system"]
    print(f"| {n}³ | {s['cycles_per_frame']:,} | {133e6 / s['cycles_per_frame']:.2f} | "
          f"{s['cycles_steady_state_interval']:,} | {s['fps_steady_state']:.2f} | {paper} |")
PY
)
printf '%s\n' "$section" | "$python" "$here/scripts/update_doc_section.py" "$here/docs/performance.md" polygon-traffic
"$build/tb/bench/cube5_connections" > "$tmp/bars.md"
section=$("$python" - "$tmp" <<'PY'
import json, sys, datetime
tmp = sys.argv[1]
print(f"Measured {datetime.date.today()} by `scripts/polygon_traffic.sh`, with §6's rates (fill 180 M fragments/s, "
      "6 M triangles/s, the dual-use buffer 357 M pixels/s, the run-length buffer's flit clock 200 MHz; scene keys "
      "`polygon_engine`).")
print()
print("Our hybrid scenes (their own size, p = 4, the scene's clock), frame time in ms as `cube4 render --report` "
      "gives it (`polygon_connections`):")
print()
print("| scene | volume alone | opaque polygons | run-length connection | dual-use connection | RLE slabs over their slice |")
print("|---|---:|---:|---:|---:|---:|")
for scene in ("brain_probe", "brain_probe_translucent", "sphere_box"):
    c = json.load(open(f"{tmp}/{scene}.json"))["polygon_connections"]
    print(f"| scenes/{scene}.json | {c['volume_s'] * 1e3:.3f} | {c['opaque_s'] * 1e3:.3f} | {c['rle_s'] * 1e3:.3f} | "
          f"{c['dual_s'] * 1e3:.3f} | {c['rle_slabs_over_slice']} |")
print()
print("The system model's frames (`cube4 render --model tlm`, the scene's `polygon_engine.connection` set to each; "
      "the clocked and RTL runs simulate the same waits, cycle for cycle: docs/system.md, \"Cycle accounting\"), "
      "cycles per frame and the waits for slab images in them:")
print()
print("| scene | ideal (the volume's) | run-length: cycles | waits | dual-use: cycles | waits |")
print("|---|---:|---:|---:|---:|---:|")
for scene in ("brain_probe", "brain_probe_translucent", "sphere_box"):
    r = {c: json.load(open(f"{tmp}/{scene}-{c}.r.json"))["system"] for c in ("rle", "dual", "ideal")}
    print(f"| scenes/{scene}.json | {r['ideal']['cycles_per_frame']:,} | {r['rle']['cycles_per_frame']:,} | "
          f"{r['rle']['polygon_wait_cycles']:,} | {r['dual']['cycles_per_frame']:,} | {r['dual']['polygon_wait_cycles']:,} |")
print()
print("Fig. 16 (256³) and Fig. 17 (512³), four pipelines at 133 MHz: `tb/bench/cube5_connections` (uniformly "
      "random translucent fragments, d·W·H a frame spread over the slabs, one triangle per 50):")
print()
sys.stdout.write(open(f"{tmp}/bars.md").read())
PY
)
printf '%s\n' "$section" | "$python" "$here/scripts/update_doc_section.py" "$here/docs/performance.md" cube5-connections
echo "polygon_traffic: docs/performance.md updated" >&2
