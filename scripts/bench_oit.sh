#!/usr/bin/env bash
# The transparency dataset's densest camera (the smoke cards, up to 30 fragments a pixel) at
# 1280 x 720, end to end through `momentbench oit` (deep frame, every technique, metrics, images),
# once per thread count given; prints the wall time and the frame's fragments (issue 43).
#   bash scripts/bench_oit.sh [MOMENTBENCH] [THREADS...]
set -euo pipefail
cd "$(dirname "$0")/.."
mb=$(realpath "${1:-build/release/momentbench}"); shift || true
threads=("${@:-1 2}")
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
sed -e 's/resolution: \[480, 320\]/resolution: [1280, 720]/' \
    -e "s|\.\./\.\./data/|$PWD/data/|" configs/scenes/particles.yaml > "$work/particles_720p.yaml"
grep -q '1280, 720' "$work/particles_720p.yaml" || { echo "bench_oit: camera resolution not found" >&2; exit 1; }
printf 'name: oit_720p\nscenes: [particles_720p.yaml]\n' > "$work/dataset.yaml"
for t in ${threads[@]}; do
  start=$(date +%s.%N)
  "$mb" oit -q --set dataset="$work/dataset.yaml" --set threads="$t" --out "$work/out_$t" > "$work/table_$t.md"
  end=$(date +%s.%N)
  fragments=$(grep '^"exact",all,' "$work/out_$t/errors.csv" | cut -d, -f4)
  printf 'threads %s: %.2f s wall, %s transparent fragments, every default technique\n' "$t" "$(echo "$end - $start" | bc)" "$fragments"
  grep -E '^\| (wboit|mboit_power4|mboit_trig4|lp:power4) \| all' "$work/table_$t.md" | cut -d'|' -f2,5,9,12
done
