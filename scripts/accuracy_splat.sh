#!/usr/bin/env bash
# bela's projection beside the ray caster: renders brainsmall and the sphere
# with the splat model (at its default kernel and at two others), the
# fixed-point and the float shear-warp models, compares each final image with
# the image-order reference using OpenImageIO's idiff, times every model with
# `cube4 render --repeat` on one core, once at the scenes' own views and once
# at bela's magnification 1 (one voxel spacing per pixel, where its 3×3
# footprint applies), writes docs/images/splat-*.png and the "accuracy-splat"
# section of docs/accuracy.md.
#   scripts/accuracy_splat.sh [repeats [build-dir]]   (default 3, build: set up by scripts/setup.sh)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
. "$here/scripts/idiff_figures.sh"
repeats=${1:-3}
if [ $# -ge 2 ]; then
  build=$(cd "$2" && pwd)
  cmake --build "$build" --target cube4 >/dev/null
else
  build=$here/build
  "$here/scripts/setup.sh" >/dev/null
fi
cube4=$build/tb/cube4
pin=()
command -v taskset >/dev/null && pin=(taskset -c "$(( $(nproc) - 1 ))")
images=$here/docs/images
mkdir -p "$images"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
step=0.125
results=$tmp/results.txt
: > "$results"
# median ms per frame from a report
ms() { python3 -c "import json,sys; print('%.1f' % json.load(open(sys.argv[1]))['frame_ms']['median'])" "$1"; }
for scene in default sphere; do
  for view in own unit; do
    json=$tmp/$scene-$view.json
    "$cube4" info "$here/scenes/$scene.json" > "$tmp/info.json"
    # unit: the zoom at which a pixel is one voxel spacing (golden/view.cpp:
    # pixel size = the volume's diagonal / the smaller image side / zoom).
    python3 - "$here/scenes/$scene.json" "$tmp/info.json" "$view" "$json" "$scene" >> "$results" <<'PY'
import json, math, sys
s, info = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
vol = info["volume"]
diagonal = math.sqrt(sum((n * d) ** 2 for n, d in zip(vol["dim"], vol["spacing"])))
side = min(info["view"]["image"])
if sys.argv[3] == "unit":
    s.setdefault("view", {})["zoom"] = diagonal / side / min(vol["spacing"])
zoom = s.get("view", {}).get("zoom", 1)
json.dump(s, open(sys.argv[4], "w"))
print(sys.argv[5], sys.argv[3], "scale", "%.2f" % (min(vol["spacing"]) * side * zoom / diagonal))
PY
    echo "accuracy_splat: $scene ($view view) reference, step $step..." >&2
    ref=$tmp/$scene-$view-ref.exr
    "${pin[@]}" "$cube4" render "$json" -q --model reference --reference-step $step -o "$ref" --report "$tmp/ref.json"
    echo "$scene $view reference - - $(ms "$tmp/ref.json") - - -" >> "$results"
    run() {  # label kernel-args... ; renders, times, compares
      local label=$1 model=$2 out=$tmp/$scene-$view-$1.exr
      shift 2
      echo "accuracy_splat: $scene ($view view) $label..." >&2
      "${pin[@]}" "$cube4" render "$json" -q --model "$model" --threads 1 --repeat "$repeats" -o "$out" \
        --report "$tmp/run.json" "$@"
      local kernel extent
      read -r kernel extent <<<"$(python3 -c "
import json, sys
r = json.load(open(sys.argv[1])).get('splat')
print('%g/%g %d' % (r['sigma'], r['distribution_width'], r['extent']) if r else '- -')" "$tmp/run.json")"
      echo "$scene $view $label $kernel $extent $(ms "$tmp/run.json") $(idiff_figures "$out" "$ref")" >> "$results"
    }
    run fixed fixed
    run float float
    run splat splat
    run splat-narrow splat --splat-kernel 0.4 1.0
    run splat-wide splat --splat-kernel 0.7 2.0
    if [ "$view" = own ]; then
      for m in ref float splat splat-narrow splat-wide; do
        oiiotool "$tmp/$scene-$view-$m.exr" --ch R,G,B -d uint8 -o "$images/splat-$scene-$m.png"
      done
    fi
  done
done
section=$(python3 - "$results" "$step" "$repeats" <<'PY'
import sys, datetime
rows = [l.split() for l in open(sys.argv[1])]
step, repeats = sys.argv[2], sys.argv[3]
print(f"Measured {datetime.date.today()} by `scripts/accuracy_splat.sh {repeats}`: final 256×256 images "
      f"(premultiplied RGBA, all four channels) compared by `idiff -a` with the image-order reference ray caster "
      f"at step {step} voxel; time per frame from `cube4 render --repeat {repeats} --threads 1` pinned to one core "
      f"(median; the shear-warp models' warp included, the volume's loading not). Kernel: the splat model's "
      f"Gaussian σ / distribution width in voxel spacings; extent: its footprint's pixels per side.")
print()
labels = {"fixed": "fixed (shear-warp, bit-exact)", "float": "float (shear-warp)", "splat": "splat (default kernel)",
          "splat-narrow": "splat, narrower kernel", "splat-wide": "splat, wider kernel",
          "reference": "reference (step %s)" % step}
names = {"default": "brainsmall (scenes/default.json)", "sphere": "volume-sampled sphere 64³ (scenes/sphere.json)"}
cell = lambda x: "" if x == "-" else x
for scene in ("default", "sphere"):
    for view in ("own", "unit"):
        scale = next(r[3] for r in rows if r[:3] == [scene, view, "scale"])
        what = "the scene's view" if view == "own" else "zoomed out to bela's magnification 1"
        print(f"**{names[scene]}, {what}: {scale} pixels per voxel spacing**")
        print()
        print("| model | kernel | extent | ms/frame | PSNR vs reference (dB) | mean error | max error |")
        print("|---|---|---:|---:|---:|---:|---:|")
        for r in rows:
            if r[0] != scene or r[1] != view or r[2] == "scale": continue
            print(f"| {labels[r[2]]} | " + " | ".join(cell(x) for x in r[3:9]) + " |")
        print()
print("| | reference | float (shear-warp) | splat σ 0.5 / 1.25 | splat σ 0.4 / 1.0 | splat σ 0.7 / 2.0 |")
print("|---|---|---|---|---|---|")
for scene in ("default", "sphere"):
    cells = " | ".join(f"![](images/splat-{scene}-{m}.png)" for m in ("ref", "float", "splat", "splat-narrow", "splat-wide"))
    print(f"| {'brainsmall' if scene == 'default' else 'sphere'} | {cells} |")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/accuracy.md" accuracy-splat
echo "accuracy_splat: docs/images/splat-*.png and docs/accuracy.md updated" >&2
