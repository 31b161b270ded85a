#!/usr/bin/env bash
# Measures the golden renderers on one core against VolPack rendering the same
# file, same view, same image size, in the same run, and writes the
# "golden-speed" section of docs/performance.md.
#   scripts/perf_golden.sh [frames]      (default 30)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/scripts/setup.sh" >/dev/null
frames=${1:-30}
bin=$here/build/tb/bench
den=/usr/share/doc/libvolpack1-dev/examples/brainsmall.den
# One core: pin to the last CPU when taskset exists.
pin=()
command -v taskset >/dev/null && pin=(taskset -c "$(( $(nproc) - 1 ))")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "perf_golden: VolPack..." >&2
"${pin[@]}" "$bin/volpack_bench" --den "$den" --size 256 --rotate 20 60 180 --frames "$frames" > "$tmp/volpack.json"
for model in fixed float; do
  echo "perf_golden: $model..." >&2
  "${pin[@]}" "$bin/bench_golden" --model "$model" --frames "$frames" > "$tmp/$model.json"
done
echo "perf_golden: reference..." >&2
"${pin[@]}" "$bin/bench_golden" --model reference --frames 3 --warmup 1 > "$tmp/reference.json"

python3 - "$tmp" "$(uname -m)" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" \
  "$frames" <<'PY' | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" golden-speed
import json, sys, datetime
tmp, arch, cpu, frames = sys.argv[1:5]
vp = json.load(open(f"{tmp}/volpack.json"))
g = {m: json.load(open(f"{tmp}/{m}.json")) for m in ("fixed", "float", "reference")}
fx = g["fixed"]["ms"]["median"]
raw = vp["raw_ms"]["median"]
cls = vp["classified_ms"]["median"]
pre = vp["classify_ms"]["median"]
print(f"Measured {datetime.date.today()} on {cpu} ({arch}), one core, by "
      f"`scripts/perf_golden.sh {frames}`: brainsmall (128×128×84), 256×256 image, "
      f"view rotate [20, 60, 180], median of {frames} frames (reference: 3).")
print()
print("| renderer | ms/frame (median) | min | samples/frame | samples/s |")
print("|---|---:|---:|---:|---:|")
for m, label in (("fixed", "cube4 fixed-point golden (bit-exact)"), ("float", "cube4 float, same algorithm"),
                 ("reference", f"cube4 reference ray caster (step {g['reference'].get('reference_step', 0.25)})")):
    r = g[m]
    print(f"| {label} | {r['ms']['median']:.2f} | {r['ms']['min']:.2f} | {r['samples_per_frame']:,} | "
          f"{r['samples_per_second']/1e6:.1f} M |")
vox = vp["voxels_per_frame"]
print(f"| VolPack `vpRenderRawVolume` (classifies on the fly) | {raw:.2f} | {vp['raw_ms']['min']:.2f} | {vox:,} voxels | {vox/raw/1e3:.1f} M |")
print(f"| VolPack `vpClassifyVolume` (pre-processing) | {pre:.2f} | {vp['classify_ms']['min']:.2f} | | |")
print(f"| VolPack `vpRenderClassifiedVolume` | {cls:.2f} | {vp['classified_ms']['min']:.2f} | | |")
print(f"| VolPack classified path incl. pre-processing | {pre+cls:.2f} | | | |")
print()
print(f"Fixed-point golden / VolPack raw path: **{fx/raw:.2f}×** (goal: within 2×). "
      f"Against the classified path with its pre-processing counted: **{(pre+cls)/fx:.2f}×** faster "
      f"(per frame, when the classification changes every frame as ours may).")
PY
echo "perf_golden: docs/performance.md updated" >&2
