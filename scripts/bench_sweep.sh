#!/usr/bin/env bash
# The full sweep's cost on this machine (issue 33), exact and screened, at 1 and 2 threads, side by
# side in one run; prints markdown tables for results/BENCHMARKS.md.
#   scripts/bench_sweep.sh [BINARY] [COUNT] [DATASET] [RESOLUTION] [SCREENED] [FRACTION] [BEFORE]
# Exact: COUNT seeded candidates (sample_seed 33), the per-candidate seconds the results database
# records (view preparation excluded), projected to all C(37, 4) = 66 045. With BEFORE (another
# build's binary), the same candidates by it first: before and after in one run.
# Screened: SCREENED seeded candidates at `--screen FRACTION` with screen.top = 1. The projection
# is 66 045 screened candidates, the exact pilot, and the exact confirmations: the share of the
# sample that reached its best estimate, times 66 045. (The full sweep confirms those reaching its
# 20th best of 66 045, a better mean than the best of a few hundred, so fewer: the projection errs
# long.)
set -euo pipefail
mb=${1:-build/release/momentbench}
count=${2:-8}
dataset=${3:-default}
resolution=${4:-0}
screened=${5:-200}
fraction=${6:-0.05}
before=${7:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
total=66045
common=(--set dataset="$dataset" --set resolution="$resolution" --set sample_seed=33 --set 'references=[]')
query() { /usr/bin/python3 -c "import sqlite3, sys; print(*sqlite3.connect(sys.argv[1]).execute(sys.argv[2]).fetchone())" "$@"; }

echo "Dataset $dataset (resolution ${resolution/#0/the dataset\'s}), seeded candidates (sample_seed 33), no references; $(nproc) cores."
echo
echo "Exact: $count candidates."
echo
echo "| binary | threads | s a candidate (mean) | LPs solved a candidate | µs core time an LP | projected hours for $total |"
echo "|---|---|---|---|---|---|"
declare -A exact_seconds
for binary in $before "$mb"; do
  label=$([ "$binary" = "$mb" ] && echo after || echo before)
  [ -z "$before" ] && label=this
  for threads in 1 2; do
    out="$work/exact-$label-$threads"
    "$binary" sweep -q "${common[@]}" --set threads="$threads" --set sample="$count" -o "$out" > /dev/null
    read -r seconds solved < <(query "$out/results.sqlite" "SELECT avg(seconds), avg(solved) FROM candidates")
    exact_seconds[$threads]=$seconds
    /usr/bin/python3 - "$label" "$threads" "$seconds" "$solved" "$total" <<'PY'
import sys
label, threads, seconds, solved, total = sys.argv[1], int(sys.argv[2]), *map(float, sys.argv[3:5]), int(sys.argv[5])
print(f"| {label} | {threads} | {seconds:.3f} | {solved:,.0f} | "
      f"{seconds * threads / solved * 1e6:.2f} | {seconds * total / 3600:.1f} |")
PY
  done
done

echo
echo "Screened: $screened candidates at \`--screen $fraction\`, screen.top 1."
echo
echo "| threads | s a screened candidate | LPs a screened candidate | confirmed of $screened | projected confirmations | projected hours for $total (screen + pilot + confirmations) |"
echo "|---|---|---|---|---|---|"
for threads in 1 2; do
  out="$work/screen-$threads"
  "$mb" sweep -q "${common[@]}" --set threads="$threads" --set sample="$screened" \
    --screen "$fraction" --set screen.top=1 -o "$out" > /dev/null
  read -r seconds lps < <(query "$out/results.sqlite" "SELECT avg(seconds), avg(solved) FROM estimates")
  read -r confirmed < <(query "$out/results.sqlite" "SELECT count(*) FROM candidates")
  /usr/bin/python3 - "$threads" "$seconds" "$lps" "$confirmed" "$screened" "${exact_seconds[$threads]}" "$total" <<'PY'
import sys
threads = int(sys.argv[1])
seconds, lps = float(sys.argv[2]), float(sys.argv[3])
confirmed, screened = int(sys.argv[4]), int(sys.argv[5])
exact, total = float(sys.argv[6]), int(sys.argv[7])
projected = confirmed / screened * total
hours = (total * seconds + (1 + projected) * exact) / 3600
print(f"| {threads} | {seconds:.3f} | {lps:,.0f} | {confirmed} | {projected:,.0f} | {hours:.2f} |")
PY
done
