#!/usr/bin/env bash
# Issue 61's measurements of stored formats on the default dataset (results/FINDINGS.md §14),
# published under results/storage-default/:
#   scripts/storage_findings.sh MOMENTBENCH WORKDIR
# Runs, each into WORKDIR/NAME (skipped when WORKDIR/NAME/report.md exists, so a killed run
# continues with the piece it stopped in):
#   formats            every stored row at its own bias beside its double closed form
#   equal-bias         the double closed forms at the stored rows' biases (hamburger4 and
#                      hausdorff4 at 3e-5, hamburger6 at 4e-3): what the format alone loses
#   alpha-A            the 16-bit rows at bias A = 1e-4, 1e-5, 3e-6, 1e-6 (seed 000 §4.3's 3e-5
#                      is `formats`)
#   six-alpha-A        six moments in double and at 10 bits at A = 1e-3, 1e-2 (seed 004 §2.5's
#                      4e-3 is `formats`)
#   lp-double          Problem 1 in double for the stored rows' other bases (power2, power6)
#   lp-stored-ROW      Problem 1 over the moment box of ROW's own format (GLPK, each box LP cold:
#                      4 to 8 minutes a row on 2 threads beside other runs)
#   scatter            the scattering dataset's stored rows (pss_msm4_16bit, pss_msm6_10bit)
#                      beside pss_lp_stored: of their maps and pss_lp: in double, scatter.beta 0
# and `storage` for the power bases m = 2..6 (transforms.jsonl). Then copies each report.md and
# errors.csv (no images) and commands.tsv (each piece's command, wall seconds and the commit of the
# binary that made it) into results/storage-default/.
set -euo pipefail
mb=$1 work=$2
repo=$(cd "$(dirname "$0")/.." && pwd)
out=$repo/results/storage-default
mkdir -p "$work"
log=$work/commands.tsv
# The git commit of the binary that made a run (its run metadata).
sha_of() { sed -n 's/^git_sha: *//p' "$1/run.yaml"; }
run() {
  local name=$1
  shift
  [ -e "$work/$name/report.md" ] && return 0
  rm -rf "$work/$name"
  local t0
  t0=$(date +%s)
  "$mb" eval --set dataset=default --set images=false "$@" --out "$work/$name" >"$work/$name.log" 2>&1
  printf '%s\tmomentbench eval --set dataset=default --set images=false %s --out %s\t%s\t%s\n' \
    "$name" "$*" "$name" "$(($(date +%s) - t0))" "$(sha_of "$work/$name")" >>"$log"
}
stored='hamburger4_16bit, hamburger4_16bit_canonical, hausdorff4_16bit, vsm_16bit, hamburger6_10bit'
run formats --set "techniques=[hamburger4, hausdorff4, vsm, hamburger6, $stored]"
run equal-bias --set 'techniques=[hamburger4, hausdorff4, hamburger6]' \
  --set hamburger4.alpha=3e-5 --set hausdorff4.alpha=3e-5 --set hamburger6.alpha=4e-3
for a in 1e-4 1e-5 3e-6 1e-6; do
  run "alpha-$a" --set 'techniques=[hamburger4_16bit, hamburger4_16bit_canonical, hausdorff4_16bit]' \
    --set "hamburger4_16bit.alpha=$a" --set "hamburger4_16bit_canonical.alpha=$a" \
    --set "hausdorff4_16bit.alpha=$a"
done
for a in 1e-3 1e-2; do
  run "six-alpha-$a" --set 'techniques=[hamburger6, hamburger6_10bit]' \
    --set "hamburger6.alpha=$a" --set "hamburger6_10bit.alpha=$a"
done
# The LP in double for each stored row's basis (lp:power4 is in results/eval-default-biased).
run lp-double --set 'techniques=[lp:power2, lp:power6]'
# hausdorff4_16bit reads the same map as hamburger4_16bit (theta_4, 16 bits): one box for both.
for row in hamburger4_16bit hamburger4_16bit_canonical vsm_16bit hamburger6_10bit; do
  run "lp-stored-$row" --set "techniques=[lp_stored:$row]"
done
# Single scattering (docs/scattering.md §3.2): the stored rows beside the LP over their maps' boxes
# and in double, at scatter.beta 0 (the box answers the sharp lower bound only).
if [ ! -e "$work/scatter/report.md" ]; then
  rm -rf "$work/scatter"
  t0=$(date +%s)
  techniques='[pss_exact, pss_lp:power4, pss_lp_stored:pss_msm4_16bit, pss_msm4, pss_msm4_16bit, pss_lp:power6, pss_lp_stored:pss_msm6_10bit, pss_msm6, pss_msm6_10bit]'
  "$mb" scatter --set dataset=scattering --set scatter.beta=0 --set images=false \
    --set "techniques=$techniques" --out "$work/scatter" >"$work/scatter.log" 2>&1
  printf 'scatter\tmomentbench scatter --set dataset=scattering --set scatter.beta=0 --set images=false --set "techniques=%s" --out scatter\t%s\t%s\n' \
    "$techniques" "$(($(date +%s) - t0))" "$(sha_of "$work/scatter")" >>"$log"
fi
if [ ! -s "$work/transforms.jsonl" ]; then
  rm -f "$work/transforms.jsonl.tmp"
  for m in 2 3 4 5 6; do
    basis=z
    for ((k = 2; k <= m; ++k)); do basis="$basis,z^$k"; done
    kinds=(canonical optimized)
    { [ "$m" = 2 ] || [ "$m" = 4 ]; } && kinds+=(seed)
    for kind in "${kinds[@]}"; do
      "$mb" storage --basis "$basis" --transform "$kind" | /usr/bin/python3 -c \
        'import json, sys; print(json.dumps(json.load(sys.stdin)))' >>"$work/transforms.jsonl.tmp"
    done
  done
  mv "$work/transforms.jsonl.tmp" "$work/transforms.jsonl"
fi
mkdir -p "$out"
for dir in "$work"/*/; do
  name=$(basename "$dir")
  mkdir -p "$out/$name"
  for f in report.md errors.csv; do
    [ -e "$dir/$f" ] && cp "$dir/$f" "$out/$name/"
  done
done
cp "$work/transforms.jsonl" "$out/"
{
  printf 'name\tcommand\twall_s\tgit\n'
  cat "$log"
} >"$out/commands.tsv"
echo "published $out"
