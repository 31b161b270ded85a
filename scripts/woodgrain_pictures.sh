#!/usr/bin/env bash
# The concentric "wood-grain" rings on brainsmall's forehead and cheeks
# (docs/accuracy.md, "Wood-grain rings") and the knob that removes them:
# scenes/woodgrain.json (the default view, zoomed 2.5x on the face) rendered
# by the fixed-point and float models with the 12-neighbourhood z gradient
# (no supersampling, z supersampling 4 and 8, x/y supersampling 3) and with
# VolumePro's voxel-difference z gradient (S = 1, 2, 4, and 4 with x/y 2),
# and by the reference ray caster, into docs/images/woodgrain-*.png, with
# each image's error against the reference (idiff) into the "woodgrain"
# section of docs/accuracy.md; then the price of each choice in cycles,
# from `cube4 explore scenes/explore/woodgrain.json` at TLM, into the
# "woodgrain-price" section.
#   scripts/woodgrain_pictures.sh        (CUBE4_BUILD: the build folder, default build/)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
. "$here/scripts/idiff_figures.sh"
build=${CUBE4_BUILD:-$here/build}
[ -n "${CUBE4_BUILD:-}" ] || "$here/scripts/setup.sh" >/dev/null
cube4=$build/tb/cube4
python=${CUBE4_PYTHON:-python3}
out=$here/docs/images
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scene() {  # name S xy z_gradient -> json path
  "$python" - "$here/scenes/woodgrain.json" "$2" "$3" "$4" "$tmp/$1.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s["supersampling"] = int(sys.argv[2])
s["xy_supersampling"] = int(sys.argv[3])
s["z_gradient"] = sys.argv[4]
json.dump(s, open(sys.argv[5], "w"))
PY
  echo "$tmp/$1.json"
}
err() {  # "PSNR | mean | max" of $1 against $2
  local psnr mean max
  read -r psnr mean max <<<"$(idiff_figures "$1" "$2")"
  echo "$psnr | $mean | $max"
}
echo "woodgrain_pictures: reference..." >&2
"$cube4" render "$here/scenes/woodgrain.json" -q --model reference --reference-step 0.125 -o "$out/woodgrain-reference.png"
rows=()
for cfg in "plain 1 1 abc" "z4 4 1 abc" "z8 8 1 abc" "xy3 1 3 abc" "z4-xy3 4 3 abc" \
           "vd 1 1 voxel_differences" "vd-z2 2 1 voxel_differences" "vd-z4 4 1 voxel_differences" \
           "vd-z4-xy2 4 2 voxel_differences"; do
  read -r name S xy zg <<<"$cfg"
  for model in fixed float; do
    echo "woodgrain_pictures: $model $name..." >&2
    "$cube4" render "$(scene "$name" "$S" "$xy" "$zg")" -q --model $model -o "$out/woodgrain-$model-$name.png"
    rows+=("| $model | $zg | $S | $xy | ![](images/woodgrain-$model-$name.png) | $(err "$out/woodgrain-$model-$name.png" "$out/woodgrain-reference.png") |")
  done
done
# The forehead, enlarged 2x: 12-neighbourhood at S = 4, voxel differences
# at S = 4, reference.
for f in fixed-z4 fixed-vd-z4 reference; do
  oiiotool "$out/woodgrain-$f.png" --cut 150x100+80+40 --resize 300x200 -o "$tmp/forehead-$f.png"
done
oiiotool "$tmp/forehead-fixed-z4.png" "$tmp/forehead-fixed-vd-z4.png" "$tmp/forehead-reference.png" --mosaic 3x1 \
  -o "$out/woodgrain-forehead.png"
{
  echo "Made $(date -u +%F) by \`scripts/woodgrain_pictures.sh\`: scenes/woodgrain.json (scenes/default.json at"
  echo "\`view.zoom\` 2.5, 320×320); error of each 8-bit image against the reference's (\`idiff -a\`, RGBA)."
  echo
  echo "| model | z_gradient | supersampling (z) | xy_supersampling | image | PSNR (dB) | mean error | max error |"
  echo "|---|---|---:|---:|---|---:|---:|---:|"
  printf '%s\n' "${rows[@]}"
  echo "| reference (step 0.125) | | | | ![](images/woodgrain-reference.png) | | | |"
} | "$python" "$here/scripts/update_doc_section.py" "$here/docs/accuracy.md" woodgrain

echo "woodgrain_pictures: the price in cycles (cube4 explore, TLM)..." >&2
"$cube4" explore "$here/scenes/explore/woodgrain.json" --out "$tmp/explore" -j 1 --no-plots
section=$("$python" - "$tmp/explore/results.csv" <<'PY'
import csv, sys, datetime
rows = list(csv.DictReader(open(sys.argv[1])))
print(f"Measured {datetime.date.today()} by `scripts/woodgrain_pictures.sh` (`cube4 explore scenes/explore/woodgrain.json`, "
      "fixed point through the loosely timed system model, p = 4 at 125 MHz): PSNR of the final image against the "
      "reference over RGB, on the whole image and on the forehead (ROI [90, 50, 150, 90] in output pixels).")
print()
print("| z_gradient | S | x/y | PSNR (dB) | forehead PSNR (dB) | cycles/image | images/s |")
print("|---|---:|---:|---:|---:|---:|---:|")
for r in rows:
    print(f"| {r['z_gradient']} | {r['supersampling']} | {r['xy_supersampling'] or 1} | {float(r['psnr_db']):.2f} | "
          f"{float(r['roi_psnr_db']):.2f} | {int(float(r['cycles_per_image'])):,} | {float(r['fps']):.1f} |")
PY
)
printf '%s\n' "$section" | "$python" "$here/scripts/update_doc_section.py" "$here/docs/accuracy.md" woodgrain-price
echo "woodgrain_pictures: docs/images/woodgrain-*.png and docs/accuracy.md updated" >&2
