#!/usr/bin/env bash
# The concentric "wood-grain" rings on brainsmall's forehead and cheeks
# (docs/accuracy.md, "Wood-grain rings"): the default view, zoomed 2.5× on
# the face, rendered by the fixed-point and float models with no
# supersampling, z supersampling 4, x/y supersampling 3, both, and z 8 with
# x/y 3, and by
# the reference ray caster, into docs/images/woodgrain-*.png, with each
# image's error against the reference (idiff) into the "woodgrain" section
# of docs/accuracy.md.
#   scripts/woodgrain_pictures.sh
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
. "$here/scripts/idiff_figures.sh"
"$here/scripts/setup.sh" >/dev/null
cube4=$here/build/tb/cube4
out=$here/docs/images
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scene() {  # name S xy -> json path
  python3 - "$here/scenes/default.json" "$2" "$3" "$tmp/$1.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s["view"]["zoom"] = 2.5
s["output"] = {"width": 320, "height": 320}
s["supersampling"] = int(sys.argv[2])
s["xy_supersampling"] = int(sys.argv[3])
json.dump(s, open(sys.argv[4], "w"))
PY
  echo "$tmp/$1.json"
}
err() {  # "PSNR | mean | max" of $1 against $2
  local psnr mean max
  read -r psnr mean max <<<"$(idiff_figures "$1" "$2")"
  echo "$psnr | $mean | $max"
}
echo "woodgrain_pictures: reference..." >&2
"$cube4" render "$(scene plain 1 1)" -q --model reference --reference-step 0.125 -o "$out/woodgrain-reference.png"
rows=()
for cfg in "plain 1 1" "z4 4 1" "xy3 1 3" "z4-xy3 4 3" "z8-xy3 8 3"; do
  read -r name S xy <<<"$cfg"
  for model in fixed float; do
    echo "woodgrain_pictures: $model $name..." >&2
    "$cube4" render "$(scene "$name" "$S" "$xy")" -q --model $model -o "$out/woodgrain-$model-$name.png"
    rows+=("| $model | $S | $xy | ![](images/woodgrain-$model-$name.png) | $(err "$out/woodgrain-$model-$name.png" "$out/woodgrain-reference.png") |")
  done
done
{
  echo "Made $(date -u +%F) by \`scripts/woodgrain_pictures.sh\`: scenes/default.json at \`view.zoom\` 2.5,"
  echo "320×320; error of each 8-bit image against the reference's (\`idiff -a\`, RGBA)."
  echo
  echo "| model | supersampling (z) | xy_supersampling | image | PSNR (dB) | mean error | max error |"
  echo "|---|---:|---:|---|---:|---:|---:|"
  printf '%s\n' "${rows[@]}"
  echo "| reference (step 0.125) | | | ![](images/woodgrain-reference.png) | | | |"
} | python3 "$here/scripts/update_doc_section.py" "$here/docs/accuracy.md" woodgrain
echo "woodgrain_pictures: docs/images/woodgrain-*.png and docs/accuracy.md updated" >&2
