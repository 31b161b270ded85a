#!/usr/bin/env bash
# The fronts of docs/explore.md: runs `cube4 explore` on the 20-point sweeps
# of brainsmall and the sphere (scenes/explore/, TLM, around VolumePro's
# widths) and on the tape-out candidate's six points (tapeout.json), times the brainsmall sweep with the gate counts already cached
# (a first run synthesises every width configuration once with yosys,
# minutes each; the script runs that first and says how long it took),
# copies the plots to docs/images/ and writes the "explore-fronts" section.
#   scripts/explore.sh [-j JOBS] [--no-gates]   (--no-gates: no yosys, the gate columns empty)
# CUBE4_BUILD: a build folder already built (skips the set-up, which builds build/).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[ -n "${CUBE4_BUILD:-}" ] || "$here/scripts/setup.sh" >/dev/null
jobs=$(nproc) gates=()
while [ $# -gt 0 ]; do
  case $1 in
    -j) jobs=$2; shift 2 ;;
    --no-gates) gates=(--no-gates); shift ;;
    *) echo "explore.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
cube4=${CUBE4_BUILD:-$here/build}/tb/cube4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cache=${CUBE4_GATES_CACHE:-$HOME/.cache/cube4/gates}
times=$tmp/times.txt
: > "$times"
for sweep in brainsmall_20 sphere_20 tapeout; do
  # Warm the gate cache (synthesis is per width configuration, not per run).
  t0=$(date +%s.%N)
  [ ${#gates[@]} = 0 ] &&
    "$cube4" explore "$here/scenes/explore/$sweep.json" --out "$tmp/$sweep-warm" -j "$jobs" --gates-cache "$cache" --no-plots
  t1=$(date +%s.%N)
  # The timed run: every point rendered again, the gates from the cache.
  "$cube4" explore "$here/scenes/explore/$sweep.json" --out "$tmp/$sweep" -j "$jobs" --gates-cache "$cache" "${gates[@]}"
  t2=$(date +%s.%N)
  echo "$sweep $t0 $t1 $t2" >> "$times"
  cp "$tmp/$sweep/plots/fronts.png" "$here/docs/images/explore-$sweep.png"
  cp "$tmp/$sweep/plots/fronts.svg" "$here/docs/images/explore-$sweep.svg"
  cp "$tmp/$sweep/results.json" "$tmp/$sweep.json"
done
section=$(python3 - "$tmp" "$times" "$jobs" "$(nproc)" "${gates[*]:-}" "$(cut -d' ' -f1 /proc/loadavg)" <<'PY'
import json, sys, datetime
tmp, times, jobs, cores, no_gates, load = sys.argv[1:7]
t = {}
for l in open(times):
    n, a, b, c = l.split()
    t[n] = (float(b) - float(a), float(c) - float(b))
print(f"Generated {datetime.date.today()} by `scripts/explore.sh{' ' + no_gates if no_gates else ''}` ({jobs} jobs on "
      f"{cores} cores, 1-minute load average {load} at the end), from `cube4 explore scenes/explore/SWEEP.json`."
      + (" Gates not counted in this run (--no-gates): the gate columns are empty." if no_gates else ""))
print()
for sweep, name in [("brainsmall_20", "brainsmall"), ("sphere_20", "the volume-sampled 64³ sphere"),
                    ("tapeout", "the tape-out candidate on brainsmall")]:
    doc = json.load(open(f"{tmp}/{sweep}.json"))
    first, timed = t[sweep]
    print(f"**{name}** (`scenes/explore/{sweep}.json`, model {doc['model']}): the timed run took {timed:.0f} s "
          f"for {len(doc['points'])} points" + ("" if no_gates else
          f" with the gate counts cached; the first run, which synthesised each unit configuration not yet in "
          f"the cache, {first:.0f} s") + ".")
    print()
    print(f"![fronts of {name}](images/explore-{sweep}.png)")
    print()
    print("| point | change from VolumePro's widths | PSNR (dB) | ROI PSNR (dB) | mean error | cycles/image | "
          "images/s | chip NAND2-eq | chip RAM (kbit) | sim s | fronts |")
    print("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for p in doc["points"]:
        change = ", ".join(f"{k} = {v}" for k, v in p["values"].items()) or "(none)"
        if p.get("status") != "ok":
            print(f"| {p['index']} | {change} | {p.get('status')}: {p.get('error', '')} | | | | | | | | |")
            continue
        e, r = p["error"], p.get("error_roi", {})
        g = p.get("gates", {})
        fronts = ", ".join(k for k, v in p.get("pareto", {}).items() if v)
        f = lambda v, fmt: fmt.format(v) if v is not None else "—"
        print(f"| {p['index']} | {change} | {f(e['psnr_db'], '{:.2f}')} | {f(r.get('psnr_db'), '{:.2f}')} | "
              f"{e['mean']:.5f} | {f(p['cycles_per_image'], '{:,.0f}')} | {f(p['fps'], '{:.1f}')} | "
              f"{f(g.get('nand2_chip'), '{:,.0f}')} | {f(g.get('ram_bits_chip') and g['ram_bits_chip'] / 1024, '{:,.0f}')} | "
              f"{p['sim_seconds']:.2f} | {fronts} |")
    print()
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/explore.md" explore-fronts
