#!/usr/bin/env bash
# How much faster an RTL frame is than in an earlier revision, measured in
# one run: builds REV's cube4 (its RTL for p = 4 only) in a worktree of this
# repository, then times `cube4 render --model rtl --no-check --repeat 3`
# (the default scene: brainsmall, p = 4; the report's median frame time)
# of that build and of this one in turn, round by round, so that a drift of
# the machine's speed reaches both alike. cube4 rather than bench_system:
# the two programs link the same verilated units, yet this build's
# bench_system runs the shading units' evaluation about 1.4x slower than
# its cube4 does (the same function, by perf; the code's placement in the
# program, most likely), so a bench_system ratio would measure the link. This build runs on its default threads (two on a machine of two
# cores: docs/system.md) and on one. Writes the "rtl-speedup" section of
# docs/performance.md.
#   scripts/perf_rtl_speedup.sh [REV] [ROUNDS]
# REV defaults to 5c52013, the last commit before the work that issue 16
# (simulation speed) was filed against; ROUNDS to 5, of 3 frames each.
# CUBE4_BUILD: this repository's build folder, already built (skips the
# set-up). REV's build stays in build-rev-REV/ for the next run.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ -z "${CUBE4_BUILD:-}" ]; then "$here/scripts/setup.sh" >/dev/null; fi
build=${CUBE4_BUILD:-$here/build}
rev=${1:-5c52013}
rounds=${2:-5}
old=$here/build-rev-$rev
if [ ! -x "$old/build/tb/cube4" ]; then
  echo "perf_rtl_speedup: building $rev's cube4 in $old (RTL for p = 4 only)..." >&2
  if [ ! -d "$old/src" ]; then
    mkdir -p "$old"
    git -C "$here" worktree add --detach "$old/src" "$rev" >/dev/null
  fi
  # Every list of built p at 4 (a revision older than a list ignores it).
  cmake -S "$old/src" -B "$old/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCUBE4_SYSTEM_PIPES=4 \
    -DCUBE4_SYSTEM_TAG_PIPES=4 -DCUBE4_SYSTEM_POLYGON_PIPES=4 -DCUBE4_SYSTEM_ZDIFF_PIPES=4 \
    -DCUBE4_SYSTEM_PERSP_PIPES=4 >/dev/null
  cmake --build "$old/build" --target cube4 >/dev/null
fi
[ -x "$build/tb/cube4" ] || cmake --build "$build" --target cube4 >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for round in $(seq "$rounds"); do
  echo "perf_rtl_speedup: round $round of $rounds..." >&2
  frame() {  # cube4 [options]: one line of JSON, the report's system part and frame times
    "$1" render --model rtl --no-check --repeat 3 -q -o "$tmp/o.png" --report "$tmp/r.json" "${@:2}"
    python3 -c 'import json, sys; r = json.load(open(sys.argv[1])); s = r["system"]
print(json.dumps({"ms": r["frame_ms"], "cycles_per_frame": s["cycles_per_frame"],
                  "threads": s.get("simulation_threads", 1)}))' "$tmp/r.json"
  }
  frame "$old/build/tb/cube4" >> "$tmp/old.json"
  frame "$build/tb/cube4" >> "$tmp/new.json"
  frame "$build/tb/cube4" --threads 1 >> "$tmp/one.json"
done
section=$(python3 - "$tmp" "$rev" "$(git -C "$here" rev-parse --short HEAD)" "$(nproc)" \
  "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" <<'PY'
import json, statistics, sys, datetime
tmp, rev, head, cores, cpu = sys.argv[1:6]
def rows(name):
    return [json.loads(l) for l in open(f"{tmp}/{name}.json") if l.strip()]
old, new, one = rows("old"), rows("new"), rows("one")
med = lambda rs: statistics.median(r["ms"]["median"] for r in rs)
print(f"Measured {datetime.date.today()} by `scripts/perf_rtl_speedup.sh {rev} {len(old)}` on {cpu} ({cores} cores): "
      f"`cube4 render --model rtl --no-check --repeat 3` of the default scene (brainsmall, p = 4), the median of "
      f"{len(old)} rounds' median frame times, the builds taking turns round by round.")
print()
print("| build | threads | ms/frame | cycles/frame | speed-up against " + rev + " |")
print("|---|---:|---:|---:|---:|")
o = med(old)
print(f"| {rev} | 1 | {o:.0f} | {old[0]['cycles_per_frame']} | 1.00× |")
print(f"| {head} | 1 | {med(one):.0f} | {one[0]['cycles_per_frame']} | {o / med(one):.2f}× |")
print(f"| {head} | {new[0].get('threads', 1)} (default) | {med(new):.0f} | {new[0]['cycles_per_frame']} | "
      f"**{o / med(new):.2f}×** |")
# Round by round: the machine's speed drifts between rounds, alike for
# both builds within one; the spread says how far one run's figure can move.
def pairs(rs):
    return sorted(a["ms"]["median"] / b["ms"]["median"] for a, b in zip(old, rs))
two, single = pairs(new), pairs(one)
print()
print(f"Round by round (the earlier build's frame over this build's of the same round): "
      f"{statistics.median(two):.2f}× on {new[0].get('threads', 1)} threads ({two[0]:.2f}× to {two[-1]:.2f}×), "
      f"{statistics.median(single):.2f}× on one ({single[0]:.2f}× to {single[-1]:.2f}×).")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" rtl-speedup
echo "perf_rtl_speedup: docs/performance.md updated" >&2
