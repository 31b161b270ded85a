#!/usr/bin/env bash
# Start-up of the cube4 command: `cube4 info` on the 64³ sphere (a run that
# writes no image) and a loosely timed render of an 8³ sphere to a 16x16
# PNG (a whole run that is nearly all start-up), each as built, against the
# same binary with OpenImageIO loaded at start (LD_PRELOAD), which is what
# every run paid before image I/O moved into the module
# libcube4_image_oiio.so (tb/image_plugin.hpp) and PNG writing into cube4
# itself (tb/image_png.hpp). Runs each pair in turn, N pairs, and writes the
# medians and their ratios into the "startup" section of docs/performance.md.
#   scripts/perf_startup.sh [N] [build-dir]   (default 20, $CUBE4_BUILD or build)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
n=${1:-20}
build=${2:-${CUBE4_BUILD:-$here/build}}
[ -x "$build/tb/cube4" ] || "$here/scripts/setup.sh" >/dev/null
oiio=$(ldd "$build/tb/libcube4_image_oiio.so" | awk '/libOpenImageIO\.so/ {print $3; exit}')
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '{"volume": {"synthetic": "sphere", "size": [8, 8, 8]}, "output": {"width": 16, "height": 16}}\n' > "$tmp/tiny.json"
section=$(python3 - "$build/tb/cube4" "$here/scenes/sphere.json" "$oiio" "$n" "$(nproc)" "$tmp" <<'PY'
import os, resource, statistics, subprocess, sys, time, datetime
cube4, scene, oiio, n, cores, tmp = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5], sys.argv[6]
commands = {
    "`cube4 info scenes/sphere.json`": [cube4, "info", scene],
    "`cube4 render` 8³ sphere, `--model tlm`, 16×16 PNG": [cube4, "render", f"{tmp}/tiny.json", "--model", "tlm", "-q",
                                                            "-o", f"{tmp}/tiny.png"],
}
def run(cmd, preload):
    env = dict(os.environ)
    if preload: env["LD_PRELOAD"] = oiio
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    subprocess.run(cmd, env=env, stdout=subprocess.DEVNULL, check=True)
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
med = lambda xs, i: statistics.median(x[i] for x in xs)
print(f"Generated {datetime.date.today()} by `scripts/perf_startup.sh {n}` ({cores} cores, {n} pairs in turn; medians).")
print()
print("| command | as built: wall ms | CPU ms | OpenImageIO loaded at start (what every run paid before): wall ms | CPU ms | wall-time ratio, pair by pair |")
print("|---|---:|---:|---:|---:|---:|")
for name, cmd in commands.items():
    run(cmd, False); run(cmd, True)  # warm the page cache
    a, b = [], []
    for _ in range(n):
        a.append(run(cmd, False)); b.append(run(cmd, True))
    ratio = statistics.median(x[0] / y[0] for x, y in zip(a, b))
    print(f"| {name} | {med(a, 0) * 1e3:.0f} | {med(a, 1) * 1e3:.0f} | {med(b, 0) * 1e3:.0f} | {med(b, 1) * 1e3:.0f} | {ratio:.3f} |")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" startup
echo "perf_startup: docs/performance.md updated" >&2
