#!/usr/bin/env bash
# Reproduces results/FINDINGS.md: the sweeps of configs/sweeps/findings-{2,3,4}.yaml on the default
# dataset (every two-function candidate, 300 of three and 600 of four; about 45 minutes on two
# cores, each resumable), their joint report, and eval of every classic technique under both
# references, and eval of the soft techniques on the soft and fusion datasets. Writes into OUTROOT (default
# out/findings).
set -euo pipefail
cd "$(dirname "$0")/.."
root=${1:-out/findings}
mkdir -p "$root"
# MB: a built binary to run instead (scripts/regenerate_results.sh); otherwise build it here.
if [ -n "${MB:-}" ]; then
  mb=$MB
else
  cmake --preset release >/dev/null
  cmake --build --preset release -j "$(nproc)" --target momentbench
  mb=./build/release/momentbench
fi
for k in 2 3 4; do
  $mb sweep -q --config "configs/sweeps/findings-$k.yaml" --resume --out "$root/sweep-$k"
done
$mb report -q "$root/sweep-2" "$root/sweep-3" "$root/sweep-4" --out "$root/report" --force >/dev/null
techniques='[pcf, vsm, esm, hamburger4, hamburger4_float, hamburger4_16bit, hausdorff4, hamburger6, tmsm, tmsm_float, lp:power4, lp:trig4]'
for reference in biased receiver_plane; do
  $mb eval -q --set dataset=default --set reference=$reference --set "techniques=$techniques" --set images=false \
    --out "$root/eval-$reference" --force >/dev/null
done
# Soft shadows (FINDINGS §11): the soft dataset's 36 view-angles against their area lights.
$mb eval -q --set dataset=soft --set 'techniques=[pcf, hamburger4, vsm, pcss_exact, pcss, pcss_vsm, pcss_esm, pcss_csm, msm_soft, msm_soft:lp:power4, msm_soft:lp:trig4]' \
  --out "$root/eval-soft" --force >/dev/null
echo "findings: $root/eval-soft/report.md"
# Seed 004's failure modes (FINDINGS §11): occluder fusion and short-range leaking.
$mb eval -q --set dataset=configs/datasets/fusion.yaml --set images=false \
  --set 'techniques=[pcf, pcss_exact, pcss, pcss_vsm, msm_soft, msm_soft:lp:power4]' --out "$root/eval-fusion" --force >/dev/null
/usr/bin/python3 scripts/fusion_interaction.py "$root/eval-fusion" > "$root/eval-fusion/fusion.md"
echo "findings: $root/eval-fusion/fusion.md"
echo "findings: $root/report/report.md, $root/eval-biased/report.md, $root/eval-receiver_plane/report.md"
