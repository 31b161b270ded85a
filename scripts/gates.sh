#!/usr/bin/env bash
# Gate counts of the RTL units (first version): synthesises every module of
# rtl/ (a file named after the module it defines) with yosys at its default
# parameters, plus extra parameter sets (other widths, and the effect
# variants without cut-plane or shading hardware), and prints a markdown
# table to stdout.
#
# Flow per module: read_verilog -sv rtl/*.sv; chparam; synth -flatten up to
# `fine` (coarse synthesis; memories stay $mem cells: memory -nomap); the
# rest of synth's fine stage without memory_map (opt, techmap, opt);
# dffunmap (enable and sync-reset flip-flops become plain ones plus gates);
# abc -g AND,NAND,OR,NOR,XOR,XNOR,MUX; opt_clean; stat; stat -tech cmos.
#
# Columns:
#   cells       gate-level cells after abc -g (gates + flip-flops, no memories)
#   FFs         flip-flop bits
#   NAND2-eq    sum of cell weights, ~ typical 45 nm X1 standard-cell area
#               relative to NAND2: NOT 0.67, NAND2/NOR2 1, AND2/OR2 1.33,
#               XOR2/XNOR2 2, MUX2 2.33, DFF 5.67, DFF with async reset 6.67
#   transistors yosys `stat -tech cmos` estimate (static CMOS, DFF = 16), plus
#               20 per async-reset flip-flop (not in yosys's table)
#   memory      $mem cells, depth x width (bits), counted apart from logic
#
# Usage: scripts/gates.sh [--json] [--set Name=value,...] [module ...]
#   (default: every module of rtl/, each also at the extra parameter sets below)
#   --set    synthesise each module once, with those parameters it declares
#            overridden (the explorer's width configurations, docs/explore.md)
#   --json   a JSON array of the rows instead of the markdown table
#   --declared  with --set: print, per module, "module overrides-it-declares"
#            and synthesise nothing (the explorer caches per module and those)
set -u
json=0 set_params="" set_given=0 declared_only=0
while [ $# -gt 0 ]; do
  case $1 in
    --json) json=1; shift ;;
    --declared) declared_only=1; shift ;;
    --set) set_params=$2; set_given=1; shift 2 ;;
    *) break ;;
  esac
done
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
command -v yosys >/dev/null || { echo "gates: yosys not found" >&2; exit 2; }
command -v python3 >/dev/null || { echo "gates: python3 not found" >&2; exit 2; }

