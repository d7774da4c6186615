#!/usr/bin/env bash
# Submits an N-shard sweep and its merge: scripts/slurm/submit.sh CONFIG OUTROOT N
set -euo pipefail
config=$1 outroot=$2 n=$3
here=$(cd "$(dirname "$0")" && pwd)
job=$(sbatch --parsable --array=1-"$n" "$here/sweep_array.sh" "$config" "$outroot")
sbatch --dependency=afterok:"$job" "$here/merge_and_report.sh" "$outroot"
echo "submitted sweep array $job ($n shards) and its merge"
