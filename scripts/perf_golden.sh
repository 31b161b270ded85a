#!/usr/bin/env bash
# Measures the golden renderers against VolPack and VTK's
# vtkFixedPointVolumeRayCastMapper (tb/bench/vtk_bench.cpp, under xvfb-run;
# left out when VTK or Xvfb is missing) rendering the same file, same view,
# same image size, in the same run, and writes the "golden-speed" section of
# docs/performance.md. The fixed-point renderer runs on one thread
# (pinned to one core, like VolPack, which has no threads) and on all cores.
# Volumes: brainsmall (128x128x84), and brainsmall at twice the resolution
# in every axis (256x256x168, nearest-neighbour, written as a .den here so
# that VolPack reads the same voxels).
# The machine may be shared: each renderer runs in ROUNDS rounds of FRAMES
# frames, the renderers taking turns round by round, so that a drift of the
# machine's speed reaches all of them alike; a row gives the median of the
# rounds' medians and the smallest frame time.
#   scripts/perf_golden.sh [frames] [rounds]     (default 10 frames, 5 rounds)
# CUBE4_BUILD: a build directory already configured (skips the set-up).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ -z "${CUBE4_BUILD:-}" ]; then "$here/scripts/setup.sh" >/dev/null; fi
build=${CUBE4_BUILD:-$here/build}
frames=${1:-10}
rounds=${2:-5}
bin=$build/tb/bench
den=/usr/share/doc/libvolpack1-dev/examples/brainsmall.den
# One core: pin to the last CPU when taskset exists.
pin=()
command -v taskset >/dev/null && pin=(taskset -c "$(( $(nproc) - 1 ))")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

python3 - "$den" "$tmp/brain2x.den" <<'PY'
import struct, sys
src, dst = sys.argv[1:3]
b = open(src, "rb").read()
nx, ny, nz = struct.unpack_from("<3h", b, 50)  # the map block's lengths (after orig and extr)
data = b[62:62 + nx * ny * nz]
out = bytearray()
for z in range(nz):
    plane = bytearray()
    for y in range(ny):
        row = data[(z * ny + y) * nx:(z * ny + y + 1) * nx]
        wide = bytes(v for v in row for _ in (0, 1))
        plane += wide + wide
    out += plane + plane
h = struct.pack("<h", 1)
for _ in range(3):
    h += struct.pack("<9h", 0, 0, 0, 2 * nx - 1, 2 * ny - 1, 2 * nz - 1, 2 * nx, 2 * ny, 2 * nz)
h += struct.pack("<h", 0) + struct.pack("<I", 8 * nx * ny * nz)
open(dst, "wb").write(h + bytes(out))
PY
# The default scene's rendering of another .den file.
python3 - "$here/scenes/default.json" "$tmp/brain2x.den" "$tmp/brain2x.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s["volume"] = {"file": sys.argv[2]}
json.dump(s, open(sys.argv[3], "w"))
PY

# VTK and Xvfb are the benchmark's own needs, not the project's: installed
# here (about 150 packages), then vtk_bench is configured and built.
"$here/scripts/install_packages.sh" perf_golden libvtk9-dev xvfb xauth ||
  echo "perf_golden: could not install VTK and Xvfb; VTK left out" >&2
if [ ! -x "$bin/vtk_bench" ] && dpkg-query -W libvtk9-dev >/dev/null 2>&1; then
  cmake "$build" >/dev/null && cmake --build "$build" --target vtk_bench >/dev/null || true