all=(rtl/*.sv)
pkgs=() mods=()
for f in "${all[@]}"; do
  if grep -qE '^[[:space:]]*package[[:space:]]' "$f"; then pkgs+=("$f"); else mods+=("$f"); fi
done
readlist="${pkgs[*]} ${mods[*]}"

# Units: every module named after its file, unless given.
units=()
if [ $# -gt 0 ]; then
  units=("$@")
else
  for f in "${mods[@]}"; do
    n=$(basename "$f" .sv)
    grep -qE "^[[:space:]]*module[[:space:]]+${n}\b" "$f" && units+=("$n")
  done
fi

# Extra parameter sets: "<module> <Name=value>,<Name=value>".
extra=(
  "cube4_interp WeightBits=6"
  "cube4_interp WeightBits=10"
  "cube4_shade AlphaBits=8"
  "cube4_shade AlphaBits=12"
  "cube4_composite AlphaBits=8"
  "cube4_composite AlphaBits=12,AccGuardBits=0"
  "cube4_composite_unit AlphaBits=12,AccGuardBits=0"
  "cube4_composite HasCutPlane=0"
  "cube4_compose_node AlphaBits=8,AccGuardBits=0"
  "cube4_compose_node AlphaBits=12,AccGuardBits=0"
  "cube4_shade_unit HasShading=0,HasMagnitude=0"
  "cube4_interp_unit HasZDiff=1"
  "cube4_gradient HasVoxelZ=1"
  "cube4_gradient_unit HasVoxelZ=1"
  "cube4_dda HasPerspective=0"
)

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# synth_one <module> <params or "">: writes $tmp/<tag>.{mem,gates,cmos}.json
runs=()
synth_one() {
  local m=$1 params=$2 tag chp="" p
  tag="$m${params:+_${params//[=,]/_}}"
  for p in ${params//,/ }; do chp="$chp chparam -set ${p%%=*} ${p#*=} $m;"; done
  if ! yosys -q -l "$tmp/$tag.log" -p "read_verilog -sv $readlist; $chp
      synth -top $m -flatten -run :fine; write_json $tmp/$tag.mem.json;
      opt -fast -full; techmap; opt -fast; dffunmap;
      abc -g AND,NAND,OR,NOR,XOR,XNOR,MUX; opt_clean;
      tee -q -o $tmp/$tag.gates.json stat -json;
      tee -q -o $tmp/$tag.cmos.json stat -tech cmos -json" >/dev/null 2>&1; then
    echo "gates: yosys failed on $m ${params}" >&2
    grep -iE 'error' "$tmp/$tag.log" | head -5 >&2
    return 1
  fi
  runs+=("$m|$params|$tag")
}

# The overrides of --set that module $1 declares as parameters.
declared() {
  local m=$1 kv out=""
  for kv in ${set_params//,/ }; do
    awk "/^module $m([^A-Za-z0-9_]|\$)/,/^\\) *\\(/" "rtl/$m.sv" | grep -qE "parameter[^=]*\\<${kv%%=*}\\>[[:space:]]*=" &&
      out="${out:+$out,}$kv"
  done
  echo "$out"
}

if [ $declared_only = 1 ]; then
  for u in "${units[@]}"; do echo "$u $(declared "$u")"; done
  exit 0
fi

status=0
for u in "${units[@]}"; do
  if [ $set_given = 1 ]; then
    synth_one "$u" "$(declared "$u")" || status=1
    continue
  fi
  synth_one "$u" "" || status=1
  for e in "${extra[@]}"; do
    [ "${e%% *}" = "$u" ] && { synth_one "$u" "${e#* }" || status=1; }
  done
done

python3 - "$tmp" "$json" "${runs[@]}" <<'EOF'
import json, re, sys

tmp, as_json = sys.argv[1], sys.argv[2] == "1"
rows = []
weights = {  # NAND2 equivalents
    "$_NOT_": 0.67, "$_BUF_": 0.0, "$_NAND_": 1.0, "$_NOR_": 1.0, "$_AND_": 1.33, "$_OR_": 1.33,
    "$_XOR_": 2.0, "$_XNOR_": 2.0, "$_MUX_": 2.33,
    "$_DFF_P_": 5.67, "$_DFF_N_": 5.67,
    "$_DFF_PN0_": 6.67, "$_DFF_PN1_": 6.67, "$_DFF_NN0_": 6.67, "$_DFF_NN1_": 6.67,
    "$_DFF_PP0_": 6.67, "$_DFF_PP1_": 6.67,
}
async_ff = {t for t in weights if re.match(r"\$_DFF_[PN][PN][01]_$", t)}

def parameters(module, overrides):
    """Numeric default parameters from rtl/<module>.sv's header, with overrides."""
    vals = {}
    try:
        src = open(f"rtl/{module}.sv").read()
        start = src.index(f"module {module}")
        header = src[start:src.index(");", start)]
        for name, val in re.findall(r"\bparameter\s+(?:int\s+unsigned\s+|int\s+|bit\s+)?(\w+)\s*=\s*(\d+)\s*[,)\n]", header):
            vals[name] = val
    except (OSError, ValueError):
        pass
    for kv in filter(None, overrides.split(",")):
        k, v = kv.split("=")
        vals[k] = v + "*"
    return ", ".join(f"{k}={v}" for k, v in vals.items()) or "-"

unknown_all = set()
for run in sys.argv[3:]:
    module, params, tag = run.split("|")
    g = json.load(open(f"{tmp}/{tag}.gates.json"))["design"]["num_cells_by_type"]
    c = json.load(open(f"{tmp}/{tag}.cmos.json"))["design"]
    cells = ffs = 0
    nand2 = 0.0
    n_async = 0
    for t, n in g.items():
        if t.startswith("$mem"):
            continue
        cells += n
        if t.startswith("$_DFF") or t.startswith("$_SDFF") or t.startswith("$_DLATCH"):
            ffs += n
        if t in async_ff:
            n_async += n
        if t in weights:
            nand2 += weights[t] * n
        else:
            unknown_all.add(t)
            nand2 += n  # counted as one NAND2 each, flagged below
    tr = str(c.get("estimated_num_transistors", "?"))
    base = int(tr.rstrip("+")) if tr.rstrip("+").isdigit() else 0
    transistors = f"{base + 20 * n_async}"
    mems = []
    mj = json.load(open(f"{tmp}/{tag}.mem.json"))
    for mod in mj["modules"].values():
        for name, cell in mod.get("cells", {}).items():
            if cell["type"].startswith("$mem"):
                p = cell["parameters"]
                mems.append((int(p["SIZE"], 2), int(p["WIDTH"], 2)))
    rows.append({"module": module, "parameters": params, "cells": cells, "ffs": ffs, "nand2": round(nand2, 2),
                 "transistors": int(transistors), "memories": [{"depth": d, "width": w} for d, w in mems],
                 "ram_bits": sum(d * w for d, w in mems)})
if as_json:
    print(json.dumps(rows, indent=1))
    sys.exit(0)
print("| module | parameters | cells | FFs | NAND2-eq | transistors | memory |")
print("|---|---|---:|---:|---:|---:|---|")
for r in rows:
    mems = ", ".join(f"{m['depth']}x{m['width']} ({m['depth'] * m['width']} b)" for m in r["memories"])
    print(f"| {r['module']} | {parameters(r['module'], r['parameters'])} | {r['cells']} | {r['ffs']} | "
          f"{r['nand2']:,.0f} | {r['transistors']:,} | {mems or '-'} |")
print()
print("NAND2-eq weights: NOT 0.67, NAND2/NOR2 1, AND2/OR2 1.33, XOR2/XNOR2 2, MUX2 2.33, "
      "DFF 5.67, DFF with async reset 6.67 (typical 45 nm X1 cell areas / NAND2). "
      "Transistors: yosys stat -tech cmos, plus 20 per async-reset DFF. Memories not in cells/NAND2-eq. "
      "* = parameter overridden.")
if unknown_all:
    print(f"Cell types without a weight (counted as 1 NAND2 each): {', '.join(sorted(unknown_all))}")
EOF
exit $status
