#!/usr/bin/env bash
# Start-up of the cube4 command: `cube4 info` on the 64³ sphere (a run that
# writes no image) as built, against the same binary with OpenImageIO loaded
# at start (LD_PRELOAD), which is what every run paid before image I/O moved
# into the module libcube4_image_oiio.so (tb/image_plugin.hpp). Runs the two
# in turn, N pairs, and writes the medians and their ratio into the
# "startup" section of docs/performance.md.
#   scripts/perf_startup.sh [N] [build-dir]   (default 20, build)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
n=${1:-20}
build=${2:-$here/build}
[ -x "$build/tb/cube4" ] || "$here/scripts/setup.sh" >/dev/null
oiio=$(ldd "$build/tb/libcube4_image_oiio.so" | awk '/libOpenImageIO\.so/ {print $3; exit}')
python3 - "$build/tb/cube4" "$here/scenes/sphere.json" "$oiio" "$n" "$(nproc)" <<'PY' | \
  python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" startup
import os, resource, statistics, subprocess, sys, time, datetime
cube4, scene, oiio, n, cores = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
def run(preload):
    env = dict(os.environ)
    if preload: env["LD_PRELOAD"] = oiio
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    subprocess.run([cube4, "info", scene], env=env, stdout=subprocess.DEVNULL, check=True)
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
run(False); run(True)  # warm the page cache
a, b = [], []
for _ in range(n):
    a.append(run(False)); b.append(run(True))
med = lambda xs, i: statistics.median(x[i] for x in xs)
ratio = statistics.median(x[0] / y[0] for x, y in zip(a, b))
print(f"Generated {datetime.date.today()} by `scripts/perf_startup.sh {n}` ({cores} cores, {n} pairs in turn; medians).")
print()
print("| `cube4 info scenes/sphere.json` | wall ms | CPU ms |")
print("|---|---:|---:|")
print(f"| as built (OpenImageIO opened only to read or write an image) | {med(a, 0) * 1e3:.0f} | {med(a, 1) * 1e3:.0f} |")
print(f"| OpenImageIO loaded at start (LD_PRELOAD: what every run paid before) | {med(b, 0) * 1e3:.0f} | {med(b, 1) * 1e3:.0f} |")
print()
print(f"Wall-time ratio, pair by pair: {ratio:.3f} (median).")
PY
echo "perf_startup: docs/performance.md updated" >&2
