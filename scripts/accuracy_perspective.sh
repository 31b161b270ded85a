#!/usr/bin/env bash
# Perspective accuracy: renders the sphere and brainsmall in perspective at
# several fields of view (and in parallel projection, for comparison) with
# the fixed-point and float models and the pinhole reference ray caster,
# compares the final images with OpenImageIO's idiff, and writes the
# "perspective" section of docs/accuracy.md and the pictures
# docs/images/perspective-*.png (fixed-point renders).
#   scripts/accuracy_perspective.sh        (CUBE4_BUILD: the build folder, default build/)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
. "$here/scripts/idiff_figures.sh"
build=${CUBE4_BUILD:-$here/build}
[ -n "${CUBE4_BUILD:-}" ] || "$here/scripts/setup.sh" >/dev/null
cube4=$build/tb/cube4
python=${CUBE4_PYTHON:-python3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
step=0.125
results=$tmp/results.txt
: > "$results"
# scene  base  view (JSON)
cases=(
  "sphere perspective_sphere parallel"
  "sphere perspective_sphere 20"
  "sphere perspective_sphere 40"
  "sphere perspective_sphere 60"
  "sphere perspective_sphere 80"
  "sphere perspective_sphere 40-s2"
  "sphere perspective_sphere 40-s2-vd"
  "head perspective_head parallel"
  "head perspective_head 20"
  "head perspective_head 40"
  "head perspective_head 60"
  "head perspective_head 40-s2"
  "head perspective_head 40-s2-vd"
  "head perspective_flyin flyin"
  "head perspective_flyin flyin-xy2"
)
for c in "${cases[@]}"; do
  read -r name base fov <<<"$c"
  scene=$tmp/$name-$fov.json
  "$python" - "$here/scenes/$base.json" "$fov" "$scene" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
fov = sys.argv[2]
if fov == "parallel":
    s["view"] = {k: v for k, v in s["view"].items() if k not in ("projection", "fov", "distance", "eye")}
elif fov == "flyin-xy2":
    s["xy_supersampling"] = 2
elif fov != "flyin":
    # "40-s2-vd": 40°, supersampling 2, VolumePro's voxel-difference z gradient.
    angle, *knobs = fov.split("-")
    s["view"]["fov"] = float(angle)
    s["view"].pop("distance", None)
    if "s2" in knobs:
        s["supersampling"] = 2
    if "vd" in knobs:
        s["z_gradient"] = "voxel_differences"
json.dump(s, open(sys.argv[3], "w"))
PY
  echo "accuracy_perspective: $name $fov..." >&2
  "$cube4" render "$scene" -q --model reference --reference-step $step -o "$tmp/$name-$fov-ref.exr"
  "$cube4" render "$scene" -q --model float -o "$tmp/$name-$fov-float.exr"
  "$cube4" render "$scene" -q --model fixed -o "$tmp/$name-$fov-fixed.exr" --report "$tmp/$name-$fov.report.json"
  spacing=$("$python" -c "import json,sys; v=json.load(open(sys.argv[1]))['view']; print('%.3f' % v['last_slice_ray_spacing'] if 'last_slice_ray_spacing' in v else '1')" "$tmp/$name-$fov.report.json")
  read -r p1 m1 x1 <<<"$(idiff_figures "$tmp/$name-$fov-fixed.exr" "$tmp/$name-$fov-ref.exr")"
  read -r p2 m2 x2 <<<"$(idiff_figures "$tmp/$name-$fov-float.exr" "$tmp/$name-$fov-ref.exr")"
  read -r p3 m3 x3 <<<"$(idiff_figures "$tmp/$name-$fov-fixed.exr" "$tmp/$name-$fov-float.exr")"
  echo "$name $fov $spacing $p1 $m1 $x1 $p2 $m2 $x2 $p3 $m3 $x3" >> "$results"
done
mkdir -p "$here/docs/images"
for v in sphere-40 head-40 head-flyin; do
  oiiotool "$tmp/$v-fixed.exr" --ch R,G,B -d uint8 -o "$here/docs/images/perspective-$v.png"
done
section=$("$python" - "$results" "$step" <<'PY'
import sys, datetime
rows = [l.split() for l in open(sys.argv[1])]
print(f"Measured {datetime.date.today()} by `scripts/accuracy_perspective.sh`: final 256×256 images (premultiplied "
      f"RGBA, all four channels) compared by `idiff -a`; the reference is the pinhole ray caster at step "
      f"{sys.argv[2]} voxel. The field of view is the full vertical angle; the eye is at the default distance "
      f"(the bounding sphere fits the view, or the box filter's limit if that is nearer), except the fly-in "
      f"(scenes/perspective_flyin.json: 60°, 150 units from the head's centre). Ray spacing: the box filter's "
      f"width on the last slice, voxels.")
print()
for name, title in (("sphere", "volume-sampled sphere 64³ (scenes/perspective_sphere.json)"),
                    ("head", "brainsmall (scenes/perspective_head.json)")):
    print(f"**{title}**")
    print()
    print("| view | ray spacing | fixed vs reference: PSNR (dB) / mean / max | float vs reference | fixed vs float |")
    print("|---|---:|---|---|---|")
    for r in rows:
        if r[0] != name: continue
        angle, *knobs = r[1].split("-")
        extra = "".join({"s2": ", S = 2", "vd": ", voxel-difference z gradient"}[k] for k in knobs) \
            if not r[1].startswith("flyin") else ""
        view = {"parallel": "parallel", "flyin": "fly-in, 60°",
                "flyin-xy2": "fly-in, 60°, xy_supersampling 2"}.get(r[1], f"perspective, {angle}°{extra}")
        print(f"| {view} | {r[2]} | {r[3]} / {r[4]} / {r[5]} | {r[6]} / {r[7]} / {r[8]} | {r[9]} / {r[10]} / {r[11]} |")
    print()
PY
)
printf '%s\n' "$section" | "$python" "$here/scripts/update_doc_section.py" "$here/docs/accuracy.md" perspective
echo "accuracy_perspective: docs/accuracy.md and docs/images/perspective-*.png updated" >&2
