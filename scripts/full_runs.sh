#!/usr/bin/env bash
# The full-scale experiments of issue 60 (results/sweep-<dataset>-full/README.md), one resumable
# run at a time:
#   scripts/full_runs.sh MOMENTBENCH RUNROOT NAME [--set KEY=VALUE ...]
# runs the sweep NAME (below) into RUNROOT/NAME with `--resume` (a killed or moved run continues
# where its database stops; <dataset>-4-confirm merges the four shards first, then confirms the
# best with the merged directory's own config), its stderr into RUNROOT/NAME.log, and when it finishes appends a line
# to RUNROOT/runs.tsv: name, command, start and end (UTC), wall seconds, peak resident KB, database
# bytes, exit status. Extra arguments (e.g. --set threads=1) go to the sweep. MOMENTBENCH_REPO
# names the checkout whose configs/ it reads (default: this script's).
set -euo pipefail
mb=$1 root=$2 name=$3
shift 3
repo=${MOMENTBENCH_REPO:-$(cd "$(dirname "$0")/.." && pwd)}
cfg=$repo/configs/sweeps
case $name in
  default-2-exact) args=(--config "$cfg/full.yaml" --set combination_size=2) ;;
  default-3-screened) args=(--config "$cfg/full-screened.yaml" --set combination_size=3) ;;
  default-4-screened-[1-4]of4)
    k=${name#default-4-screened-}
    args=(--config "$cfg/full-screened.yaml" --set screen.top=100 --shard "${k%of4}/4") ;;
  default-4-exact-sample) args=(--config "$cfg/full.yaml" --set sample=1000 --set sample_seed=2015) ;;
  translucent-4-screened-[1-4]of4)
    k=${name#translucent-4-screened-}
    args=(--config "$cfg/full-translucent.yaml" --shard "${k%of4}/4") ;;
  translucent-4-exact-sample)
    args=(--config "$cfg/full-translucent.yaml" --set screen.fraction=0 --set sample=1000
      --set sample_seed=2015) ;;
  transparency-4-screened-[1-4]of4)
    k=${name#transparency-4-screened-}
    args=(--config "$cfg/full-transparency.yaml" --shard "${k%of4}/4") ;;
  # A quarter of the seeded 1 000 (every fourth by rank, `--shard 1/4`): the budget's share.
  transparency-4-exact-sample)
    args=(--config "$cfg/full-transparency.yaml" --set screen.fraction=0 --set sample=1000
      --shard 1/4) ;;
  # After every shard of a screened run: merge them (once) and confirm, in <dataset>-4-confirm.
  default-4-confirm | translucent-4-confirm | transparency-4-confirm)
    shards=("$root/${name%-confirm}-screened-"[1-4]of4)
    if [ ! -e "$root/$name/results.sqlite" ]; then
      "$mb" merge "${shards[@]}" -o "$root/$name" >>"$root/$name.log" 2>&1
    fi
    args=() ;;
  *) echo "full_runs.sh: unknown run '$name'" >&2; exit 2 ;;
esac
mkdir -p "$root"
out=$root/$name
command=("$mb" sweep "${args[@]}" "$@" --resume -o "$out")
start=$(date -u +%FT%TZ)
t0=$(date +%s)
set +e
/usr/bin/time -f "%M" -o "$root/$name.rss" "${command[@]}" 2>>"$root/$name.log"
status=$?
set -e
t1=$(date +%s)
bytes=$(stat -c %s "$out/results.sqlite" 2>/dev/null || echo 0)
shown="${command[*]}"
printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "momentbench ${shown#"$mb "}" "$start" \
  "$(date -u +%FT%TZ)" "$((t1 - t0))" "$(tail -1 "$root/$name.rss")" "$bytes" "$status" \
  >>"$root/runs.tsv"
exit $status
