#!/usr/bin/env bash
# Runs a `cube4 explore` sweep on a Slurm cluster: `cube4 explore --emit-jobs`
# writes one command per point (jobs.txt), a job array runs line
# $SLURM_ARRAY_TASK_ID + 1 in each task (sbatch --array), and a collect job
# runs when every task has ended (--dependency=afterany: a failed point is
# in the table as failed, not lost). The results folder must be on a file
# system every node sees, and cube4 must run on every node; points already
# done are skipped, so the script resumes an interrupted sweep.
#   scripts/explore_slurm.sh SWEEP.json --out DIR [--cube4 BIN] [--wait] [-- SBATCH-OPTION...]
# --wait: return when the collect job has finished, with its exit code;
# options after -- go to both sbatch calls (partition, account, time).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
usage() { sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 1 ] || usage
sweep=$1
shift
out="" cube4=$here/build/tb/cube4 wait=0 sbatch_opts=()
while [ $# -gt 0 ]; do
  case $1 in
    --out) out=$2; shift 2 ;;
    --cube4) cube4=$2; shift 2 ;;
    --wait) wait=1; shift ;;
    --) shift; sbatch_opts=("$@"); break ;;
    *) echo "explore_slurm: unknown option $1" >&2; usage ;;
  esac
done
[ -n "$out" ] || { echo "explore_slurm: give --out DIR on a shared file system" >&2; exit 2; }
command -v sbatch >/dev/null || { echo "explore_slurm: sbatch not found (a Slurm client is needed)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
sweep=$(cd "$(dirname "$sweep")" && pwd)/$(basename "$sweep")
"$cube4" explore "$sweep" --out "$out" --emit-jobs -q
n=$(wc -l < "$out/jobs.txt")
cat > "$out/points.sbatch" <<JOB
#!/bin/bash
#SBATCH --job-name=cube4-explore
#SBATCH --array=0-$((n - 1))
#SBATCH --output=$out/slurm-point%a.log
exec bash -c "\$(sed -n "\$((SLURM_ARRAY_TASK_ID + 1))p" "$out/jobs.txt")"
JOB
cat > "$out/collect.sbatch" <<JOB
#!/bin/bash
#SBATCH --job-name=cube4-explore-collect
#SBATCH --output=$out/slurm-collect.log
exec "$cube4" explore "$sweep" --out "$out" --collect
JOB
array=$(sbatch --parsable "${sbatch_opts[@]}" "$out/points.sbatch")
array=${array%%;*}
wait_opt=()
[ $wait = 1 ] && wait_opt=(--wait)
echo "explore_slurm: $n points in job array $array; collect after it" >&2
collect=$(sbatch --parsable --dependency=afterany:"$array" "${wait_opt[@]}" "${sbatch_opts[@]}" "$out/collect.sbatch") ||
  { echo "explore_slurm: collect failed (logs in $out)" >&2; exit 1; }
echo "$array ${collect%%;*}"
