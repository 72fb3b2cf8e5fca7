#!/usr/bin/env bash
# Submits a randomised peg-transfer batch as a Slurm job array: one array task per shard, each
# running its share of the runs one after another and writing its own results into DIR.
#
#   scripts/slurm/submit-batch.sh --out DIR --runs 1000 --shards 50 [--seed 1] -- --randomize
#   build/scenario/raven_batch merge DIR               # whole? else it names the shards to rerun
#   scripts/slurm/submit-batch.sh --out DIR --array 7,23   # rerun only those (the plan is kept)
#
# Per-cluster settings are flags or environment (flags win): --partition (RAVEN_SLURM_PARTITION),
# --time (RAVEN_SLURM_TIME, per task), --cpus-per-task (RAVEN_SLURM_CPUS_PER_TASK, default 1;
# each task runs that many runs at once), --max-running (array throttle, %M), --wait (when
# every task has ended, merge and exit with the merge's status: 0 whole, 3 shards to rerun;
# squeue is asked every RAVEN_SLURM_POLL seconds, default 10).
# sbatch's own SBATCH_* variables (SBATCH_ACCOUNT, SBATCH_QOS, ...) apply as usual.
# RAVEN_BUILD: the build folder on a path every node sees (default: this checkout's build/).
# Task logs: DIR/slurm/shard-<i>-job<id>.out.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${RAVEN_BUILD:-$here/../../build}
partition=${RAVEN_SLURM_PARTITION:-}
time_limit=${RAVEN_SLURM_TIME:-}
cpus=${RAVEN_SLURM_CPUS_PER_TASK:-1}
poll=${RAVEN_SLURM_POLL:-10}
out="" runs="" shards="" seed=0 array="" max_running="" wait=""
options=()

usage() {
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "${BASH_SOURCE[0]}" >&2
  exit 2
}
while [[ $# -gt 0 ]]; do
  case $1 in
    --out) out=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --shards) shards=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --array) array=$2; shift 2 ;;
    --partition) partition=$2; shift 2 ;;
    --time) time_limit=$2; shift 2 ;;
    --cpus-per-task) cpus=$2; shift 2 ;;
    --max-running) max_running=$2; shift 2 ;;
    --wait) wait=yes; shift ;;
    --) shift; options=("$@"); break ;;
    -h|--help) usage ;;
    *) echo "submit-batch.sh: unknown option '$1'" >&2; usage ;;
  esac
done
[[ -n $out ]] || { echo "submit-batch.sh: --out DIR is needed" >&2; usage; }
raven_batch=$(realpath "$build/scenario/raven_batch" 2>/dev/null) || true
[[ -x $raven_batch ]] || {
  echo "submit-batch.sh: no raven_batch in $build/scenario (build it, or set RAVEN_BUILD)" >&2
  exit 1
}
command -v sbatch >/dev/null || { echo "submit-batch.sh: sbatch not found (install slurm-wlm)" >&2; exit 1; }
out=$(realpath -m "$out")

if [[ -n $runs || -n $shards ]]; then
  [[ -n $runs && -n $shards ]] || { echo "submit-batch.sh: a new batch needs --runs and --shards" >&2; exit 2; }
  "$raven_batch" plan "$out" --runs "$runs" --shards "$shards" --seed "$seed" -- "${options[@]}"
elif [[ ! -f $out/batch.json ]]; then
  echo "submit-batch.sh: $out has no plan: give --runs and --shards for a new batch" >&2
  exit 2
fi
shards=$(/usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["shards"])' "$out/batch.json")
array=${array:-1-$shards}
mkdir -p "$out/slurm"

args=(--parsable --array="$array${max_running:+%$max_running}" --cpus-per-task="$cpus"
  --output="$out/slurm/shard-%a-job%A.out" --chdir="$out")
[[ -n $partition ]] && args+=(--partition="$partition")
[[ -n $time_limit ]] && args+=(--time="$time_limit")
job=$(sbatch "${args[@]}" "$here/peg-transfer-shard.sbatch" "$raven_batch" "$out")
job=${job%%;*}  # --parsable: "id" or "id;cluster"
echo "submitted job $job: shards $array of $shards, results in $out"
if [[ -z $wait ]]; then
  echo "when it is done: $raven_batch merge $out"
  exit 0
fi
# Not sbatch --wait: when a task is cancelled it takes its caller's pipeline down with it.
while [[ -n $(squeue --noheader --jobs "$job" --format %i 2>/dev/null) ]]; do sleep "$poll"; done
exec "$raven_batch" merge "$out"  # every task has ended: is the batch whole?
