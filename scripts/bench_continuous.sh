#!/usr/bin/env bash
# The continuous Problem 1 (lp.discretization=continuous, docs/reference.md §2) against the grid (256
# points, warm-started) on the default dataset: per candidate, eval's wall time and mean error in
# both modes, side by side in one run. Candidates: power4, trig4 and COUNT seeded random
# 4-function combinations of the catalog. Prints a markdown table for results/BENCHMARKS.md.
#   scripts/bench_continuous.sh [BINARY] [RESOLUTION] [COUNT] [THREADS]
set -euo pipefail
mb=${1:-build/release/momentbench}
resolution=${2:-32}
count=${3:-20}
threads=${4:-2}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The catalog in order, from the source (docs/reference.md §5).
mapfile -t catalog < <(grep -o '^      {"[^"]*", \[\]' "$root/src/basis/basis.cpp" | sed 's/^      {"//; s/", \[\]$//')
candidates=(power4 trig4)
mapfile -t -O 2 candidates < <(/usr/bin/python3 - "$count" "${catalog[@]}" <<'PY'
import random, sys
count, names = int(sys.argv[1]), sys.argv[2:]
rng = random.Random(2015)
for _ in range(count):
    print(";".join(names[i] for i in sorted(rng.sample(range(len(names)), 4))))
PY
)
calc() { /usr/bin/python3 -c "print($1)"; }
mean_of() {  # the all-views mean error % of the technique row in eval's stdout
  awk -F'|' 'NR == 3 { gsub(/ /, "", $5); print $5 }' "$1"
}
# Rendering and the views' preparation, timed alone (pcf needs no LP): subtracted from both modes,
# so that the ratio is the LPs' own.
start=$(date +%s.%N)
"$mb" eval -q --set "techniques=[pcf]" --set resolution="$resolution" --set threads="$threads" \
  --out "$work/base" --force > /dev/null
base=$(calc "$(date +%s.%N) - $start")
printf 'Resolution %s, %s threads; the fixed part (eval with pcf alone) took %.2f s and is subtracted.\n\n' \
  "$resolution" "$threads" "$base"
echo "| candidate | grid 256: LP s | continuous: LP s | LP time ratio | grid mean error % | continuous mean error % | continuous - grid, pp |"
echo "|---|---|---|---|---|---|---|"
total_grid=0 total_cont=0
for c in "${candidates[@]}"; do
  row="| \`$c\` |"
  for disc in grid continuous; do
    start=$(date +%s.%N)
    "$mb" eval -q --set "techniques=[lp:$c]" --set resolution="$resolution" --set threads="$threads" \
      --set lp.discretization=$disc --out "$work/$disc" --force > "$work/$disc.txt"
    end=$(date +%s.%N)
    t=$(calc "max(0.01, $end - $start - $base)")
    eval "time_$disc=$t"
    eval "mean_$disc=$(mean_of "$work/$disc.txt")"
  done
  total_grid=$(calc "$total_grid + $time_grid")
  total_cont=$(calc "$total_cont + $time_continuous")
  printf '%s %.2f | %.2f | %.1f | %s | %s | %.4f |\n' "$row" "$time_grid" "$time_continuous" \
    "$(calc "$time_continuous / $time_grid")" "$mean_grid" "$mean_continuous" \
    "$(calc "$mean_continuous - $mean_grid")"
done
printf '| all %d | %.1f | %.1f | %.1f | | | |\n' "${#candidates[@]}" "$total_grid" "$total_cont" \
  "$(calc "$total_cont / $total_grid")"
