#!/usr/bin/env bash
# Small speed differences on a noisy machine (results/bench-log/sessions-01-35.md, session 20): runs lp_bench
# binaries in alternation, ROUNDS rounds of 10 short repetitions each, and prints per row and binary
# the best, 80th-percentile and median items/s, each also as a ratio to the first binary. Noise
# only ever slows a repetition down, so the fast end of the distribution moves least.
#   bash scripts/bench_best.sh ROUNDS FILTER BINARY [BINARY ...]
# e.g. bash scripts/bench_best.sh 4 'SolveRuns/fast_warm_.*_256' /tmp/lp_bench_before build/release/tests/bench/lp_bench
set -euo pipefail
rounds=${1:?rounds}; filter=${2:?filter}; shift 2
(($#)) || { echo "usage: $0 ROUNDS FILTER BINARY [BINARY ...]" >&2; exit 2; }
python=/usr/bin/python3
log=$(mktemp); trap 'rm -f "$log"' EXIT
pin=(); command -v taskset >/dev/null && pin=(taskset -c "$(($(nproc) - 1))")
for ((round = 1; round <= rounds; ++round)); do
  # Each round in a fresh random order: the VM drifts within a set by as much as the effects
  # measured (results/bench-log/sessions-01-35.md, session 26), and a fixed order can turn drift into a bias.
  mapfile -t order < <(printf '%s\n' "$@" | shuf)
  for binary in "${order[@]}"; do
    "${pin[@]}" "$binary" --benchmark_filter="$filter" --benchmark_min_time=0.05 --benchmark_repetitions=10 \
        --benchmark_format=json 2>/dev/null |
      "$python" -c 'import json, sys
for b in json.load(sys.stdin)["benchmarks"]:
    if b.get("run_type") == "iteration": print(sys.argv[1], b["name"].split("/")[1], b["items_per_second"])' "$binary" >>"$log"
  done
done
"$python" - "$log" "$@" <<'PY'
import collections, sys
rates = collections.defaultdict(list)
for line in open(sys.argv[1]):
    binary, row, rate = line.split()
    rates[(row, binary)].append(float(rate))
binaries = sys.argv[2:]
def quantile(values, q):
    values = sorted(values)
    return values[min(len(values) - 1, int(q * len(values)))]
for row in sorted({r for r, _ in rates}):
    first = rates[(row, binaries[0])]
    for binary in binaries:
        v = rates[(row, binary)]
        cells = ["%s %8.0f (%.3f)" % (name, quantile(v, q), quantile(v, q) / quantile(first, q))
                 for name, q in (("best", 1.0), ("p80", 0.8), ("median", 0.5))]
        print("%-22s %-40s %s  n=%d" % (row, binary[-40:], "  ".join(cells), len(v)))
PY
