#!/usr/bin/env bash
# Lint of every rtl/*.sv, the RTL acceptance rule (docs/architecture.md, Conventions):
#   1. verilator --lint-only -Wall --assert -Irtl <packages> <file>
#      rtl/assert/*.sv: no warning, no error; the checkers of rtl/assert/
#      bind themselves to the units they watch, so each unit is linted with
#      its assertions attached; each checker is also linted as a top of its
#      own (the assertion tests verilate them so);
#   2. yosys: read_verilog -sv of all rtl/*.sv (packages first), then
#      synth -top <module> for every file that defines the module it is
#      named after (every such module must synthesise with its default
#      parameters), then check -assert: no warning, no error. The checkers
#      are simulation only, never synthesised.
# By default synth runs up to its `fine` label (front end, elaboration,
# proc, coarse synthesis, memory inference: everything the source decides,
# ~0.5 s a module); --full runs all of synth, whose fine/abc stages map the
# LUT memories to flip-flops and take minutes on this machine (the complete
# logic synthesis, memories kept, is what scripts/gates.sh runs).
# Prints each problem and a one-line summary; exits 1 on any problem.
# Usage: scripts/lint_rtl.sh [--full] [file.sv ...]   (default: rtl/*.sv)
set -u
synth_run="-run :fine"
if [ "${1:-}" = "--full" ]; then synth_run=""; shift; fi
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

command -v verilator >/dev/null || { echo "lint_rtl: verilator not found" >&2; exit 2; }
command -v yosys >/dev/null || { echo "lint_rtl: yosys not found" >&2; exit 2; }

checkers=(rtl/assert/*.sv)
[ -e "${checkers[0]}" ] || checkers=()
if [ $# -gt 0 ]; then files=("$@"); else files=(rtl/*.sv "${checkers[@]}"); fi
all=(rtl/*.sv)
[ -e "${all[0]}" ] || { echo "lint_rtl: no rtl/*.sv" >&2; exit 2; }

# Packages go first in yosys's read (qualified names need the package).
pkgs=() mods=()
for f in "${all[@]}"; do
  if grep -qE '^[[:space:]]*package[[:space:]]' "$f"; then pkgs+=("$f"); else mods+=("$f"); fi
done
readlist="${pkgs[*]} ${mods[*]}"
# Files named on the command line outside rtl/ are read too (checkers not:
# yosys never sees them).
for f in "${files[@]}"; do
  case " ${all[*]} ${checkers[*]} " in *" $f "*) ;; *) readlist="$readlist $f" ;; esac
done

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
problems=0 linted=0 synthesised=0

for f in "${files[@]}"; do
  name=$(basename "$f" .sv)
  # 1. Verilator.
  # The packages first (Verilator needs them declared before their use).
  vfiles=("${pkgs[@]}")
  top=()
  case " ${pkgs[*]} " in *" $f "*) ;; *)
    vfiles+=("$f")
    # With the checkers (a bind to a unit the file lacks is ignored), the
    # file's module is the top.
    for c in "${checkers[@]}"; do [ "$c" = "$f" ] || vfiles+=("$c"); done
    top=(--top-module "$name") ;;
  esac
  if ! verilator --lint-only -Wall --assert -Irtl -Irtl/assert "${top[@]}" "${vfiles[@]}" >"$tmp/v.log" 2>&1 || [ -s "$tmp/v.log" ]; then
    echo "FAIL verilator $f"
    sed 's/^/    /' "$tmp/v.log" | head -40
    problems=$((problems + 1))
  fi
  linted=$((linted + 1))
  # 2. yosys, for files that define the module they are named after.
  case " ${checkers[*]} " in *" $f "*) continue ;; esac
  grep -qE "^[[:space:]]*module[[:space:]]+${name}\b" "$f" || continue
  if ! yosys -q -l "$tmp/y.log" -p "read_verilog -sv $readlist; synth -top $name $synth_run; check -assert" >/dev/null 2>&1 ||
     grep -qiE '^(warning|error)|^ERROR' "$tmp/y.log"; then
    echo "FAIL yosys synth -top $name"
    grep -iE 'warning|error' "$tmp/y.log" | sort | uniq | sed 's/^/    /' | head -40
    problems=$((problems + 1))
  fi
  synthesised=$((synthesised + 1))
done

if [ "$problems" -eq 0 ]; then
  echo "lint_rtl: OK: ${linted} files Verilator -Wall clean (with the assertions of rtl/assert/), ${synthesised} modules through yosys synth${synth_run:+ ($synth_run)} without warnings"
  exit 0
fi
echo "lint_rtl: FAILED: ${problems} problems (${linted} files linted, ${synthesised} modules synthesised)"
exit 1
