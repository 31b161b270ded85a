#!/usr/bin/env bash
# Accuracy against time: renders brainsmall and the sphere with the fixed-point
# and float models at supersampling 1, 2, 4, 8, compares each final image with
# the image-order reference using OpenImageIO's idiff, times each with
# bench_golden on one core, and writes the "accuracy-time" section of
# docs/accuracy.md.
#   scripts/accuracy.sh [frames]     (default 10)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
. "$here/scripts/idiff_figures.sh"
"$here/scripts/setup.sh" >/dev/null
frames=${1:-10}
cube4=$here/build/tb/cube4
bench=$here/build/tb/bench/bench_golden
pin=()
command -v taskset >/dev/null && pin=(taskset -c "$(( $(nproc) - 1 ))")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
step=0.125
results=$tmp/results.txt
: > "$results"
for scene in default sphere; do
  src=$here/scenes/$scene.json
  echo "accuracy: $scene reference (step $step)..." >&2
  "$cube4" render "$src" -q --model reference --reference-step $step -o "$tmp/$scene-ref.exr"
  for S in 1 2 4 8; do
    python3 -c "import json,sys; s=json.load(open(sys.argv[1])); s['supersampling']=int(sys.argv[2]); json.dump(s, open(sys.argv[3],'w'))" \
      "$src" "$S" "$tmp/$scene-$S.json"
    for model in fixed float; do
      echo "accuracy: $scene $model S=$S..." >&2
      "$cube4" render "$tmp/$scene-$S.json" -q --model $model -o "$tmp/$scene-$model-$S.exr"
      read -r psnr mean max <<<"$(idiff_figures "$tmp/$scene-$model-$S.exr" "$tmp/$scene-ref.exr")"
      ms=$("${pin[@]}" "$bench" "$tmp/$scene-$S.json" --model $model --frames "$frames" --warmup 1 |
           python3 -c "import json,sys; print('%.2f' % json.load(sys.stdin)['ms']['median'])")
      echo "$scene $model $S $ms $psnr $mean $max" >> "$results"
    done
  done
done
section=$(python3 - "$results" "$step" "$frames" <<'PY'
import sys, datetime
rows = [l.split() for l in open(sys.argv[1])]
step, frames = sys.argv[2], sys.argv[3]
print(f"Measured {datetime.date.today()} by `scripts/accuracy.sh {frames}`: final 256×256 images (premultiplied RGBA, "
      f"all four channels) compared by `idiff -a` with the image-order reference ray caster at step {step} voxel; "
      f"time per frame from `bench_golden` on one core (median of {frames}).")
print()
for scene in ("default", "sphere"):
    name = "brainsmall (scenes/default.json)" if scene == "default" else "volume-sampled sphere 64³ (scenes/sphere.json)"
    print(f"**{name}**")
    print()
    print("| model | supersampling | ms/frame | PSNR vs reference (dB) | mean error | max error |")
    print("|---|---:|---:|---:|---:|---:|")
    for r in rows:
        if r[0] != scene: continue
        print(f"| {r[1]} | {r[2]} | {r[3]} | {r[4]} | {r[5]} | {r[6]} |")
    print()
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/accuracy.md" accuracy-time
echo "accuracy: docs/accuracy.md updated" >&2
