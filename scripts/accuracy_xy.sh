#!/usr/bin/env bash
# What x/y supersampling buys: renders brainsmall and the sphere with the
# fixed-point model at xy_supersampling 1..4 (n² frames per image, VolumePro
# §4.1), compares each final image with the image-order reference using
# OpenImageIO's idiff, takes the modelled cycles per image from the system
# model's cycle model (--model tlm: n² frames of the frame's cycles) and the
# host time per image from `cube4 render --repeat`, and writes the
# "accuracy-xy" section of docs/accuracy.md.
#   scripts/accuracy_xy.sh [repeats]     (default 3)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
. "$here/scripts/idiff_figures.sh"
"$here/scripts/setup.sh" >/dev/null
repeats=${1:-3}
cube4=$here/build/tb/cube4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
step=0.125
results=$tmp/results.txt
: > "$results"
for scene in default sphere; do
  src=$here/scenes/$scene.json
  echo "accuracy_xy: $scene reference (step $step)..." >&2
  "$cube4" render "$src" -q --model reference --reference-step $step -o "$tmp/$scene-ref.exr"
  for n in 1 2 3 4; do
    python3 -c "import json,sys; s=json.load(open(sys.argv[1])); s['xy_supersampling']=int(sys.argv[2]); json.dump(s, open(sys.argv[3],'w'))" \
      "$src" "$n" "$tmp/$scene-$n.json"
    echo "accuracy_xy: $scene xy_supersampling $n..." >&2
    "$cube4" render "$tmp/$scene-$n.json" -q --model fixed --repeat "$repeats" -o "$tmp/$scene-$n.exr" \
      --report "$tmp/$scene-$n-fixed.json"
    "$cube4" render "$tmp/$scene-$n.json" -q --model tlm -o "$tmp/$scene-$n-tlm.exr" --report "$tmp/$scene-$n-tlm.json"
    read -r psnr mean max <<<"$(idiff_figures "$tmp/$scene-$n.exr" "$tmp/$scene-ref.exr")"
    python3 - "$tmp/$scene-$n-fixed.json" "$tmp/$scene-$n-tlm.json" "$scene $n $psnr $mean $max" >> "$results" <<'PY'
import json, sys
fixed, tlm = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
frames = tlm["frames_per_image"]
cycles = tlm["system"]["cycles_steady_state_interval"] * frames
print(sys.argv[3], frames, cycles, "%.1f" % tlm["system"]["image_fps_steady_state"], "%.1f" % fixed["frame_ms"]["median"])
PY
  done
done
section=$(python3 - "$results" "$step" "$repeats" <<'PY'
import sys, datetime
rows = [l.split() for l in open(sys.argv[1])]
step, repeats = sys.argv[2], sys.argv[3]
print(f"Measured {datetime.date.today()} by `scripts/accuracy_xy.sh {repeats}`: final 256×256 images of the "
      f"fixed-point model (premultiplied RGBA, all four channels) compared by `idiff -a` with the image-order "
      f"reference ray caster at step {step} voxel; cycles per image from the cycle model (`--model tlm`: the "
      f"steady-state interval of one frame times the frames per image) and images per second at the scene's "
      f"clock and pipelines; host time per image from `cube4 render --model fixed --repeat {repeats}` (median, "
      f"all cores, warp and blend included).")
print()
for scene in ("default", "sphere"):
    name = "brainsmall (scenes/default.json)" if scene == "default" else "volume-sampled sphere 64³ (scenes/sphere.json)"
    print(f"**{name}**")
    print()
    print("| xy_supersampling | frames per image | PSNR vs reference (dB) | mean error | max error | cycles per image | images/s | host ms per image |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        if r[0] != scene: continue
        print(f"| {r[1]} | {r[5]} | {r[2]} | {r[3]} | {r[4]} | {int(r[6]):,} | {r[7]} | {r[8]} |")
    print()
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/accuracy.md" accuracy-xy
