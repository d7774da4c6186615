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
# sbatch runs a spooled copy of this script, so $0 does not locate the checkout: submit.sh
# exports MOMENTBENCH_REPO, and a direct sbatch from the checkout's root is found by its submit dir.
repo=${MOMENTBENCH_REPO:-$(cd "$(dirname "$0")/../.." && pwd)}
[ -z "${MOMENTBENCH_REPO:-}" ] && [ -n "${SLURM_JOB_ID:-}" ] && repo=${SLURM_SUBMIT_DIR:-$repo}
mb=${MOMENTBENCH:-$repo/build/release/momentbench}
threads=${SLURM_CPUS_PER_TASK:-0}
out=$outroot/shard$k
# --resume continues the shard's database, or starts the shard when it has none yet (a task
# killed before its database existed included).
resume=(--resume)
mkdir -p "$outroot"
exec "$mb" sweep --config "$config" --set threads="$threads" --shard "$k/$n" "${resume[@]}" -o "$out"
