#!/usr/bin/env bash
# Ray marching against the exact in-scattering (docs/scattering.md §3): `momentbench scatter` with
# raymarch:<N> for N = 8, 16, ..., 4096 on a dataset's light views and cameras, one run (the
# reference is computed once); prints a Markdown table of N, the errors of errors.csv's `all` row
# (mean_error, too_bright, too_dark, max_error), mean_error x N (flat where the mean error falls
# like 1/N, docs/scattering.md §3) and the time per view ray.
#   bash scripts/bench_scatter_convergence.sh [MOMENTBENCH] [DATASET] [THREADS]
set -euo pipefail
cd "$(dirname "$0")/.."
mb=$(realpath "${1:-build/release/momentbench}")
dataset=${2:-scattering}
threads=${3:-2}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
ns=(8 16 32 64 128 256 512 1024 2048 4096)
list=$(printf 'raymarch:%s, ' "${ns[@]}")
"$mb" scatter -q --set dataset="$dataset" --set threads="$threads" --set images=false \
  --set "techniques=[exact, ${list%, }]" --out "$work/out" > /dev/null
rays=$(grep -o '[0-9]* view rays in all' "$work/out/report.md" | cut -d' ' -f1)
echo "| N | mean_error | too_bright | too_dark | max_error | mean_error x N | wall µs per ray |"
echo "|---|---|---|---|---|---|---|"
for n in "${ns[@]}"; do
  grep "^\"raymarch:$n\",all,all,all," "$work/out/errors.csv" |
    awk -F, -v n="$n" -v rays="$rays" '{ printf "| %d | %.3e | %.3e | %.3e | %.3e | %.3f | %.2f |\n", n, $5, $6, $7, $8, $5 * n, $9 / rays * 1e6 }'
done
grep '^"exact",all,all,all,' "$work/out/errors.csv" |
  awk -F, -v rays="$rays" '{ printf "\nexact reference: %.2f wall µs per ray (%d rays)\n", $9 / rays * 1e6, rays }'
