#!/usr/bin/env bash
# What VolumePro's z gradient (z_gradient voxel_differences) costs one
# pipeline in the rings: the interpolation and gradient units with and
# without their effect parameters (HasZDiff, HasVoxelZ), synthesised by
# scripts/gates.sh (its flow; default widths, the rings' storage at
# MaxDim 256 and p = 4), and the difference per pipeline. Writes the table
# into docs/rtl-interp-zdiff.md's "zdiff-cost" section and prints it.
# Usage: scripts/gates_zdiff.sh   (about a minute)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
json=$(scripts/gates.sh --json cube4_interp_unit cube4_gradient_unit)
yosys_version=$(yosys -V | head -1)
section=$(GATES_JSON="$json" YOSYS_VERSION="$yosys_version" python3 - <<'EOF'
import json, os, datetime
rows = json.loads(os.environ["GATES_JSON"])
def row(module, with_z):
    for r in rows:
        if r["module"] == module and (("HasZDiff=1" in r["parameters"] or "HasVoxelZ=1" in r["parameters"]) == with_z):
            return r
    raise SystemExit(f"gates_zdiff: no row for {module} (with the method: {with_z})")
out = [f"Generated {datetime.date.today()} by `scripts/gates_zdiff.sh` ({os.environ['YOSYS_VERSION']}; "
       "the flow of scripts/gates.sh, default widths, storage for MaxDim 256 at p = 4).", "",
       "| unit | z gradient | NAND2-eq | FFs | RAM bits |", "|---|---|---:|---:|---:|"]
total = {False: [0.0, 0, 0], True: [0.0, 0, 0]}
for module in ("cube4_interp_unit", "cube4_gradient_unit"):
    for with_z in (False, True):
        r = row(module, with_z)
        out.append(f"| {module} | {'voxel differences' if with_z else '12-neighbourhood'} | "
                   f"{r['nand2']:,.0f} | {r['ffs']:,} | {r['ram_bits']:,} |")
        t = total[with_z]
        t[0] += r["nand2"]; t[1] += r["ffs"]; t[2] += r["ram_bits"]
a, b = total[False], total[True]
out.append(f"| both | 12-neighbourhood | {a[0]:,.0f} | {a[1]:,} | {a[2]:,} |")
out.append(f"| both | voxel differences | {b[0]:,.0f} | {b[1]:,} | {b[2]:,} |")
out.append("")
out.append(f"Per pipeline the method adds {b[0] - a[0]:+,.0f} NAND2-eq of logic ({(b[0] - a[0]) / a[0]:+.1%} "
           f"of the two units) and {b[2] - a[2]:+,} RAM bits ({(b[2] - a[2]) / a[2]:+.1%}).")
print("\n".join(out))
EOF
)
printf '%s\n' "$section" | python3 scripts/update_doc_section.py docs/rtl-interp-zdiff.md zdiff-cost
printf '%s\n' "$section"
