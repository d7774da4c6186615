#!/usr/bin/env bash
# Ratios on a noisy machine (results/BENCHMARKS.md, session 16): runs lp_bench binaries in
# alternation, ROUNDS rounds of 3 randomly interleaved repetitions each, and prints per binary and
# row the median and the best items/s of all its repetitions, and our warm runs' ratio to GLPK by
# each, also with lp_bench's timer cost left in (as sessions before 27 measured). The VM's
# interference only ever adds time, so the best repetition is the one least disturbed (as in
# scripts/bench_best.sh); the median is the established statistic here.
#   bash scripts/bench_alternate.sh ROUNDS BINARY [BINARY ...]
# e.g. bash scripts/bench_alternate.sh 3 /tmp/lp_bench_before build/release/tests/bench/lp_bench
set -euo pipefail
rounds=${1:?rounds}; shift
(($#)) || { echo "usage: $0 ROUNDS BINARY [BINARY ...]" >&2; exit 2; }
log=$(mktemp); trap 'rm -f "$log"' EXIT
pin=(); command -v taskset >/dev/null && pin=(taskset -c "$(($(nproc) - 1))")
for ((round = 1; round <= rounds; ++round)); do
  # Each round in a fresh random order: the VM drifts within a set by as much as the effects
  # measured (results/BENCHMARKS.md, session 26), and a fixed order can turn drift into a bias.
  mapfile -t order < <(printf '%s\n' "$@" | shuf)
  for binary in "${order[@]}"; do
    "${pin[@]}" "$binary" --benchmark_filter="${BENCH_FILTER:-SolveRuns/(fast_warm|glpk)}" --benchmark_repetitions=3 \
        --benchmark_enable_random_interleaving=true 2>/dev/null |
      awk -v b="$binary" '/^BM_SolveRuns/ && !/_(mean|median|stddev|cv) / {
          split($1, name, "/"); rate = ""; share = 0
          for (i = 2; i <= NF; ++i) {
            if ($i ~ /^items_per_second=/) rate = substr($i, 18)
            if ($i ~ /^timer_share=/) share = substr($i, 13)
          }
          if (rate ~ /k\/s$/) rate = substr(rate, 1, length(rate) - 3) * 1e3
          else if (rate ~ /M\/s$/) rate = substr(rate, 1, length(rate) - 3) * 1e6
          else sub(/\/s$/, "", rate)
          if (share ~ /u$/) share = substr(share, 1, length(share) - 1) * 1e-6
          else if (share ~ /m$/) share = substr(share, 1, length(share) - 1) * 1e-3
          # The rate with the timer cost that lp_bench subtracts (its counter timer_share) left in.
          print b, name[2], rate; print b, name[2] ":uncorrected", rate * (1 - share) }' >>"$log"
  done
done
sort -k1,1 -k2,2 -k3,3g "$log" | awk '
  function flush() { if (n) { m[key] = (n % 2) ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2; b[key] = v[n]; cnt[key] = n } }
  { k = $1 " " $2; if (k != key) { flush(); key = k; n = 0 } v[++n] = $3 }
  END { flush()
        for (k in m) { split(k, p, " "); if (p[2] ~ /:uncorrected$/) continue
          printf "%s %-22s median %9.0f LPs/s, best %9.0f (%d runs)\n", p[1], p[2], m[k], b[k], cnt[k] }
        for (k in m) { split(k, p, " "); if (p[2] !~ /^fast_warm_/ || p[2] ~ /:uncorrected$/) continue
          g = p[1] " glpk_" substr(p[2], 11); r = k ":uncorrected"
          if (g in m) printf "%s %-22s ratio to GLPK %.1fx (medians), %.1fx (best); timer cost left in: %.1fx, %.1fx\n",
                             p[1], p[2], m[k] / m[g], b[k] / b[g], m[r] / m[g ":uncorrected"], b[r] / b[g ":uncorrected"] } }' | sort
