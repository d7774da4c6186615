#!/usr/bin/env bash
# Submits an N-shard sweep and its merge: scripts/slurm/submit.sh CONFIG OUTROOT N [SBATCH OPTION...]
# Options after N go to both sbatch calls and override the scripts' #SBATCH lines, e.g.
# --cpus-per-task=2 --time=2:00:00 --partition=short.
set -euo pipefail
config=$1 outroot=$2 n=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
export MOMENTBENCH_REPO=${MOMENTBENCH_REPO:-$(cd "$here/../.." && pwd)}
job=$(sbatch --parsable "$@" --array=1-"$n" "$here/sweep_array.sh" "$config" "$outroot")
# The merge needs one core, unless the sweep is screened: then it also confirms the best candidates
# exactly, with the shards' cores.
merge_cpus=(--cpus-per-task=1)
grep -Eq "^screen(:|\.)" "$config" && merge_cpus=()
merge=$(sbatch --parsable "$@" "${merge_cpus[@]}" --dependency=afterok:"$job" "$here/merge_and_report.sh" "$outroot")
echo "submitted sweep array $job ($n shards) and its merge $merge"
