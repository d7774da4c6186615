#!/usr/bin/env bash
# What must not change when the LP engine is restructured (issue 30): the answers hash of the four
# lp_bench warm rows (every G's bits, one pass) and the sweep means of three candidates on the
# default dataset with 1 and 2 threads. Prints one line per number; diff two builds' outputs.
#   bash scripts/lp_fingerprint.sh [BUILD_DIR]        (default build/release)
set -euo pipefail
build=${1:-build/release}
python=/usr/bin/python3
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT

"$build/tests/bench/lp_bench" --benchmark_filter='SolveRuns/fast_warm' --benchmark_min_time=0.01 \
    --benchmark_repetitions=1 --benchmark_format=json 2>/dev/null |
  "$python" -c 'import json, sys
for b in json.load(sys.stdin)["benchmarks"]:
    print("answers", b["name"].split("/")[1], "%d" % b["answers"], "pivots %.6f" % b["pivots"])'

candidates='["z; z^2; z^3; z^4", "sin(2 pi z); cos(2 pi z); sin(4 pi z); cos(4 pi z)", "exp(8z); z^6; 1/(1+4z); atan(4z)"]'
for threads in 1 2; do
  "$build/momentbench" sweep -q --set threads=$threads --set 'references=[]' \
      --set "candidates=$candidates" -o "$out/t$threads" >/dev/null
  "$python" - "$out/t$threads" "$threads" <<'PY'
import glob, sqlite3, sys
db = glob.glob(sys.argv[1] + "/*.sqlite")[0]
for name, mean, unstable in sqlite3.connect(db).execute(
        "SELECT name, mean, unstable FROM candidates ORDER BY id"):
    print("sweep threads=%s %-50s %r unstable %d" % (sys.argv[2], name, mean, unstable))
PY
done
