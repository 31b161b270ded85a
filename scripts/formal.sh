#!/usr/bin/env bash
# Formal proofs of the small RTL units (issue 10, point 3), with the tools
# Debian ships: yosys (read_verilog -formal) writes SMT-LIB2, yosys-smtbmc
# proves it with z3. No SymbiYosys: each proof is the two steps below.
#
# A proof is a harness in rtl/formal/<top>.sv that instantiates a unit
# unchanged and adds assume/assert. Kinds:
#   bmc K  bounded model check: no assertion fails in the first K cycles
#          from the initial state (for a combinational unit K = 1 is all of
#          it);
#   ind K  k-induction: the K-cycle base case (as bmc K) and the induction
#          step (K cycles satisfying every assertion are never followed by
#          one that fails one): holds in every reachable cycle.
#   bug K  a planted bug (a mutant copy of a unit in rtl/formal/mutants/,
#          or a harness with an assumption removed): the bmc K run must FIND
#          a counterexample; the line says FAIL if the proof stays green.
# Engine flags among a proof's parameters: +noincr runs a fresh z3 per
# query (z3 then bit-blasts: far faster on the multiplier miters);
# +yosys-sat uses yosys's own SAT solver (sat -seq K, BMC only) for models
# z3 does not solve (the address generator, cube4_addr).
# Internal signals: yosys 0.23 has no hierarchical references, so a harness
# declares an undriven probe_* wire and the proof lists "probe=signal"; the
# script connects it to the flattened signal (u_dut.ptr_q) after flatten.
#
# Output: one line per proof, "<status> <name> <kind> k=<K> <seconds>s";
# logs and smt2 files in $FORMAL_OUT (default build/formal). Exit status:
# 0 if every proof went as expected, 1 otherwise, 2 if a tool is missing.
#
# Usage: scripts/formal.sh [--quick|--slow|--bugs|--all|--list] [name ...]
#   default --quick (the default ctest suite's set); names select proofs.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
for t in yosys yosys-smtbmc z3; do
  command -v "$t" >/dev/null || { echo "formal: $t not found" >&2; exit 2; }
done
out=${FORMAL_OUT:-$root/build/formal}
mkdir -p "$out"
nice_cmd=(nice -n "${FORMAL_NICE:-10}")
# FORMAL_TIMEOUT (seconds, default none) bounds each solver run.
if [ -n "${FORMAL_TIMEOUT:-}" ]; then nice_cmd=(timeout --foreground "$FORMAL_TIMEOUT" "${nice_cmd[@]}"); fi

# proof <name> <group> <kind> <K> <top> "<files>" "<Param=value ...>" [probe=signal ...]
# group: quick (default suite), slow, bug (planted bugs, quick ones).
names=()
declare -A P_GROUP P_KIND P_K P_TOP P_FILES P_PARAMS P_PROBES
proof() {
  local n=$1
  names+=("$n")
  P_GROUP[$n]=$2 P_KIND[$n]=$3 P_K[$n]=$4 P_TOP[$n]=$5 P_FILES[$n]=$6 P_PARAMS[$n]=$7
  shift 7
  P_PROBES[$n]="$*"
}
F=rtl/formal
source "$F/proofs.sh"

mode=quick sel=()
for a in "$@"; do
  case $a in
    --quick) mode=quick ;;
    --slow) mode=slow ;;
    --bugs) mode=bug ;;
    --all) mode=all ;;
    --list) for n in "${names[@]}"; do echo "$n ${P_GROUP[$n]} ${P_KIND[$n]} ${P_K[$n]}"; done; exit 0 ;;
    -*) echo "formal: unknown option $a" >&2; exit 2 ;;
    *) sel+=("$a") ;;
  esac
