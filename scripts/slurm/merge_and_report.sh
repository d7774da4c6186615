#!/usr/bin/env bash
# After every shard finished: merge OUTROOT/shard* into OUTROOT/merged (and, for a screened sweep,
# evaluate its best candidates exactly there) and write OUTROOT/report.
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
# A screened sweep (screen.fraction > 0) confirms its best candidates once every shard's estimates
# are merged: the same config, resumed in the merged directory.
screened=$(/usr/bin/python3 -c "import sqlite3, sys; print(sqlite3.connect(sys.argv[1]).execute('select count(*) from estimates').fetchone()[0])" "$outroot/merged/results.sqlite")
if [ "$screened" -gt 0 ]; then
  "$mb" sweep --config "$outroot/merged/config.yaml" --set threads="${SLURM_CPUS_PER_TASK:-0}" \
    --resume -o "$outroot/merged"
fi
"$mb" report "$outroot/merged" -o "$outroot/report"
