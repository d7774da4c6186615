#!/usr/bin/env bash
# The full sweep's cost on this machine (issue 33): times COUNT seeded candidates of the dataset's
# sweep at 1 and 2 threads, side by side in one run, from the per-candidate seconds the results
# database records (view preparation excluded), and projects all C(37, 4) = 66 045 candidates.
# Prints a markdown table for results/BENCHMARKS.md.
#   scripts/bench_sweep.sh [BINARY] [COUNT] [DATASET] [RESOLUTION]
set -euo pipefail
mb=${1:-build/release/momentbench}
count=${2:-8}
dataset=${3:-default}
resolution=${4:-0}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
total=66045
echo "Dataset $dataset (resolution ${resolution/#0/the dataset\'s}), $count seeded candidates (sample_seed 33), no references."
echo
echo "| threads | s a candidate (mean) | receivers a candidate | LPs solved a candidate | µs core time an LP | projected hours for $total |"
echo "|---|---|---|---|---|---|"
for threads in 1 2; do
  "$mb" sweep -q --set dataset="$dataset" --set resolution="$resolution" --set threads="$threads" \
    --set sample="$count" --set sample_seed=33 --set 'references=[]' -o "$work/t$threads" \
    > /dev/null
  read -r seconds fragments solved < <(sqlite3 -separator ' ' "$work/t$threads/results.sqlite" \
    "SELECT avg(seconds), avg(fragments), avg(solved) FROM candidates")
  /usr/bin/python3 - "$threads" "$seconds" "$fragments" "$solved" "$total" <<'PY'
import sys
threads, seconds, fragments, solved, total = int(sys.argv[1]), *map(float, sys.argv[2:5]), int(sys.argv[5])
print(f"| {threads} | {seconds:.3f} | {fragments:,.0f} | {solved:,.0f} | "
      f"{seconds * threads / solved * 1e6:.2f} | {seconds * total / 3600:.1f} |")
PY
done
