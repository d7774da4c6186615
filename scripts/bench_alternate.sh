#!/usr/bin/env bash
# Ratios on a noisy machine (results/bench-log/sessions-01-35.md, session 16): runs lp_bench binaries in
# alternation, ROUNDS rounds of 3 randomly interleaved repetitions each, and prints per binary and
# row the median and the best items/s of all its repetitions, and our warm runs' ratio to GLPK by
# each. The VM's interference only ever adds time, so the best repetition is the one least
# disturbed (as in scripts/bench_best.sh); the median is the established statistic here.
#   bash scripts/bench_alternate.sh ROUNDS BINARY [BINARY ...]
# e.g. bash scripts/bench_alternate.sh 3 /tmp/lp_bench_before build/release/tests/bench/lp_bench
set -euo pipefail
rounds=${1:?rounds}; shift
(($#)) || { echo "usage: $0 ROUNDS BINARY [BINARY ...]" >&2; exit 2; }
log=$(mktemp); trap 'rm -f "$log"' EXIT
pin=(); command -v taskset >/dev/null && pin=(taskset -c "$(($(nproc) - 1))")
for ((round = 1; round <= rounds; ++round)); do
  # Each round in a fresh random order: the VM drifts within a set by as much as the effects
  # measured (results/bench-log/sessions-01-35.md, session 26), and a fixed order can turn drift into a bias.
  mapfile -t order < <(printf '%s\n' "$@" | shuf)
  for binary in "${order[@]}"; do
    "${pin[@]}" "$binary" --benchmark_filter="${BENCH_FILTER:-SolveRuns/(fast_warm|glpk)}" --benchmark_repetitions=3 \
        --benchmark_enable_random_interleaving=true 2>/dev/null |
      awk -v b="$binary" '/^BM_SolveRuns/ && !/_(mean|median|stddev|cv) / {
          split($1, name, "/"); rate = ""
          for (i = 2; i <= NF; ++i) if ($i ~ /^items_per_second=/) rate = substr($i, 18)
          if (rate ~ /k\/s$/) rate = substr(rate, 1, length(rate) - 3) * 1e3
          else if (rate ~ /M\/s$/) rate = substr(rate, 1, length(rate) - 3) * 1e6
          else sub(/\/s$/, "", rate)
          print b, name[2], rate }' >>"$log"
  done
done
sort -k1,1 -k2,2 -k3,3g "$log" | awk '
  function flush() { if (n) { m[key] = (n % 2) ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2; b[key] = v[n]; cnt[key] = n } }
  { k = $1 " " $2; if (k != key) { flush(); key = k; n = 0 } v[++n] = $3 }
  END { flush()
        for (k in m) { split(k, p, " "); printf "%s %-22s median %9.0f LPs/s, best %9.0f (%d runs)\n", p[1], p[2], m[k], b[k], cnt[k] }
        for (k in m) { split(k, p, " "); if (p[2] !~ /^fast_warm_/) continue
          g = p[1] " glpk_" substr(p[2], 11)
          if (g in m) printf "%s %-22s ratio to GLPK %.1fx (medians), %.1fx (best)\n", p[1], p[2], m[k] / m[g], b[k] / b[g] } }' | sort
