#!/usr/bin/env bash
# Synthesises every RTL unit with yosys (scripts/gates.sh: default widths and
# the alternative widths listed there) and writes the "gates" section of
# docs/gates.md: per-unit cells, NAND2 equivalents, transistor estimates and
# RAM bits, one pipeline's total, and the published figures beside them.
#   scripts/gates_doc.sh [TABLE]
# TABLE: the output of an earlier `scripts/gates.sh` run to reuse (the full
# synthesis takes about ten minutes on two shared cores).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
# Every unit but the *_ring wrappers: a ring is p units and their wiring, and
# flattening four units' multipliers through abc takes over twenty minutes.
units=()
for f in "$here"/rtl/*.sv; do
  grep -qE '^[[:space:]]*package[[:space:]]' "$f" && continue  # cube4_pkg: no logic of its own
  n=$(basename "$f" .sv)
  case $n in *_ring) ;; *) units+=("$n") ;; esac
done
if [ $# -ge 1 ]; then cp "$1" "$tmp"; else "$here/scripts/gates.sh" "${units[@]}" > "$tmp"; fi
section=$(python3 - "$tmp" "$(yosys -V | head -1)" <<'PY'
import re, sys, datetime
table = open(sys.argv[1]).read()
rows = {}
for line in table.splitlines():
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) == 7 and cells[0].startswith("cube4_") and "*" not in cells[1]:
        rows[cells[0]] = cells
def num(s): return float(s.replace(",", "")) if s not in ("", "-") else 0.0
def mem_bits(s): return sum(int(b) for b in re.findall(r"\((\d+) b\)", s))
# One pipeline at the default widths: the streaming units with their storage
# (interpolation, gradient, compositing; each contains its datapath) and the
# shading unit (gradient magnitude + shader).
pipeline = ["cube4_interp_unit", "cube4_gradient_unit", "cube4_shade_unit", "cube4_composite_unit"]
have = [m for m in pipeline if m in rows]
missing = [m for m in pipeline if m not in rows]
cells = sum(num(rows[m][2]) for m in have)
nand2 = sum(num(rows[m][4]) for m in have)
trans = sum(num(rows[m][5]) for m in have)
ram = sum(mem_bits(rows[m][6]) for m in have)
print(f"Generated {datetime.date.today()} by `scripts/gates_doc.sh` ({sys.argv[2]}).")
print()
print(table.rstrip())
print()
print("**One pipeline** (default widths: " + " + ".join(have) + "):")
print()
print("| | logic cells | NAND2-eq | transistors (logic) | RAM bits |")
print("|---|---:|---:|---:|---:|")
print(f"| one pipeline | {cells:,.0f} | {nand2:,.0f} | {trans:,.0f} | {ram:,} |")
print(f"| four pipelines (vg500 configuration) | {4*cells:,.0f} | {4*nand2:,.0f} | {4*trans:,.0f} | {4*ram:,} |")
print(f"| five pipelines (Cube-4 prototype) | {5*cells:,.0f} | {5*nand2:,.0f} | {5*trans:,.0f} | {5*ram:,} |")
print()
if missing:
    print("Not yet in the total: " + ", ".join(missing) + ".")
print("Not in the total: the address generator (one per chip, `cube4_addr` above), the "
      "stream former and weight generator, the host interface and pixel memory. The storage "
      "units are sized for 256-voxel volumes (MaxDim 256) with p = 4; the vg500 kept its "
      "on-chip storage to 2 Mbit with sectioning (VolumePro §5.4), which is not modelled.")
PY
)
printf '%s\n' "$section" | python3 "$here/scripts/update_doc_section.py" "$here/docs/gates.md" gates
echo "gates_doc: docs/gates.md updated" >&2