fi
vtk=()
if [ -x "$bin/vtk_bench" ] && command -v xvfb-run >/dev/null; then vtk=(xvfb-run -a "${pin[@]}" "$bin/vtk_bench"); fi
for round in $(seq "$rounds"); do
  for vol in brainsmall brain2x; do
    if [ "$vol" = brainsmall ]; then d=$den; scene=(); else d=$tmp/brain2x.den; scene=("$tmp/brain2x.json"); fi
    echo "perf_golden: round $round: $vol: VolPack, VTK, fixed on 1 thread (block ranges per frame, per volume), on all..." >&2
    "${pin[@]}" "$bin/volpack_bench" --den "$d" --size 256 --rotate 20 60 180 --frames "$frames" >> "$tmp/$vol.volpack.json"
    if [ ${#vtk[@]} -gt 0 ]; then
      "${vtk[@]}" --volume "$d" --size 256 --rotate 20 60 180 --threads 1 --frames "$frames" >> "$tmp/$vol.vtk.json"
    fi
    "${pin[@]}" "$bin/bench_golden" "${scene[@]}" --model fixed --threads 1 --frames "$frames" >> "$tmp/$vol.fixed1.json"
    "${pin[@]}" "$bin/bench_golden" "${scene[@]}" --model fixed --threads 1 --ranges volume --frames "$frames" \
      >> "$tmp/$vol.fixed1v.json"
    "$bin/bench_golden" "${scene[@]}" --model fixed --threads 0 --frames "$frames" >> "$tmp/$vol.fixedN.json"
  done
done
echo "perf_golden: float..." >&2
"${pin[@]}" "$bin/bench_golden" --model float --frames "$frames" > "$tmp/float.json"
echo "perf_golden: reference..." >&2
"${pin[@]}" "$bin/bench_golden" --model reference --frames 3 --warmup 1 > "$tmp/reference.json"

# The section is made whole before the document is touched: a failure
# leaves docs/performance.md as it was.
section=$(python3 - "$tmp" "$(uname -m)" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" \
  "$frames" "$(nproc)" "$rounds" <<'PY'
import json, statistics, sys, datetime
tmp, arch, cpu, frames, cores, rounds = sys.argv[1:7]
def load(name):
    text, runs, at = open(f"{tmp}/{name}.json").read(), [], 0
    while text[at:].strip():  # one JSON object per round, one after the other
        obj, at = json.JSONDecoder().raw_decode(text, len(text) - len(text[at:].lstrip()))
        runs.append(obj)
    r = dict(runs[0])
    for key in [k for k in r if k.endswith("ms") and isinstance(r[k], dict)]:  # not volume_load_ms
        r[key] = {"median": statistics.median(x[key]["median"] for x in runs), "min": min(x[key]["min"] for x in runs)}
    if "samples_per_frame" in r:
        r["samples_per_second"] = r["samples_per_frame"] / (r["ms"]["median"] * 1e-3)
    return r
print(f"Measured {datetime.date.today()} on {cpu} ({arch}, {cores} cores) by `scripts/perf_golden.sh {frames} {rounds}`: "
      f"256×256 image, view rotate [20, 60, 180], median of {rounds} rounds' medians of {frames} frames, the "
      f"renderers taking turns round by round (float: one round; reference: 3 frames); one thread pinned to one "
      f"core unless the row says otherwise. The fixed-point renderer builds its block ranges for empty-space "
      f"skipping inside every frame, except in the row that says it builds them once per volume (outside the "
      f"timing, as VolPack's normals and VTK's gradients and min-max blocks are built: neither rebuilds them "
      f"for a frame of an unchanged volume).")
print()
print("| volume | renderer | threads | ms/frame (median) | min | samples/frame | samples/s |")
print("|---|---|---:|---:|---:|---:|---:|")
ratios = []
for vol, label in (("brainsmall", "brainsmall 128×128×84"), ("brain2x", "brainsmall ×2, 256×256×168")):
    vp = load(f"{vol}.volpack")
    f1, fn, f1v = load(f"{vol}.fixed1"), load(f"{vol}.fixedN"), load(f"{vol}.fixed1v")
    for r, name in ((f1, "cube4 fixed-point golden (bit-exact)"),
                    (f1v, "cube4 fixed-point golden (bit-exact), block ranges once per volume"),
                    (fn, "cube4 fixed-point golden (bit-exact)")):
        shaded = f" ({r['shaded_per_frame']/1e6:.2f} M shaded)" if "shaded_per_frame" in r else ""
        print(f"| {label} | {name} | {r['threads']} | {r['ms']['median']:.2f} | {r['ms']['min']:.2f} | "
              f"{r['samples_per_frame']:,}{shaded} | {r['samples_per_second']/1e6:.1f} M |")
    raw, cls, pre = vp["raw_ms"]["median"], vp["classified_ms"]["median"], vp["classify_ms"]["median"]
    vox = vp["voxels_per_frame"]
    print(f"| {label} | VolPack `vpRenderRawVolume` (classifies on the fly) | 1 | {raw:.2f} | "
          f"{vp['raw_ms']['min']:.2f} | {vox:,} voxels | {vox/raw/1e3:.1f} M |")
    print(f"| {label} | VolPack `vpClassifyVolume` (pre-processing) | 1 | {pre:.2f} | {vp['classify_ms']['min']:.2f} | | |")
    print(f"| {label} | VolPack `vpRenderClassifiedVolume` | 1 | {cls:.2f} | {vp['classified_ms']['min']:.2f} | | |")
    vtk = None
    try:
        vtk = load(f"{vol}.vtk")
        vt = vtk["ms"]["median"]
        print(f"| {label} | VTK 9.1 `vtkFixedPointVolumeRayCastMapper` | 1 | {vt:.2f} | {vtk['ms']['min']:.2f} | "
              f"{vtk['voxels_per_frame']:,} voxels | {vtk['voxels_per_frame']/vt/1e3:.1f} M |")
    except FileNotFoundError:
        pass
    one_v = f1v["ms"]["median"]
    # The smallest frames too: on a shared machine one renderer's rounds
    # can meet a busier spell than another's, and the medians then move
    # apart by more than the renderers differ (2026-12-08: VolPack's round
    # medians at nearly twice its smallest frame); the smallest frame of
    # each is the least disturbed.
    least = (f1["ms"]["min"] / vp["raw_ms"]["min"], f1["ms"]["min"] / vtk["ms"]["min"] if vtk else None)
    ratios.append((label, f1["ms"]["median"] / raw, fn["ms"]["median"] / raw, fn["threads"], (pre + cls) / f1["ms"]["median"],
                   f1["ms"]["median"] / vtk["ms"]["median"] if vtk else None,
                   one_v / raw, one_v / vtk["ms"]["median"] if vtk else None, least))
for m, label in (("float", "cube4 float, same algorithm"),
                 ("reference", None)):
    r = load(m)
    label = label or f"cube4 reference ray caster (step {r.get('reference_step', 0.25)})"
    print(f"| brainsmall 128×128×84 | {label} | 1 | {r['ms']['median']:.2f} | {r['ms']['min']:.2f} | "
          f"{r['samples_per_frame']:,} | {r['samples_per_second']/1e6:.1f} M |")
print()
for label, one, alln, n, cls, vt, one_v, vt_v, least in ratios:
    print(f"- {label}: fixed-point golden / VolPack raw path **{one:.2f}×** on one thread (smallest frames: "
          f"{least[0]:.2f}×), **{alln:.2f}×** on {n} threads"
          + (f"; fixed-point golden / VTK **{vt:.2f}×**, one thread each (smallest frames: {least[1]:.2f}×)" if vt
             else "; VTK not measured (no vtk_bench or xvfb-run)")
          + f"; with the block ranges built once per volume, **{one_v:.2f}×** VolPack's raw path"
          + (f" and **{vt_v:.2f}×** VTK" if vt_v else "")
          + f"; VolPack's classified path with its pre-processing takes **{cls:.2f}×** the one-thread golden frame.")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" golden-speed
echo "perf_golden: docs/performance.md updated" >&2
