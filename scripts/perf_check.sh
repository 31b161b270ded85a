#!/usr/bin/env bash
# What --check costs an RTL frame: `cube4 render --model rtl` of the default
# scene (brainsmall, p = 4) with --check and with --no-check, N pairs in
# turn, on every core (the simulation on two threads where there are two:
# docs/system.md) and pinned to one core with one simulation thread (where
# the stream checker's thread cannot run beside the simulation). Writes the median frame times
# (the report's frame_ms) and their ratios into the "check-cost" section of
# docs/performance.md.
#   scripts/perf_check.sh [N]     (default 5; CUBE4_BUILD: the build folder)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CUBE4_BUILD:-$here/build}
[ -n "${CUBE4_BUILD:-}" ] || "$here/scripts/setup.sh" >/dev/null
n=${1:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
section=$(python3 - "$build/tb/cube4" "$n" "$(nproc)" "$tmp" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" <<'PY'
import json, shutil, statistics, subprocess, sys, datetime
cube4, n, cores, tmp, cpu = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4], sys.argv[5]
def frame_ms(check, pin):
    cmd = [cube4, "render", "--model", "rtl", check, "-q", "-o", f"{tmp}/o.png", "--report", f"{tmp}/r.json"]
    # One core: one simulation thread (beside the checker's).
    if pin and shutil.which("taskset"): cmd = ["taskset", "-c", str(cores - 1)] + cmd + ["--threads", "1"]
    subprocess.run(cmd, check=True)
    return json.load(open(f"{tmp}/r.json"))["frame_ms"]["median"]
print(f"Measured {datetime.date.today()} by `scripts/perf_check.sh {n}` on {cpu} ({cores} cores): "
      f"`cube4 render --model rtl` of the default scene (brainsmall, p = 4), median frame time of {n} runs, "
      "checked and unchecked in turn.")
print()
print("| cores | `--no-check` (ms) | `--check` (ms) | ratio |")
print("|---|---:|---:|---:|")
for pin in (False, True):
    if pin and cores == 1: continue
    t = {"--check": [], "--no-check": []}
    for _ in range(n):
        for c in t: t[c].append(frame_ms(c, pin))
    a, b = statistics.median(t["--no-check"]), statistics.median(t["--check"])
    print(f"| {'1 (taskset)' if pin else cores} | {a:.0f} | {b:.0f} | {b / a:.2f} |")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" check-cost
echo "perf_check: docs/performance.md updated" >&2
