#!/usr/bin/env bash
# Renders a scene as blocks on a Slurm cluster: a job array of one cube4
# process per block (sbatch --array), then a compose job that runs when
# every block has succeeded (--dependency=afterok). The work folder must be
# on a file system every node sees; cube4 must run on every node.
#   scripts/render_blocks_slurm.sh SCENE AxBxC OUT.png --work DIR [--model M] [--network tlm|rtl]
#                                  [--cube4 BIN] [--wait] [-- SBATCH-OPTION...]
# --wait: return when the compose job has finished, with its exit code;
# options after -- go to both sbatch calls (partition, account, time).
# Prints the two job ids. The image equals one process's
# `cube4 render --blocks AxBxC` bit for bit.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
usage() { sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 3 ] || usage
scene=$1 counts=$2 out=$3
shift 3
model=tlm network="" work="" cube4=$here/build/tb/cube4 wait=0 sbatch_opts=()
while [ $# -gt 0 ]; do
  case $1 in
    --model) model=$2; shift 2 ;;
    --network) network=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --cube4) cube4=$2; shift 2 ;;
    --wait) wait=1; shift ;;
    --) shift; sbatch_opts=("$@"); break ;;
    *) echo "render_blocks_slurm: unknown option $1" >&2; usage ;;
  esac
done
[ -n "$work" ] || { echo "render_blocks_slurm: give --work DIR on a shared file system" >&2; exit 2; }
[ -n "$network" ] || { [ "$model" = rtl ] && network=rtl || network=tlm; }
command -v sbatch >/dev/null || { echo "render_blocks_slurm: sbatch not found (a Slurm client is needed)" >&2; exit 2; }
mkdir -p "$work"
work=$(cd "$work" && pwd)
out=$(cd "$(dirname "$out")" && pwd)/$(basename "$out")
n=$("$cube4" plan "$scene" --blocks "$counts" -o "$work/plan.json")
cat > "$work/blocks.sbatch" <<JOB
#!/bin/bash
#SBATCH --job-name=cube4-blocks
#SBATCH --array=0-$((n - 1))
#SBATCH --output=$work/block%a.log
exec "$cube4" render --plan "$work/plan.json" --block "\$SLURM_ARRAY_TASK_ID" \\
  --partial "$work/block\$SLURM_ARRAY_TASK_ID.cpart" --model "$model" -q --report "$work/block\$SLURM_ARRAY_TASK_ID.json"
JOB
parts=""
for ((i = 0; i < n; ++i)); do parts+=" \"$work/block$i.cpart\""; done
cat > "$work/compose.sbatch" <<JOB
#!/bin/bash
#SBATCH --job-name=cube4-compose
#SBATCH --output=$work/compose.log
exec "$cube4" compose "$work/plan.json"$parts -o "$out" --model "$network" -q --report "$work/compose.json"
JOB
array=$(sbatch --parsable "${sbatch_opts[@]}" "$work/blocks.sbatch")
array=${array%%;*}
wait_opt=()
[ $wait = 1 ] && wait_opt=(--wait)
echo "render_blocks_slurm: $n blocks in job array $array; compose after it" >&2
compose=$(sbatch --parsable --dependency=afterok:"$array" --kill-on-invalid-dep=yes "${wait_opt[@]}" \
  "${sbatch_opts[@]}" "$work/compose.sbatch") || { echo "render_blocks_slurm: compose failed (logs in $work)" >&2; exit 1; }
echo "$array ${compose%%;*}"
