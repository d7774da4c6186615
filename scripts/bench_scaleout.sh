#!/usr/bin/env bash
# The sweep's scale-out on this machine (issue 33): COUNT seeded candidates of DATASET run as one
# process on every core, then as N shards of one thread side by side (N = cores, 2 x cores), then,
# when a Slurm cluster answers (scripts/slurm/local_cluster.sh), as cores shards through
# scripts/slurm/submit.sh; each with its merge. Wall times include view preparation. Prints a
# markdown table for README "Sweeps" and results/BENCHMARKS.md.
#   scripts/bench_scaleout.sh [BINARY] [COUNT] [DATASET]
set -euo pipefail
mb=$(realpath "${1:-build/release/momentbench}")
count=${2:-8}
dataset=${3:-default}
cores=$(nproc)
work=$(mktemp -d /tmp/scaleout.XXXXXX)
trap 'rm -rf "$work"' EXIT
config="$work/config.yaml"
cat > "$config" <<YAML
dataset: $dataset
sample: $count
sample_seed: 33
references: []
lp:
  grid: 256
YAML
now() { date +%s.%N; }
query() { /usr/bin/python3 -c "import sqlite3, sys; print(*sqlite3.connect(sys.argv[1]).execute(sys.argv[2]).fetchone())" "$@"; }
declare -A wall merge core
run_shards() {  # name shards threads
  local name=$1 n=$2 threads=$3 start
  start=$(now)
  for k in $(seq 1 "$n"); do
    "$mb" sweep -q --config "$config" --set threads="$threads" --shard "$k/$n" -o "$work/$name/shard$k" &
  done
  wait
  wall[$name]=$(echo "$(now) - $start" | bc)
  start=$(now)
  "$mb" merge "$work/$name"/shard* -o "$work/$name/merged" > /dev/null
  merge[$name]=$(printf "%.2f" "$(echo "$(now) - $start" | bc)")
  core[$name]=$(query "$work/$name/merged/results.sqlite" "SELECT sum(seconds) FROM candidates")
}
run_shards one 1 "$cores"
run_shards "x$cores" "$cores" 1
run_shards "x$((2 * cores))" "$((2 * cores))" 1
rows=(one "x$cores" "x$((2 * cores))")
if command -v sinfo > /dev/null && sinfo -h > /dev/null 2>&1; then
  start=$(now)
  # From the work directory: the jobs' logs (sbatch --output) land there, not in the checkout.
  submit=$(realpath scripts/slurm/submit.sh)
  (cd "$work" && MOMENTBENCH="$mb" bash "$submit" "$config" "$work/slurm" "$cores" \
    --cpus-per-task=1 --time=1:00:00 > /dev/null)
  until [ -e "$work/slurm/report/report.md" ] || [ -z "$(squeue -h 2>/dev/null)" ]; do sleep 0.5; done
  until [ -z "$(squeue -h 2>/dev/null)" ]; do sleep 0.5; done
  [ -e "$work/slurm/report/report.md" ] || { echo "bench_scaleout: the Slurm jobs left no report" >&2; exit 1; }
  wall[slurm]=$(echo "$(now) - $start" | bc)
  merge[slurm]=-
  core[slurm]=$(query "$work/slurm/merged/results.sqlite" "SELECT sum(seconds) FROM candidates")
  rows+=(slurm)
fi
echo "Dataset $dataset, $count seeded candidates (sample_seed 33), $cores cores; wall times include view preparation."
echo
echo "| run | shards x threads | wall s | merge s | candidate-seconds in the database | throughput against one process |"
echo "|---|---|---|---|---|---|"
for name in "${rows[@]}"; do
  case $name in
  one) layout="1 x $cores" ;;
  slurm) layout="$cores x 1 (Slurm array + merge job)" ;;
  *) layout="${name#x} x 1" ;;
  esac
  printf "| %s | %s | %.1f | %s | %.1f | %.2f |\n" "$name" "$layout" "${wall[$name]}" "${merge[$name]}" \
    "${core[$name]}" "$(echo "${wall[one]} / ${wall[$name]}" | bc -l)"
done
