#!/usr/bin/env bash
# Renders a scene as blocks, one cube4 process per block, run by GNU
# parallel, then composes their partial images through the composition
# network (tb/block_jobs.hpp). The image equals one process's
# `cube4 render --blocks AxBxC` bit for bit.
#   scripts/render_blocks.sh SCENE AxBxC OUT.png [--model M] [--network tlm|rtl]
#                            [-j N] [--work DIR] [--cube4 BIN] [--baseplane F.png] [--report F.json]
# --model: the machines' level (fixed, tlm, rtl, mixed:...; default tlm);
# --network: the network's (default: rtl when --model is rtl, else tlm);
# -j: parallel jobs (default: one per core); --work: where the plan, the
# partial images and each block's report and log go (default: a temporary
# folder, removed afterwards). Exit: 0, or the first failing job's code.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
usage() { sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 3 ] || usage
scene=$1 counts=$2 out=$3
shift 3
model=tlm network="" jobs=$(nproc) work="" cube4=$here/build/tb/cube4 extra=()
while [ $# -gt 0 ]; do
  case $1 in
    --model) model=$2; shift 2 ;;
    --network) network=$2; shift 2 ;;
    -j) jobs=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --cube4) cube4=$2; shift 2 ;;
    --baseplane|--report) extra+=("$1" "$2"); shift 2 ;;
    *) echo "render_blocks: unknown option $1" >&2; usage ;;
  esac
done
[ -n "$network" ] || { [ "$model" = rtl ] && network=rtl || network=tlm; }
command -v parallel >/dev/null || { echo "render_blocks: GNU parallel is not installed (apt-get install parallel)" >&2; exit 2; }
if [ -z "$work" ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"
n=$("$cube4" plan "$scene" --blocks "$counts" -o "$work/plan.json")
echo "render_blocks: $n blocks, $jobs at a time (machines: $model, network: $network)" >&2
seq 0 $((n - 1)) | parallel --will-cite --halt now,fail=1 -j "$jobs" \
  "$cube4" render --plan "$work/plan.json" --block {} --partial "$work/block{}.cpart" --model "$model" -q \
  --report "$work/block{}.json" ">" "$work/block{}.log" "2>&1" \
  || { code=$?; echo "render_blocks: a block failed (logs in $work/block*.log)" >&2; tail -n 3 "$work"/block*.log >&2 || true; exit $code; }
parts=()
for ((i = 0; i < n; ++i)); do parts+=("$work/block$i.cpart"); done
"$cube4" compose "$work/plan.json" "${parts[@]}" -o "$out" --model "$network" -q "${extra[@]}"
echo "render_blocks: $out" >&2
