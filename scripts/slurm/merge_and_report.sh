#!/usr/bin/env bash
# After every shard finished: merge OUTROOT/shard* into OUTROOT/merged and write OUTROOT/report.
#   sbatch --dependency=afterok:JOBID scripts/slurm/merge_and_report.sh OUTROOT
#SBATCH --job-name=momentbench-merge
#SBATCH --cpus-per-task=1
#SBATCH --time=01:00:00
#SBATCH --output=momentbench-merge-%j.log
set -euo pipefail
outroot=$1
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
"$mb" merge "$outroot"/shard* -o "$outroot/merged"
"$mb" report "$outroot/merged" -o "$outroot/report"