done
run=()
if [ ${#sel[@]} -gt 0 ]; then
  for n in "${sel[@]}"; do
    [ -n "${P_KIND[$n]:-}" ] || { echo "formal: no proof named $n" >&2; exit 2; }
    run+=("$n")
  done
else
  for n in "${names[@]}"; do
    g=${P_GROUP[$n]}
    if [ "$mode" = all ] || [ "$g" = "$mode" ] || { [ "$mode" = quick ] && [ "$g" = bug ]; }; then
      run+=("$n")
    fi
  done
fi

# yosys: harness + units -> one flat SMT-LIB2 model with probes connected.
# A file f.sed in a proof's list is a planted bug: the sed script applied
# to the unit named in its "# file:" line, written to $out (it must change
# the unit, or the bug is not planted).
elaborate() {
  # The package first: the units' parameter defaults and types come from it.
  local n=$1 ys=$out/$1.ys files=(rtl/cube4_pkg.sv) f
  for f in ${P_FILES[$n]}; do
    if [[ $f == *.sed ]]; then
      local unit mutant
      unit=$(sed -n 's/^# file: *//p' "$f")
      mutant=$out/$(basename "$f" .sed).sv
      sed -f "$f" "$unit" >"$mutant" || return 1
      if cmp -s "$unit" "$mutant"; then
        echo "formal: $f does not change $unit" >&2
        return 1
      fi
      files+=("$mutant")
    else
      files+=("$f")
    fi
  done
  {
    echo "read_verilog -formal -sv -Irtl ${files[*]}"
    for p in ${P_PARAMS[$n]}; do
      [[ $p == +* ]] || echo "chparam -set ${p%%=*} ${p#*=} ${P_TOP[$n]}"
    done
    echo "hierarchy -check -top ${P_TOP[$n]}"
    echo "proc"
    echo "flatten"
    echo "memory_map"
    for pr in ${P_PROBES[$n]}; do echo "connect -set ${pr%%=*} ${pr#*=}"; done
    echo "opt_clean"
    echo "check"
    # Reads past a RAM's last entry (memory_map of a depth not a power of
    # two) are undriven: any value, so that a proof cannot rely on them.
    echo "setundef -undriven -anyseq"
    echo "async2sync"
    echo "opt -fast"
    echo "dffunmap"
    if [[ " ${P_PARAMS[$n]} " == *" +yosys-sat "* ]]; then
      # yosys's own SAT solver (MiniSat), BMC of K cycles from a free
      # initial state, reset in the first. For models z3 does not solve.
      echo "tee -o $out/$n.sat.log sat -seq ${P_K[$n]} -prove-asserts -set-assumes -set-at 1 rst_ni 0 -show-inputs"
    else
      echo "write_smt2 -wires $out/$n.smt2"
    fi
  } >"$ys"
  "${nice_cmd[@]}" yosys -q -l "$out/$n.yosys.log" -s "$ys" >/dev/null 2>&1 || return 1
  # An undriven probe is one whose signal was not found.
  if grep -q "Wire ${P_TOP[$n]}\.probe_.* is used but has no driver" "$out/$n.yosys.log"; then
    echo "formal: $n: a probe is not connected (see $out/$n.yosys.log)" >&2
    return 1
  fi
}

fail=0
for n in "${run[@]}"; do
  kind=${P_KIND[$n]} k=${P_K[$n]}
  t0=$(date +%s.%N)
  status=PASS
  if [[ " ${P_PARAMS[$n]} " == *" +yosys-sat "* ]]; then
    elaborate "$n"
    if grep -q 'SAT proof finished - no model found: SUCCESS' "$out/$n.sat.log" 2>/dev/null; then
      [ "$kind" = bug ] && status=MISSED || status=PASS
    elif grep -q 'SAT proof finished - model found: FAIL' "$out/$n.sat.log" 2>/dev/null; then
      [ "$kind" = bug ] && status=CAUGHT || status=FAIL
    else
      status=ERROR
    fi
  elif ! elaborate "$n"; then
    status=ERROR
  else
    # +noincr in the parameters: a fresh z3 per query, which lets z3 use its
    # bit-blasting tactic (far faster on the multiplier miters, slower on
    # deep BMC, which gains from incremental solving).
    smt=(yosys-smtbmc -s z3 --presat)
    [[ " ${P_PARAMS[$n]} " == *" +noincr "* ]] && smt+=(--noincr)
    "${nice_cmd[@]}" "${smt[@]}" -t "$k" --dump-vcd "$out/$n.bmc.vcd" "$out/$n.smt2" >"$out/$n.bmc.log" 2>&1
    rc_bmc=$?
    if [ "$kind" = bug ]; then
      if grep -q 'Assert failed' "$out/$n.bmc.log"; then status=CAUGHT
      elif [ $rc_bmc -eq 0 ]; then status=MISSED
      else status=ERROR; fi
    elif [ $rc_bmc -eq 124 ]; then
      status=TIMEOUT
    elif [ $rc_bmc -ne 0 ]; then
      grep -q 'Assert failed' "$out/$n.bmc.log" && status=FAIL || status=ERROR
    elif [ "$kind" = ind ]; then
      "${nice_cmd[@]}" "${smt[@]}" -i -t "$k" --dump-vcd "$out/$n.ind.vcd" \
        "$out/$n.smt2" >"$out/$n.ind.log" 2>&1
      case $? in 0) ;; 124) status=TIMEOUT ;; *) status=FAIL ;; esac
    fi
  fi
  t1=$(date +%s.%N)
  secs=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }')
  case $status in PASS|CAUGHT) ;; *) fail=1 ;; esac
  printf '%-6s %-28s %-3s k=%-4s %8ss\n' "$status" "$n" "$kind" "$k" "$secs"
done
exit $fail
