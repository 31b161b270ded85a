#!/usr/bin/env bash
# Cube-4's Table 1 (docs/data/cube4-table1.csv: 64^3, 128^3, 256^3 with
# 8 to 128 pipelines, 33 MHz) beside this model's cycles for the same
# configurations, plus VolumePro's (256^3, 4 pipelines, 125 MHz), written to
# the "table1" section of docs/performance.md. The cycles are the system
# model's (cube4 render --model tlm: the cycle model, which the system tests
# assert equal to the RTL's count); volumes are spheres viewed along z with
# shading on (gradient unit running, so a lone frame has its zero pass; frames
# back to back do not: the steady-state interval).
#   scripts/table1.sh
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# CUBE4_BIN: a cube4 binary already built (skips the set-up).
if [ -z "${CUBE4_BIN:-}" ]; then "$here/scripts/setup.sh" >/dev/null; fi
cube4=${CUBE4_BIN:-$here/build/tb/cube4}
csv=${CUBE4_TABLE1:-$here/docs/data/cube4-table1.csv}
[ -r "$csv" ] || { echo "table1: cannot read $csv" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() {  # n p mhz -> report json path
  local n=$1 p=$2 mhz=$3 out=$tmp/r_$1_$2.json
  printf '{"volume": {"synthetic": "sphere", "size": [%s, %s, %s]}, "view": {"direction": [0, 0, 1]}, "clock_mhz": %s}\n' \
    "$n" "$n" "$n" "$mhz" > "$tmp/s_$n.json"
  "$cube4" render "$tmp/s_$n.json" --model tlm --pipes "$p" -q -o "$tmp/i.png" --report "$out"
  echo "$out"
}
rows=()
while IFS=, read -r n p cyc fps; do
  case "$n" in \#*|"") continue ;; esac
  echo "table1: ${n}^3, p = $p" >&2
  rows+=("$n,$p,$cyc,$fps,$(run "$n" "$p" 33)")
done < "$csv"
vp=$(run 256 4 125)
section=$(python3 - "$vp" "${rows[@]}" <<'PY'
import json, sys
vp = json.load(open(sys.argv[1]))["system"]
print("| n³ | p | Cube-4 cycles/frame | Cube-4 fps @ 33 MHz | cube4 cycles/frame (first frame) | ratio | steady-state interval | ratio | cube4 fps @ 33 MHz (steady) | n³/p |")
print("|---|---|---|---|---|---|---|---|---|---|")
for row in sys.argv[2:]:
    n, p, cyc, fps, path = row.split(",")
    s = json.load(open(path))["system"]
    n, p, cyc = int(n), int(p), int(cyc)
    print(f"| {n} | {p} | {cyc} | {fps} | {s['cycles_per_frame']} | {s['cycles_per_frame'] / cyc:.3f} | "
          f"{s['cycles_steady_state_interval']} | {s['cycles_steady_state_interval'] / cyc:.3f} | "
          f"{s['fps_steady_state']:.0f} | {n**3 // p} |")
print()
print(f"VolumePro configuration (256³, 4 pipelines, 125 MHz): {vp['cycles_per_frame']} cycles for the first frame, "
      f"{vp['cycles_steady_state_interval']} between back-to-back frames: {vp['fps_steady_state']:.1f} fps "
      f"({vp['samples_per_cycle']:.2f} samples per cycle; the vg500 is quoted at 30 fps, 500 M samples/s).")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/performance.md" table1
echo "table1: docs/performance.md updated" >&2
