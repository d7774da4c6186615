#!/usr/bin/env bash
# One shard of a momentbench sweep as a Slurm job-array task (see README "Sweeps on a cluster").
#   sbatch --array=1-N scripts/slurm/sweep_array.sh CONFIG OUTROOT
# Task K of N runs shard K/N into OUTROOT/shardK; a re-submitted task resumes where it stopped.
# Without Slurm, set the two variables yourself:
#   SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_COUNT=3 bash scripts/slurm/sweep_array.sh CONFIG OUTROOT
#SBATCH --job-name=momentbench-sweep
#SBATCH --cpus-per-task=16
#SBATCH --time=48:00:00
#SBATCH --output=momentbench-sweep-%A_%a.log
set -euo pipefail
config=$1 outroot=$2
k=${SLURM_ARRAY_TASK_ID:?set by Slurm (or by hand)} n=${SLURM_ARRAY_TASK_COUNT:?set by Slurm (or by hand)}
# sbatch runs a copy of this script from its spool directory, so $0 does not locate the checkout:
# submit.sh exports MOMENTBENCH_REPO; a direct sbatch from the checkout falls back to the submit
# directory; by hand, the script's own place.
repo=${MOMENTBENCH_REPO:-}
if [ -z "$repo" ]; then
  if [ -n "${SLURM_SUBMIT_DIR:-}" ] && [ -x "$SLURM_SUBMIT_DIR/build/release/momentbench" ]; then
    repo=$SLURM_SUBMIT_DIR
  else
    repo=$(cd "$(dirname "$0")/../.." && pwd)
  fi
fi
mb=${MOMENTBENCH:-$repo/build/release/momentbench}
threads=${SLURM_CPUS_PER_TASK:-0}
out=$outroot/shard$k
resume=()
[ -e "$out/results.sqlite" ] && resume=(--resume)
mkdir -p "$outroot"
exec "$mb" sweep --config "$config" --set threads="$threads" --shard "$k/$n" "${resume[@]}" -o "$out"
