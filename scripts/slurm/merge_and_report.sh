#!/usr/bin/env bash
# After every shard finished: merge OUTROOT/shard* into OUTROOT/merged and write OUTROOT/report.
#   sbatch --dependency=afterok:JOBID scripts/slurm/merge_and_report.sh OUTROOT
#SBATCH --job-name=momentbench-merge
#SBATCH --cpus-per-task=1
#SBATCH --time=01:00:00
#SBATCH --output=momentbench-merge-%j.log
set -euo pipefail
outroot=$1
repo=$(cd "$(dirname "$0")/../.." && pwd)
mb=${MOMENTBENCH:-$repo/build/release/momentbench}
"$mb" merge "$outroot"/shard* -o "$outroot/merged"
"$mb" report "$outroot/merged" -o "$outroot/report"
