#!/usr/bin/env bash
# After every shard finished: merge OUTROOT/shard* into OUTROOT/merged and write OUTROOT/report.
#   sbatch --dependency=afterok:JOBID scripts/slurm/merge_and_report.sh OUTROOT
#SBATCH --job-name=momentbench-merge
#SBATCH --cpus-per-task=1
#SBATCH --time=01:00:00
#SBATCH --output=momentbench-merge-%j.log
set -euo pipefail
outroot=$1
# sbatch runs a spooled copy of this script, so $0 does not locate the checkout: submit.sh
# exports MOMENTBENCH_REPO, and a direct sbatch from the checkout's root is found by its submit dir.
repo=${MOMENTBENCH_REPO:-$(cd "$(dirname "$0")/../.." && pwd)}
[ -z "${MOMENTBENCH_REPO:-}" ] && [ -n "${SLURM_JOB_ID:-}" ] && repo=${SLURM_SUBMIT_DIR:-$repo}
mb=${MOMENTBENCH:-$repo/build/release/momentbench}
"$mb" merge "$outroot"/shard* -o "$outroot/merged"
"$mb" report "$outroot/merged" -o "$outroot/report"
