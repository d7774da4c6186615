#!/usr/bin/env bash
# The full sweep's cost on this machine (issue 33), exact and screened, at 1 and 2 threads, side by
# side in one run; prints markdown tables for results/BENCHMARKS.md.
#   scripts/bench_sweep.sh [BINARY] [COUNT] [DATASET] [RESOLUTION] [SCREENED] [FRACTION] [REFINE]
#                          [MARGIN] [BEFORE]
# Exact: COUNT seeded candidates (sample_seed 33), the per-candidate seconds the results database
# records (view preparation excluded), projected to all C(37, 4) = 66 045. With BEFORE (another
# build's binary), the same candidates by it first: before and after in one run.
# Screened: SCREENED seeded candidates at `--screen FRACTION`, screen.refine = REFINE,
# screen.top = 1 and screen.margin = MARGIN (defaults: configs/sweeps/full-screened.yaml's). The
# projection: 66 045 candidates screened, the shares of the sample that reached the refining
# stage and the exact stage times 66 045, and the exact pilot. (The full sweep compares with its
# 20th best of 66 045, a better mean than the best of a few hundred, so fewer reach it: the
# projection errs long.)
set -euo pipefail
mb=${1:-build/release/momentbench}
count=${2:-8}
dataset=${3:-default}
resolution=${4:-0}
screened=${5:-200}
fraction=${6:-0.05}
refine=${7:-0.25}
margin=${8:--1e-4}
before=${9:-}
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
echo "Screened: $screened candidates at \`--screen $fraction\`, screen.refine $refine, screen.top 1, screen.margin $margin."
echo
echo "| threads | s a screened candidate | s a refined candidate | LPs screened / refined | refined of $screened | exact of $screened | projected hours for $total: screen + refine + exact = total |"
echo "|---|---|---|---|---|---|---|"
for threads in 1 2; do
  out="$work/screen-$threads"
  "$mb" sweep -q "${common[@]}" --set threads="$threads" --set sample="$screened" \
    --screen "$fraction" --set screen.refine="$refine" --set screen.top=1 \
    --set screen.margin="$margin" -o "$out" > /dev/null
  read -r s1 l1 < <(query "$out/results.sqlite" "SELECT avg(seconds), avg(solved) FROM estimates WHERE stage = 1")
  read -r s2 l2 n2 < <(query "$out/results.sqlite" "SELECT coalesce(avg(seconds), 0), coalesce(avg(solved), 0), count(*) FROM estimates WHERE stage = 2")
  read -r n3 < <(query "$out/results.sqlite" "SELECT count(*) FROM candidates")
  /usr/bin/python3 - "$threads" "$s1" "$l1" "$s2" "$l2" "$n2" "$n3" "$screened" "${exact_seconds[$threads]}" "$total" <<'PY'
import sys
threads = int(sys.argv[1])
s1, l1, s2, l2 = map(float, sys.argv[2:6])
n2, n3, screened = int(sys.argv[6]), int(sys.argv[7]), int(sys.argv[8])
exact, total = float(sys.argv[9]), int(sys.argv[10])
h1 = total * s1 / 3600
h2 = n2 / screened * total * s2 / 3600
h3 = (1 + n3 / screened * total) * exact / 3600
print(f"| {threads} | {s1:.3f} | {s2:.3f} | {l1:,.0f} / {l2:,.0f} | {n2} | {n3} | "
      f"{h1:.2f} + {h2:.2f} + {h3:.2f} = {h1 + h2 + h3:.2f} |")
PY
done
